// The trapezoid planner of motion_time.h: the path as straight blocks and
// arcs with their top speeds and accelerations, the speed at each block end
// (a stop, or a corner's), a backward and a forward pass, then each block's
// time from its entry, top and exit speeds.
#include "machine/motion_time.h"

#include "model/turn_path.h"
#include "model/turned_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace taiwa {

namespace {

struct Block {
    double length = 0.0;   // [mm]
    double top = 0.0;      // the highest speed in it [mm/s]
    double accel = 0.0;    // [mm/s²]
    Point3 dirIn{}, dirOut{};  // unit directions at its start and end
    bool stopAfter = false;    // exact stop at its end (rapids, drill cycles, the path's end)
};

Point3 unit(Point3 v)
{
    const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return l > 0 ? Point3{v.x / l, v.y / l, v.z / l} : Point3{};
}

class Planner {
public:
    explicit Planner(const Machine& m) : m_(m)
    {
        for (const char* a : {"x", "y", "z"}) {
            const auto acc = m.acceleration.find(a);
            accel_[axis(a[0])] = acc != m.acceleration.end() ? acc->second : 0.0;
            const auto r = m.rapid.find(a);
            rapid_[axis(a[0])] = (r != m.rapid.end() ? r->second : m.maxFeed) / 60.0;
        }
        // A lathe's X and Z are the tool path's X and Z here; its Y never moves.
    }

    // The acceleration and rapid rate in direction d: the slowest axis' share.
    double accelAlong(Point3 d) const { return along(d, accel_); }
    double rapidAlong(Point3 d) const { return along(d, rapid_); }

    void rapid(Point3 from, Point3 to)
    {
        const Point3 d{to.x - from.x, to.y - from.y, to.z - from.z};
        const Point3 u = unit(d);
        const double l = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (l <= 0.0) return;
        blocks_.push_back({l, rapidAlong(u), accelAlong(u), u, u, true});
    }
    void feed(Point3 from, Point3 to, double perMinute, bool stop = false)
    {
        const Point3 d{to.x - from.x, to.y - from.y, to.z - from.z};
        const Point3 u = unit(d);
        const double l = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (l <= 0.0) return;
        blocks_.push_back({l, std::min(perMinute, m_.maxFeed) / 60.0, accelAlong(u), u, u, stop});
    }
    void arc(Point3 from, const Move& m, double perMinute)
    {
        const double r = std::hypot(from.x - m.centre.x, from.y - m.centre.y);
        const double sweep = arcSweep(from, m);
        const double planar = std::abs(sweep) * r, dz = m.end.z - from.z;
        const double a0 = std::atan2(from.y - m.centre.y, from.x - m.centre.x), a1 = a0 + sweep;
        const double s = sweep > 0 ? 1.0 : -1.0;
        const Point3 in = unit({-std::sin(a0) * s * planar, std::cos(a0) * s * planar, dz});
        const Point3 out = unit({-std::sin(a1) * s * planar, std::cos(a1) * s * planar, dz});
        arcBlock(std::hypot(planar, dz), r, in, out, perMinute, std::min(accel_[0], accel_[1]));
    }
    // An arc of `length` and `radius` with the tangents `in` and `out`, in
    // the plane of two axes whose lower acceleration is `a`.
    void arcBlock(double length, double radius, Point3 in, Point3 out, double perMinute, double a)
    {
        if (length <= 0.0) return;
        // Around the arc the tool accelerates towards its centre by v² / r.
        const double centripetal = radius > 0 ? std::sqrt(0.5 * a * radius) : std::numeric_limits<double>::infinity();
        // Half the acceleration goes along the arc, half towards its centre.
        blocks_.push_back({length, std::min(std::min(perMinute, m_.maxFeed) / 60.0, centripetal), 0.5 * a, in, out, false});
    }
    double accel(char a) const { return accel_[axis(a)]; }
    void stop()
    {
        if (!blocks_.empty()) blocks_.back().stopAfter = true;
    }

    double seconds() const
    {
        const std::size_t n = blocks_.size();
        if (n == 0) return 0.0;
        // v[i]: the speed at the end of block i (the start of i + 1).
        std::vector<double> v(n, 0.0);
        const double deviation = m_.cornerTolerance;
        std::vector<double> ahead(n, 0.0);  // the length of the next lookAhead blocks
        const int window = std::max(1, m_.lookAhead);
        double sum = 0.0;
        for (std::size_t i = n; i-- > 0;) {
            // ahead[i] = length of blocks i+1 .. i+window
            ahead[i] = sum;
            sum += blocks_[i].length;
            if (i + static_cast<std::size_t>(window) < n) sum -= blocks_[i + static_cast<std::size_t>(window)].length;
        }
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const Block& a = blocks_[i];
            const Block& b = blocks_[i + 1];
            if (a.stopAfter || window <= 1) continue;
            const double cosTheta = -(a.dirOut.x * b.dirIn.x + a.dirOut.y * b.dirIn.y + a.dirOut.z * b.dirIn.z);
            const double sinHalf = std::sqrt(std::max(0.0, (1.0 - cosTheta) / 2.0));
            const double accel = std::min(a.accel, b.accel);
            double corner = sinHalf >= 1.0 - 1e-12 ? std::numeric_limits<double>::infinity()
                                                   : std::sqrt(accel * deviation * sinHalf / (1.0 - sinHalf));
            // It must still be able to stop within the blocks it looks ahead at.
            corner = std::min({corner, a.top, b.top, std::sqrt(2.0 * b.accel * ahead[i])});
            v[i] = corner;
        }
        // Backward: each block can slow down to its exit speed; forward: each
        // can reach its exit speed from its entry speed.
        for (std::size_t i = n - 1; i-- > 0;)
            v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2.0 * blocks_[i + 1].accel * blocks_[i + 1].length));
        double entry = 0.0, t = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const Block& b = blocks_[i];
            v[i] = std::min(v[i], std::sqrt(entry * entry + 2.0 * b.accel * b.length));
            t += blockSeconds(b, entry, v[i]);
            entry = v[i];
        }
        return t;
    }

private:
    static int axis(char a) { return a - 'x'; }
    static double along(Point3 d, const double (&limit)[3])
    {
        double best = std::numeric_limits<double>::infinity();
        const double c[3] = {std::abs(d.x), std::abs(d.y), std::abs(d.z)};
        for (int k = 0; k < 3; ++k)
            if (c[k] > 1e-12 && limit[k] > 0) best = std::min(best, limit[k] / c[k]);
        return std::isfinite(best) ? best : 0.0;
    }

    // Accelerate from u to at most the top speed, cruise, decelerate to w.
    static double blockSeconds(const Block& b, double u, double w)
    {
        const double a = b.accel, V = b.top, L = b.length;
        if (!(a > 0.0) || !(V > 0.0)) return V > 0 ? L / V : 0.0;
        const double up = (V * V - u * u) / (2 * a), down = (V * V - w * w) / (2 * a);
        if (up + down <= L) return (V - u) / a + (V - w) / a + (L - up - down) / V;
        const double peak = std::sqrt((2 * a * L + u * u + w * w) / 2);
        return (peak - u) / a + (peak - w) / a;
    }

    const Machine& m_;
    double accel_[3] = {0, 0, 0};
    double rapid_[3] = {0, 0, 0};
    std::vector<Block> blocks_;
};

}  // namespace

bool hasMotionModel(const Machine& m)
{
    return !m.acceleration.empty() && std::all_of(m.acceleration.begin(), m.acceleration.end(),
                                                  [](const auto& a) { return a.second > 0.0; });
}

double machineMinutes(const ToolPath& path, const MotionFeeds& feeds, const Machine& machine)
{
    Planner p(machine);
    Point3 at = path.start;
    for (const Move& m : path.moves) {
        const double f = m.feed == FeedKind::Cut ? feeds.feed : feeds.plungeFeed;
        switch (m.kind) {
        case MoveKind::Rapid: p.rapid(at, m.end); break;
        case MoveKind::Feed: p.feed(at, m.end, f); break;
        case MoveKind::ArcCW:
        case MoveKind::ArcCCW: p.arc(at, m, f); break;
        case MoveKind::DrillCycle: {
            // G98: over the hole, down to R, drill (pecking back to R and
            // down again), out to the level it started at; stops between.
            const Point3 above{m.end.x, m.end.y, at.z}, r{m.end.x, m.end.y, m.retractZ};
            p.rapid(at, above);
            p.rapid(above, r);
            const double depth = m.retractZ - m.end.z;
            const double peck = m.peck > 0 ? m.peck : depth;
            for (double reached = 0.0; reached < depth - 1e-9;) {
                const double next = std::min(depth, reached + peck);
                if (reached > 0) p.rapid(r, {m.end.x, m.end.y, m.retractZ - reached});
                p.feed({m.end.x, m.end.y, m.retractZ - reached}, {m.end.x, m.end.y, m.retractZ - next}, feeds.feed, true);
                p.rapid({m.end.x, m.end.y, m.retractZ - next}, r);
                reached = next;
            }
            p.rapid(r, above);
            at = above;
            continue;
        }
        }
        at = m.end;
    }
    p.stop();
    return p.seconds() / 60.0;
}

namespace {

// A lathe's point (z, r) on the machine: the radius along X, z along Z.
Point3 onLathe(turning::ZR p) { return {p.r, 0.0, p.z}; }

}  // namespace

double turnMachineMinutes(const TurnStep& step, const Machine& machine)
{
    const TurnCutting& c = step.cutting;
    const double limit = c.maxRpm > 0 ? c.maxRpm : machine.maxSpindleSpeed > 0 ? machine.maxSpindleSpeed
                                                                                 : std::numeric_limits<double>::infinity();
    // Under G96 the spindle speed changes with the radius: a feed across
    // the axis is cut into pieces over which the radius changes by at most
    // 1 % (none below the radius where the spindle limit holds it), each
    // at the speed of its smaller diameter; collinear, the planner runs
    // through them.
    constexpr double kRatio = 1.01;
    const double capped = c.constantSurfaceSpeed && std::isfinite(limit) && limit > 0
                              ? 1000.0 * c.surfaceSpeed / (std::numbers::pi * 2.0 * limit)
                              : 0.0;
    Planner p(machine);
    const double planeAccel = std::min(p.accel('x'), p.accel('z'));
    turning::ZR at = step.path.start;
    for (const TurnMove& m : step.path.moves) {
        const double perRev = m.feed == FeedKind::Plunge ? c.plungeFeedPerRev : c.feedPerRev;
        switch (m.kind) {
        case TurnMove::Rapid: p.rapid(onLathe(at), onLathe(m.end)); break;
        case TurnMove::Feed: {
            const double r0 = std::abs(at.r), r1 = std::abs(m.end.r);
            const double lo = std::min(r0, r1), hi = std::max(r0, r1);
            std::vector<double> radii{hi};  // the piece ends, from the larger radius down
            if (c.constantSurfaceSpeed && hi - lo > 1e-9) {
                const double floor = std::max({lo, capped, hi * 1e-4});
                for (double r = hi / kRatio; r > floor && radii.size() < 100000; r /= kRatio) radii.push_back(r);
            }
            radii.push_back(lo);
            if (r0 < r1) std::reverse(radii.begin(), radii.end());
            // The pieces in the direction of travel, by where their radius falls.
            turning::ZR from = at;
            for (std::size_t k = 1; k < radii.size(); ++k) {
                const double t = hi - lo > 1e-9 ? (radii[k] - r0) / (r1 - r0) : 1.0;
                const turning::ZR to = k + 1 == radii.size() ? m.end
                                                             : turning::ZR{at.z + t * (m.end.z - at.z), at.r + t * (m.end.r - at.r)};
                p.feed(onLathe(from), onLathe(to), perRev * c.rpmAt(2.0 * std::min(radii[k - 1], radii[k]), limit));
                from = to;
            }
            break;
        }
        case TurnMove::ArcCW:
        case TurnMove::ArcCCW: {
            const turning::Segment s = turning::arcSegment(at, m.end, m.centre, m.kind == TurnMove::ArcCCW);
            const double sweep = turning::sweep(s), sense = s.ccw ? 1.0 : -1.0;
            // Angles in the profile view (Z right, X up); the tangent of
            // a counter-clockwise arc at angle φ is (-sin φ, cos φ) in (z, r).
            const double a0 = std::atan2(at.r - m.centre.r, at.z - m.centre.z), a1 = a0 + sense * sweep;
            const auto tangent = [&](double a) { return onLathe({-std::sin(a) * sense, std::cos(a) * sense}); };
            // Its smallest radius: an end's, or its lowest point if it passes it.
            double lowest = std::min(std::abs(at.r), std::abs(m.end.r));
            const double toBottom = std::remainder(sense * (-std::numbers::pi / 2 - a0), 2 * std::numbers::pi);
            if ((toBottom < 0 ? toBottom + 2 * std::numbers::pi : toBottom) <= sweep)
                lowest = std::min(lowest, std::abs(m.centre.r - s.radius));
            p.arcBlock(turning::length(s), s.radius, tangent(a0), tangent(a1), perRev * c.rpmAt(2.0 * lowest, limit), planeAccel);
            break;
        }
        }
        at = m.end;
    }
    p.stop();
    return p.seconds() / 60.0;
}

}  // namespace taiwa
