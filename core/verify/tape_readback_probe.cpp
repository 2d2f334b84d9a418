// A probing unit's programs read back (tape_readback.h, readBackProbing):
// run by the probing programs' reader (tape_reader_probe.h) against the
// unit's nominal part, each touch made where the stylus ball meets it, and
// every motion held against what the cycle is meant to do. The cycle runs
// in the part's own frame (its nominal centre X0 Y0, its top face Z0, every
// work offset zero, the probe started over the centre at the clearance
// above the top face); the setting program in machine coordinates, the
// measured centre where the part is. docs/verification.md "The tape read back".
#include "verify/tape_readback.h"

#include "verify/tape_reader_probe.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::verify {

namespace {

constexpr double kTolerance = 0.002;  // [mm]: the programs' 4 decimals, rounded twice
constexpr double kTouch = 0.01;       // [mm]: deeper than this into the part is a collision

// The unit's nominal part as the stylus ball meets it: the outline (a
// boss, a bore, a block, a pocket) below the top face Z0 about X0 Y0, and
// the table under the stock; the controlled point is the ball's bottom.
struct Part {
    bool round = true, inside = false;
    double hx = 0.0, hy = 0.0, ball = 0.0, table = 0.0;

    // Signed distance from the ball's centre to the material [mm]: negative inside it.
    double distance(const Point3& tip) const
    {
        const Point3 c{tip.x, tip.y, tip.z + ball};
        double outside;  // across, from the outline: positive off the material
        if (round) {
            outside = std::hypot(c.x, c.y) - hx;
        } else {
            const double qx = std::abs(c.x) - hx, qy = std::abs(c.y) - hy;
            outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
        }
        if (inside) outside = -outside;
        const double part = (c.z > 0.0 || outside > 0.0) ? std::hypot(std::max(c.z, 0.0), std::max(outside, 0.0))
                                                         : std::max(c.z, outside);
        return std::min(part, c.z - table);
    }
    // How deep [mm] the ball goes into the material along a straight motion.
    double depth(const Point3& a, const Point3& b) const
    {
        if (std::isnan(b.z) || std::isnan(b.x) || std::isnan(b.y)) return 0.0;  // up at the machine's top
        const Point3 from = std::isnan(a.z) || std::isnan(a.x) || std::isnan(a.y) ? b : a;
        const int samples = std::clamp(static_cast<int>(std::hypot(b.x - from.x, b.y - from.y, b.z - from.z) / 0.05), 1, 20000);
        double deepest = 0.0;
        for (int k = 0; k <= samples; ++k) {
            const double t = static_cast<double>(k) / samples;
            deepest = std::max(deepest, ball - distance({from.x + (b.x - from.x) * t, from.y + (b.y - from.y) * t, from.z + (b.z - from.z) * t}));
        }
        return deepest;
    }
    // Where a probing move from `a` to `b` first touches.
    std::optional<Point3> touch(const Point3& a, const Point3& b) const
    {
        const auto at = [&](double t) { return Point3{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t}; };
        const int samples = std::clamp(static_cast<int>(std::hypot(b.x - a.x, b.y - a.y, b.z - a.z) / 0.05), 1, 20000);
        if (distance(a) <= ball) return a;
        for (int k = 1; k <= samples; ++k) {
            double hi = static_cast<double>(k) / samples;
            if (distance(at(hi)) > ball) continue;
            double lo = static_cast<double>(k - 1) / samples;
            for (int i = 0; i < 50; ++i) (distance(at((lo + hi) / 2)) > ball ? lo : hi) = (lo + hi) / 2;
            return at(lo);
        }
        return std::nullopt;
    }
};

Part partOf(const WorkSetup& s, double stockHeight)
{
    return {s.round, s.inside, s.sizeX / 2, (s.round ? s.sizeX : s.sizeY) / 2, s.ballRadius, -stockHeight};
}

bool near(const Point3& a, const Point3& b)
{
    const auto same = [](double p, double q) { return (std::isnan(p) && std::isnan(q)) || std::abs(p - q) <= kTolerance; };
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

// What the cycle is meant to do, in the part's frame: where it starts, the
// places its rapids go to (across and in height), and each touch's target
// and point of touch, in the program's order (the top face, -X, +X, -Y, +Y).
struct Cycle {
    Point3 start;
    std::vector<Point3> across;  // X Y (z unused)
    std::vector<double> heights;
    std::vector<Point3> targets, touches;
};

Cycle cycleOf(const WorkSetup& s, const Part& p)
{
    Cycle c;
    const double r = s.ballRadius, out = s.inside ? -1.0 : 1.0;
    c.start = {0.0, 0.0, s.clearance};
    const double topAt = s.inside ? -(p.hx + s.clearance) : 0.0;
    c.across = {{0, 0, 0}, {topAt, 0, 0}};
    c.heights = {c.start.z, s.clearance, -s.touchDepth};
    c.targets.push_back({topAt, 0.0, c.start.z - (s.search + s.clearance)});
    c.touches.push_back({topAt, 0.0, 0.0});
    for (int k = 0; k < 4; ++k) {
        const double sign = k % 2 == 0 ? -1.0 : 1.0, h = k < 2 ? p.hx : p.hy;
        const auto along = [&](double v) { return k < 2 ? Point3{v, 0.0, -s.touchDepth} : Point3{0.0, v, -s.touchDepth}; };
        if (!s.inside) c.across.push_back(along(sign * (h + s.clearance)));
        c.targets.push_back(along(sign * (h - out * s.search)));
        c.touches.push_back(along(sign * (h + out * r)));
    }
    return c;
}

Finding moveFinding(const TapeMotion& m, const std::string& part, double depth, const std::string& program)
{
    Finding f;
    f.kind = FindingKind::UnplannedMove;
    f.line = m.line;
    f.position = m.end;
    f.size = depth > kTouch ? depth : 0.0;
    f.part = part;
    f.program = program;
    return f;
}

// The reading's end: where it stopped unread, or at an abort or alarm.
void readingEnd(std::vector<Finding>& out, const ProbeReading& r, const std::string& program)
{
    Report report;
    addUnreadTape(report, r.tape);
    if (!r.stop.empty()) {
        TapeReading stopped;
        stopped.error = "line " + std::to_string(r.stopLine) + ": the program stops [" + r.stop + "]";
        stopped.errorLine = r.stopLine;
        addUnreadTape(report, stopped);
    }
    for (Finding& f : report.findings) out.push_back((f.program = program, f));
}

// The cycle again from a start off the centre (half the distance it may
// be off, in X and Y) with the part away from the active work offset's
// origin (every offset at Y12.25 Z-100): each touch made, nothing
// into the part, and the program's last motion over the true centre,
// which only its arithmetic finds from there.
void offCentre(std::vector<Finding>& out, const WorkSetup& s, const Part& part, const std::string& text, const post::Dialect& dialect,
               const std::string& program)
{
    const Point3 start{0.5 * s.maxOffCentre, -0.5 * s.maxOffCentre, s.clearance};
    const ProbeReading r = readProbingProgram(
        text, dialect, start, [&](const Point3& a, const Point3& b) { return part.touch(a, b); }, {-37.5, 12.25, -100.0});
    const double k = r.tape.inches ? 25.4 : 1.0;
    for (std::size_t i = 0; i < r.tape.motions.size(); ++i) {
        TapeMotion m = r.tape.motions[i];
        m.start = {m.start.x * k, m.start.y * k, m.start.z * k}, m.end = {m.end.x * k, m.end.y * k, m.end.z * k};
        const double depth = part.depth(m.start, m.end);
        const auto probe = std::find(r.probes.begin(), r.probes.end(), static_cast<int>(i));
        const Point3 sent = probe == r.probes.end() ? Point3{} : r.targets[static_cast<std::size_t>(probe - r.probes.begin())];
        const bool last = i + 1 == r.tape.motions.size() && r.stop.empty() && r.tape.error.empty();
        const bool centred = std::abs(m.end.x) <= kTolerance && std::abs(m.end.y) <= kTolerance;
        if (probe != r.probes.end() && near(m.end, {sent.x * k, sent.y * k, sent.z * k}) && !part.touch(m.start, m.end))
            out.push_back(moveFinding(m, "probing move that touches nothing", depth, program));
        else if (depth > kTouch || (last && !centred))
            out.push_back(moveFinding(m, m.kind == TapeMotion::Traverse ? "rapid" : "feed", depth, program));
    }
    readingEnd(out, r, program);
}

}  // namespace

std::vector<Finding> probingFindings(const WorkSetup& s, double stockHeight, const std::string& text, const post::Dialect& dialect,
                                     const std::string& program)
{
    const Part part = partOf(s, stockHeight);
    const Cycle cycle = cycleOf(s, part);
    const ProbeReading r = readProbingProgram(text, dialect, cycle.start,
                                              [&](const Point3& a, const Point3& b) { return part.touch(a, b); });
    const double k = r.tape.inches ? 25.4 : 1.0;
    const auto mm = [k](const Point3& p) { return Point3{p.x * k, p.y * k, p.z * k}; };
    std::vector<Finding> out;
    for (std::size_t i = 0; i < r.tape.motions.size() && out.size() < static_cast<std::size_t>(kMaxTapeFindings); ++i) {
        TapeMotion m = r.tape.motions[i];
        m.start = mm(m.start), m.end = mm(m.end);
        const double depth = part.depth(m.start, m.end);
        const auto probe = std::find(r.probes.begin(), r.probes.end(), static_cast<int>(i));
        if (probe != r.probes.end()) {
            const std::size_t n = static_cast<std::size_t>(probe - r.probes.begin());
            const Point3 target = mm(r.targets[n]);
            if (near(m.end, target) && !part.touch(m.start, m.end)) out.push_back(moveFinding(m, "probing move that touches nothing", depth, program));
            else if (n >= cycle.targets.size() || !near(target, cycle.targets[n]) || !near(m.end, cycle.touches[n]))
                out.push_back(moveFinding(m, "probing move", depth, program));
            continue;
        }
        const bool across = std::any_of(cycle.across.begin(), cycle.across.end(), [&](const Point3& p) {
            return std::abs(m.end.x - p.x) <= kTolerance && std::abs(m.end.y - p.y) <= kTolerance;
        });
        const bool height = std::abs(m.end.z - m.start.z) <= kTolerance ||
                            std::any_of(cycle.heights.begin(), cycle.heights.end(), [&](double z) { return std::abs(m.end.z - z) <= kTolerance; });
        if (!across || !height || depth > kTouch)
            out.push_back(moveFinding(m, m.kind == TapeMotion::Traverse ? "rapid" : "feed", depth, program));
    }
    readingEnd(out, r, program);
    if (out.empty()) offCentre(out, s, part, text, dialect, program);
    return out;
}

std::vector<Finding> settingFindings(const WorkSetup& s, double stockHeight, const std::string& text, const post::Dialect& dialect,
                                     const std::string& program)
{
    const Point3 nan{std::nan(""), std::nan(""), std::nan("")};
    const ProbeReading r = readProbingProgram(text, dialect, nan, [](const Point3&, const Point3&) { return std::nullopt; });
    const double k = r.tape.inches ? 25.4 : 1.0;
    const Point3 centre = s.measured ? Point3{s.measured->centre.x, s.measured->centre.y, s.measured->top.value_or(0.0)} : Point3{};
    // In the part's frame: the measured centre X0 Y0, its top face Z0.
    const auto frame = [&](const Point3& p) { return Point3{p.x * k - centre.x, p.y * k - centre.y, p.z * k - centre.z}; };
    const Part part = partOf(s, stockHeight);
    std::vector<Finding> out;
    for (std::size_t i = 0; i < r.tape.motions.size() && out.size() < static_cast<std::size_t>(kMaxTapeFindings); ++i) {
        TapeMotion m = r.tape.motions[i];
        m.start = frame(m.start), m.end = frame(m.end);
        // Every motion at the machine's top; the last to the centre.
        const bool last = i + 1 == r.tape.motions.size();
        const bool planned = std::isnan(m.end.z) && (!last || (std::abs(m.end.x) <= kTolerance && std::abs(m.end.y) <= kTolerance));
        if (planned || std::find(r.probes.begin(), r.probes.end(), static_cast<int>(i)) != r.probes.end()) continue;
        const bool anywhere = std::isnan(m.end.x) || std::isnan(m.end.y);
        const double depth = anywhere ? (m.end.z < 0.0 ? -m.end.z : 0.0) : part.depth(m.start, m.end);
        m.end = {m.end.x + centre.x, m.end.y + centre.y, m.end.z + centre.z};
        out.push_back(moveFinding(m, m.kind == TapeMotion::Traverse ? "rapid" : "feed", depth, program));
    }
    for (const int p : r.probes) out.push_back(moveFinding(r.tape.motions[static_cast<std::size_t>(p)], "probing move", 0.0, program));
    readingEnd(out, r, program);
    return out;
}

void readBackProbing(Report& report, const Plan& plan, const std::vector<PostedProbing>& programs, const post::Dialect& dialect,
                     const PostOptions& post)
{
    const double height = plan.mmJob.stock.height;
    for (const PostedProbing& p : programs) {
        const auto w = std::find_if(plan.setups.begin(), plan.setups.end(), [&](const WorkSetup& s) { return s.unit == p.unit; });
        if (w == plan.setups.end()) continue;
        const std::string unit = ".u" + std::to_string(p.unit + 1);
        std::vector<Finding> found;
        if (!p.setting.empty()) found = settingFindings(*w, height, p.setting, dialect, programFile(post, unit + ".setting.nc"));
        const auto cycle = probingFindings(*w, height, p.probe, dialect, programFile(post, unit + ".probe.nc"));
        found.insert(found.end(), cycle.begin(), cycle.end());
        report.findings.insert(report.findings.end(), found.begin(), found.end());
    }
}

}  // namespace taiwa::verify
