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

// How far above the last peck's bottom a pecking cycle comes back down in
// rapid: rs274's G83_RAPID_DELTA, 0.010 inch (0.254 mm). The real controls
// take it from a machine setting (Haas setting 22, SINUMERIK's anticipation
// distance, HEIDENHAIN's advanced stop distance), never from the tape, so the
// readers take LinuxCNC's.
double peckReturn(bool inches) { return inches ? 0.010 : 0.254; }

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
    // Drill..Bore: the canned cycles G81, G83, G84, G85, G86 (Haas).
    enum class Mode { None, Rapid, Feed, Clockwise, CounterClockwise, Drill, Peck, Tap, Ream, Bore };

    // A SINUMERIK cycle called modally: CYCLE81, 83, 84, 85 or 86.
    struct ModalCycle {
        int number = 81;
        double rtp = 0, rfp = 0, sdis = 0, dp = 0;
        double fdep = 0, dam = 0;          // CYCLE83: the first depth (absolute), each further peck
        double pit = 0, sst = 0, sst1 = 0; // CYCLE84: the pitch, the speeds in and out
        double ffr = 0, rff = 0;           // CYCLE85: the feeds in and out
    };

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
            const std::string letters = sinumerik_ ? "XYZIJFSTD" : "XYZIJRFPQSTH";
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
            else if (!sinumerik_ && g == 83) setMotion(Mode::Peck);
            else if (!sinumerik_ && g == 84) setMotion(Mode::Tap);
            else if (!sinumerik_ && g == 85) setMotion(Mode::Ream);
            else if (!sinumerik_ && g == 86) setMotion(Mode::Bore);
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
        if (b.has('Q') && (motion ? *motion : mode_) != Mode::Peck) refuse("Q without G83");
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
            cycleQ_.reset();
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
            mcall_ = modalCycle(b.cycle);
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
        const bool cycle = mode_ >= Mode::Drill;
        if (!cycle && b.has('Z')) to.z = b.v.at('Z');
        const bool centre = b.has('I') || b.has('J');
        if (!cycle && b.has('R')) refuse("R without a canned cycle (radius arcs are not supported)");

        if (mcall_) {
            // SINUMERIK: the modal call runs after each positioning block.
            if (mode_ != Mode::Rapid || b.has('Z') || centre)
                refuse("under MCALL only G0 X Y positioning blocks are understood");
            m_.traverse(to);
            calledCycle(*mcall_, to);
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
        case Mode::Peck:
        case Mode::Tap:
        case Mode::Ream:
        case Mode::Bore:
            drill(b, to);
            return;
        }
    }

    // G98 G81/G83/G84/G85/G86 as rs274 expands G81, G83, G85 and G86: up to
    // R first when below it, across at the initial level, down to R, then
    // - G81: feed to Z;
    // - G83: pecks of Q from R, each back up to R and down again in rapid to
    //   peckReturn() above its bottom, the last one to Z;
    // - G84 (rigid tapping, as the linuxcnc tape's G33.1): feed to Z and
    //   back out to R at F (F = pitch x S);
    // - G85: feed to Z and back out to R;
    // - G86: feed to Z (the spindle stops there);
    // then back to the initial level in rapid.
    void drill(const Block& b, const Point3& hole)
    {
        const std::string code = mode_ == Mode::Drill ? "G81"
                                 : mode_ == Mode::Peck ? "G83"
                                 : mode_ == Mode::Tap  ? "G84"
                                 : mode_ == Mode::Ream ? "G85"
                                                       : "G86";
        if (!g98_) refuse(code + " without G98 (only the return to the initial level is understood)");
        if (b.has('Z')) cycleZ_ = b.v.at('Z');
        if (b.has('R')) cycleR_ = b.v.at('R');
        if (b.has('Q')) cycleQ_ = b.v.at('Q');
        if (!cycleZ_ || !cycleR_) refuse(code + " needs Z and R");
        if (mode_ == Mode::Peck && !cycleQ_) refuse("G83 needs Q (the peck)");
        if (mode_ == Mode::Peck && !(*cycleQ_ > 0)) refuse("G83's Q must be positive");
        const double r = *cycleR_, bottom = *cycleZ_;
        if (bottom > r) refuse(code + "'s Z above its R");
        if (!known(m_.at)) refuse("a canned cycle from an unknown position");
        double initial = m_.at.z;
        if (initial < r) {
            m_.traverse({m_.at.x, m_.at.y, r});
            initial = r;
        }
        m_.traverse({hole.x, hole.y, initial});
        m_.traverse({hole.x, hole.y, r});
        if (mode_ == Mode::Peck) {
            // rs274's loop, to the same arithmetic.
            const double q = *cycleQ_;
            for (double depth = r - q; depth > bottom; depth -= q) {
                m_.feedTo({hole.x, hole.y, depth}, m_.feed);
                m_.traverse({hole.x, hole.y, r});
                m_.traverse({hole.x, hole.y, depth + peckReturn(m_.out.inches)});
            }
        }
        m_.feedTo({hole.x, hole.y, bottom}, m_.feed);
        if (mode_ == Mode::Tap || mode_ == Mode::Ream) m_.feedTo({hole.x, hole.y, r}, m_.feed);
        m_.traverse({hole.x, hole.y, initial});
    }

    // SINUMERIK: the modally called cycle at the position just reached (the
    // tool at its height there): down to RFP + SDIS in rapid, then
    // - CYCLE81: feed to DP at F;
    // - CYCLE83 (VARI=1, chip removal): pecks to FDEP, then DAM deeper each
    //   time, each back up to RFP + SDIS and down again in rapid to
    //   peckReturn() above its bottom, the last one to DP, at F (as G83);
    // - CYCLE84 (rigid tapping): to DP at PIT x SST, out to RFP + SDIS at
    //   PIT x SST1;
    // - CYCLE85: to DP at FFR, out to RFP + SDIS at RFF;
    // - CYCLE86: to DP at F, the spindle stopped, out in rapid;
    // then up to RTP in rapid (CYCLE86: its two rapids up the hole's axis as
    // the one straight move they make).
    void calledCycle(const ModalCycle& c, const Point3& to)
    {
        const double top = c.rfp + c.sdis;
        if (c.dp > c.rfp) refuse("CYCLE" + std::to_string(c.number) + "'s depth above its reference plane");
        m_.traverse({to.x, to.y, top});
        switch (c.number) {
        case 81:
        case 86:
            m_.feedTo({to.x, to.y, c.dp}, m_.feed);
            break;
        case 83:
            for (double depth = c.fdep; depth > c.dp; depth -= c.dam) {
                m_.feedTo({to.x, to.y, depth}, m_.feed);
                m_.traverse({to.x, to.y, top});
                m_.traverse({to.x, to.y, depth + peckReturn(m_.out.inches)});
            }
            m_.feedTo({to.x, to.y, c.dp}, m_.feed);
            break;
        case 84:
            m_.feedTo({to.x, to.y, c.dp}, c.pit * c.sst);
            m_.feedTo({to.x, to.y, top}, c.pit * c.sst1);
            break;
        case 85:
            m_.feedTo({to.x, to.y, c.dp}, c.ffr);
            m_.feedTo({to.x, to.y, top}, c.rff);
            break;
        }
        m_.traverse({to.x, to.y, c.rtp});
    }

    // The parameters of "NAME(p1,p2,...)", an empty one as nothing.
    static std::vector<std::optional<double>> cycleParameters(const std::string& call, const std::string& name)
    {
        if (!call.ends_with(")")) refuse("'" + call + "' is not understood");
        const std::string inside = call.substr(name.size() + 1, call.size() - name.size() - 2);
        std::vector<std::optional<double>> p;
        std::size_t from = 0;
        for (int k = 1;; ++k) {
            const auto comma = inside.find(',', from);
            const std::size_t size = comma == std::string::npos ? std::string::npos : comma - from;
            const std::string_view part = std::string_view(inside).substr(from, size);
            if (part.empty()) {
                p.emplace_back();
            } else {
                const auto value = decimal(part, false);
                if (!value) refuse(name + "'s parameter " + std::to_string(k) + " is not a number");
                p.emplace_back(*value);
            }
            if (comma == std::string::npos) break;
            from = comma + 1;
        }
        return p;
    }

    // CYCLE81(RTP,RFP,SDIS,DP); CYCLE83(RTP,RFP,SDIS,DP,,FDEP,,DAM,0,0,1,1);
    // CYCLE84(RTP,RFP,SDIS,DP,,0,3,,PIT,POSS,SST,SST1);
    // CYCLE85(RTP,RFP,SDIS,DP,,0,FFR,RFF); CYCLE86(RTP,RFP,SDIS,DP,,0,3,0,0,0,POSS).
    // Any other value of the fixed parameters (dwells, relative depths,
    // degression, chip breaking, left-hand tapping, lift off the wall) is
    // refused.
    static ModalCycle modalCycle(const std::string& call)
    {
        const auto paren = call.find('(');
        const std::string name = call.substr(0, paren == std::string::npos ? call.size() : paren);
        if (paren == std::string::npos || !(name == "CYCLE81" || name == "CYCLE83" || name == "CYCLE84" ||
                                            name == "CYCLE85" || name == "CYCLE86"))
            refuse("'" + call + "' is not understood");
        ModalCycle c;
        c.number = std::stoi(name.substr(5));
        const auto p = cycleParameters(call, name);
        const auto need = [&](std::size_t k, const char* what) {
            if (k > p.size() || !p[k - 1]) refuse(name + " needs " + what + " (parameter " + std::to_string(k) + ")");
            return *p[k - 1];
        };
        const auto empty = [&](std::size_t k, const char* what) {
            if (k <= p.size() && p[k - 1])
                refuse(name + "'s " + what + " (parameter " + std::to_string(k) + ") is not supported by this reader");
        };
        const auto only = [&](std::size_t k, double value, const char* what) {
            if (need(k, what) != value) refuse(name + " with " + what + " other than " + show(value) + " is not supported by this reader");
        };
        const std::size_t counts[] = {4, 0, 12, 12, 8, 11};  // CYCLE81, -, 83, 84, 85, 86
        if (c.number == 81 && p.size() != 4) refuse("CYCLE81 needs exactly RTP, RFP, SDIS and DP");
        if (p.size() != counts[c.number - 81]) refuse(name + " needs " + std::to_string(counts[c.number - 81]) + " parameters");
        c.rtp = need(1, "RTP");
        c.rfp = need(2, "RFP");
        c.sdis = need(3, "SDIS");
        c.dp = need(4, "DP (the depth, absolute)");
        if (c.number != 81) empty(5, "DPR (a relative depth)");
        if (c.number == 83) {
            c.fdep = need(6, "FDEP (the first depth, absolute)");
            empty(7, "FDPR (a relative first depth)");
            c.dam = need(8, "DAM (the peck)");
            if (!(c.dam > 0)) refuse("CYCLE83's DAM must be positive (a degression is not supported by this reader)");
            only(9, 0, "DTB (a dwell at depth)");
            only(10, 0, "DTS (a dwell at the start)");
            only(11, 1, "FRF (the first feed's factor)");
            only(12, 1, "VARI (1: chip removal)");
        } else if (c.number == 84) {
            only(6, 0, "DTB (a dwell at depth)");
            only(7, 3, "SDAC (the spindle after the cycle)");
            empty(8, "MPIT (a thread size)");
            c.pit = need(9, "PIT (the pitch)");
            if (!(c.pit > 0)) refuse("CYCLE84's PIT must be positive (left-hand tapping is not supported by this reader)");
            need(10, "POSS (the spindle's stop angle)");
            c.sst = need(11, "SST (the tapping speed)");
            c.sst1 = need(12, "SST1 (the speed out)");
            if (!(c.sst > 0 && c.sst1 > 0)) refuse("CYCLE84's SST and SST1 must be positive");
        } else if (c.number == 85) {
            only(6, 0, "DTB (a dwell at depth)");
            c.ffr = need(7, "FFR (the feed in)");
            c.rff = need(8, "RFF (the feed out)");
            if (!(c.ffr > 0 && c.rff > 0)) refuse("CYCLE85's FFR and RFF must be positive");
        } else if (c.number == 86) {
            only(6, 0, "DTB (a dwell at depth)");
            only(7, 3, "SDIR (the spindle's direction)");
            only(8, 0, "RPA (a lift off the wall)");
            only(9, 0, "RPO (a lift off the wall)");
            only(10, 0, "RPAP (a lift off the wall)");
            need(11, "POSS (the spindle's stop angle)");
        }
        return c;
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
    std::optional<double> cycleZ_, cycleR_, cycleQ_;
    std::optional<ModalCycle> mcall_;
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
        if (!b.more.empty() && !h.starts_with("CYCL DEF 247 ") && !h.starts_with("CYCL DEF 200 ") &&
            !h.starts_with("CYCL DEF 201 ") && !h.starts_with("CYCL DEF 202 ") && !h.starts_with("CYCL DEF 207 "))
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
            holeCycle(b, 200);
        } else if (h == "CYCL DEF 201 REAMING ~") {
            holeCycle(b, 201);
        } else if (h == "CYCL DEF 202 BORING ~") {
            holeCycle(b, 202);
        } else if (h == "CYCL DEF 207 RIGID TAPPING NEW ~") {
            holeCycle(b, 207);
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
        if (i < t.size() && t[i].starts_with("S") && decimal(std::string_view(t[i]).substr(1), false)) {
            rpm_ = *decimal(std::string_view(t[i]).substr(1), false);
            ++i;
        }
        if (i != t.size()) refuse("'" + t[i] + "' is not understood in TOOL CALL");
    }

    // Cycles 200 (drilling), 201 (reaming), 202 (boring) and 207 (rigid
    // tapping), their Q parameters in the order the TNC writes them. Dwells,
    // a lift off the wall (Q214) and left-hand tapping are refused.
    void holeCycle(const Block& b, int number)
    {
        static const std::regex q(R"(Q([0-9]+)=([-+][0-9.]+|FMAX) ;[A-Z0-9 -]+?( ~)?)");
        static const std::map<int, std::vector<int>> orders{
            {200, {200, 201, 206, 202, 210, 203, 204, 211}},
            {201, {200, 201, 206, 211, 208, 203, 204}},
            {202, {200, 201, 206, 211, 208, 203, 204, 214, 336}},
            {207, {200, 201, 239, 203, 204}},
        };
        const std::vector<int>& order = orders.at(number);
        if (b.more.size() != order.size()) {
            std::string all;
            for (const int n : order) all += " Q" + std::to_string(n);
            refuse("cycle " + std::to_string(number) + " needs" + all);
        }
        std::map<int, double> v;
        for (std::size_t i = 0; i < b.more.size(); ++i) {
            m_.line = b.more[i].first;
            std::smatch match;
            const int n = order[i];
            if (!std::regex_match(b.more[i].second, match, q) || std::stoi(match[1].str()) != n)
                refuse("Q" + std::to_string(n) + " expected");
            // Q208=FMAX: out at rapid (kept as -1, a feed no cycle writes).
            if (match[2].str() == "FMAX" && n != 208) refuse("FMAX is only a retraction feed (Q208)");
            const auto value = match[2].str() == "FMAX" ? std::optional<double>(-1.0) : decimal(match[2].str(), true);
            if (!value) refuse("Q" + std::to_string(n) + " is not a number");
            v[n] = *value;
            if ((n == 200 || n == 204) && *value < 0) refuse("a negative set-up clearance");
            if (n == 201 && *value >= 0) refuse("Q201 (depth) must be negative");
            if (n == 206 && !(*value > 0)) refuse("Q206 (plunge feed) must be positive");
            if (n == 202 && !(*value > 0)) refuse("Q202 (plunging depth) must be positive");
            if (n == 208 && *value < 0 && match[2].str() != "FMAX") refuse("Q208 (retraction feed) must not be negative");
            if (n == 239 && !(*value > 0)) refuse("Q239 (pitch) must be positive: left-hand tapping is not supported by this reader");
            if (n == 214 && *value != 0) refuse("Q214 (a lift off the wall) is not supported by this reader");
            if ((n == 210 || n == 211) && *value != 0)
                refuse("dwells in cycle " + std::to_string(number) + " are not supported by this reader");
        }
        m_.line = b.line;
        cycleNumber_ = number;
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

    // The cycle in force at the position just reached: to the set-up
    // clearance (Q203 + Q200) in rapid, then
    // - 200: plunges of Q202 from the surface at Q206, each but the last
    //   back up to the set-up clearance and down again in rapid to
    //   peckReturn() above its bottom, the last one to the depth (Q202 at
    //   least |Q201|: one plunge);
    // - 201: to the depth at Q206, out to the set-up clearance at Q208 (0:
    //   at Q206);
    // - 202: to the depth at Q206, the spindle stopped at Q336, out to the
    //   set-up clearance at Q208 (0: at Q206);
    // - 207: to the depth and out to the set-up clearance at Q239 x S (the
    //   TOOL CALL's speed);
    // then out to the 2nd set-up clearance (Q203 + Q204) in rapid.
    void cycleCall()
    {
        if (cycle_.empty()) refuse("M99 with no cycle defined");
        const double surface = cycle_.at(203);
        const double clearance = surface + cycle_.at(200);
        const double bottom = surface + cycle_.at(201);
        const Point3 at = m_.at;
        m_.traverse({at.x, at.y, clearance});
        switch (cycleNumber_) {
        case 200: {
            const double plunge = cycle_.at(202);
            for (double depth = surface - plunge; depth > bottom; depth -= plunge) {
                m_.feedTo({at.x, at.y, depth}, cycle_.at(206));
                m_.traverse({at.x, at.y, clearance});
                m_.traverse({at.x, at.y, depth + peckReturn(m_.out.inches)});
            }
            m_.feedTo({at.x, at.y, bottom}, cycle_.at(206));
            break;
        }
        case 201:
        case 202: {
            m_.feedTo({at.x, at.y, bottom}, cycle_.at(206));
            if (cycle_.at(208) < 0) break;  // FMAX: straight out at rapid to the 2nd set-up clearance, below
            m_.feedTo({at.x, at.y, clearance}, cycle_.at(208) > 0 ? cycle_.at(208) : cycle_.at(206));
            break;
        }
        case 207:
            if (!(rpm_ > 0)) refuse("cycle 207 with no spindle speed (TOOL CALL ... S)");
            m_.feedTo({at.x, at.y, bottom}, cycle_.at(239) * rpm_);
            m_.feedTo({at.x, at.y, clearance}, cycle_.at(239) * rpm_);
            break;
        }
        m_.traverse({at.x, at.y, surface + std::max(cycle_.at(200), cycle_.at(204))});
    }

    Machine m_;
    std::vector<Block> blocks_;
    std::string name_, unit_;
    bool ended_ = false;
    bool dwellDue_ = false;
    bool blankDue_ = false;
    std::optional<Point2> pole_;
    int cycleNumber_ = 0;          // the CYCL DEF 200, 201, 202 or 207 in force
    std::map<int, double> cycle_;  // its Q parameters: Q number -> value
    double rpm_ = 0.0;             // the spindle speed of the last TOOL CALL with S
};

}  // namespace

DialectMoves readIsoTape(const std::string& text, bool sinumerik) { return IsoReader(sinumerik).read(text); }

DialectMoves readKlartext(const std::string& text) { return KlartextReader().read(text); }

}  // namespace taiwa::test
