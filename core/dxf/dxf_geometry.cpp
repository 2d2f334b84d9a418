// DXF entities to pieces of contour (see dxf_geometry.h): arcs from angles and
// from bulges, the object coordinate system, NURBS evaluation by de Boor's
// algorithm and the adaptive replacement of curves by lines.
#include "dxf/dxf_geometry.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::dxf::detail {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMinLength = 1e-9;          // mm: shorter segments are left out
constexpr std::size_t kMaxPerEntity = 100000;  // lines for one curve
constexpr double kFlat = 1e-6;               // drawing units: Z differences taken as flat

// The entity's plane: its object coordinate system seen from +Z.
enum class Plane { Up, Down, Tilted };

Plane planeOf(const Vec3& n)
{
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!std::isfinite(len) || len < 1e-12) return Plane::Tilted;
    if (std::abs(n[0]) > 1e-9 * len || std::abs(n[1]) > 1e-9 * len) return Plane::Tilted;
    return n[2] > 0 ? Plane::Up : Plane::Down;
}

// The arbitrary axis algorithm for a normal (0, 0, -1) gives the OCS x axis
// as world -X and y as world Y: a mirror in X, turning counter-clockwise
// arcs clockwise.
Point2 toWorld(double x, double y, Plane p, double scale) { return {scale * (p == Plane::Down ? -x : x), scale * y}; }

// cos and sin of an angle in degrees, exact at multiples of 90°.
Point2 cosSinDeg(double deg)
{
    double r = std::fmod(deg, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0.0) return {1, 0};
    if (r == 90.0) return {0, 1};
    if (r == 180.0) return {-1, 0};
    if (r == 270.0) return {0, -1};
    return {std::cos(r * kPi / 180.0), std::sin(r * kPi / 180.0)};
}

double distanceToChord(Point2 p, Point2 a, Point2 b)
{
    const Point2 ab = b - a;
    const double len2 = dot(ab, ab);
    if (len2 <= 0) return distance(p, a);
    const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
    return distance(p, a + t * ab);
}

// Replaces f on [a, b] by chords within `tol`, appending the points after
// f(a); false when more than `budget` chords would be needed.
template <class F>
bool subdivide(const F& f, double a, double b, Point2 pa, Point2 pb, double tol, int depth, std::vector<Point2>& out,
               std::size_t& budget)
{
    const double m = 0.5 * (a + b);
    const Point2 pm = f(m), q1 = f(0.5 * (a + m)), q3 = f(0.5 * (m + b));
    const bool flat = distanceToChord(pm, pa, pb) <= tol && distanceToChord(q1, pa, pb) <= tol &&
                      distanceToChord(q3, pa, pb) <= tol;
    if ((depth >= 2 && flat) || depth >= 40 || !(b - a > 0)) {
        if (budget == 0) return false;
        --budget;
        out.push_back(pb);
        return true;
    }
    return subdivide(f, a, m, pa, pm, tol, depth + 1, out, budget) &&
           subdivide(f, m, b, pm, pb, tol, depth + 1, out, budget);
}

class Builder {
public:
    Builder(double scale, double tol, std::vector<Piece>& out, Notes& notes)
        : scale_(scale), tol_(tol), out_(out), notes_(notes)
    {
    }

    void add(const RawEntity& e)
    {
        ref_ = {typeName(e.type), e.layer, e.line};
        const Plane plane = planeOf(e.extrusion);
        const bool planar = e.type == RawEntity::Type::Line || e.type == RawEntity::Type::Spline ||
                            (e.type == RawEntity::Type::Polyline && (e.flags & 8));
        if (!planar && plane == Plane::Tilted) {
            skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its plane is not the XY plane (extrusion {:.4g}, {:.4g}, {:.4g})"), e.extrusion[0],
                             e.extrusion[1], e.extrusion[2]));
            return;
        }
        switch (e.type) {
        case RawEntity::Type::Line:
            if (std::abs(e.a[2] - e.b[2]) > kFlat) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it leaves the XY plane (its ends differ in Z)"));
            return single(ContourSegment::line({scale_ * e.a[0], scale_ * e.a[1]}, {scale_ * e.b[0], scale_ * e.b[1]}));
        case RawEntity::Type::Arc:
        case RawEntity::Type::Circle: return arc(e, plane);
        case RawEntity::Type::Ellipse: return ellipse(e, plane);
        case RawEntity::Type::LwPolyline:
        case RawEntity::Type::Polyline: return polyline(e, plane);
        case RawEntity::Type::Spline: return spline(e);
        }
    }

private:
    void skip(const std::string& why) { notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} not read: {}"), ref_.text(), why)); }

    void single(const ContourSegment& s, bool closed = false)
    {
        if (!closed && distance(s.start, s.end) < kMinLength) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it has no length"));
        out_.push_back({{s}, ref_, closed});
    }

    void arc(const RawEntity& e, Plane plane)
    {
        const double r = e.radius;
        if (!(r * scale_ >= kMinLength)) return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its radius {:g} is not positive"), r));
        const bool circle = e.type == RawEntity::Type::Circle;
        double sweep = circle ? 360.0 : std::fmod(e.angle2 - e.angle1, 360.0);
        if (sweep <= 0) sweep += 360.0;  // equal angles: a full circle
        const Point2 cs = circle ? Point2{1, 0} : cosSinDeg(e.angle1), ce = circle ? cs : cosSinDeg(e.angle2);
        const bool full = sweep >= 360.0;
        const Point2 c = toWorld(e.a[0], e.a[1], plane, scale_);
        const Point2 s = toWorld(e.a[0] + r * cs.x, e.a[1] + r * cs.y, plane, scale_);
        const Point2 t = full ? s : toWorld(e.a[0] + r * ce.x, e.a[1] + r * ce.y, plane, scale_);
        single(ContourSegment::arc(s, t, c, plane == Plane::Up), full);
    }

    void ellipse(const RawEntity& e, Plane plane)
    {
        const double ratio = e.radius;
        const Point2 c{scale_ * e.a[0], scale_ * e.a[1]};
        const Point2 major{scale_ * e.b[0], scale_ * e.b[1]};
        if (std::abs(e.b[2]) > kFlat) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its major axis leaves the XY plane"));
        if (!(ratio > 1e-9 && ratio <= 1e3) || length(major) < kMinLength)
            return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it is degenerate (axis {:g}, ratio {:g})"), length(major), ratio));
        const double s = plane == Plane::Up ? 1.0 : -1.0;
        const Point2 minor = ratio * Point2{-s * major.y, s * major.x};
        double t1 = e.angle1, t2 = e.angle2;
        if (!(std::abs(t1) < 1e3 && std::abs(t2) < 1e3)) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its parameters are out of range"));
        while (t2 <= t1) t2 += 2 * kPi;
        const bool full = t2 - t1 >= 2 * kPi - 1e-12;
        const auto at = [&](double t) { return c + std::cos(t) * major + std::sin(t) * minor; };
        if (std::abs(ratio - 1.0) < 1e-12) {  // a circle
            const Point2 p = at(t1);
            return single(ContourSegment::arc(p, full ? p : at(t2), c, plane == Plane::Up), full);
        }
        const int parts = std::max(1, static_cast<int>(std::ceil((t2 - t1) / (kPi / 4))));
        std::vector<Point2> pts{at(t1)};
        std::size_t budget = kMaxPerEntity;
        for (int i = 0; i < parts; ++i) {
            const double a = t1 + (t2 - t1) * i / parts, b = t1 + (t2 - t1) * (i + 1) / parts;
            if (!subdivide(at, a, b, pts.back(), at(b), tol_, 0, pts, budget))
                return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it needs more than {} lines at the spline tolerance"), kMaxPerEntity));
        }
        if (full) pts.back() = pts.front();
        lines(pts, full);
    }

    void lines(const std::vector<Point2>& pts, bool closed)
    {
        Piece piece{{}, ref_, closed};
        for (std::size_t i = 1; i < pts.size(); ++i)
            if (distance(pts[i - 1], pts[i]) >= kMinLength) {
                const Point2 from = piece.segments.empty() ? pts[i - 1] : piece.segments.back().end;
                piece.segments.push_back(ContourSegment::line(from, pts[i]));
            }
        if (piece.segments.empty()) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it has no length"));
        out_.push_back(std::move(piece));
    }

    void polyline(const RawEntity& e, Plane plane)
    {
        const bool is3d = e.type == RawEntity::Type::Polyline && (e.flags & 8);
        const bool closed = e.flags & 1;
        const auto& v = e.vertices;
        if (is3d) {
            const auto [lo, hi] = std::minmax_element(v.begin(), v.end(), [](auto& a, auto& b) { return a.z < b.z; });
            if (!v.empty() && hi->z - lo->z > kFlat) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it leaves the XY plane (its vertices differ in Z)"));
        }
        Piece piece{{}, ref_, closed};
        const std::size_t n = v.size(), count = closed ? n : (n == 0 ? 0 : n - 1);
        for (std::size_t i = 0; i < count; ++i) {
            const RawVertex& va = v[i];
            const RawVertex& vb = v[(i + 1) % n];
            const Point2 p = is3d ? Point2{scale_ * va.x, scale_ * va.y} : toWorld(va.x, va.y, plane, scale_);
            const Point2 q = is3d ? Point2{scale_ * vb.x, scale_ * vb.y} : toWorld(vb.x, vb.y, plane, scale_);
            const double chord = distance(p, q);
            if (chord < kMinLength) continue;
            const double bulge = is3d ? 0.0 : va.bulge;
            if (std::abs(bulge) < 1e-12 || std::abs(bulge) > 1e6) {
                if (std::abs(bulge) > 1e6) notes_.add(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: a bulge of {:g} read as a straight line"), ref_.text(), bulge));
                piece.segments.push_back(ContourSegment::line(piece.segments.empty() ? p : piece.segments.back().end, q));
                continue;
            }
            // The bulge is tan(θ/4) of the included angle θ, positive
            // counter-clockwise in the OCS; the centre lies off the chord's
            // midpoint by chord·(1 − b²)/(4b) to the left.
            const bool ccw = (bulge > 0) == (plane != Plane::Down);
            const double b = ccw ? std::abs(bulge) : -std::abs(bulge);
            const Point2 mid = 0.5 * (p + q);
            const Point2 left{-(q.y - p.y) / chord, (q.x - p.x) / chord};
            const Point2 centre = mid + (chord * (1 - b * b) / (4 * b)) * left;
            piece.segments.push_back(ContourSegment::arc(p, q, centre, ccw));
        }
        if (piece.segments.empty()) return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its {} vertices give no segment"), n));
        if (closed && piece.segments.back().end != piece.segments.front().start) piece.closedByItself = false;
        out_.push_back(std::move(piece));
    }

    void spline(const RawEntity& e)
    {
        const auto& cp = e.vertices;
        const auto& U = e.knots;
        const int p = e.degree;
        const std::size_t n = cp.size();
        if (n == 0) return skip(e.fitPoints > 0 ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "it is given by fit points only, without control points") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "it has no control points"));
        if (p < 1 || p > 20) return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its degree {} is not 1 to 20"), p));
        const std::size_t deg = static_cast<std::size_t>(p);
        if (n < deg + 1 || U.size() != n + deg + 1)
            return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} knots do not fit {} control points of degree {}"), U.size(), n, p));
        for (std::size_t i = 1; i < U.size(); ++i)
            if (!(U[i] >= U[i - 1])) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its knots decrease"));
        if (!(U[n] > U[deg])) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its knots span nothing"));
        const auto [lo, hi] = std::minmax_element(cp.begin(), cp.end(), [](auto& a, auto& b) { return a.z < b.z; });
        if (hi->z - lo->z > kFlat) return skip(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it leaves the XY plane (its control points differ in Z)"));
        std::vector<std::array<double, 3>> pw;  // homogeneous: x·w, y·w, w
        for (const RawVertex& v : cp) {
            if (!(v.bulge > 0 && std::isfinite(v.bulge))) return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a weight {:g} is not positive"), v.bulge));
            pw.push_back({scale_ * v.x * v.bulge, scale_ * v.y * v.bulge, v.bulge});
        }
        std::vector<Point2> pts;
        std::size_t budget = kMaxPerEntity;
        for (std::size_t k = deg; k < n; ++k) {
            if (!(U[k + 1] > U[k])) continue;
            const auto at = [&](double u) {  // de Boor on the span [U[k], U[k+1]]
                std::array<std::array<double, 3>, 21> d{};
                for (std::size_t j = 0; j <= deg; ++j) d[j] = pw[j + k - deg];
                for (std::size_t r = 1; r <= deg; ++r)
                    for (std::size_t j = deg; j >= r; --j) {
                        const std::size_t i = j + k - deg;
                        const double alpha = (u - U[i]) / (U[i + deg - r + 1] - U[i]);
                        for (int c = 0; c < 3; ++c) d[j][c] = (1 - alpha) * d[j - 1][c] + alpha * d[j][c];
                    }
                return Point2{d[deg][0] / d[deg][2], d[deg][1] / d[deg][2]};
            };
            const Point2 first = at(U[k]);
            if (!pts.empty() && distance(pts.back(), first) >= kMinLength) {  // a break at a full-multiplicity knot
                lines(pts, false);
                pts.clear();
            }
            if (pts.empty()) pts.push_back(first);
            if (!subdivide(at, U[k], U[k + 1], pts.back(), at(U[k + 1]), tol_, 0, pts, budget))
                return skip(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it needs more than {} lines at the spline tolerance"), kMaxPerEntity));
        }
        lines(pts, false);
    }

    double scale_, tol_;
    std::vector<Piece>& out_;
    Notes& notes_;
    EntityRef ref_;
};

}  // namespace

const char* typeName(RawEntity::Type t)
{
    switch (t) {
    case RawEntity::Type::Line: return "LINE";
    case RawEntity::Type::Arc: return "ARC";
    case RawEntity::Type::Circle: return "CIRCLE";
    case RawEntity::Type::Ellipse: return "ELLIPSE";
    case RawEntity::Type::LwPolyline: return "LWPOLYLINE";
    case RawEntity::Type::Polyline: return "POLYLINE";
    case RawEntity::Type::Spline: return "SPLINE";
    }
    return "?";
}

Result<void> buildPieces(const std::vector<RawEntity>& entities, double scale, double splineTolerance, std::size_t segmentBudget,
                         std::vector<Piece>& out, Notes& notes)
{
    Builder b(scale, splineTolerance, out, notes);
    std::size_t segments = 0;
    for (const RawEntity& e : entities) {
        const std::size_t before = out.size();
        b.add(e);
        for (std::size_t i = before; i < out.size(); ++i) segments += out[i].segments.size();
        if (segments > segmentBudget)
            return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the drawing needs more than {} segments: too large or too fine a spline tolerance"), segmentBudget)};
    }
    return {};
}

}  // namespace taiwa::dxf::detail
