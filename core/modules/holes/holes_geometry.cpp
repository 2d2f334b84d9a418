// The geometry of a HOLES unit: the thread table, the hole centres of each
// pattern in machining order, the depths each tool reaches, and the figure
// at the top surface for the interference check.
#include "modules/holes/holes.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::holes {

const std::vector<Thread>& threadTable()
{
    static const std::vector<Thread> table{
        {"M3", 3, 0.5, 2.5},     {"M4", 4, 0.7, 3.3},   {"M5", 5, 0.8, 4.2},   {"M6", 6, 1.0, 5.0},
        {"M8", 8, 1.25, 6.8},    {"M10", 10, 1.5, 8.5}, {"M12", 12, 1.75, 10.2}, {"M14", 14, 2.0, 12.0},
        {"M16", 16, 2.0, 14.0},  {"M18", 18, 2.5, 15.5}, {"M20", 20, 2.5, 17.5},
    };
    return table;
}

const Thread* findThread(const std::string& name)
{
    for (const Thread& t : threadTable())
        if (name == t.name) return &t;
    return nullptr;
}

Depths depths(const HolePattern& h)
{
    Depths d;
    if (h.hole == "tapped") {
        const Thread* t = findThread(h.thread);
        if (!t) return d;
        d.finishDiameter = t->size;
        d.drillDiameter = t->tapDrill;
        d.finish = h.depth + 2 * t->pitch;
        d.drillFull = h.depth + 3 * t->pitch;
    } else if (h.hole == "reamed") {
        d.finishDiameter = h.diameter;
        d.finish = h.depth + kReamLead;
        d.drillFull = h.depth + kPreDrillBelow;
    } else if (h.hole == "bored") {
        d.finishDiameter = h.diameter;
        d.finish = h.depth;
        d.drillFull = h.depth + kPreDrillBelow;
    } else {
        d.finishDiameter = d.drillDiameter = h.diameter;
        d.drillFull = h.depth;
    }
    return d;
}

double pointLength(double drillDiameter, double pointAngle)
{
    if (!(pointAngle > 0.0) || pointAngle >= 180.0) return drillDiameter / 2.0;
    return drillDiameter / 2.0 / std::tan(pointAngle / 2.0 * std::numbers::pi / 180.0);
}

double lowestPoint(const HolePattern& h)
{
    const Depths d = depths(h);
    const double drill = d.drillDiameter > 0.0 ? d.drillDiameter : d.finishDiameter;
    return std::max(d.finish, d.drillFull + pointLength(drill, 0.0));
}

namespace {

Point2 polar(Point2 centre, double radius, double degrees)
{
    const double a = degrees * std::numbers::pi / 180.0;
    return {centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
}

Point2 direction(double degrees) { return polar({0.0, 0.0}, 1.0, degrees); }

// Points of a circle's arc from a0 to a1 [deg] at `radius`, the polygon's
// vertices `out` of the circle by a factor (1 / cos of half a step) so that
// the chords stay outside the circle (inside when `outward` is false).
void arcPoints(std::vector<Point2>& out, Point2 c, double radius, double a0, double a1, bool outward)
{
    constexpr int kPerTurn = 96;
    const int n = std::max(2, static_cast<int>(std::ceil(std::abs(a1 - a0) / 360.0 * kPerTurn)));
    const double half = std::abs(a1 - a0) / n / 2.0 * std::numbers::pi / 180.0;
    const double r = outward ? radius / std::cos(half) : radius;
    for (int i = 0; i <= n; ++i) out.push_back(polar(c, r, a0 + (a1 - a0) * i / n));
}

}  // namespace

std::vector<Point2> positions(const HolePattern& h)
{
    std::vector<Point2> out;
    const Point2 origin{h.x, h.y};
    if (h.pattern == "single") {
        out.push_back(origin);
    } else if (h.pattern == "line") {
        const Point2 u = direction(h.angle);
        for (int i = 0; i < h.count; ++i) out.push_back(origin + (h.pitch * i) * u);
    } else if (h.pattern == "grid") {
        const Point2 u = direction(h.angle), v = direction(h.angle + 90.0);
        for (int r = 0; r < h.rows; ++r)
            for (int k = 0; k < h.count; ++k) {
                const int c = r % 2 == 0 ? k : h.count - 1 - k;
                out.push_back(origin + (h.pitch * c) * u + (h.pitchY * r) * v);
            }
    } else if (h.pattern == "bolt circle") {
        for (int i = 0; i < h.count; ++i) out.push_back(polar(origin, h.radius, h.angle + 360.0 * i / h.count));
    } else if (h.pattern == "arc") {
        for (int i = 0; i < h.count; ++i) out.push_back(polar(origin, h.radius, h.angle + h.angularPitch * i));
    }
    return out;
}

std::vector<Point2> topPolygon(const HolePattern& h)
{
    const double r = depths(h).finishDiameter / 2.0;
    const Point2 origin{h.x, h.y};
    std::vector<Point2> out;
    if (h.pattern == "single" || ((h.pattern == "line" || h.pattern == "arc") && h.count == 1) ||
        (h.pattern == "grid" && h.count == 1 && h.rows == 1)) {
        const Point2 c = positions(h).front();
        arcPoints(out, c, r, 0.0, 360.0, true);
        out.pop_back();
        return out;
    }
    if (h.pattern == "line" || h.pattern == "grid") {
        // The rectangle around the holes, along the rows.
        const Point2 u = direction(h.angle), v = direction(h.angle + 90.0);
        const double length = h.pitch * (h.count - 1), width = h.pattern == "grid" ? h.pitchY * (h.rows - 1) : 0.0;
        const Point2 a = origin - r * u - r * v;
        return {a, a + (length + 2 * r) * u, a + (length + 2 * r) * u + (width + 2 * r) * v, a + (width + 2 * r) * v};
    }
    // A ring (or a sector of it) between radius - r and radius + r: the
    // outer arc counter-clockwise, the inner one back. Its ends reach past
    // the end holes by the angle a hole takes.
    double a0 = h.angle, a1 = h.angle + 360.0;
    if (h.pattern == "arc") {
        const double first = std::min(h.angle, h.angle + h.angularPitch * (h.count - 1));
        const double last = std::max(h.angle, h.angle + h.angularPitch * (h.count - 1));
        const double margin = h.radius > r ? std::asin(r / h.radius) * 180.0 / std::numbers::pi : 90.0;
        if (last - first + 2 * margin < 360.0) a0 = first - margin, a1 = last + margin;
    }
    arcPoints(out, origin, h.radius + r, a0, a1, true);
    const double inner = h.radius - r;
    if (inner <= 0.0) {
        if (a1 - a0 >= 360.0) out.pop_back();
        else out.push_back(origin);
        return out;
    }
    if (h.pattern == "arc" && a1 - a0 < 360.0) {
        std::vector<Point2> in;
        arcPoints(in, origin, inner, a0, a1, false);
        out.insert(out.end(), in.rbegin(), in.rend());
        return out;
    }
    // The full ring: the slit at the start angle, the inner circle clockwise.
    std::vector<Point2> in;
    arcPoints(in, origin, inner, a0, a1, false);
    out.insert(out.end(), in.rbegin(), in.rend());
    return out;
}

std::vector<std::string> stepKeys(const std::string& hole)
{
    if (hole == "tapped") return {"centre-drill", "drill", "tap"};
    if (hole == "reamed") return {"centre-drill", "drill", "ream"};
    if (hole == "bored") return {"centre-drill", "drill", "bore"};
    return {"centre-drill", "drill"};
}

std::vector<std::string> allStepKeys() { return {"centre-drill", "drill", "tap", "ream", "bore"}; }

}  // namespace taiwa::holes
