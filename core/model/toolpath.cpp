// Length of a tool path, cutting and rapid travel apart.
#include "model/toolpath.h"

#include <cmath>
#include <numbers>

namespace taiwa {

namespace {
double dist(Point3 a, Point3 b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z)); }

double arcLength(Point3 from, const Move& m)
{
    const Point2 a{from.x - m.centre.x, from.y - m.centre.y};
    const Point2 b{m.end.x - m.centre.x, m.end.y - m.centre.y};
    double sweep = std::atan2(cross(a, b), dot(a, b));
    if (m.kind == MoveKind::ArcCCW && sweep <= 0) sweep += 2 * std::numbers::pi;
    if (m.kind == MoveKind::ArcCW && sweep >= 0) sweep -= 2 * std::numbers::pi;
    const double planar = std::abs(sweep) * length(a);
    return std::hypot(planar, m.end.z - from.z);
}
}  // namespace

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
