// The reader of the ISO and SINUMERIK tapes (readTape, tape_reader.h): every
// block understood word by word, the drilling cycles expanded as the manuals
// describe, or the reading stopped at its line. The Klartext reader is in
// tape_reader_klartext.cpp.
#include "verify/tape_reader_machine.h"

#include <cmath>
#include <map>
#include <optional>
#include <string_view>

namespace taiwa::verify {

TapeReading readKlartext(const std::string& text);  // tape_reader_klartext.cpp

namespace {

using namespace tape;

class IsoReader {
public:
    explicit IsoReader(const post::Dialect& d)
        : sinumerik_(d.syntax == post::Syntax::Sinumerik),
          framed_(!sinumerik_ && d.percentFraming),
          numbered_(!sinumerik_ && !d.programNumberLine.empty()),
          points_(!sinumerik_ && d.decimalPointAlways),
          offsetNeeded_(!d.lengthOffset.empty()),
          dwellWord_(sinumerik_ ? 'F' : d.dwellWord),
          tapSynchronised_(d.tap == "G33.1")
    {
    }

    TapeReading read(const std::string& text)
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

private:
    // Drill..Bore: the canned cycles G81, G83, G84, G85, G86 (ISO);
    // Synchronised: LinuxCNC's G33.1.
    enum class Mode { None, Rapid, Feed, Clockwise, CounterClockwise, Synchronised, Drill, Peck, Tap, Ream, Bore };

    // A SINUMERIK cycle called modally: CYCLE81, 83, 84, 85 or 86.
    struct ModalCycle {
        int number = 81;
        double rtp = 0, rfp = 0, sdis = 0, dp = 0;
        double fdep = 0, dam = 0;          // CYCLE83: the first depth (absolute), each further peck
        double pit = 0, sst = 0, sst1 = 0; // CYCLE84: the pitch, the speeds in and out
        double ffr = 0, rff = 0;           // CYCLE85: the feeds in and out
    };

    struct Block {
        std::vector<int> g, m;        // G in tenths (G59.1: 591), M whole
        std::map<char, double> v;     // X Y Z I J K R F P Q S T H D
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

    void line(const std::string& raw)
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

    void block(const Block& b)
    {
        // G codes: at most one of the motion group.
        std::optional<Mode> motion;
        bool g4 = false, g28 = false, g43 = false, g53 = false, g80 = false, indexed = false, g64 = false, g641 = false;
        const auto setMotion = [&](Mode mode) {
            if (motion || g80) refuse("two motion codes in one block");
            motion = mode;
        };
        const auto named = [](int g) {
            return "G" + std::to_string(g / 10) + (g % 10 != 0 ? "." + std::to_string(g % 10) : std::string());
        };
        for (const int g : b.g) {
            if (g % 10 != 0) {
                // G59.1..G59.3 (LinuxCNC), G54.1 P (FANUC), G33.1 (LinuxCNC's tapping).
                if (!sinumerik_ && g >= 591 && g <= 593) continue;
                if (!sinumerik_ && g == 541) indexed = true;
                else if (!sinumerik_ && g == 331 && tapSynchronised_) setMotion(Mode::Synchronised);
                else refuse(named(g) + " is not understood");
                continue;
            }
            const int n = g / 10;
            if (n == 0) setMotion(Mode::Rapid);
            else if (n == 1) setMotion(Mode::Feed);
            else if (n == 2) setMotion(Mode::Clockwise);
            else if (n == 3) setMotion(Mode::CounterClockwise);
            else if (n == 17 || n == 40 || n == 94) continue;
            else if (n == 90) incremental_ = false;
            else if (n == 4) g4 = true;
            else if (!sinumerik_ && n == 81) setMotion(Mode::Drill);
            else if (!sinumerik_ && n == 83) setMotion(Mode::Peck);
            else if (!sinumerik_ && n == 84 && !tapSynchronised_) setMotion(Mode::Tap);
            else if (!sinumerik_ && n == 85) setMotion(Mode::Ream);
            else if (!sinumerik_ && n == 86) setMotion(Mode::Bore);
            else if (!sinumerik_ && n == 80) {
                if (motion) refuse("two motion codes in one block");
                g80 = true;
            } else if (!sinumerik_ && (n == 20 || n == 21)) m_.units(n == 20);
            else if (sinumerik_ && (n == 700 || n == 710)) m_.units(n == 700);
            else if (!sinumerik_ && n == 49) continue;
            else if (!sinumerik_ && n == 91) incremental_ = true;
            else if (!sinumerik_ && n == 43) g43 = true;
            else if (!sinumerik_ && n == 28) g28 = true;
            else if (!sinumerik_ && n == 53) g53 = true;
            else if (!sinumerik_ && n == 64) g64 = true;
            else if (!sinumerik_ && n == 98) g98_ = true;
            else if (!sinumerik_ && n == 154) indexed = true;
            else if (!sinumerik_ && n >= 54 && n <= 59) continue;
            else if (sinumerik_ && ((n >= 54 && n <= 57) || (n >= 505 && n <= 599))) continue;
            else if (sinumerik_ && n == 641) g641 = true;
            else refuse(named(g) + " is not understood");
        }
        if (b.adis && !g641) refuse("ADIS without G641");
        if (g641 && !b.adis) refuse("G641 without ADIS");

        // F: the feed rate, or on SINUMERIK with G4 the dwell time.
        if (b.has('F') && !(g4 && dwellWord_ == 'F')) {
            if (!(b.v.at('F') > 0)) refuse("a feed rate of zero");
            m_.feed = b.v.at('F');
        }
        const Mode modeNow = motion ? *motion : mode_;
        // P: G4's time, G154's or G54.1's offset, G64's tolerance, G86's dwell (LinuxCNC).
        if (b.has('P') && !g4 && !indexed && !g64 && modeNow != Mode::Bore) refuse("P without G4, G54.1, G64, G86 or G154");
        if (indexed) {
            if (!b.has('P') || b.point.at('P') || b.v.at('P') < 1 || b.v.at('P') > 99) refuse("G154 or G54.1 needs P1 to P99");
        }
        if (b.has('Q') && modeNow != Mode::Peck) refuse("Q without G83");
        if (b.has('K') && (!motion || *motion != Mode::Synchronised)) refuse("K without G33.1");
        if (b.has('T')) selected_ = static_cast<int>(b.v.at('T'));
        if (b.has('S')) rpm_ = b.v.at('S');
        for (const int mf : b.m) {
            if (mf == 6) {
                if (selected_ == 0) refuse("M6 with no tool selected");
                m_.tool = selected_;
                lengthOffset_ = !offsetNeeded_;
            } else if (mf == 30) {
                ended_ = true;
            } else if (mf == 29 && !sinumerik_) {
                if (!b.has('S')) refuse("M29 (rigid tapping) needs the speed in S");
            } else if (mf == 97 || mf == 98 || mf == 99 || mf == 198) {
                // A subprogram runs motion the tape does not hold: it cannot be judged.
                refuse("M" + std::to_string(mf) + " calls or leaves a subprogram, whose motion is not on the tape");
            }
            // Any other M word (M7 mist, M0/M1 stops, a shop's M51 through-spindle
            // coolant) is a switch of the machine's, no motion: taken as it is.
        }
        if (b.has('D')) {
            // D0 takes the tool's offsets off (SINUMERIK); D1 puts them on.
            if (b.v.at('D') == 0) {
                dInForce_ = false;
                if (m_.tool != 0) lengthOffset_ = false;  // a Z move needs D1 again
            } else {
                if (m_.tool == 0 || b.v.at('D') < 1) refuse("D with no tool in the spindle");
                lengthOffset_ = true;
                dInForce_ = true;
            }
        }
        if (b.has('H') != g43) refuse("G43 and H go together");
        if (g43) {
            if (static_cast<int>(b.v.at('H')) != m_.tool)
                refuse("G43 H" + show(b.v.at('H')) + " with T" + std::to_string(m_.tool) + " in the spindle");
            lengthOffset_ = true;
        }
        if (g4) {
            const char time = dwellWord_;
            if (!b.has(time) || b.v.at(time) < 0) refuse(std::string("G4 needs the dwell time in ") + time);
            if (points_ && !b.point.at(time)) refuse(std::string("G4 ") + time + " without a decimal point (milliseconds on this control)");
            if ((time != 'X' && b.has('X')) || b.has('Y') || b.has('Z') || motion) refuse("a dwell with a move");
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
        if (g53) {
            if (!motion || *motion != Mode::Rapid || b.has('X') || b.has('Y') || !b.has('Z') || b.v.at('Z') != 0.0)
                refuse("only 'G53 G0 Z0' is understood");
            return;
        }
        if (b.supa) {
            if (!motion || *motion != Mode::Rapid || b.has('X') || b.has('Y') || !b.has('Z') || b.v.at('Z') != 0.0)
                refuse("only 'G0 SUPA Z0 [D0]' is understood");
            // SUPA suppresses the frames, not the tool's length (MD
            // G53_TOOLCORR = 0, the default): with D1 in force the tool tip
            // would go to machine Z0, the spindle above the end of travel.
            if (dInForce_) refuse("G0 SUPA Z0 with a D in force moves the tool tip to machine Z0: write D0 in the block");
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
        case Mode::Synchronised:
            synchronisedTap(b, to);
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

    // LinuxCNC's G33.1 Z K at the hole the tool is over: down to Z at K x S
    // and back up to where it began at the same rate (the spindle reversed
    // at the bottom).
    void synchronisedTap(const Block& b, const Point3& to)
    {
        if (!b.has('Z') || !b.has('K')) refuse("G33.1 needs Z and K");
        if (b.has('X') || b.has('Y')) refuse("G33.1 only along Z is understood");
        if (!known(m_.at)) refuse("G33.1 from an unknown position");
        if (!(rpm_ > 0)) refuse("G33.1 with no spindle speed");
        if (!(b.v.at('K') > 0)) refuse("G33.1's K must be positive");
        if (to.z > m_.at.z) refuse("G33.1 upwards");
        const double rate = b.v.at('K') * rpm_;
        const Point3 top = m_.at;
        m_.feedTo(to, rate);
        m_.feedTo(top, rate);
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
    bool framed_;          // '%' lines lead and end the tape
    bool numbered_;        // an "O1000" program number line
    bool points_;          // lengths and feeds must carry a decimal point
    bool offsetNeeded_;    // a Z move after M6 waits for the length offset
    char dwellWord_;       // G4's time: P, X (FANUC) or F (SINUMERIK)
    bool tapSynchronised_; // tapping is G33.1 (LinuxCNC), not G84
    double rpm_ = 0.0;     // the last S
    Machine m_;
    Mode mode_ = Mode::None;
    bool incremental_ = false;
    bool g98_ = false;
    bool ended_ = false;
    bool lengthOffset_ = true;  // false from a tool change to its G43 H / D
    bool dInForce_ = false;     // SINUMERIK: a D (1 or more) in force, no D0 since
    bool programNumber_ = false;
    int percents_ = 0;
    int selected_ = 0;
    std::optional<double> cycleZ_, cycleR_, cycleQ_;
    std::optional<ModalCycle> mcall_;
};

}  // namespace

TapeReading readTape(const std::string& text, const post::Dialect& dialect)
{
    if (dialect.syntax == post::Syntax::Klartext) return readKlartext(text);
    return IsoReader(dialect).read(text);
}

}  // namespace taiwa::verify
