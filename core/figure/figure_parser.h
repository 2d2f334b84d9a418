// The figure language's recursive-descent parser (parseFigure in
// figure_text.cpp runs it): statements, names, arguments and the checks
// text alone can make. The element statements (POINT, LINE, CIRCLE,
// CONTOUR...) are read in figure_parse_elements.cpp. Internal to core/figure.
#pragma once

#include "figure/figure_lexer.h"
#include "figure/figure_text.h"
#include "model/result.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace taiwa::figure::text {

// Each modifier by its word (keyword(Modifier)'s, read back).
inline const std::map<std::string, Modifier, std::less<>>& modifierWords()
{
    static const auto m = [] {
        std::map<std::string, Modifier, std::less<>> words;
        for (int i = 0; i <= static_cast<int>(Modifier::In); ++i)
            words.emplace(keyword(static_cast<Modifier>(i)), static_cast<Modifier>(i));
        return words;
    }();
    return m;
}

inline bool isReserved(std::string_view w)
{
    static const std::array<std::string_view, 15> words{"POINT",  "LINE",   "CIRCLE", "INTOF",   "CENTER",
                                                        "ATANGL", "PARLEL", "TANTO",  "RADIUS",  "ON",
                                                        "CONTOUR", "CLW",   "CCLW",   "ROUND",   "CHAMF"};
    for (const auto r : words)
        if (w == r) return true;
    return modifierWords().count(w) > 0;
}

inline bool isXY(Modifier m)
{
    return m == Modifier::XLarge || m == Modifier::XSmall || m == Modifier::YLarge || m == Modifier::YSmall;
}

inline constexpr const char* kXY = TAIWA_TRANSLATE_NOOP("taiwa::msg", "XLARGE, XSMALL, YLARGE or YSMALL");

// The parser refuses with taiwa::Refusal (model/result.h) at the text's line
// and column; parseFigure catches it and returns it as a FigureError, so the
// recursive descent stays readable.

class Parser {
public:
    explicit Parser(std::string_view text) : lex_(text), expected_(lex_.statementEstimate()) { advance(); }

    std::vector<Definition> statements()
    {
        std::vector<Definition> out;
        out.reserve(expected_);
        eachStatement([&](Definition&& d) {
            out.push_back(std::move(d));
            return true;
        });
        return out;
    }

    // Each statement as it is read, handed to `each`, which stops the
    // reading by returning false (a text read back and compared with what
    // was written, none of it kept).
    template <class F>
    void eachStatement(F&& each)
    {
        defined_.reserve(expected_);
        for (;;) {
            while (cur_.tok == Tok::EndOfLine) advance();
            if (cur_.tok == Tok::EndOfText) return;
            if (!each(statement())) return;
        }
    }

private:
    struct Defined {
        Kind kind;
        int line;
    };

    void advance()
    {
        prev_ = std::move(cur_);
        cur_ = lex_.next();
    }

    static std::string describe(const Token& t)
    {
        switch (t.tok) {
        case Tok::EndOfLine: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the end of the line");
        case Tok::EndOfText: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the end of the text");
        case Tok::Bad: return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the character '{}'"), printable(t.text));
        default: {
            std::string s = printable(t.text);
            if (s.size() > 24) s = s.substr(0, 24) + "...";
            return "'" + s + "'";
        }
        }
    }

    std::string after() const
    {
        if (prev_.tok == Tok::Word || prev_.tok == Tok::Number) return "'" + printable(prev_.text) + "'";
        return "'" + prev_.text + "'";
    }

    [[noreturn]] void fail(const Token& at, std::string message) const
    {
        throw taiwa::Refusal(std::move(message), taiwa::Place::inText(at.line, at.column));
    }

    [[noreturn]] static void failAt(const Place& at, std::string message)
    {
        throw taiwa::Refusal(std::move(message), taiwa::Place::inText(at.line, at.column));
    }

    [[noreturn]] void expected(const std::string& what) const
    {
        fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "expected {} after {}, found {}"), what, after(), describe(cur_)));
    }

    bool atWord(std::string_view w) const { return cur_.tok == Tok::Word && cur_.text == w; }

    // Past the word w when it stands next; whether it did.
    bool accept(std::string_view w)
    {
        if (!atWord(w)) return false;
        advance();
        return true;
    }

    std::optional<Modifier> atModifier() const
    {
        if (cur_.tok != Tok::Word) return std::nullopt;
        const auto it = modifierWords().find(cur_.text);
        if (it == modifierWords().end()) return std::nullopt;
        return it->second;
    }

    bool atName() const { return cur_.tok == Tok::Word && !isReserved(cur_.text); }

    void comma()
    {
        if (cur_.tok != Tok::Comma) expected("','");
        advance();
    }

    void word(const char* w)
    {
        if (!accept(w)) expected(w);
    }

    Modifier modifier(bool xy, const char* what)
    {
        const auto m = atModifier();
        if (!m || isXY(*m) != xy) expected(what);
        advance();
        return *m;
    }

    Modifier leftRight()
    {
        const auto m = atModifier();
        if (!m || (*m != Modifier::Left && *m != Modifier::Right)) expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "LEFT or RIGHT"));
        advance();
        return *m;
    }

    // A number; with `quantity` ("the radius") zero and negatives are refused.
    double number(const std::string& what, const char* quantity = nullptr)
    {
        if (cur_.tok != Tok::Number) expected(what);
        const double v = cur_.value;
        if (!(std::abs(v) <= kMaxNumber))
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the number {} is out of range (at most 1000000 either way)"), describe(cur_)));
        if (quantity && !(v > 0)) fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} must be greater than 0, found {}"), quantity, describe(cur_)));
        advance();
        return v;
    }

    // A reference to an element defined earlier, of the kind its place needs.
    std::string ref(Kind wanted, const std::string& what)
    {
        if (!atName()) expected(what);
        const auto it = defined_.find(cur_.text);
        if (it == defined_.end())
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is not defined: an element must be defined before it is used"), name_, cur_.text));
        if (it->second.kind != wanted)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is {} where {} is needed"), name_, cur_.text,
                                   noun(it->second.kind), noun(wanted)));
        std::string n = cur_.text;
        advance();
        return n;
    }

    // Either a line or a circle (an intersection's arguments).
    std::string curve(Kind& kind)
    {
        if (!atName()) expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a line or circle name"));
        const auto it = defined_.find(cur_.text);
        if (it == defined_.end())
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is not defined: an element must be defined before it is used"), name_, cur_.text));
        if (it->second.kind != Kind::Line && it->second.kind != Kind::Circle)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "in {}, {} is {} where a line or a circle is needed"), name_, cur_.text,
                                   noun(it->second.kind)));
        kind = it->second.kind;
        std::string n = cur_.text;
        advance();
        return n;
    }

    Definition statement()
    {
        Definition d;
        d.line = cur_.line;
        d.column = cur_.column;
        if (cur_.tok != Tok::Word)
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "expected an element name at the start of a statement, found {}"), describe(cur_)));
        if (isReserved(cur_.text))
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "'{}' is a word of the language and cannot name an element"), cur_.text));
        d.name = cur_.text;
        name_ = d.name;
        if (const auto it = defined_.find(d.name); it != defined_.end())
            fail(cur_, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is already defined on line {}"), d.name, it->second.line));
        const Token nameToken = cur_;
        advance();
        if (cur_.tok != Tok::Equals) expected("'='");
        advance();
        if (accept("POINT")) {
            slash();
            point(d);
        } else if (accept("LINE")) {
            slash();
            line(d);
        } else if (accept("CIRCLE")) {
            slash();
            circle(d);
        } else if (accept("CONTOUR")) {
            slash();
            contour(d);
        } else {
            expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "POINT, LINE, CIRCLE or CONTOUR"));
        }
        if (cur_.tok != Tok::EndOfLine && cur_.tok != Tok::EndOfText) expected(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the end of the statement"));
        defined_[d.name] = Defined{d.kind(), nameToken.line};
        return d;
    }

    void slash()
    {
        if (cur_.tok != Tok::Slash) expected("'/'");
        advance();
    }

    void point(Definition& d);

    void line(Definition& d);
    // LEFT|RIGHT, TANTO, C1: the side of a tangent line and the circle it touches.
    void tangentCircle(Definition& d);

    void circle(Definition& d);

    void radius(Definition& d);

    static Place placeOf(const Token& t) { return {t.line, t.column, static_cast<int>(t.text.size())}; }

    // The kind of an element already defined, or a refusal naming it.
    Kind definedKind() const;

    // CONTOUR/[P1,] step, step... [, P2] with step = [XLARGE,] [CLW|CCLW,] NAME [, ROUND|CHAMF, value].
    void contour(Definition& d);

    Lexer lex_;
    std::size_t expected_;  // about how many statements the text holds: room made once
    Token cur_;
    Token prev_;
    std::string name_;  // the element being defined, for messages
    std::unordered_map<std::string, Defined> defined_;
};

}  // namespace taiwa::figure::text
