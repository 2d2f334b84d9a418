// Helpers shared by the tool-path tests: hand-made tools and steps, the
// points a path feeds through (arcs sampled), how far it strays outside a
// region, and on which side of the tool the wall lies.
#pragma once

#include "modules/registry.h"
#include "support/pocket_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace taiwa::test {

inline Tool makeTool(ToolType type, double d)
{
    Tool t;
    t.id = 1;
    t.type = type;
    t.diameter = d;
    t.fluteLength = 3 * d;
    return t;
}

inline Step makePocketStep(StepKind kind, Quad outline, double start, double cut)
{
    Step s;
    s.module = "M4";  // its door makes the path
    s.kind = kind;
    editMilling(s).outline = outline;
    editMilling(s).startDepth = start;
    editMilling(s).cutDepth = cut;
    editMilling(s).position = centroid(outline.corners);
    return s;
}

inline Quad rectangle(double w, double h, double r) { return {{{{0, 0}, {w, 0}, {w, h}, {0, h}}}, r}; }

inline bool isCut(const Move& m) { return m.kind == MoveKind::Feed || m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW; }

// A cutting move with where it starts.
struct Piece {
    Point3 from;
    Move move;
};
inline std::vector<Piece> cuttingPieces(const ToolPath& p)
{
    std::vector<Piece> out;
    Point3 at = p.start;
    for (const auto& m : p.moves) {
        if (isCut(m)) out.push_back({at, m});
        if (m.kind != MoveKind::DrillCycle) at = m.end;
    }
    return out;
}

// Points along a cutting move: lines every 0.5 mm, arcs every 2 degrees.
inline std::vector<Point3> samples(const Piece& q)
{
    std::vector<Point3> pts;
    const Move& m = q.move;
    if (m.kind == MoveKind::Feed) {
        const double len = std::hypot(m.end.x - q.from.x, m.end.y - q.from.y);
        const int n = std::max(1, static_cast<int>(std::ceil(len / 0.5)));
        for (int i = 0; i <= n; ++i) {
            const double t = static_cast<double>(i) / n;
            pts.push_back({q.from.x + t * (m.end.x - q.from.x), q.from.y + t * (m.end.y - q.from.y), q.from.z + t * (m.end.z - q.from.z)});
        }
        return pts;
    }
    const double sweep = arcSweep(q.from, m), r = std::hypot(q.from.x - m.centre.x, q.from.y - m.centre.y);
    const double a0 = std::atan2(q.from.y - m.centre.y, q.from.x - m.centre.x);
    const int n = std::max(4, static_cast<int>(std::ceil(std::abs(sweep) / (2 * std::numbers::pi / 180))));
    for (int i = 0; i <= n; ++i) {
        const double a = a0 + sweep * i / n;
        pts.push_back({m.centre.x + r * std::cos(a), m.centre.y + r * std::sin(a), q.from.z + (m.end.z - q.from.z) * i / n});
    }
    return pts;
}

inline std::vector<Point3> feedPoints(const ToolPath& p)
{
    std::vector<Point3> pts;
    for (const auto& q : cuttingPieces(p))
        for (const auto& s : samples(q)) pts.push_back(s);
    return pts;
}

// Largest distance (mm) by which the tool centre leaves the outline shrunk
// by `radius`; <= 0 when it stays inside.
inline double worstOutside(const Quad& outline, double radius, const ToolPath& p)
{
    double worst = -1e9;
    for (const auto& q : feedPoints(p)) worst = std::max(worst, signedDistance(outline, {q.x, q.y}) + radius);
    return worst;
}

// Where the path ends: a drilling cycle returns to the level it came from.
inline Point3 endOf(const ToolPath& p)
{
    Point3 at = p.start;
    for (const auto& m : p.moves)
        if (m.kind != MoveKind::DrillCycle) at = m.end;
    return at;
}

// Of the cutting moves that run along the wall (tool edge on the outline
// within 1 µm at both ends and the middle), how many have the wall on the
// tool's right (climb with an M3 spindle) and how many on its left.
struct WallSides {
    int right = 0;
    int left = 0;
};
inline WallSides wallSides(const ToolPath& p, const Quad& outline, double radius)
{
    WallSides w;
    for (const auto& q : cuttingPieces(p)) {
        const auto pts = samples(q);
        const Point3 a = pts[pts.size() / 2 - 1], b = pts[pts.size() / 2];
        const auto onWall = [&](Point3 c) { return std::abs(signedDistance(outline, {c.x, c.y}) + radius) < 1e-3; };
        if (!onWall(pts.front()) || !onWall(pts.back()) || !onWall(a) || !onWall(b)) continue;
        const Point2 d{b.x - a.x, b.y - a.y};
        if (length(d) < 1e-9) continue;
        const Point2 mid{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}, right = (0.01 / length(d)) * Point2{d.y, -d.x};
        (signedDistance(outline, mid + right) > signedDistance(outline, mid - right) ? w.right : w.left)++;
    }
    return w;
}

}  // namespace taiwa::test
