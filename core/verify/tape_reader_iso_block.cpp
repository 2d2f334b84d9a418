// What the ISO and SINUMERIK tape reader (tape_reader_iso.h) does with a
// block's words: the G codes checked and the modal state kept (motion,
// units, cycles, length offset, D, MCALL), the machine retracts taken as no
// move, and the move, arc, G33.1 tap or canned cycle made on the reader's
// machine.
#include "verify/tape_reader_iso.h"

#include <cmath>

namespace taiwa::verify::tape {

// The block's G codes: at most one of the motion group; the modal ones
// (units, G90/G91, G98) taken at once.
IsoReader::GCodes IsoReader::gCodes(const Block& b)
{
    GCodes c;
    auto& [motion, g4, g28, g43, g53, g80, indexed, g64, g641] = c;
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
    return c;
}

// The block's other words: F, P, Q, K, T, S, the M functions, D and H, each
// where its G code allows it.
void IsoReader::words(const Block& b, const GCodes& c)
{

    // F: the feed rate, or on SINUMERIK with G4 the dwell time.
    if (b.has('F') && !(c.g4 && dwellWord_ == 'F')) {
        if (!(b.v.at('F') > 0)) refuse("a feed rate of zero");
        m_.feed = b.v.at('F');
    }
    const Mode modeNow = c.motion ? *c.motion : mode_;
    // P: G4's time, G154's or G54.1's offset, G64's tolerance, G86's dwell (LinuxCNC).
    if (b.has('P') && !c.g4 && !c.indexed && !c.g64 && modeNow != Mode::Bore) refuse("P without G4, G54.1, G64, G86 or G154");
    if (c.indexed) {
        if (!b.has('P') || b.point.at('P') || b.v.at('P') < 1 || b.v.at('P') > 99) refuse("G154 or G54.1 needs P1 to P99");
    }
    if (b.has('Q') && modeNow != Mode::Peck) refuse("Q without G83");
    if (b.has('K') && (!c.motion || *c.motion != Mode::Synchronised)) refuse("K without G33.1");
    if (b.has('T')) selected_ = static_cast<int>(b.v.at('T'));
    if (b.has('S')) rpm_ = b.v.at('S');
    for (const int mf : b.m) {
        if (mf == 6) {
            if (selected_ == 0) refuse("M6 with no tool selected");
            m_.tool = selected_;
            lengthOffset_ = !offsetNeeded_;
        } else if (mf == 30) {
            m_.ended = true;
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
    if (b.has('H') != c.g43) refuse("G43 and H go together");
    if (c.g43) {
        if (static_cast<int>(b.v.at('H')) != m_.tool)
            refuse("G43 H" + show(b.v.at('H')) + " with T" + std::to_string(m_.tool) + " in the spindle");
        lengthOffset_ = true;
    }
}

void IsoReader::block(const Block& b)
{
    const GCodes c = gCodes(b);
    words(b, c);
    if (c.g4) {
        const char time = dwellWord_;
        if (!b.has(time) || b.v.at(time) < 0) refuse(std::string("G4 needs the dwell time in ") + time);
        if (points_ && !b.point.at(time)) refuse(std::string("G4 ") + time + " without a decimal point (milliseconds on this control)");
        if ((time != 'X' && b.has('X')) || b.has('Y') || b.has('Z') || c.motion) refuse("a dwell with a move");
        ++m_.out.dwells;
        return;
    }
    if (c.g80) {
        mode_ = Mode::None;
        cycleZ_.reset();
        cycleR_.reset();
        cycleQ_.reset();
    }
    if (c.motion) mode_ = *c.motion;

    const bool axes = b.has('X') || b.has('Y') || b.has('Z');
    // The machine retracts: no move in the program's coordinates.
    if (c.g28) {
        if (!incremental_ || b.has('X') || b.has('Y') || !b.has('Z') || b.v.at('Z') != 0.0 || c.motion)
            refuse("only 'G28 G91 Z0.' is understood");
        return;
    }
    if (c.g53) {
        if (!c.motion || *c.motion != Mode::Rapid || b.has('X') || b.has('Y') || !b.has('Z') || b.v.at('Z') != 0.0)
            refuse("only 'G53 G0 Z0' is understood");
        return;
    }
    if (b.supa) {
        if (!c.motion || *c.motion != Mode::Rapid || b.has('X') || b.has('Y') || !b.has('Z') || b.v.at('Z') != 0.0)
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
        mcall_ = sinumerikCycle(b.cycle);
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
        runCalledCycle(m_, *mcall_, to);
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

void IsoReader::synchronisedTap(const Block& b, const Point3& to)
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

void IsoReader::drill(const Block& b, const Point3& hole)
{
    const int code = mode_ == Mode::Drill ? 81 : mode_ == Mode::Peck ? 83 : mode_ == Mode::Tap ? 84 : mode_ == Mode::Ream ? 85 : 86;
    const std::string name = "G" + std::to_string(code);
    if (!g98_) refuse(name + " without G98 (only the return to the initial level is understood)");
    if (b.has('Z')) cycleZ_ = b.v.at('Z');
    if (b.has('R')) cycleR_ = b.v.at('R');
    if (b.has('Q')) cycleQ_ = b.v.at('Q');
    if (!cycleZ_ || !cycleR_) refuse(name + " needs Z and R");
    runCannedCycle(m_, code, hole, *cycleR_, *cycleZ_, cycleQ_);
}

}  // namespace taiwa::verify::tape
