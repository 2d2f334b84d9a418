// Flattening of tool paths: arcs to chords, drill cycles to straight pieces.
#include "sim/path_samples.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::sim {

namespace {

void addArc(std::vector<PathPiece>& out, Point3 from, const Move& m, int index, double tol)
{
    const double r = std::hypot(from.x - m.centre.x, from.y - m.centre.y);
    const double sweep = arcSweep(from, m);
    const double maxStep = r > tol ? 2.0 * std::acos(1.0 - tol / r) : std::numbers::pi / 2;
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / std::min(maxStep, std::numbers::pi / 8))));
    const double a0 = std::atan2(from.y - m.centre.y, from.x - m.centre.x);
    Point3 prev = from;
    for (int i = 1; i <= n; ++i) {
        const double t = static_cast<double>(i) / n;
        const Point3 p = i == n ? m.end
                                : Point3{m.centre.x + r * std::cos(a0 + t * sweep), m.centre.y + r * std::sin(a0 + t * sweep),
                                         from.z + t * (m.end.z - from.z)};
        out.push_back({prev, p, index, false});
        prev = p;
    }
}

}  // namespace

std::vector<PathPiece> flattenPath(const ToolPath& path, double chordTolerance)
{
    std::vector<PathPiece> out;
    out.reserve(path.moves.size());
    Point3 at = path.start;
    for (int i = 0; i < static_cast<int>(path.moves.size()); ++i) {
        const Move& m = path.moves[i];
        switch (m.kind) {
        case MoveKind::Rapid:
        case MoveKind::Feed: out.push_back({at, m.end, i, m.kind == MoveKind::Rapid}); break;
        case MoveKind::ArcCW:
        case MoveKind::ArcCCW: addArc(out, at, m, i, chordTolerance); break;
        case MoveKind::DrillCycle: {
            const Point3 above{m.end.x, m.end.y, at.z};
            const Point3 rPlane{m.end.x, m.end.y, m.retractZ};
            if (!(above == at)) out.push_back({at, above, i, true});
            out.push_back({above, rPlane, i, true});
            out.push_back({rPlane, m.end, i, false});
            out.push_back({m.end, above, i, true});
            at = above;
            continue;
        }
        }
        at = m.end;
    }
    return out;
}

std::vector<SweptPiece> sweptPieces(const ToolPath& path)
{
    std::vector<SweptPiece> out;
    out.reserve(path.moves.size());
    // The straight pieces as flattenPath makes them (drill cycles unrolled),
    // arcs replaced by one piece each.
    Point3 at = path.start;
    for (int i = 0; i < static_cast<int>(path.moves.size()); ++i) {
        const Move& m = path.moves[i];
        if (m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW) {
            out.push_back({at, m.end, i, false, true, m.centre, arcSweep(at, m)});
            at = m.end;
            continue;
        }
        ToolPath one{at, {m}};
        for (const PathPiece& p : flattenPath(one)) out.push_back({p.from, p.to, i, p.rapid, false, {}, 0.0});
        at = positionAfter(one, 0);
    }
    return out;
}

Point3 positionAfter(const ToolPath& path, int index)
{
    Point3 at = path.start;
    for (int i = 0; i <= index && i < static_cast<int>(path.moves.size()); ++i) {
        const Move& m = path.moves[i];
        at = m.kind == MoveKind::DrillCycle ? Point3{m.end.x, m.end.y, at.z} : m.end;
    }
    return at;
}

}  // namespace taiwa::sim
