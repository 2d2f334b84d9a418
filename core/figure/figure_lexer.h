// The figure language's lexer (figure_text.cpp's parser reads its tokens):
// words upper-cased, numbers, punctuation, ends of line, with their line
// and column for messages. Internal to core/figure.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <system_error>

namespace taiwa::figure::text {

enum class Tok { Word, Number, Comma, Equals, Slash, EndOfLine, EndOfText, Bad };

struct Token {
    Tok tok = Tok::EndOfText;
    std::string text;  // as written (a word upper-cased)
    double value = 0;  // a number's value
    int line = 1;
    int column = 1;
};

inline bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The text of a byte that is not printable ASCII, so that messages stay one
// line of valid UTF-8 whatever the input.
inline std::string printable(std::string_view s)
{
    std::string out;
    for (const char ch : s) {
        const auto u = static_cast<unsigned char>(ch);
        if (u >= 0x20 && u < 0x7f) {
            out += ch;
        } else {
            std::array<char, 8> buf{};
            std::snprintf(buf.data(), buf.size(), "\\x%02X", static_cast<unsigned>(u));
            out += buf.data();
        }
    }
    return out;
}

class Lexer {
public:
    explicit Lexer(std::string_view text) : s_(text) {}

    // About how many statements the text holds (each has one '='): room
    // made at once for a text of many thousands of them.
    std::size_t statementEstimate() const { return static_cast<std::size_t>(std::count(s_.begin(), s_.end(), '=')); }

    Token next()
    {
        skipBlanksAndComments();
        Token t;
        t.line = line_;
        t.column = static_cast<int>(i_ - lineStart_) + 1;
        if (i_ >= s_.size()) return t;
        const char c = s_[i_];
        if (c == '\n') {
            t.tok = Tok::EndOfLine;
            ++i_;
            ++line_;
            lineStart_ = i_;
            return t;
        }
        if (isLetter(c)) {
            t.tok = Tok::Word;
            while (i_ < s_.size() && (isLetter(s_[i_]) || isDigit(s_[i_]))) {
                const char w = s_[i_++];
                t.text += (w >= 'a' && w <= 'z') ? static_cast<char>(w - 'a' + 'A') : w;
            }
            return t;
        }
        const bool sign = c == '+' || c == '-';
        const std::size_t body = i_ + (sign ? 1 : 0);
        const bool startsNumber =
            body < s_.size() &&
            (isDigit(s_[body]) || (s_[body] == '.' && body + 1 < s_.size() && isDigit(s_[body + 1])));
        if (startsNumber) return number(t, sign);
        ++i_;
        t.text = std::string(1, c);
        t.tok = c == ',' ? Tok::Comma : c == '=' ? Tok::Equals : c == '/' ? Tok::Slash : Tok::Bad;
        return t;
    }

private:
    void skipBlanksAndComments()
    {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == ' ' || c == '\t' || c == '\r') {
                ++i_;
            } else if (c == '$' && i_ + 1 < s_.size() && s_[i_ + 1] == '$') {
                while (i_ < s_.size() && s_[i_] != '\n') ++i_;  // $$ comment to the end of the line
            } else {
                return;
            }
        }
    }

    // APT numbers: an optional sign, digits with an optional decimal point
    // (`10`, `10.`, `.5`, `-2.25`); no exponent.
    Token number(Token t, bool sign)
    {
        const std::size_t start = i_;
        const bool negative = sign && s_[i_] == '-';
        if (sign) ++i_;
        const std::size_t digits = i_;
        while (i_ < s_.size() && isDigit(s_[i_])) ++i_;
        if (i_ < s_.size() && s_[i_] == '.') {
            ++i_;
            while (i_ < s_.size() && isDigit(s_[i_])) ++i_;
        }
        t.tok = Tok::Number;
        t.text = std::string(s_.substr(start, i_ - start));
        double v = 0;
        const auto r = std::from_chars(s_.data() + digits, s_.data() + i_, v, std::chars_format::fixed);
        if (r.ec != std::errc() || r.ptr != s_.data() + i_) v = HUGE_VAL;  // out of range: refused by the parser
        t.value = negative ? -v : v;
        return t;
    }

    std::string_view s_;
    std::size_t i_ = 0;
    std::size_t lineStart_ = 0;
    int line_ = 1;
};

}  // namespace taiwa::figure::text
