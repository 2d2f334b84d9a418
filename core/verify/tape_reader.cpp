// The reader of the ISO and SINUMERIK tapes (readTape, tape_reader.h): the
// tape split into lines, each line's comments taken out and its words read
// strictly (tape_reader_iso.h's IsoReader), or the reading stopped at its
// line. What each block's words do is in tape_reader_iso_block.cpp, the
// Klartext reader in tape_reader_klartext.cpp, the drilling cycles in
// tape_reader_cycles.cpp.
#include "verify/tape_reader_iso.h"

#include <string_view>

namespace taiwa::verify {

TapeReading readKlartext(const std::string& text);  // tape_reader_klartext.cpp

namespace tape {

IsoReader::IsoReader(const post::Dialect& d)
    : sinumerik_(d.syntax == post::Syntax::Sinumerik),
      framed_(!sinumerik_ && d.percentFraming),
      numbered_(!sinumerik_ && !d.programNumberLine.empty()),
      points_(!sinumerik_ && d.decimalPointAlways),
      offsetNeeded_(!d.lengthOffset.empty()),
      dwellWord_(sinumerik_ ? 'F' : d.dwellWord),
      tapSynchronised_(d.tap == "G33.1")
{
}

TapeReading IsoReader::read(const std::string& text)
{
    const auto lines = splitLines(text);
    try {
        for (std::size_t i = 0; i < lines.size(); ++i) {
            m_.line = static_cast<int>(i) + 1;
            line(lines[i]);
        }
        m_.line = static_cast<int>(lines.size());
        if (!ended_) refuse("the program does not end with M30");
        if (framed_ && (lines.empty() || lines.front() != "%" || lines.back() != "%"))
            refuse("the dialect's tape begins and ends with a '%' line");
    } catch (const Unread& r) {
        m_.out.error = lineError(m_.line, r, lines);
        m_.out.errorLine = m_.line;
    }
    return std::move(m_.out);
}

std::string IsoReader::withoutComments(const std::string& s)
{
    if (sinumerik_) {
        const auto semicolon = s.find(';');
        // Parentheses belong to CYCLE81(...) only: anywhere else the
        // word is not understood ("(text)" is no SINUMERIK comment).
        if (semicolon != std::string::npos) m_.comment(s.substr(semicolon + 1));
        return s.substr(0, semicolon);
    }
    std::string rest;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] == ')') refuse("')' with no '(' before it");
        if (s[i] == ';') refuse("';': this dialect's comments are in parentheses");
        if (s[i] != '(') {
            rest += s[i];
            continue;
        }
        const auto close = s.find(')', i);
        if (close == std::string::npos) refuse("a comment with no ')'");
        const std::string inside = s.substr(i + 1, close - i - 1);
        if (inside.find('(') != std::string::npos) refuse("a nested comment");
        m_.comment(inside);
        rest += ' ';
        i = close;
    }
    return rest;
}

IsoReader::Block IsoReader::words(const std::vector<std::string>& tokens)
{
    Block b;
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const std::string& t = tokens[k];
        if (sinumerik_ && t == "SUPA") {
            b.supa = true;
            continue;
        }
        if (sinumerik_ && t == "MCALL") {
            b.mcall = true;
            continue;
        }
        if (sinumerik_ && t.starts_with("CYCLE")) {
            if (!b.cycle.empty()) refuse("two cycles in one block");
            b.cycle = t;
            continue;
        }
        if (sinumerik_ && t.starts_with("ADIS=")) {
            b.adis = decimal(std::string_view(t).substr(5), false);
            if (!b.adis) refuse("'" + t + "' is not understood");
            continue;
        }
        const char letter = t[0];
        const std::string_view number = std::string_view(t).substr(1);
        if (letter == 'N') {
            if (k != 0 || !whole(number)) refuse("'" + t + "': a sequence number only at the start of a block");
            continue;
        }
        if (letter == 'M') {
            const auto n = whole(number);
            if (!n) refuse("'" + t + "' is not understood");
            b.m.push_back(*n);
            continue;
        }
        if (letter == 'G') {
            // G59.1, G33.1, G54.1: in tenths.
            const auto dot = number.find('.');
            const auto n = whole(number.substr(0, dot));
            const auto tenth = dot == std::string_view::npos ? std::optional<int>(0) : whole(number.substr(dot + 1));
            if (!n || !tenth || *tenth > 9 || (dot != std::string_view::npos && number.size() != dot + 2))
                refuse("'" + t + "' is not understood");
            b.g.push_back(*n * 10 + *tenth);
            continue;
        }
        const std::string letters = sinumerik_ ? "XYZIJFSTD" : "XYZIJKRFPQSTH";
        if (letters.find(letter) == std::string::npos || number.empty()) refuse("'" + t + "' is not understood");
        if (b.has(letter)) refuse(std::string("two ") + letter + " words in one block");
        if (letter == 'S' || letter == 'T' || letter == 'D' || letter == 'H') {
            const auto n = whole(number);
            if (!n) refuse("'" + t + "' is not understood (a whole number expected)");
            b.v[letter] = *n;
            continue;
        }
        const auto value = decimal(number, false);
        if (!value) refuse("'" + t + "' is not understood");
        b.v[letter] = *value;
        b.point[letter] = number.find('.') != std::string_view::npos;
        // A FANUC or a Haas reads a number without a point in least
        // increments (X10 = 0.01 mm); their tapes always write the point.
        if (points_ && letter != 'P' && !b.point[letter])
            refuse("'" + t + "' without a decimal point (this control reads it in least increments)");
    }
    return b;
}

void IsoReader::line(const std::string& raw)
{
    if (raw.find_first_of("\r\t") != std::string::npos) refuse("a carriage return or tab");
    const std::string s = trim(withoutComments(raw));
    if (s.empty()) return;
    if (framed_ && s == "%") {
        if (++percents_ > 2) refuse("a third '%' line");
        return;
    }
    if (percents_ == 2) refuse("text after the closing '%'");
    if (framed_ && percents_ == 0) refuse("a block before the leading '%'");
    if (ended_) refuse("a block after M30");
    const auto tokens = splitWords(s);
    if (numbered_ && tokens.size() == 1 && tokens[0][0] == 'O') {
        if (!whole(std::string_view(tokens[0]).substr(1)) || programNumber_) refuse("'" + tokens[0] + "' is not understood");
        programNumber_ = true;
        return;
    }
    block(words(tokens));
}

}  // namespace tape

TapeReading readTape(const std::string& text, const post::Dialect& dialect)
{
    if (dialect.syntax == post::Syntax::Klartext) return readKlartext(text);
    return tape::IsoReader(dialect).read(text);
}

}  // namespace taiwa::verify
