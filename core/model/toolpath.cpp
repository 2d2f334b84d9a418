// Length of a tool path, cutting and rapid travel apart, and the sweep of an arc move.
#include "model/toolpath.h"

#include <cmath>
#include <numbers>

namespace taiwa {

namespace {
double dist(Point3 a, Point3 b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z)); }

double arcLength(Point3 from, const Move& m)
{
    const double planar = std::abs(arcSweep(from, m)) * std::hypot(from.x - m.centre.x, from.y - m.centre.y);
    return std::hypot(planar, m.end.z - from.z);
}
}  // namespace

double arcSweep(Point3 from, const Move& arc)
{
    const Point2 a{from.x - arc.centre.x, from.y - arc.centre.y};
    const Point2 b{arc.end.x - arc.centre.x, arc.end.y - arc.centre.y};
    double sweep = std::atan2(cross(a, b), dot(a, b));
    if (arc.kind == MoveKind::ArcCCW && sweep <= 0) sweep += 2 * std::numbers::pi;
    if (arc.kind == MoveKind::ArcCW && sweep >= 0) sweep -= 2 * std::numbers::pi;
    return sweep;
}

PathLength pathLength(const ToolPath& p)
{
    PathLength len;
    Point3 at = p.start;
    for (const auto& m : p.moves) {
        switch (m.kind) {
        case MoveKind::Rapid: len.rapid += dist(at, m.end); break;
        case MoveKind::Feed: len.feed += dist(at, m.end); break;
        case MoveKind::ArcCW:
        case MoveKind::ArcCCW: len.feed += arcLength(at, m); break;
        case MoveKind::DrillCycle: {
            const Point3 above{m.end.x, m.end.y, at.z};
            len.rapid += dist(at, above) + std::abs(at.z - m.retractZ);
            len.feed += std::abs(m.retractZ - m.end.z);
            len.rapid += std::abs(m.retractZ - m.end.z) + std::abs(at.z - m.retractZ);
            at = above;
            continue;
        }
        }
        at = m.end;
    }
    return len;
}

}  // namespace taiwa
