// Side milling's geometry oracle: nearest points on exact lines and arcs,
// the side from the local direction (or the turn at a corner).
#include "support/side_oracle.h"

#include "modules/side/side.h"
#include "support/pocket_geometry.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace taiwa::test {

namespace {

struct Piece {
    bool arc = false;
    bool ccw = true;
    Point2 a{}, b{}, centre{};  // a line from a to b (b unused for a ray), an arc from a to b
    bool ray = false;           // a ray from a along `dir`
    bool rayBack = false;       // a ray that ends at a, coming from infinity along `dir`
    Point2 dir{};
};

Point2 unit(Point2 v) { return (1.0 / std::hypot(v.x, v.y)) * v; }

// The nearest point of a piece to p, whether it lies at the piece's start
// (-1), inside (0) or at its end (+1), and the direction of travel there.
struct Near {
    Point2 q{};
    int at = 0;
    Point2 tangent{};
};

Near nearestOn(const Piece& s, Point2 p)
{
    if (s.ray || s.rayBack) {
        const double t = dot(p - s.a, s.dir);
        if (s.ray) return t <= 0 ? Near{s.a, -1, s.dir} : Near{s.a + t * s.dir, 0, s.dir};
        return t >= 0 ? Near{s.a, 1, s.dir} : Near{s.a + t * s.dir, 0, s.dir};
    }
    if (!s.arc) {
        const Point2 d = s.b - s.a;
        const double t = dot(p - s.a, d) / dot(d, d);
        const Point2 dir = unit(d);
        if (t <= 0) return {s.a, -1, dir};
        if (t >= 1) return {s.b, 1, dir};
        return {s.a + t * d, 0, dir};
    }
    const double r = std::hypot(s.a.x - s.centre.x, s.a.y - s.centre.y);
    const double sign = s.ccw ? 1.0 : -1.0;
    const auto angleFromStart = [&](Point2 v) {
        const Point2 u = s.a - s.centre;
        double ang = sign * std::atan2(cross(u, v), dot(u, v));
        if (ang < 0) ang += 2 * std::numbers::pi;
        return ang;
    };
    double sweep = angleFromStart(s.b - s.centre);
    if (sweep < 1e-12) sweep = 2 * std::numbers::pi;
    const auto tangentAt = [&](Point2 q) {
        const Point2 u = unit(q - s.centre);
        return s.ccw ? Point2{-u.y, u.x} : Point2{u.y, -u.x};
    };
    const Point2 v = p - s.centre;
    if (std::hypot(v.x, v.y) > 1e-12) {
        const double ang = angleFromStart(v);
        if (ang <= sweep) {
            const Point2 q = s.centre + r * unit(v);
            return {q, 0, tangentAt(q)};
        }
    }
    return distance(p, s.a) <= distance(p, s.b) ? Near{s.a, -1, tangentAt(s.a)} : Near{s.b, 1, tangentAt(s.b)};
}

}  // namespace

double leftSignedDistance(const Contour& c, Point2 p)
{
    std::vector<Piece> pieces;
    const auto& segs = c.segments;
    if (!c.closed) {
        Piece r;
        r.rayBack = true;
        r.a = segs.front().start;
        r.dir = segs.front().startDirection();
        pieces.push_back(r);
    }
    for (const auto& s : segs) {
        Piece k;
        k.arc = s.isArc();
        k.ccw = s.kind == ContourSegment::Kind::ArcCCW;
        k.a = s.start;
        k.b = s.end;
        k.centre = s.centre;
        pieces.push_back(k);
    }
    if (!c.closed) {
        Piece r;
        r.ray = true;
        r.a = segs.back().end;
        r.dir = segs.back().endDirection();
        pieces.push_back(r);
    }
    double best = std::numeric_limits<double>::infinity();
    double sign = 1.0;
    const std::size_t n = pieces.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Near near = nearestOn(pieces[i], p);
        const double d = distance(p, near.q);
        if (d >= best) continue;
        best = d;
        if (near.at == 0) {
            sign = cross(near.tangent, p - near.q) >= 0 ? 1.0 : -1.0;
            continue;
        }
        // A corner: the point lies outside the turn (left of a right turn).
        const std::size_t j = near.at < 0 ? (i + n - 1) % n : (i + 1) % n;
        const Near other = nearestOn(pieces[j], near.q);
        const Point2 in = near.at < 0 ? other.tangent : near.tangent, out = near.at < 0 ? near.tangent : other.tangent;
        const double turn = cross(in, out);
        sign = std::abs(turn) < 1e-12 ? (cross(in, p - near.q) >= 0 ? 1.0 : -1.0) : (turn > 0 ? -1.0 : 1.0);
    }
    return sign * best;
}

std::optional<double> sideWallDistance(const ModuleInput& m, Point3 tip)
{
    const auto* s = m.getIf<SideMill>();
    if (!s) return std::nullopt;
    const double left = leftSignedDistance(s->path.value(), {tip.x, tip.y});
    return s->side == 1 ? -left : left;  // negative on the tool's side
}

std::optional<double> sideDepth(const ModuleInput& m)
{
    if (const auto* s = m.getIf<SideMill>()) return s->depth;
    return std::nullopt;
}

std::optional<double> sideGouge(const ModuleInput& m, const Tool& tool, Point3 tip)
{
    const auto* s = m.getIf<SideMill>();
    if (!s) return std::nullopt;
    if (tip.z >= 0.0) return -std::numeric_limits<double>::infinity();
    const double depth = -tip.z;
    return std::max(depth - s->depth, *sideWallDistance(m, tip) + toolRadiusAt(tool, depth));
}

}  // namespace taiwa::test
