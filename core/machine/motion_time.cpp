// The trapezoid planner of motion_time.h: the path as straight blocks and
// arcs with their top speeds and accelerations, the speed at each block end
// (a stop, or a corner's), a backward and a forward pass, then each block's
// time from its entry, top and exit speeds.
#include "machine/motion_time.h"

#include <algorithm>
#include <cmath>
#include <limits>
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
            accel_[axis(a)] = acc != m.acceleration.end() ? acc->second : 0.0;
            const auto r = m.rapid.find(a);
            rapid_[axis(a)] = (r != m.rapid.end() ? r->second : m.maxFeed) / 60.0;
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
        const double l = std::hypot(planar, dz);
        if (l <= 0.0) return;
        const double a0 = std::atan2(from.y - m.centre.y, from.x - m.centre.x), a1 = a0 + sweep;
        const double s = sweep > 0 ? 1.0 : -1.0;
        const Point3 in = unit({-std::sin(a0) * s * planar, std::cos(a0) * s * planar, dz});
        const Point3 out = unit({-std::sin(a1) * s * planar, std::cos(a1) * s * planar, dz});
        const double a = std::min(accel_[0], accel_[1]);
        // Around the arc the tool accelerates towards its centre by v² / r.
        const double centripetal = r > 0 ? std::sqrt(0.5 * a * r) : std::numeric_limits<double>::infinity();
        // Half the acceleration goes along the arc, half towards its centre.
        blocks_.push_back({l, std::min(std::min(perMinute, m_.maxFeed) / 60.0, centripetal), 0.5 * a, in, out, false});
    }
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
    static int axis(const char* a) { return a[0] - 'x'; }
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

}  // namespace taiwa
