// The lathe tape reader (tape_reader_lathe.h): the tape split into lines,
// their comments taken out, each block's words read strictly and acted on
// (the modal state, the tool, the moves); the cycles' words in
// tape_reader_lathe_cycles.cpp.
#include "verify/tape_reader_lathe.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace taiwa::verify {

namespace tape {

LatheReader::LatheReader(const post::Dialect& d, const WaitCodeRange* twoPath)
    : family_(d.syntax == post::Syntax::Sinumerik ? Family::Siemens : d.macroSyntax == "fanuc" ? Family::Fanuc : Family::LinuxCnc),
      oneBlock_(d.oneBlockRoughingCycle),
      numbered_(family_ != Family::Siemens && !d.programNumberLine.empty()),
      points_(family_ != Family::Siemens && d.decimalPointAlways), diameter_(family_ == Family::Fanuc)
{
    m_.framed = family_ != Family::Siemens && d.percentFraming;
    if (twoPath && family_ != Family::Siemens) waits_ = *twoPath;
}

TapeReading LatheReader::read(const std::string& text)
{
    return m_.readLines(text, [&](const std::string& raw) { line(raw); }, [&](const std::vector<std::string>& lines) {
        if (inSub_ >= 0) refuse("o" + std::to_string(inSub_) + " sub is never closed by its endsub");
        if (inTimeout_ >= 0) refuse("o" + std::to_string(inTimeout_) + " if is never closed by its endif");
        if (pending_) refuse("G71's contour blocks N" + std::to_string(pendingFrom_) + " to N" + std::to_string(pendingTo_) + " never end");
        m_.endOfTape(lines);
    });
}

LatheReader::Block LatheReader::words(const std::string& s)
{
    const bool siemens = family_ == Family::Siemens;
    Block b;
    const auto tokens = splitWords(s);
    for (std::size_t k = 0; k < tokens.size(); ++k) {
        const std::string& t = tokens[k];
        if (siemens && (t == "DIAMON" || t.starts_with("CR=") || t.starts_with("LIMS="))) {
            if (t == "DIAMON") {
                b.diamon = true;
                continue;
            }
            const bool cr = t[0] == 'C';
            const auto value = decimal(std::string_view(t).substr(cr ? 3 : 5), false);
            if (!value || (cr ? b.cr : b.lims)) refuse("'" + t + "' is not understood");
            (cr ? b.cr : b.lims) = *value;
            continue;
        }
        if (codeWord(t, k, b.g, b.m, &b.n)) continue;
        // L: a two-path LinuxCNC program's M66 (its wait's kind).
        const bool l = waits_ && family_ == Family::LinuxCnc;
        if (!letterWord(t, siemens ? "XZKFSTD" : l ? "XZIKFSTDPQUWRHJAL" : "XZIKFSTDPQUWRHJA", l ? "STHL" : "STH", b)) continue;
        const char letter = t[0];
        // A FANUC or a Haas reads a length without a point in least increments.
        if (points_ && std::string_view("XZIKUWRFD").find(letter) != std::string_view::npos && !b.point[letter])
            refuse("'" + t + "' without a decimal point (this control reads it in least increments)");
    }
    return b;
}

void LatheReader::line(const std::string& raw)
{
    if (raw.find_first_of("\r\t") != std::string::npos) refuse("a carriage return or tab");
    const std::string s = trim(m_.withoutComments(raw, family_ == Family::Siemens));
    if (s.empty() || m_.framingLine(s)) return;
    const auto tokens = splitWords(s);
    if (timeout(s, tokens)) return;
    // LinuxCNC's contour subroutines: defined, not run.
    if (family_ == Family::LinuxCnc && tokens[0][0] == 'o') {
        const auto n = whole(std::string_view(tokens[0]).substr(1));
        if (!n || tokens.size() != 2 || (tokens[1] != "sub" && tokens[1] != "endsub")) refuse("'" + s + "' is not understood");
        if (tokens[1] == "sub") {
            if (inSub_ >= 0) refuse("a subroutine inside a subroutine");
            if (subs_.count(*n)) refuse("o" + std::to_string(*n) + " defined twice");
            inSub_ = *n;
            subs_[*n];
        } else {
            if (inSub_ != *n) refuse("an endsub with no sub o" + std::to_string(*n) + " open");
            inSub_ = -1;
        }
        return;
    }
    if (inSub_ >= 0) {
        subs_[inSub_].push_back(words(s));
        return;
    }
    if (numbered_ && tokens.size() == 1 && tokens[0][0] == 'O') {
        if (!whole(std::string_view(tokens[0]).substr(1)) || programNumber_) refuse("'" + tokens[0] + "' is not understood");
        programNumber_ = true;
        return;
    }
    const Block b = words(s);
    if (pending_) {
        // A FANUC or Haas G71's contour blocks P..Q: the cycle's, not run.
        if (pendingBlocks_.empty() && b.n != pendingFrom_)
            refuse("G71's contour should begin here with N" + std::to_string(pendingFrom_));
        pendingBlocks_.push_back(b);
        if (b.n != pendingTo_) return;
        TapeCycle c = *pending_;
        pending_.reset();
        contour(c, pendingBlocks_);
        pendingBlocks_.clear();
        const int here = m_.line;
        m_.line = pendingLine_;
        runCycle(c);
        m_.line = here;
        return;
    }
    afterWait_ = false;
    block(b);
}

std::optional<LatheReader::Mode> LatheReader::gCodes(const Block& b, int& cycle, bool& limit)
{
    const bool siemens = family_ == Family::Siemens, fanuc = family_ == Family::Fanuc, linuxcnc = family_ == Family::LinuxCnc;
    std::optional<Mode> motion;
    const auto set = [&](Mode m) {
        if (motion || cycle) refuse("two motion codes in one block");
        motion = m;
    };
    const auto named = [](int g) {
        return "G" + std::to_string(g / 10) + (g % 10 != 0 ? "." + std::to_string(g % 10) : std::string());
    };
    bool indexed = false;
    for (const int g : b.g) {
        const int n = g / 10;
        if (g % 10 != 0) {
            if (linuxcnc && g >= 591 && g <= 593) continue;
            if (!siemens && g == 541) indexed = true;
            else refuse(named(g) + " is not understood");
            continue;
        }
        if (n <= 3) set(n == 0 ? Mode::Rapid : n == 1 ? Mode::Feed : n == 2 ? Mode::Clockwise : Mode::CounterClockwise);
        else if (n == 33) set(Mode::Thread);
        else if (n == 18) plane_ = true;
        else if (n == 40 || n == 41 || n == 42 || n == 90 || n == 96 || n == 97) continue;
        else if (linuxcnc && n == 7) diameter_ = true;
        else if ((!fanuc && n == 95) || (fanuc && n == 99)) perRevolution_ = true;
        else if (!siemens && (n == 20 || n == 21)) m_.units(n == 20);
        else if (siemens && (n == 700 || n == 710)) m_.units(n == 700);
        else if (!siemens && n == 80) continue;
        else if (linuxcnc && n == 43) {
            if (b.has('H')) refuse("G43 H on a lathe tape (the tool's own offset is taken)");
        } else if (fanuc && n == 50) limit = true;
        else if (!siemens && (n == 71 || n == 76)) {
            if (motion || cycle) refuse("two motion codes in one block");
            cycle = n;
        } else if (!siemens && n == 154) indexed = true;
        else if (!siemens && n >= 54 && n <= 59) continue;
        else if (siemens && ((n >= 54 && n <= 57) || (n >= 505 && n <= 599))) continue;
        else refuse(named(g) + " is not understood");
    }
    if (b.diamon) diameter_ = true;
    if (indexed && (!b.has('P') || b.point.at('P') || b.v.at('P') < 1 || b.v.at('P') > 99)) refuse("G154 or G54.1 needs P1 to P99");
    if (!indexed && !cycle && b.has('P')) refuse("P without G71, G76, G54.1 or G154");
    if (limit && (!b.has('S') || b.has('X') || b.has('Z'))) refuse("only 'G50 S<limit>' is understood (G50 with X or Z sets the coordinates)");
    return motion;
}

void LatheReader::otherWords(const Block& b)
{
    const bool siemens = family_ == Family::Siemens, fanuc = family_ == Family::Fanuc;
    if (b.has('F')) {
        if (!(b.v.at('F') > 0)) refuse("a feed rate of zero");
        m_.feed = b.v.at('F');
    }
    if (b.lims && !siemens) refuse("LIMS= is not understood");
    for (const char c : std::string("QUWRHJA"))
        if (b.has(c)) refuse(std::string(1, c) + " without G71 or G76");
    if (b.has('T')) {
        const int t = static_cast<int>(b.v.at('T'));
        if (fanuc) {
            // T0101: the station and its offset; the turret indexes at the T word.
            if (t < 100 || t % 100 == 0) refuse("T" + std::to_string(t) + ": a station and its offset (T0101) expected");
            m_.tool = t / 100;
        } else if (siemens) {
            if (t < 1) refuse("T0 is not understood");
            m_.tool = t;
        } else {
            selected_ = t;
        }
    }
    if (b.has('D')) {
        if (siemens && !(b.v.at('D') == 0 || (b.v.at('D') == 1 && m_.tool != 0))) refuse("only D1 with a tool, or D0, is understood");
        // LinuxCNC's D with G96: the spindle's limit.
        if (!siemens && (fanuc || std::find(b.g.begin(), b.g.end(), 960) == b.g.end())) refuse("D without G96, G71 or G76");
    }
    for (const int mf : b.m) {
        if (mf == 6) {
            if (fanuc || siemens) refuse("M6: this control changes the tool with its T word");
            if (selected_ == 0) refuse("M6 with no tool selected");
            m_.tool = selected_;
        } else if (mf == 30) {
            m_.ended = true;
        } else if (mf == 97 || mf == 98 || mf == 99 || mf == 198) {
            refuse("M" + std::to_string(mf) + " calls or leaves a subprogram, whose motion is not on the tape");
        }
        // Any other M word is a switch of the machine's: no motion.
    }
}

void LatheReader::block(const Block& b)
{
    if (sync(b)) return;
    int cycle = 0;
    bool limit = false;
    const auto motion = gCodes(b, cycle, limit);
    if (cycle == 71) return roughing(b);
    if (cycle == 76) return threading(b);
    otherWords(b);  // G50 S, G96 S, G97 S: the spindle's, no motion
    if (motion) mode_ = *motion;
    if (b.has('X') || b.has('Z')) return move(b);
    if (b.has('I') || b.has('K') || b.cr) refuse("I, K or CR= with no move");
}

void LatheReader::move(const Block& b)
{
    if (!plane_) refuse("a move before G18 (the lathe's plane)");
    if (b.has('X') && !diameter_)
        refuse(family_ == Family::Siemens ? "an X word before DIAMON (it would be a radius)" : "an X word before G7 (it would be a radius)");
    Point3 to = m_.at;
    to.y = 0.0;
    if (b.has('X')) to.x = b.v.at('X');
    if (b.has('Z')) to.z = b.v.at('Z');
    const bool arc = mode_ == Mode::Clockwise || mode_ == Mode::CounterClockwise;
    if (!arc && (b.has('I') || b.cr)) refuse("I or CR= without G2 or G3");
    if (!arc && mode_ != Mode::Thread && b.has('K')) refuse("K without G2, G3 or G33");
    if ((mode_ == Mode::Feed || arc) && !perRevolution_)
        refuse(std::string("a feed with no feed per revolution in force (") + (family_ == Family::Fanuc ? "G99" : "G95") + ")");
    switch (mode_) {
    case Mode::None: refuse("coordinates with no motion mode in force");
    case Mode::Rapid: return m_.traverse(to);
    case Mode::Feed: return m_.feedTo(to, m_.feed);
    case Mode::Thread:
        if (!b.has('K')) refuse("G33 needs the lead in K");
        return m_.threadTo(to, b.v.at('K'));
    case Mode::Clockwise:
    case Mode::CounterClockwise: break;
    }
    if (!known(m_.at)) refuse("an arc from an unknown position");
    const int turn = mode_ == Mode::Clockwise ? -1 : 1;
    if (family_ != Family::Siemens) {
        if (!b.has('I') || !b.has('K')) refuse("an arc needs both I and K");
        return m_.latheArc(to, {m_.at.x + 2.0 * b.v.at('I'), m_.at.z + b.v.at('K')}, turn, m_.feed);
    }
    // SINUMERIK's CR=: the centre on the chord's bisector, to the right of
    // the chord (Z right, X up) for a clockwise arc of at most a half turn.
    if (!b.cr) refuse("an arc needs CR=");
    const double az = m_.at.z, ar = m_.at.x / 2.0, dz = to.z - az, dr = to.x / 2.0 - ar;
    const double chord = std::hypot(dz, dr), radius = std::abs(*b.cr);
    const double tolerance = m_.out.inches ? 0.0005 : 0.005;
    if (chord < tolerance || chord > 2.0 * radius + tolerance) refuse("CR=" + show(*b.cr) + " cannot join these points");
    const double h = std::sqrt(std::max(0.0, radius * radius - chord * chord / 4.0));
    const double side = (turn < 0 ? 1.0 : -1.0) * (*b.cr > 0 ? 1.0 : -1.0);
    const double cz = az + dz / 2.0 + side * h * dr / chord, cr = ar + dr / 2.0 - side * h * dz / chord;
    m_.latheArc(to, {2.0 * cr, cz}, turn, m_.feed);
}

}  // namespace tape

TapeReading readLatheTape(const std::string& text, const post::Dialect& dialect, const WaitCodeRange* twoPath)
{
    if (dialect.syntax == post::Syntax::Klartext) {
        TapeReading r;
        r.error = "line 1: a Klartext tape of a lathe is not read (no lathe tape is written in Klartext)";
        r.errorLine = 1;
        return r;
    }
    return tape::LatheReader(dialect, twoPath).read(text);
}

}  // namespace taiwa::verify
