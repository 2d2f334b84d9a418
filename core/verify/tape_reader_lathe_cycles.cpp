// The lathe controls' cycles on the tape (tape_reader_lathe.h): G71
// roughing and G76 threading in LinuxCNC's, FANUC's two-block and Haas's
// one-block forms, read into TapeCycle (the words as the lathe post writes
// them, post/lathe_writer.cpp) with the box their motions stay within, and
// recorded as one Cycle motion that ends where it began.
#include "verify/tape_reader_lathe.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace taiwa::verify::tape {

namespace {

// The block has exactly the words `need` (and maybe `may`) besides its N and G.
void onlyWords(const LatheReader::Block& b, const std::string& need, const std::string& may, const std::string& what)
{
    for (const char c : need)
        if (!b.has(c)) refuse(what + " needs " + std::string(1, c));
    for (const auto& [c, v] : b.v)
        if (need.find(c) == std::string::npos && may.find(c) == std::string::npos)
            refuse(std::string(1, c) + " is not understood in " + what);
    if (!b.m.empty() || b.g.size() != 1 || b.cr || b.lims || b.diamon) refuse(what + " with other words");
}

}  // namespace

// A cycle of `kind` from where the tool stands (`word` names it when that
// is not known yet).
TapeCycle LatheReader::cycleHere(TapeCycle::Kind kind, const char* word) const
{
    if (!known(m_.at)) refuse(std::string(word) + " from an unknown position");
    TapeCycle c;
    c.kind = kind;
    c.start = m_.at;
    return c;
}

// G71: LinuxCNC's "G71 Q<n> X Z D I R F" (the contour in o<n>, D the
// allowance, I the depth of a pass, R the lift), FANUC's "G71 U R" (the
// depth, the lift) then "G71 P Q U W F", Haas's "G71 P Q U W D F" (D the
// depth; the lift the control's setting). U is on the diameter.
void LatheReader::roughing(const Block& b)
{
    if (!plane_ || !diameter_ || !perRevolution_) refuse("G71 before G18, diameter mode and feed per revolution");
    TapeCycle c = cycleHere(TapeCycle::Roughing, "G71");
    if (family_ == Family::LinuxCnc) {
        onlyWords(b, "QXZDIRF", "", "G71");
        const auto q = b.v.at('Q');
        const auto sub = subs_.find(static_cast<int>(q));
        if (q != std::floor(q) || sub == subs_.end()) refuse("G71 Q" + show(q) + " calls no o-subroutine defined before it");
        c.start = {b.v.at('X'), 0.0, b.v.at('Z')};
        c.allowanceX = b.v.at('D');
        c.depth = b.v.at('I');
        c.retract = b.v.at('R');
        c.allowanceZ = kUnknown;  // not on this tape
        c.feed = b.v.at('F');
        contour(c, sub->second);
        return runCycle(c);
    }
    if (!b.has('P')) {
        if (oneBlock_) refuse("this control's G71 is one block with P and Q");
        onlyWords(b, "UR", "", "G71's first block");
        firstRoughing_ = b;
        return;
    }
    onlyWords(b, oneBlock_ ? "PQUWDF" : "PQUWF", "", "G71");
    if (!oneBlock_ && !firstRoughing_) refuse("G71 P Q without its first block 'G71 U R'");
    if (b.point.at('P') || b.point.at('Q')) refuse("G71's P and Q are sequence numbers");
    c.depth = oneBlock_ ? b.v.at('D') : firstRoughing_->v.at('U');
    c.retract = oneBlock_ ? 0.0 : firstRoughing_->v.at('R');
    firstRoughing_.reset();
    c.allowanceX = b.v.at('U') / 2.0;
    c.allowanceZ = b.v.at('W');
    c.feed = b.v.at('F');
    if (!(c.feed > 0 && c.depth > 0)) refuse("G71 with no feed or no depth of cut");
    pending_ = c;
    pendingFrom_ = static_cast<int>(b.v.at('P'));
    pendingTo_ = static_cast<int>(b.v.at('Q'));
    pendingLine_ = m_.line;
}

// From the cycle's start: G0 or G1 onto the first point (FANUC, Haas: X
// alone, type I), then lines and arcs (I on the radius, K, from the last
// point), X and Z absolute.
void LatheReader::contour(TapeCycle& c, const std::vector<Block>& blocks) const
{
    if (blocks.empty()) refuse("G71's contour is empty");
    Point3 at = c.start;
    Mode mode = Mode::None;
    const double tolerance = m_.out.inches ? 0.0005 : 0.005;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
        const Block& b = blocks[k];
        for (const auto& [w, v] : b.v)
            if (std::string("XZIK").find(w) == std::string::npos) refuse(std::string(1, w) + " in G71's contour is not understood");
        if (!b.m.empty() || b.g.size() > 1 || b.cr) refuse("G71's contour: only G0 to G3, X, Z, I and K are understood");
        if (!b.g.empty()) {
            const int g = b.g.front();
            if (g > 30 || g % 10 != 0) refuse("G71's contour: only G0 to G3 are understood");
            if (g == 0 && k != 0) refuse("G71's contour: G0 only onto its first point");
            mode = g == 0 ? Mode::Rapid : g == 10 ? Mode::Feed : g == 20 ? Mode::Clockwise : Mode::CounterClockwise;
        }
        if (k == 0 && mode != Mode::Rapid && mode != Mode::Feed) refuse("G71's contour begins with G0 or G1");
        if (k == 0 && family_ != Family::LinuxCnc && b.has('Z')) refuse("G71's first contour block moves X alone here (type I)");
        if (!b.has('X') && !b.has('Z')) refuse("G71's contour: a block with no move");
        Point3 to = at;
        if (b.has('X')) to.x = b.v.at('X');
        if (b.has('Z')) to.z = b.v.at('Z');
        TapeCycle::Point p{to.x, to.z, 0, 0.0, 0.0};
        if (mode == Mode::Clockwise || mode == Mode::CounterClockwise) {
            if (!b.has('I') || !b.has('K')) refuse("an arc of G71's contour needs I and K");
            p.turn = mode == Mode::Clockwise ? -1 : 1;
            p.cx = at.x + 2.0 * b.v.at('I');
            p.cz = at.z + b.v.at('K');
            const double r0 = std::hypot((at.x - p.cx) / 2.0, at.z - p.cz), r1 = std::hypot((to.x - p.cx) / 2.0, to.z - p.cz);
            if (std::abs(r0 - r1) > tolerance || r0 < tolerance) refuse("an arc of G71's contour whose end is not on its circle");
        } else if (b.has('I') || b.has('K')) {
            refuse("I or K on a line of G71's contour");
        }
        c.contour.push_back(p);
        at = to;
    }
}

// G76: LinuxCNC's "G76 P(pitch) Z I(crest from the drive line) J(first
// depth) [R] K(depth) [Q] [H]" with I, J, K on the diameter; FANUC's "G76
// P(m)(r)(a) Q R" then "G76 X(root) Z P(depth) Q(first) F(pitch)", P and Q
// in least increments; Haas's "G76 X Z K D F A P1". From the drive point,
// where the tool stands.
void LatheReader::threading(const Block& b)
{
    if (!plane_ || !diameter_) refuse("G76 before G18 and diameter mode");
    TapeCycle c = cycleHere(TapeCycle::Threading, "G76");
    if (family_ == Family::LinuxCnc) {
        onlyWords(b, "PZIJK", "RQH", "G76");
        c.feed = b.v.at('P');
        c.zEnd = b.v.at('Z');
        c.crestX = m_.at.x + b.v.at('I');
        c.rootX = c.crestX + (b.v.at('I') < 0 ? -b.v.at('K') : b.v.at('K'));
        c.depth = b.v.at('K') / 2.0;
        c.firstDepth = b.v.at('J') / 2.0;
        if (b.has('H')) c.springPasses = static_cast<int>(b.v.at('H'));
    } else if (!oneBlock_ && !b.has('X')) {
        onlyWords(b, "PQR", "", "G76's first block");
        const double p = b.v.at('P');
        if (b.point.at('P') || p >= 1e6 || static_cast<int>(p) / 100 % 100 != 0)
            refuse("G76 P(m)(r)(a): six digits, no chamfer out (rr 00) understood");
        firstThreading_ = b;
        return;
    } else if (!oneBlock_) {
        onlyWords(b, "XZPQF", "", "G76");
        if (!firstThreading_) refuse("G76 X Z without its first block 'G76 P Q R'");
        if (b.point.at('P') || b.point.at('Q')) refuse("G76's P and Q are in least increments (no decimal point)");
        c.springPasses = static_cast<int>(firstThreading_->v.at('P')) / 10000 - 1;
        firstThreading_.reset();
        c.rootX = b.v.at('X');
        c.zEnd = b.v.at('Z');
        c.depth = increments(b.v.at('P'));
        c.firstDepth = increments(b.v.at('Q'));
        c.feed = b.v.at('F');
    } else {
        onlyWords(b, "XZKDFAP", "", "G76");
        if (b.v.at('P') != 1) refuse("only G76 P1 (one edge, constant amount) is understood");
        c.rootX = b.v.at('X');
        c.zEnd = b.v.at('Z');
        c.depth = b.v.at('K');
        c.firstDepth = b.v.at('D');
        c.feed = b.v.at('F');
    }
    if (!(c.feed > 0 && c.depth > 0 && c.firstDepth > 0)) refuse("G76 with no pitch, depth or first depth");
    runCycle(c);
}

// The box: roughing between the start and the contour (an arc's whole
// circle), grown by the allowances, the lift (Haas: the control's, taken
// as no more than a pass) and a pass; threading between the drive point
// and the root and end, grown along Z by the depth.
void LatheReader::runCycle(TapeCycle c)
{
    double xl = std::min(c.start.x, m_.at.x), xh = std::max(c.start.x, m_.at.x);
    double zl = std::min(c.start.z, m_.at.z), zh = std::max(c.start.z, m_.at.z);
    const auto take = [&](double x, double z) {
        xl = std::min(xl, x), xh = std::max(xh, x), zl = std::min(zl, z), zh = std::max(zh, z);
    };
    if (c.kind == TapeCycle::Roughing) {
        for (const auto& p : c.contour) {
            take(p.x, p.z);
            if (p.turn == 0) continue;
            const double r = std::hypot((p.x - p.cx) / 2.0, p.z - p.cz);
            take(p.cx - 2.0 * r, p.cz - r);
            take(p.cx + 2.0 * r, p.cz + r);
        }
        const double grow = std::abs(c.allowanceX) + std::max(c.retract, 0.0) + c.depth;
        const double along = std::isnan(c.allowanceZ) ? 0.0 : std::abs(c.allowanceZ);
        xl -= 2.0 * grow, xh += 2.0 * grow, zl -= along, zh += along;
    } else {
        take(c.rootX, c.zEnd);
        if (c.crestX >= 0) take(c.crestX, c.zEnd);
        zl -= c.depth, zh += c.depth;
    }
    c.xLow = xl, c.xHigh = xh, c.zLow = zl, c.zHigh = zh;
    const Point3 end = c.start;
    m_.out.cycles.push_back(std::move(c));
    m_.cycle(static_cast<int>(m_.out.cycles.size()) - 1, end);
    // The control's cycle leaves the modal motion and feed to the next block.
    mode_ = Mode::None;
    m_.feed = kUnknown;
}

}  // namespace taiwa::verify::tape
