// Readers of the Haas, SINUMERIK and HEIDENHAIN Klartext tapes, for the
// outside check of those dialects against rs274 (see dialect_reader.h):
// every block is understood word by word, or the tape is refused at its line.
#include "support/dialect_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

namespace taiwa::test {

namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

struct Refusal {
    std::string what;
};

[[noreturn]] void refuse(const std::string& what) { throw Refusal{what}; }

// "line 12: why [the line]" (1-based).
std::string lineError(int line, const Refusal& r, const std::vector<std::string>& lines)
{
    const std::size_t i = static_cast<std::size_t>(line) - 1;
    return "line " + std::to_string(line) + ": " + r.what + (i < lines.size() ? " [" + lines[i] + "]" : std::string());
}

std::vector<std::string> splitLines(const std::string& text)
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

std::vector<std::string> splitWords(const std::string& s)
{
    std::vector<std::string> words;
    std::istringstream in(s);
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

std::string trim(const std::string& s)
{
    const auto b = s.find_first_not_of(' ');
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(' ') - b + 1);
}

// A decimal number: a sign ('+' only when `plusAllowed`), digits and at most
// one point; no exponent, no "inf", nothing after it.
std::optional<double> decimal(std::string_view s, bool plusAllowed)
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
std::optional<int> whole(std::string_view s)
{
    if (s.empty() || s.size() > 9) return std::nullopt;
    int v = 0;
    for (const char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        v = v * 10 + (c - '0');
    }
    return v;
}

std::string show(double v)
{
    std::ostringstream o;
    o << v;
    return o.str();
}

bool known(const Point3& p) { return !std::isnan(p.x) && !std::isnan(p.y) && !std::isnan(p.z); }

// The machine the readers drive: the position, feed, tool and step, and the
// moves as rs274 would report them.
class Machine {
public:
    DialectMoves out;
    Point3 at{kUnknown, kUnknown, kUnknown};
    double feed = kUnknown;  // the modal feed rate
    int tool = 0;
    int step = 0;
    int line = 0;
    bool unitsStated = false;

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
    void traverse(const Point3& to) { record(CanonMove::Traverse, to, 0.0, {}, 0); }
    void feedTo(const Point3& to, double feedRate)
    {
        if (!known(at)) refuse("a feed move from an unknown position");
        if (!(feedRate > 0)) refuse("a feed move with no feed rate in force");
        record(CanonMove::Feed, to, feedRate, {}, 0);
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
        record(CanonMove::Arc, to, feedRate, centre, rotation);
    }

private:
    void record(CanonMove::Kind kind, const Point3& to, double feedRate, Point2 centre, int rotation)
    {
        if (!unitsStated) refuse("a move before the units are stated");
        CanonMove c;
        c.kind = kind;
        c.start = at;
        c.end = to;
        c.centre = centre;
        c.rotation = rotation;
        c.plane = 17;
        c.feed = kind == CanonMove::Traverse ? 0.0 : feedRate;
        c.step = step;
        c.tool = tool;
        out.moves.push_back(c);
        out.lines.push_back(line);
        at = to;
    }
};

// ---------------------------------------------------------------- ISO G-code

class IsoReader {
public:
    explicit IsoReader(bool sinumerik) : sinumerik_(sinumerik) {}

    DialectMoves read(const std::string& text)
    {
        const auto lines = splitLines(text);
        try {
            for (std::size_t i = 0; i < lines.size(); ++i) {
                m_.line = static_cast<int>(i) + 1;
                line(lines[i]);
            }
            m_.line = static_cast<int>(lines.size());
            if (!ended_) refuse("the program does not end with M30");
            if (!sinumerik_ && (lines.empty() || lines.front() != "%" || lines.back() != "%"))
                refuse("a Haas tape begins and ends with a '%' line");
        } catch (const Refusal& r) {
            m_.out.error = lineError(m_.line, r, lines);
        }
        return std::move(m_.out);
    }

private:
    enum class Mode { None, Rapid, Feed, Clockwise, CounterClockwise, Drill };

    struct Block {
        std::vector<int> g, m;
        std::map<char, double> v;     // X Y Z I J R F P S T H D
        std::map<char, bool> point;   // whether the number had a decimal point
        bool supa = false;
        bool mcall = false;
        std::string cycle;            // "CYCLE81(...)"
        std::optional<double> adis;
        bool has(char c) const { return v.count(c) != 0; }
    };

    // Takes the comments out of `s` (passing them on) and returns the rest.
    std::string withoutComments(const std::string& s)
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
            if (s[i] == ';') refuse("';': Haas comments are in parentheses");
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

    Block words(const std::vector<std::string>& tokens)
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
            if (letter == 'G' || letter == 'M') {
                const auto n = whole(number);
                if (!n) refuse("'" + t + "' is not understood");
                (letter == 'G' ? b.g : b.m).push_back(*n);
                continue;
            }
            const std::string letters = sinumerik_ ? "XYZIJFSTD" : "XYZIJRFPSTH";
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
            // A Haas reads a number without a point in least increments
            // (X10 = 0.01 mm); our tapes always write the point.
            if (!sinumerik_ && letter != 'P' && !b.point[letter])
                refuse("'" + t + "' without a decimal point (a Haas reads it in least increments)");
        }
        return b;
    }

    void line(const std::string& raw)
    {
        if (raw.find_first_of("\r\t") != std::string::npos) refuse("a carriage return or tab");
        const std::string s = trim(withoutComments(raw));
        if (s.empty()) return;
        if (!sinumerik_ && s == "%") {
            if (++percents_ > 2) refuse("a third '%' line");
            return;
        }
        if (percents_ == 2) refuse("text after the closing '%'");
        if (!sinumerik_ && percents_ == 0) refuse("a block before the leading '%'");
        if (ended_) refuse("a block after M30");
        const auto tokens = splitWords(s);
        if (!sinumerik_ && tokens.size() == 1 && tokens[0][0] == 'O') {
            if (!whole(std::string_view(tokens[0]).substr(1)) || programNumber_) refuse("'" + tokens[0] + "' is not understood");
            programNumber_ = true;
            return;
        }
        block(words(tokens));
    }

    void block(const Block& b)
    {
        // G codes: at most one of the motion group.
        std::optional<Mode> motion;
        bool g4 = false, g28 = false, g43 = false, g80 = false, g154 = false, g641 = false;
        const auto setMotion = [&](Mode mode) {
            if (motion || g80) refuse("two motion codes in one block");
            motion = mode;
        };
        for (const int g : b.g) {
            if (g == 0) setMotion(Mode::Rapid);
            else if (g == 1) setMotion(Mode::Feed);
            else if (g == 2) setMotion(Mode::Clockwise);
            else if (g == 3) setMotion(Mode::CounterClockwise);
            else if (g == 17 || g == 40 || g == 94) continue;
            else if (g == 90) incremental_ = false;
            else if (g == 4) g4 = true;
            else if (!sinumerik_ && g == 81) setMotion(Mode::Drill);
            else if (!sinumerik_ && g == 83) refuse("G83 (peck drilling) is not supported by this reader");
            else if (!sinumerik_ && g == 80) {
                if (motion) refuse("two motion codes in one block");
                g80 = true;
            } else if (!sinumerik_ && (g == 20 || g == 21)) m_.units(g == 20);
            else if (sinumerik_ && (g == 700 || g == 710)) m_.units(g == 700);
            else if (!sinumerik_ && g == 49) continue;
            else if (!sinumerik_ && g == 91) incremental_ = true;
            else if (!sinumerik_ && g == 43) g43 = true;
            else if (!sinumerik_ && g == 28) g28 = true;
            else if (!sinumerik_ && g == 98) g98_ = true;
            else if (!sinumerik_ && g == 154) g154 = true;
            else if (!sinumerik_ && g >= 54 && g <= 59) continue;
            else if (sinumerik_ && ((g >= 54 && g <= 57) || (g >= 505 && g <= 599))) continue;
            else if (sinumerik_ && g == 641) g641 = true;
            else refuse("G" + std::to_string(g) + " is not understood");
        }
        if (b.adis && !g641) refuse("ADIS without G641");
        if (g641 && !b.adis) refuse("G641 without ADIS");

        // F: the feed rate, or on SINUMERIK with G4 the dwell time.
        if (b.has('F') && !(g4 && sinumerik_)) {
            if (!(b.v.at('F') > 0)) refuse("a feed rate of zero");
            m_.feed = b.v.at('F');
        }
        if (b.has('P') && !g4 && !g154) refuse("P without G4 or G154");
        if (g154) {
            if (!b.has('P') || b.point.at('P') || b.v.at('P') < 1 || b.v.at('P') > 99) refuse("G154 needs P1 to P99");
        }
        if (b.has('T')) selected_ = static_cast<int>(b.v.at('T'));
        for (const int mf : b.m) {
            if (mf == 6) {
                if (selected_ == 0) refuse("M6 with no tool selected");
                m_.tool = selected_;
                lengthOffset_ = false;
            } else if (mf == 30) {
                ended_ = true;
            } else if (mf != 3 && mf != 4 && mf != 5 && mf != 8 && mf != 9) {
                refuse("M" + std::to_string(mf) + " is not understood");
            }
        }
        if (b.has('D')) {
            if (m_.tool == 0 || b.v.at('D') < 1) refuse("D with no tool in the spindle");
            lengthOffset_ = true;
        }
        if (b.has('H') != g43) refuse("G43 and H go together");
        if (g43) {
            if (static_cast<int>(b.v.at('H')) != m_.tool)
                refuse("G43 H" + show(b.v.at('H')) + " with T" + std::to_string(m_.tool) + " in the spindle");
            lengthOffset_ = true;
        }
        if (g4) {
            const char time = sinumerik_ ? 'F' : 'P';
            if (!b.has(time) || b.v.at(time) < 0) refuse(std::string("G4 needs the dwell time in ") + time);
            if (!sinumerik_ && !b.point.at('P')) refuse("G4 P without a decimal point (milliseconds on a Haas)");
            if (b.has('X') || b.has('Y') || b.has('Z') || motion) refuse("a dwell with a move");
            ++m_.out.dwells;
            return;
        }
        if (g80) {
            mode_ = Mode::None;
            cycleZ_.reset();
            cycleR_.reset();
        }
        if (motion) mode_ = *motion;

        const bool axes = b.has('X') || b.has('Y') || b.has('Z');
        // The machine retracts: no move in the program's coordinates.
        if (g28) {
            if (!incremental_ || b.has('X') || b.has('Y') || !b.has('Z') || b.v.at('Z') != 0.0 || motion)
                refuse("only 'G28 G91 Z0.' is understood");
            return;
        }
        if (b.supa) {
            if (!motion || *motion != Mode::Rapid || b.has('X') || b.has('Y') || !b.has('Z') || b.v.at('Z') != 0.0)
                refuse("only 'G0 SUPA Z0' is understood");
            return;
        }
        if (b.mcall) {
            if (b.cycle.empty()) {
                if (axes || !b.g.empty() || !b.m.empty() || !b.v.empty()) refuse("a bare MCALL has no other words");
                if (!mcall_) refuse("MCALL with no modal call in force");
                mcall_.reset();
                return;
            }
            if (axes || !b.g.empty() || !b.m.empty() || !b.v.empty()) refuse("MCALL with other words");
            mcall_ = cycle81(b.cycle);
            return;
        }
        if (!b.cycle.empty()) refuse("a cycle called without MCALL");
        if (!axes) {
            if (b.has('I') || b.has('J') || b.has('R')) refuse("I, J or R with no move");
            return;
        }
        if (incremental_) refuse("incremental moves (G91) are not supported by this reader");
        if (b.has('Z') && !lengthOffset_)
            refuse("a Z move before T" + std::to_string(m_.tool) + "'s length offset (" + (sinumerik_ ? "D1" : "G43 H") + ")");

        Point3 to = m_.at;
        if (b.has('X')) to.x = b.v.at('X');
        if (b.has('Y')) to.y = b.v.at('Y');
        if (mode_ != Mode::Drill && b.has('Z')) to.z = b.v.at('Z');
        const bool centre = b.has('I') || b.has('J');
        if (mode_ != Mode::Drill && b.has('R')) refuse("R without G81 (radius arcs are not supported)");

        if (mcall_) {
            // SINUMERIK: the modal call runs after each positioning block.
            if (mode_ != Mode::Rapid || b.has('Z') || centre)
                refuse("under MCALL only G0 X Y positioning blocks are understood");
            m_.traverse(to);
            const auto& [rtp, rfp, sdis, dp] = *mcall_;
            if (dp > rfp) refuse("CYCLE81's depth above its reference plane");
            m_.traverse({to.x, to.y, rfp + sdis});
            m_.feedTo({to.x, to.y, dp}, m_.feed);
            m_.traverse({to.x, to.y, rtp});
            return;
        }
        if (centre && mode_ != Mode::Clockwise && mode_ != Mode::CounterClockwise) refuse("I or J without G2 or G3");
        switch (mode_) {
        case Mode::None:
            refuse("coordinates with no motion mode in force");
        case Mode::Rapid:
            m_.traverse(to);
            return;
        case Mode::Feed:
            m_.feedTo(to, m_.feed);
            return;
        case Mode::Clockwise:
        case Mode::CounterClockwise:
            if (!b.has('I') || !b.has('J')) refuse("an arc needs both I and J");
            if (std::isnan(m_.at.x) || std::isnan(m_.at.y)) refuse("an arc from an unknown position");
            m_.arc(to, {m_.at.x + b.v.at('I'), m_.at.y + b.v.at('J')}, mode_ == Mode::Clockwise ? -1 : 1, m_.feed);
            return;
        case Mode::Drill:
            drill(b, to);
            return;
        }
    }

    // G98 G81 as rs274 expands it: up to R first when below it, across at
    // the initial level, down to R, feed to Z, back to the initial level.
    void drill(const Block& b, const Point3& hole)
    {
        if (!g98_) refuse("G81 without G98 (only the return to the initial level is understood)");
        if (b.has('Z')) cycleZ_ = b.v.at('Z');
        if (b.has('R')) cycleR_ = b.v.at('R');
        if (!cycleZ_ || !cycleR_) refuse("G81 needs Z and R");
        const double r = *cycleR_, bottom = *cycleZ_;
        if (bottom > r) refuse("G81's Z above its R");
        if (!known(m_.at)) refuse("a drilling cycle from an unknown position");
        double initial = m_.at.z;
        if (initial < r) {
            m_.traverse({m_.at.x, m_.at.y, r});
            initial = r;
        }
        m_.traverse({hole.x, hole.y, initial});
        m_.traverse({hole.x, hole.y, r});
        m_.feedTo({hole.x, hole.y, bottom}, m_.feed);
        m_.traverse({hole.x, hole.y, initial});
    }

    static std::array<double, 4> cycle81(const std::string& call)
    {
        if (call.starts_with("CYCLE83")) refuse("CYCLE83 (deep-hole drilling) is not supported by this reader");
        if (!call.starts_with("CYCLE81(") || !call.ends_with(")")) refuse("'" + call + "' is not understood");
        const std::string inside = call.substr(8, call.size() - 9);
        std::array<double, 4> p{};
        std::size_t from = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            const auto comma = inside.find(',', from);
            if ((k < 3) != (comma != std::string::npos)) refuse("CYCLE81 needs exactly RTP, RFP, SDIS and DP");
            const std::size_t size = comma == std::string::npos ? std::string::npos : comma - from;
            const auto value = decimal(std::string_view(inside).substr(from, size), false);
            if (!value) refuse("CYCLE81's parameter " + std::to_string(k + 1) + " is not a number");
            p[k] = *value;
            from = comma + 1;
        }
        return p;
    }

    bool sinumerik_;
    Machine m_;
    Mode mode_ = Mode::None;
    bool incremental_ = false;
    bool g98_ = false;
    bool ended_ = false;
    bool lengthOffset_ = true;  // false from a tool change to its G43 H / D
    bool programNumber_ = false;
    int percents_ = 0;
    int selected_ = 0;
    std::optional<double> cycleZ_, cycleR_;
    std::optional<std::array<double, 4>> mcall_;  // RTP, RFP, SDIS, DP
};

// ---------------------------------------------------------------- Klartext

class KlartextReader {
public:
    DialectMoves read(const std::string& text)
    {
        const auto lines = splitLines(text);
        try {
            group(lines);
            for (std::size_t k = 0; k < blocks_.size(); ++k) {
                m_.line = blocks_[k].line;
                block(k);
            }
        } catch (const Refusal& r) {
            m_.out.error = lineError(m_.line, r, lines);
        }
        return std::move(m_.out);
    }

private:
    struct Block {
        int line = 0;                                     // of its first line
        std::string head;                                 // after the block number
        std::vector<std::pair<int, std::string>> more;    // continuation lines (line, text)
    };

    struct Words {
        std::optional<double> x, y, z, ipa, iz, f;
        bool fmax = false, r0 = false;
        int dr = 0;
        std::vector<int> m;
    };

    // Lines into numbered blocks with their '~' continuation lines.
    void group(const std::vector<std::string>& lines)
    {
        bool open = false;
        int expected = 0;
        for (std::size_t i = 0; i < lines.size(); ++i) {
            m_.line = static_cast<int>(i) + 1;
            const std::string& l = lines[i];
            if (l.find_first_of("\r\t") != std::string::npos) refuse("a carriage return or tab");
            if (l.starts_with("  ")) {
                if (!open) refuse("a continuation line with no '~' before it");
                const std::string t = trim(l);
                blocks_.back().more.emplace_back(m_.line, t);
                open = t.ends_with("~");
                continue;
            }
            if (open) refuse("the block before ends with '~' but this line does not continue it");
            const auto space = l.find(' ');
            const auto n = whole(std::string_view(l).substr(0, space));
            if (space == std::string::npos || !n) refuse("a block that does not begin with its number");
            if (*n != expected) refuse("block number " + std::to_string(*n) + ", expected " + std::to_string(expected));
            ++expected;
            blocks_.push_back({m_.line, l.substr(space + 1), {}});
            open = blocks_.back().head.ends_with("~");
        }
        if (open) refuse("the last block ends with '~'");
        if (blocks_.size() < 2) refuse("a program has at least BEGIN PGM and END PGM");
    }

    void block(std::size_t k)
    {
        const Block& b = blocks_[k];
        const std::string& h = b.head;
        std::smatch match;
        static const std::regex begin(R"(BEGIN PGM (\S+) (MM|INCH))");
        static const std::regex end(R"(END PGM (\S+) (MM|INCH))");
        static const std::regex blk1(R"(BLK FORM 0\.1 Z X[-+][0-9.]+ Y[-+][0-9.]+ Z[-+][0-9.]+)");
        static const std::regex blk2(R"(BLK FORM 0\.2 X[-+][0-9.]+ Y[-+][0-9.]+ Z[-+][0-9.]+)");
        static const std::regex dwell(R"(CYCL DEF 9\.1 DWELL ([0-9.]+))");
        static const std::regex datum(R"(Q339=\+[0-9]+ ;DATUM NUMBER)");
        if (k == 0) {
            if (!std::regex_match(h, match, begin)) refuse("a program begins with BEGIN PGM name MM|INCH");
            name_ = match[1].str();
            unit_ = match[2].str();
            m_.units(unit_ == "INCH");
            return;
        }
        if (k + 1 == blocks_.size()) {
            if (dwellDue_) refuse("CYCL DEF 9.0 with no 9.1 after it");
            if (!std::regex_match(h, match, end) || match[1].str() != name_ || match[2].str() != unit_)
                refuse("a program ends with END PGM " + name_ + " " + unit_);
            if (!ended_) refuse("END PGM with no M30 before it");
            return;
        }
        if (!b.more.empty() && !h.starts_with("CYCL DEF 247 ") && !h.starts_with("CYCL DEF 200 "))
            refuse("continuation lines after a block that has none");
        if (dwellDue_ != h.starts_with("CYCL DEF 9.1 ")) refuse("CYCL DEF 9.0 and 9.1 go together");
        if (ended_) refuse("a block after M30 other than END PGM");
        if (h.starts_with(";")) {
            m_.comment(h.substr(1));
        } else if (h.starts_with("BLK FORM 0.1 ")) {
            if (!std::regex_match(h, blk1)) refuse("BLK FORM 0.1 not understood");
            blankDue_ = true;
        } else if (h.starts_with("BLK FORM 0.2 ")) {
            if (!blankDue_ || !std::regex_match(h, blk2)) refuse("BLK FORM 0.2 not understood (or without 0.1 before it)");
            blankDue_ = false;
        } else if (h == "CYCL DEF 247 DATUM SETTING ~") {
            if (b.more.size() != 1 || !std::regex_match(b.more[0].second, datum)) refuse("cycle 247 needs Q339 alone");
        } else if (h == "CYCL DEF 200 DRILLING ~") {
            drilling(b);
        } else if (h == "CYCL DEF 9.0 DWELL TIME") {
            dwellDue_ = true;
        } else if (h.starts_with("CYCL DEF 9.1 ")) {
            if (!std::regex_match(h, dwell)) refuse("CYCL DEF 9.1 DWELL needs the time in seconds");
            dwellDue_ = false;
            ++m_.out.dwells;
        } else if (h.starts_with("TOOL CALL ")) {
            toolCall(splitWords(h.substr(10)));
        } else {
            const auto tokens = splitWords(h);
            if (tokens.empty()) refuse("an empty block");
            const std::string& kind = tokens[0];
            if (kind == "L" || kind == "CC" || kind == "C" || kind == "CP") {
                move(kind, parseWords(kind, tokens));
            } else if (std::all_of(tokens.begin(), tokens.end(), [](const std::string& t) { return t.starts_with("M"); })) {
                const Words w = parseWords("", tokens);
                mFunctions(w, false);
            } else {
                refuse("block not understood");
            }
        }
    }

    static double signedNumber(const std::string& t, std::size_t skip)
    {
        const std::string_view s = std::string_view(t).substr(skip);
        if (s.empty() || (s.front() != '+' && s.front() != '-')) refuse("'" + t + "': a signed number expected");
        const auto v = decimal(s, true);
        if (!v) refuse("'" + t + "' is not understood");
        return *v;
    }

    // The words of an L, CC, C or CP block, or of a bare M block (`kind` "").
    static Words parseWords(const std::string& kind, const std::vector<std::string>& tokens)
    {
        Words w;
        std::set<std::string> seen;
        const auto once = [&](const std::string& key) {
            if (!seen.insert(key).second) refuse("two " + key + " words in one block");
        };
        const auto allowed = [&](const std::string& word, const char* kinds) {
            const std::string k = " " + kind + " ";
            if (std::string(kinds).find(k) == std::string::npos)
                refuse("'" + word + "' in a " + (kind.empty() ? "bare M" : kind) + " block");
        };
        for (std::size_t i = kind.empty() ? 0 : 1; i < tokens.size(); ++i) {
            const std::string& t = tokens[i];
            if (t == "FMAX") {
                allowed(t, " L ");
                once("F");
                w.fmax = true;
            } else if (t == "R0") {
                allowed(t, " L ");
                once(t);
                w.r0 = true;
            } else if (t == "DR+" || t == "DR-") {
                allowed(t, " C CP ");
                once("DR");
                w.dr = t == "DR+" ? 1 : -1;
            } else if (t.starts_with("IPA")) {
                allowed(t, " CP ");
                once("IPA");
                w.ipa = signedNumber(t, 3);
            } else if (t.starts_with("IZ")) {
                allowed(t, " CP ");
                once("IZ");
                w.iz = signedNumber(t, 2);
            } else if (t.size() > 1 && (t[0] == 'X' || t[0] == 'Y' || t[0] == 'Z')) {
                allowed(t, t[0] == 'Z' ? " L " : " L CC C ");
                once(t.substr(0, 1));
                (t[0] == 'X' ? w.x : t[0] == 'Y' ? w.y : w.z) = signedNumber(t, 1);
            } else if (t.size() > 1 && t[0] == 'F') {
                allowed(t, " L C CP ");
                once("F");
                w.f = decimal(std::string_view(t).substr(1), false);
                if (!w.f || !(*w.f > 0)) refuse("'" + t + "' is not a feed rate");
            } else if (t.size() > 1 && t[0] == 'M') {
                const auto n = whole(std::string_view(t).substr(1));
                if (!n) refuse("'" + t + "' is not understood");
                w.m.push_back(*n);
            } else {
                refuse("'" + t + "' is not understood");
            }
        }
        return w;
    }

    // M3 M4 M5 M8 M9 and M30 anywhere; M91 and M99 on L blocks only.
    void mFunctions(const Words& w, bool onL)
    {
        for (const int mf : w.m) {
            if (mf == 30) ended_ = true;
            else if ((mf == 91 || mf == 99) && onL) continue;
            else if (mf != 3 && mf != 4 && mf != 5 && mf != 8 && mf != 9) refuse("M" + std::to_string(mf) + " is not understood here");
        }
    }

    void toolCall(const std::vector<std::string>& t)
    {
        std::size_t i = 0;
        if (i < t.size() && whole(t[i])) {
            m_.tool = *whole(t[i]);
            if (m_.tool == 0) refuse("TOOL CALL 0");
            ++i;
        } else if (m_.tool == 0) {
            refuse("a TOOL CALL with no tool number and no tool in the spindle");
        }
        if (i >= t.size() || t[i] != "Z") refuse("TOOL CALL needs the tool axis Z");
        ++i;
        if (i < t.size() && t[i].starts_with("S") && decimal(std::string_view(t[i]).substr(1), false)) ++i;
        if (i != t.size()) refuse("'" + t[i] + "' is not understood in TOOL CALL");
    }

    void drilling(const Block& b)
    {
        static const std::regex q(R"(Q([0-9]+)=([-+][0-9.]+) ;[A-Z0-9 -]+?( ~)?)");
        static const int order[] = {200, 201, 206, 202, 210, 203, 204, 211};
        if (b.more.size() != std::size(order)) refuse("cycle 200 needs Q200 Q201 Q206 Q202 Q210 Q203 Q204 Q211");
        std::map<int, double> v;
        for (std::size_t i = 0; i < b.more.size(); ++i) {
            m_.line = b.more[i].first;
            std::smatch match;
            const int n = order[i];
            if (!std::regex_match(b.more[i].second, match, q) || std::stoi(match[1].str()) != n)
                refuse("Q" + std::to_string(n) + " expected");
            const auto value = decimal(match[2].str(), true);
            if (!value) refuse("Q" + std::to_string(n) + " is not a number");
            v[n] = *value;
            if ((n == 200 || n == 204) && *value < 0) refuse("a negative set-up clearance");
            if (n == 201 && *value >= 0) refuse("Q201 (depth) must be negative");
            if (n == 206 && !(*value > 0)) refuse("Q206 (plunge feed) must be positive");
            if (n == 202 && *value != -v[201])
                refuse("Q202 (plunging depth) other than |Q201|: pecking is not supported by this reader");
            if ((n == 210 || n == 211) && *value != 0) refuse("dwells in cycle 200 are not supported by this reader");
        }
        m_.line = b.line;
        cycle_ = v;
    }

    void move(const std::string& kind, const Words& w)
    {
        if (kind == "CC") {
            if (!w.x || !w.y) refuse("CC needs X and Y");
            pole_ = Point2{*w.x, *w.y};
            return;
        }
        const bool machine = std::find(w.m.begin(), w.m.end(), 91) != w.m.end();
        const bool call = std::find(w.m.begin(), w.m.end(), 99) != w.m.end();
        mFunctions(w, kind == "L");
        if (ended_) refuse("M30 on a move");
        if (w.f) m_.feed = *w.f;
        if (kind == "L") {
            if (!w.x && !w.y && !w.z) refuse("L with no coordinate");
            if (w.fmax && !w.r0) refuse("FMAX without R0");
            if (machine) {
                // The machine datum (M91): a retract, no move in the program.
                if (call || !w.fmax) refuse("M91 is understood only on a rapid with no cycle call");
                return;
            }
            Point3 to = m_.at;
            if (w.x) to.x = *w.x;
            if (w.y) to.y = *w.y;
            if (w.z) to.z = *w.z;
            if (w.fmax) m_.traverse(to);
            else m_.feedTo(to, m_.feed);
            if (call) cycleCall();
            return;
        }
        if (!pole_) refuse(kind + " with no CC before it");
        if (w.dr == 0) refuse(kind + " needs DR+ or DR-");
        if (!known(m_.at)) refuse("an arc from an unknown position");
        const Point2 c = *pole_;
        if (kind == "C") {
            const Point3 to{w.x ? *w.x : m_.at.x, w.y ? *w.y : m_.at.y, m_.at.z};
            m_.arc(to, c, w.dr, m_.feed);
            return;
        }
        // CP: the start turned by IPA about the pole, Z by IZ.
        if (!w.ipa || *w.ipa == 0.0) refuse("CP needs IPA");
        if ((*w.ipa > 0) != (w.dr > 0)) refuse("IPA and DR turn opposite ways");
        const double ipa = *w.ipa;
        const double a = ipa * std::numbers::pi / 180.0;
        const double turns = std::abs(ipa) / 360.0;
        const bool wholeTurns = std::abs(turns - std::round(turns)) < 1e-12;
        const double dx = m_.at.x - c.x, dy = m_.at.y - c.y;
        const Point3 to{wholeTurns ? m_.at.x : c.x + dx * std::cos(a) - dy * std::sin(a),
                        wholeTurns ? m_.at.y : c.y + dx * std::sin(a) + dy * std::cos(a), m_.at.z + (w.iz ? *w.iz : 0.0)};
        // rs274's turn count: ±1 up to one whole turn, one more per turn beyond.
        const int rotation = w.dr * std::max(1, static_cast<int>(std::ceil(turns - 1e-9)));
        m_.arc(to, c, rotation, m_.feed);
    }

    // Cycle 200 at the position just reached: to the set-up clearance, one
    // plunge to depth at Q206, out to the 2nd set-up clearance.
    void cycleCall()
    {
        if (cycle_.empty()) refuse("M99 with no cycle defined");
        const double surface = cycle_.at(203);
        const Point3 at = m_.at;
        m_.traverse({at.x, at.y, surface + cycle_.at(200)});
        m_.feedTo({at.x, at.y, surface + cycle_.at(201)}, cycle_.at(206));
        m_.traverse({at.x, at.y, surface + std::max(cycle_.at(200), cycle_.at(204))});
    }

    Machine m_;
    std::vector<Block> blocks_;
    std::string name_, unit_;
    bool ended_ = false;
    bool dwellDue_ = false;
    bool blankDue_ = false;
    std::optional<Point2> pole_;
    std::map<int, double> cycle_;  // the CYCL DEF 200 in force: Q number -> value
};

}  // namespace

DialectMoves readIsoTape(const std::string& text, bool sinumerik) { return IsoReader(sinumerik).read(text); }

DialectMoves readKlartext(const std::string& text) { return KlartextReader().read(text); }

}  // namespace taiwa::test
