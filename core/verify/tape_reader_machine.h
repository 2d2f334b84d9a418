// What the tape readers of tape_reader.h share: the strict reading of
// lines, words and numbers, the refusal that names a line, and the machine
// the readers drive (position, feed, tool, step) recording the motions as
// rs274 reports them (a lathe's arcs, threading passes and cycles too).
// Internal to core/verify (the readers: tape_reader*.h and tape_reader*.cpp).
#pragma once

#include "verify/tape_reader.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::verify::tape {

inline constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

// How far above the last peck's bottom a pecking cycle comes back down in
// rapid: rs274's G83_RAPID_DELTA, 0.010 inch (0.254 mm). The real controls
// take it from a machine setting (Haas setting 22, SINUMERIK's anticipation
// distance, HEIDENHAIN's advanced stop distance), never from the tape, so the
// readers take LinuxCNC's.
inline double peckReturn(bool inches) { return inches ? 0.010 : 0.254; }

// A block the reader does not understand (not model/result.h's Refusal:
// this one never leaves the reader).
struct Unread {
    std::string what;
};

[[noreturn]] inline void refuse(const std::string& what) { throw Unread{what}; }

// "line 12: why [the line]" (1-based).
inline std::string lineError(int line, const Unread& r, const std::vector<std::string>& lines)
{
    const std::size_t i = static_cast<std::size_t>(line) - 1;
    return "line " + std::to_string(line) + ": " + r.what + (i < lines.size() ? " [" + lines[i] + "]" : std::string());
}

inline std::vector<std::string> splitLines(const std::string& text)
{
    std::vector<std::string> lines;
    std::size_t from = 0;
    while (from < text.size()) {
        const std::size_t end = text.find('\n', from);
        if (end == std::string::npos) {
            lines.push_back(text.substr(from));
            break;
        }
        lines.push_back(text.substr(from, end - from));
        from = end + 1;
    }
    return lines;
}

inline std::vector<std::string> splitWords(const std::string& s)
{
    std::vector<std::string> words;
    std::istringstream in(s);
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

inline std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(' ');
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// A decimal number: a sign ('+' only when `plusAllowed`), digits and at most
// one point; no exponent, no "inf", nothing after it.
inline std::optional<double> decimal(std::string_view s, bool plusAllowed)
{
    std::string_view body = s;
    if (!body.empty() && (body.front() == '-' || body.front() == '+')) {
        if (body.front() == '+' && !plusAllowed) return std::nullopt;
        body.remove_prefix(1);
    }
    if (body.empty() || body == ".") return std::nullopt;
    int points = 0;
    for (const char c : body) {
        if (c == '.') ++points;
        else if (c < '0' || c > '9') return std::nullopt;
    }
    if (points > 1) return std::nullopt;
    const std::string_view digits = s.front() == '+' ? s.substr(1) : s;
    double v = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
    return v;
}

// A whole number of digits only (leading zeros allowed: "M06").
inline std::optional<int> whole(std::string_view s)
{
    if (s.empty() || s.size() > 9) return std::nullopt;
    int v = 0;
    for (const char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + (c - '0');
    }
    return v;
}

inline std::string show(double v)
{
    std::ostringstream o;
    o << v;
    return o.str();
}

inline bool known(const Point3& p) { return !std::isnan(p.x) && !std::isnan(p.y) && !std::isnan(p.z); }

// The machine the readers drive: the position, feed, tool and step, and the
// moves as rs274 would report them.
// The words both ISO readers take alike: a sequence number (N, first in its
// block; its value in `n` when asked), an M word and a G word (in tenths:
// G59.1 is 591). False when `t` is none of them.
inline bool codeWord(const std::string& t, std::size_t k, std::vector<int>& g, std::vector<int>& m, int* n = nullptr)
{
    const char letter = t[0];
    const std::string_view number = std::string_view(t).substr(1);
    if (letter == 'N') {
        const auto value = whole(number);
        if (k != 0 || !value) refuse("'" + t + "': a sequence number only at the start of a block");
        if (n) *n = *value;
        return true;
    }
    if (letter == 'M') {
        const auto value = whole(number);
        if (!value) refuse("'" + t + "' is not understood");
        m.push_back(*value);
        return true;
    }
    if (letter != 'G') return false;
    const auto dot = number.find('.');
    const auto value = whole(number.substr(0, dot));
    const auto tenth = dot == std::string_view::npos ? std::optional<int>(0) : whole(number.substr(dot + 1));
    if (!value || !tenth || *tenth > 9 || (dot != std::string_view::npos && number.size() != dot + 2))
        refuse("'" + t + "' is not understood");
    g.push_back(*value * 10 + *tenth);
    return true;
}

// A letter word of `letters`, once a block, into b.v: a whole number for
// the letters of `wholes`, else a decimal, b.point saying whether it was
// written with its point. True for a decimal (the caller then holds it to
// its dialect's points), false for a whole number.
template <class Block>
bool letterWord(const std::string& t, std::string_view letters, std::string_view wholes, Block& b)
{
    const char letter = t[0];
    const std::string_view number = std::string_view(t).substr(1);
    if (letters.find(letter) == std::string_view::npos || number.empty()) refuse("'" + t + "' is not understood");
    if (b.has(letter)) refuse(std::string("two ") + letter + " words in one block");
    if (wholes.find(letter) != std::string_view::npos) {
        const auto n = whole(number);
        if (!n) refuse("'" + t + "' is not understood (a whole number expected)");
        b.v[letter] = *n;
        return false;
    }
    const auto value = decimal(number, false);
    if (!value) refuse("'" + t + "' is not understood");
    b.v[letter] = *value;
    b.point[letter] = number.find('.') != std::string_view::npos;
    return true;
}

class Machine {
public:
    TapeReading out;
    Point3 at{kUnknown, kUnknown, kUnknown};
    double feed = kUnknown;  // the modal feed rate
    int tool = 0;
    int step = 0;
    int line = 0;
    bool unitsStated = false;
    // An ISO tape's framing: '%' lines lead and end it (`framed`), how many
    // were read, and whether M30 was.
    bool framed = false;
    bool ended = false;
    int percents = 0;

    // Whether the line `s` (its comments out, trimmed, not empty) is a '%'
    // line of the framing; one out of place, text after the closing one, a
    // block before the leading one or after M30 is refused.
    bool framingLine(const std::string& s)
    {
        if (framed && s == "%") {
            if (++percents > 2) refuse("a third '%' line");
            return true;
        }
        if (percents == 2) refuse("text after the closing '%'");
        if (framed && percents == 0) refuse("a block before the leading '%'");
        if (ended) refuse("a block after M30");
        return false;
    }
    // At the tape's end: it ended with M30, and is framed as its dialect frames it.
    void endOfTape(const std::vector<std::string>& lines) const
    {
        if (!ended) refuse("the program does not end with M30");
        if (framed && (lines.empty() || lines.front() != "%" || lines.back() != "%"))
            refuse("the dialect's tape begins and ends with a '%' line");
    }

    void units(bool inches)
    {
        if (unitsStated && inches != out.inches) refuse("the units change in the middle of the program");
        out.inches = inches;
        unitsStated = true;
    }
    void comment(const std::string& text)
    {
        static const std::regex stepComment(R"(^\s*STEP (\d+):)", std::regex::icase);
        std::smatch m;
        if (std::regex_search(text, m, stepComment)) step = std::stoi(m[1].str());
    }
    // A line without its comments, each handed to comment(): after ';' on
    // SINUMERIK (`semicolon`; parentheses there belong to CYCLE81(...)
    // only: "(text)" is no SINUMERIK comment), else in parentheses, closed,
    // not nested, and no ';'.
    std::string withoutComments(const std::string& s, bool semicolon)
    {
        if (semicolon) {
            const auto semicolonAt = s.find(';');
            if (semicolonAt != std::string::npos) comment(s.substr(semicolonAt + 1));
            return s.substr(0, semicolonAt);
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
            comment(inside);
            rest += ' ';
            i = close;
        }
        return rest;
    }
    // An ISO tape read line by line through eachLine(raw), then end(lines)
    // at its end; the first refusal stops the reading, its line named.
    template <class EachLine, class End>
    TapeReading readLines(const std::string& text, EachLine&& eachLine, End&& end)
    {
        const auto lines = splitLines(text);
        try {
            for (std::size_t i = 0; i < lines.size(); ++i) {
                line = static_cast<int>(i) + 1;
                eachLine(lines[i]);
            }
            line = static_cast<int>(lines.size());
            end(lines);
        } catch (const Unread& r) {
            out.error = lineError(line, r, lines);
            out.errorLine = line;
        }
        return std::move(out);
    }
    void traverse(const Point3& to) { record(TapeMotion::Traverse, to, 0.0, {}, 0); }
    void feedTo(const Point3& to, double feedRate)
    {
        if (!known(at)) refuse("a feed move from an unknown position");
        if (!(feedRate > 0)) refuse("a feed move with no feed rate in force");
        record(TapeMotion::Feed, to, feedRate, {}, 0);
    }
    void arc(const Point3& to, Point2 centre, int rotation, double feedRate)
    {
        if (!known(at)) refuse("an arc from an unknown position");
        if (!(feedRate > 0)) refuse("an arc with no feed rate in force");
        // As rs274: the end must lie on the circle through the start.
        const double r0 = std::hypot(at.x - centre.x, at.y - centre.y);
        const double r1 = std::hypot(to.x - centre.x, to.y - centre.y);
        const double tolerance = out.inches ? 0.0005 : 0.005;
        if (std::abs(r0 - r1) > tolerance)
            refuse("the arc's end is not on its circle: radius " + show(r0) + " at the start, " + show(r1) + " at the end");
        if (r0 < tolerance) refuse("an arc of no radius");
        record(TapeMotion::Arc, to, feedRate, centre, rotation);
    }

    // A lathe's (tape_reader_lathe.h): X a diameter, the arc's centre (X, Z)
    // and its turn with Z right and X up; the end must lie on the circle
    // through the start (in radius, Z).
    void latheArc(const Point3& to, Point2 centre, int rotation, double feedPerRev)
    {
        if (!known(at)) refuse("an arc from an unknown position");
        if (!(feedPerRev > 0)) refuse("an arc with no feed rate in force");
        const double r0 = std::hypot((at.x - centre.x) / 2.0, at.z - centre.y);
        const double r1 = std::hypot((to.x - centre.x) / 2.0, to.z - centre.y);
        const double tolerance = out.inches ? 0.0005 : 0.005;
        if (std::abs(r0 - r1) > tolerance)
            refuse("the arc's end is not on its circle: radius " + show(r0) + " at the start, " + show(r1) + " at the end");
        if (r0 < tolerance) refuse("an arc of no radius");
        record(TapeMotion::Arc, to, feedPerRev, centre, rotation);
    }
    // A lathe's threading pass (G33): `lead` along Z a revolution.
    void threadTo(const Point3& to, double lead)
    {
        if (!known(at)) refuse("a threading pass from an unknown position");
        if (!(lead > 0)) refuse("a threading pass with no lead");
        record(TapeMotion::Feed, to, lead, {}, 0);
        out.motions.back().synchronised = true;
    }
    // A lathe's cycle `index` (out.cycles), ending at `end` (its start).
    void cycle(int index, const Point3& end)
    {
        if (!known(at)) refuse("a cycle from an unknown position");
        record(TapeMotion::Cycle, end, 0.0, {}, 0);
        out.motions.back().cycle = index;
    }

private:
    void record(TapeMotion::Kind kind, const Point3& to, double feedRate, Point2 centre, int rotation)
    {
        if (!unitsStated) refuse("a move before the units are stated");
        out.motions.push_back({.kind = kind, .start = at, .end = to, .centre = centre, .rotation = rotation,
                               .feed = kind == TapeMotion::Traverse ? 0.0 : feedRate, .step = step, .tool = tool,
                               .line = line});
        at = to;
    }
};

}  // namespace taiwa::verify::tape
