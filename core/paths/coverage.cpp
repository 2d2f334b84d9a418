// Coverage of a pocket layer with Clipper: swept area of the tool along its
// centre path versus the region to clear.
#include "paths/coverage.h"

#include "model/clipper_scale.h"
#include "paths/contour.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::paths {

namespace {

// XY polyline of the path's cutting moves, arcs flattened.
std::vector<std::vector<Point2>> feedPolylines(const ToolPath& path)
{
    std::vector<std::vector<Point2>> lines;
    std::vector<Point2> current;
    Point3 at = path.start;
    for (const auto& m : path.moves) {
        const bool cuts = m.kind == MoveKind::Feed || m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW;
        if (!cuts) {
            if (current.size() > 1) lines.push_back(current);
            current.clear();
            if (m.kind != MoveKind::DrillCycle) at = m.end;
            continue;
        }
        if (current.empty()) current.push_back({at.x, at.y});
        if (m.kind == MoveKind::Feed) {
            current.push_back({m.end.x, m.end.y});
        } else {
            const double sweep = arcSweep(at, m);
            const double r = std::hypot(at.x - m.centre.x, at.y - m.centre.y);
            // Chords within 1 µm of the arc.
            const double stepAngle = 2 * std::acos(std::max(0.0, 1 - 0.001 / std::max(r, 0.001)));
            const int n = std::max(2, static_cast<int>(std::ceil(std::abs(sweep) / std::max(stepAngle, 1e-3))));
            const double a0 = std::atan2(at.y - m.centre.y, at.x - m.centre.x);
            for (int i = 1; i <= n; ++i) {
                const double ang = a0 + sweep * i / n;
                current.push_back({m.centre.x + r * std::cos(ang), m.centre.y + r * std::sin(ang)});
            }
        }
        at = m.end;
    }
    if (current.size() > 1) lines.push_back(current);
    return lines;
}

// What the tool leaves inside the region, the region shrunk by `band` first
// (so that reaching the outline within `band` counts as reaching it) and
// arcs approximated within half of it.
ClipperLib::Paths leftover(const Quad& region, const ToolPath& path, double radius, double band)
{
    // The swept area piece by piece (a short run of the path each): offsetting
    // one long self-overlapping path makes Clipper resolve every overlap at
    // once; the difference below unites the pieces anyway (non-zero fill).
    ClipperLib::Paths swept;
    constexpr std::size_t kPiece = 16;
    for (const auto& line : feedPolylines(path)) {
        for (std::size_t from = 0; from + 1 < line.size(); from += kPiece) {
            const std::size_t to = std::min(line.size(), from + kPiece + 1);
            ClipperLib::ClipperOffset sweep(2.0, 0.5 * band * kClipperScale);
            sweep.AddPath(toClipper({line.begin() + static_cast<std::ptrdiff_t>(from), line.begin() + static_cast<std::ptrdiff_t>(to)}),
                          ClipperLib::jtRound, ClipperLib::etOpenRound);
            ClipperLib::Paths piece;
            sweep.Execute(piece, radius * kClipperScale);
            swept.insert(swept.end(), piece.begin(), piece.end());
        }
    }
    ClipperLib::Clipper c;
    c.AddPath(toClipper(flatten(offsetInward(region, band), 0.5 * band)), ClipperLib::ptSubject, true);
    c.AddPaths(swept, ClipperLib::ptClip, true);
    ClipperLib::Paths left;
    c.Execute(ClipperLib::ctDifference, left, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return left;
}

// The point of a convex rounded quad nearest to p (p itself when inside).
Point2 clampInto(const Quad& q, Point2 p)
{
    const auto poly = flatten(q, 0.001);
    bool inside = true;
    for (std::size_t i = 0; i < poly.size(); ++i)
        if (cross(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]) < 0) inside = false;
    if (inside) return p;
    Point2 best = poly[0];
    double bestD = distance(p, best);
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Point2 a = poly[i], ab = poly[(i + 1) % poly.size()] - a;
        const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
        const Point2 c = a + t * ab;
        if (distance(p, c) < bestD) best = c, bestD = distance(p, c);
    }
    // Step a hair inside so that rounding never puts the centre outside.
    const Point2 towards = centroid({poly[0], poly[poly.size() / 4], poly[poly.size() / 2], poly[3 * poly.size() / 4]}) - best;
    return best + (1e-4 / std::max(length(towards), 1e-9)) * towards;
}

}  // namespace

double uncutArea(const Quad& region, const ToolPath& path, double radius, double band)
{
    double a = 0;
    for (const auto& p : leftover(region, path, radius, band)) a += clipperAreaMm2(p);
    return a;
}

// Why the rule of ringsClearRectangle holds. K_d is the outline offset inward
// by d, ring d its boundary. (1) The outline's corners are rounded to at
// least R, so the outline is K_R grown by R: every point within R of the
// outline's edge is within R of ring R. (2) Between neighbour rings d < d',
// gap g = d' - d: a point p of K_d at depth s in it is s from ring d. K_d is
// a rectangle C grown by a radius rho (rho may be 0), and K_d' is C grown by
// rho - g, or C shrunk by g - rho: either way p is at most sqrt 2 (g - s)
// from K_d' (C shrunk by t lies within sqrt 2 t of every point of C, the
// corner's diagonal), so from ring d'. min(s, sqrt 2 (g - s)) <= R for every
// s when g <= (1 + 1/sqrt 2) R, the worst p being on a corner's bisector.
// (3) Inside the last ring, which is within 1e-4 of collapsing, every point
// is within 1e-4 of it.
bool ringsClearRectangle(const Quad& outline, double radius, const std::vector<double>& offsets)
{
    std::vector<double> d = offsets;
    std::sort(d.begin(), d.end());
    if (d.empty() || outline.cornerRadius < radius || std::abs(d.front() - radius) > 1e-12) return false;
    const auto& c = outline.corners;
    for (std::size_t i = 0; i < 4; ++i) {
        const Point2 a = c[(i + 1) % 4] - c[i], b = c[(i + 2) % 4] - c[(i + 1) % 4];
        if (std::abs(dot(a, b)) > 1e-12 * dot(a, a) + 1e-12 * dot(b, b)) return false;  // not a right angle
    }
    if (maxOffset(outline) - d.back() > 1e-4 + 1e-9) return false;
    const double widest = (1 + std::numbers::sqrt2 / 2) * radius * (1 - 1e-9);
    for (std::size_t k = 0; k + 1 < d.size(); ++k)
        if (!(d[k + 1] - d[k] <= widest)) return false;
    return true;
}

std::vector<Point2> cleanupPoints(const Quad& region, const Quad& allowedCentres, const ToolPath& path, double radius,
                                  double tolerance)
{
    std::vector<Point2> points;
    for (const auto& piece : leftover(region, path, radius, 0.005)) {
        if (clipperAreaMm2(piece) < tolerance) continue;
        // Visit the piece's centre of area, kept where the tool may go.
        double cx = 0, cy = 0, a = 0;
        for (std::size_t i = 0; i < piece.size(); ++i) {
            const Point2 p = fromClipper(piece[i]), q = fromClipper(piece[(i + 1) % piece.size()]);
            const double w = cross(p, q);
            a += w;
            cx += (p.x + q.x) * w;
            cy += (p.y + q.y) * w;
        }
        const Point2 c = std::abs(a) > 1e-12 ? Point2{cx / (3 * a), cy / (3 * a)} : fromClipper(piece[0]);
        points.push_back(clampInto(allowedCentres, c));
    }
    return points;
}

}  // namespace taiwa::paths
