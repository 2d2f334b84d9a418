// The lathe tape oracle's geometry (turning_oracle.cpp): lines and arcs in
// the (z, r) half-plane, a Point2 with x = z and y = r throughout; the part's
// material between the axis and a profile; the tools' shapes (insert nose,
// blade, drill) and how deep a shape enters the material. Internal to
// tests/support.
#pragma once

#include "support/turning_oracle.h"

#include "model/turned.h"

#include <QString>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

namespace taiwa::test::lathe_oracle {


using P = Point2;  // x: z along the axis, y: r the radius
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline P zrOf(const turning::ZR& p) { return {p.z, p.r}; }
inline P unit(P v)
{
    const double l = length(v);
    return l > 0 ? P{v.x / l, v.y / l} : P{0, 0};
}

inline QString mm(double v) { return QString::number(v, 'f', 4); }
// A point as the tape writes it: X a diameter.
inline QString where(P p) { return QString("X%1 Z%2").arg(mm(2 * p.y), mm(p.x)); }

// ---- elements: lines and arcs ---------------------------------------------

struct Elem {
    bool arc = false;
    P a, b, c;
    double radius = 0.0;
    bool ccw = false;
    std::string id;  // the deformed edge's; empty for the material's closing lines
    turning::Origin origin = turning::Origin::Original;
};

inline double normAngle(double a)
{
    a = std::fmod(a, 2 * kPi);
    return a < 0 ? a + 2 * kPi : a;
}
inline double angleOf(P v) { return std::atan2(v.y, v.x); }

// Signed sweep of an arc from a to b (positive counter-clockwise).
inline double sweepOf(const Elem& e)
{
    const double ta = angleOf(e.a - e.c), tb = angleOf(e.b - e.c);
    return e.ccw ? normAngle(tb - ta) : -normAngle(ta - tb);
}

inline bool withinSweep(const Elem& e, P p)
{
    const double ta = angleOf(e.a - e.c), t = angleOf(p - e.c), s = sweepOf(e);
    return s >= 0 ? normAngle(t - ta) <= s + 1e-12 : normAngle(ta - t) <= -s + 1e-12;
}

inline P nearestOn(const Elem& e, P p)
{
    if (!e.arc) {
        const P d = e.b - e.a;
        const double l2 = dot(d, d);
        const double t = l2 > 0 ? std::clamp(dot(p - e.a, d) / l2, 0.0, 1.0) : 0.0;
        return e.a + t * d;
    }
    const P v = p - e.c;
    const double l = length(v);
    if (l > 1e-12 && withinSweep(e, p)) return e.c + (e.radius / l) * v;
    return distance(p, e.a) <= distance(p, e.b) ? e.a : e.b;
}

inline double distanceTo(const Elem& e, P p) { return distance(p, nearestOn(e, p)); }

inline double lengthOf(const Elem& e) { return e.arc ? e.radius * std::abs(sweepOf(e)) : distance(e.a, e.b); }

// The direction of travel at a point of the element.
inline P tangentAt(const Elem& e, P q)
{
    if (!e.arc) return unit(e.b - e.a);
    const P v = unit(q - e.c);
    return e.ccw ? P{-v.y, v.x} : P{v.y, -v.x};
}

// Points along the element, at most `tol` off it (arcs: chords), its start
// included, its end not.
inline void flattenInto(const Elem& e, double tol, std::vector<P>& out)
{
    out.push_back(e.a);
    if (!e.arc) return;
    const double s = sweepOf(e);
    const double step = 2.0 * std::acos(std::max(0.0, 1.0 - tol / std::max(e.radius, 1e-9)));
    const int n = std::max(4, static_cast<int>(std::ceil(std::abs(s) / std::max(step, 1e-6))));
    const double a0 = angleOf(e.a - e.c);
    for (int i = 1; i < n; ++i) {
        const double t = a0 + s * i / n;
        out.push_back(e.c + e.radius * P{std::cos(t), std::sin(t)});
    }
}

// ---- the part's material ---------------------------------------------------

class Material {
public:
    // The deformed profile's material (drawn = false), or the part as drawn.
    Material(const TurnedPart& part, const BarStock& bar, bool drawn = false)
    {
        inner_ = part.deformed.side == turning::ProfileSide::Inner;
        const auto add = [&](const turning::Segment& g, const std::string& id, turning::Origin origin) {
            Elem e;
            e.arc = g.arc;
            e.a = zrOf(g.a);
            e.b = zrOf(g.b);
            e.c = zrOf(g.centre);
            e.radius = g.radius;
            e.ccw = g.ccw;
            e.id = id;
            e.origin = origin;
            profile_.push_back(e);
        };
        if (drawn)
            for (const auto& d : part.profile.edges) add(d.geometry, d.id, turning::Origin::Original);
        else
            for (const auto& d : part.deformed.edges) add(d.geometry, d.id, d.origin);
        loop_ = profile_;
        const P start = profile_.front().a, end = profile_.back().b;
        // Outer: down to the axis at both ends; inner: out past the bar.
        const double rClose = inner_ ? bar.diameter / 2.0 + 5.0 : 0.0;
        const std::vector<P> close = {end, {end.x, rClose}, {start.x, rClose}, start};
        for (std::size_t i = 0; i + 1 < close.size(); ++i)
            if (distance(close[i], close[i + 1]) > 1e-9) {
                Elem e;
                e.a = close[i];
                e.b = close[i + 1];
                loop_.push_back(e);
            }
        for (const auto& e : loop_) flattenInto(e, 5e-5, poly_);
        if (!drawn)
            for (const auto& d : part.deformed.edges)
                if (d.attributes.thread) {
                    const double pitch = d.attributes.thread->pitch;
                    threads_.push_back({std::min(d.geometry.a.z, d.geometry.b.z) - pitch, kInf, d.geometry.a.r - d.attributes.threadDepth()});
                }
        for (const auto& p : poly_) {
            lo_.x = std::min(lo_.x, p.x);
            lo_.y = std::min(lo_.y, p.y);
            hi_.x = std::max(hi_.x, p.x);
            hi_.y = std::max(hi_.y, p.y);
        }
        zFront_ = -kInf;
        for (const auto& e : profile_) zFront_ = std::max({zFront_, e.a.x, e.b.x});
    }

    bool inner() const { return inner_; }
    const std::vector<Elem>& profile() const { return profile_; }
    const std::vector<P>& boundary() const { return poly_; }
    double zFront() const { return zFront_; }
    double zEnd() const { return profile_.back().b.x; }

    // Whether profile element i is one of the leading ones on the front
    // plane (the facing's, not the turning's).
    bool onFrontFace(std::size_t i) const
    {
        for (std::size_t k = 0; k <= i; ++k)
            if (std::abs(profile_[k].a.x - zFront_) > 1e-6 || std::abs(profile_[k].b.x - zFront_) > 1e-6 || profile_[k].arc) return false;
        return true;
    }

    bool inside(P p) const
    {
        if (p.x < lo_.x || p.x > hi_.x || p.y < lo_.y || p.y > hi_.y) return false;
        bool in = false;
        for (std::size_t i = 0, j = poly_.size() - 1; i < poly_.size(); j = i++) {
            const P& a = poly_[i];
            const P& b = poly_[j];
            if ((a.y > p.y) != (b.y > p.y)) {
                const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
                if (p.x < x) in = !in;
            }
        }
        return in;
    }

    // Positive in the air, negative in the material.
    double signedDistance(P p) const
    {
        double d = kInf;
        for (const auto& e : loop_) d = std::min(d, distanceTo(e, p));
        return inside(p) ? -d : d;
    }

    // A threading insert's signed distance: the material is cut down to
    // the thread's root over the threaded edge and everything in front of
    // it, and over a pitch behind it (the run-out into the relief), as the
    // thread attribute of the deformed profile's edge says.
    double threadedDistance(P p) const
    {
        double d = signedDistance(p);
        for (const auto& t : threads_)
            if (p.x >= t.zFrom && p.x <= t.zTo + 1e-9) d = std::max(d, p.y - t.root);
        return d;
    }

    double profileDistance(P p) const
    {
        double d = kInf;
        for (const auto& e : profile_) d = std::min(d, distanceTo(e, p));
        return d;
    }

    // The unit normal into the air at a point q of profile element i.
    P airNormal(std::size_t i, P q) const
    {
        const P t = tangentAt(profile_[i], q);
        P n{-t.y, t.x};
        if (signedDistance(q + 0.01 * n) < signedDistance(q - 0.01 * n)) n = -1.0 * n;
        return n;
    }

private:
    bool inner_ = false;
    std::vector<Elem> profile_, loop_;
    struct Thread {
        double zFrom, zTo, root;  // Z from a pitch behind the threaded edge on; the root's radius
    };
    std::vector<Thread> threads_;
    std::vector<P> poly_;
    P lo_{kInf, kInf}, hi_{-kInf, -kInf};
    double zFront_ = 0.0;
};

// ---- tools -----------------------------------------------------------------

struct Shape {
    enum Kind { None, Insert, Blade, Drill } kind = None;
    bool inner = false;      // cuts outward from inside (boring bar, inside blade, drill)
    double nose = 0.0;       // insert
    P tip{};                 // insert: controlled point minus nose centre
    double width = 0.0;      // blade
    double radius = 0.0, tanHalf = 1.0;  // drill
    int id = 0, orientation = 0;
    std::string name;
    double approach = 0.0, tipAngle = 0.0;  // insert: the holder's κr and the insert's ε [deg]; 0: unknown
    // The point the shape is drawn about, for a controlled point.
    P ref(P controlled) const { return kind == Insert ? controlled - tip : controlled; }
};

inline Shape shapeOf(const Tool& t, int orientation)
{
    Shape s;
    s.id = t.id;
    s.name = t.name;
    s.orientation = orientation;
    switch (t.type) {
    case ToolType::TurningInsert:
        s.kind = Shape::Insert;
        s.inner = t.turning.inside;
        s.nose = t.cornerRadius;
        s.tip = orientationOffset(orientation, t.cornerRadius);
        s.approach = t.turning.approachAngle;
        if (!t.turning.insertCode.empty()) {
            // ISO 1832 shape letter.
            const std::map<char, double> shapes{{'C', 80}, {'D', 55}, {'V', 35}, {'T', 60}, {'W', 80}, {'S', 90}, {'K', 55}, {'E', 75}, {'M', 86}};
            const auto it = shapes.find(t.turning.insertCode.front());
            if (it != shapes.end()) s.tipAngle = it->second;
        }
        break;
    case ToolType::Threading:  // its nose as an insert's (its flanks are not modelled)
        s.kind = Shape::Insert;
        s.inner = t.turning.inside;
        s.nose = t.cornerRadius;
        s.tip = orientationOffset(orientation, t.cornerRadius);
        break;
    case ToolType::Grooving:
        s.kind = Shape::Blade;
        s.inner = t.turning.inside;
        s.width = t.turning.width > 0 ? t.turning.width : t.diameter;
        break;
    case ToolType::Drill:
    case ToolType::CentreDrill:
        s.kind = Shape::Drill;
        s.inner = true;
        s.radius = t.diameter / 2.0;
        s.tanHalf = std::tan(std::clamp(t.pointAngle, 1.0, 180.0) / 2.0 * kPi / 180.0);
        break;
    default: break;
    }
    return s;
}

// An insert's cutting corner about its nose centre: the nose and both
// edges `reach` mm long, as a convex polygon; empty when its angles are unknown.
inline std::vector<P> insertCorner(const Shape& s, P c, double reach)
{
    if (s.approach <= 0 || s.tipAngle <= 0) return {};
    // Angles from +Z, counter-clockwise (Z right, X up): outside, cutting
    // toward -Z, the major edge leaves the nose upward at 180 - κr, the
    // minor one ε clockwise of it; inside (a boring bar) mirrored in X.
    const double sign = s.inner ? -1.0 : 1.0;
    const double major = sign * (180.0 - s.approach) * kPi / 180.0, minor = sign * (180.0 - s.approach - s.tipAngle) * kPi / 180.0;
    const P d1{std::cos(major), std::sin(major)}, d2{std::cos(minor), std::sin(minor)};
    // Outward normals: away from the other edge.
    P n1{-d1.y, d1.x}, n2{d2.y, -d2.x};
    if (s.inner) {
        n1 = -1.0 * n1;
        n2 = -1.0 * n2;
    }
    std::vector<P> pts;
    for (int k = 0; k < 72; ++k) pts.push_back(c + s.nose * P{std::cos(k * kPi / 36), std::sin(k * kPi / 36)});
    pts.push_back(c + s.nose * n1 + reach * d1);
    pts.push_back(c + s.nose * n2 + reach * d2);
    return pts;
}

// A blade's or drill's outline about its reference point, a convex polygon.
inline std::vector<P> outline(const Shape& s, P p, double rTop, double zBack)
{
    if (s.kind == Shape::Blade) {
        const double w = s.width;
        if (!s.inner) {
            const double top = std::max(rTop, p.y + 1.0);
            return {{p.x - w, p.y}, {p.x, p.y}, {p.x, top}, {p.x - w, top}};
        }
        const double bottom = std::min(p.y, 0.0) - 1.0;
        return {{p.x - w, bottom}, {p.x, bottom}, {p.x, p.y}, {p.x - w, p.y}};
    }
    // Drill: the point on the axis, the body toward +Z.
    const double h = s.radius / std::max(s.tanHalf, 1e-9);
    const double back = std::max(zBack, p.x + h + 1.0);
    return {{p.x, p.y}, {p.x + h, p.y + s.radius}, {back, p.y + s.radius}, {back, p.y}};
}

inline std::vector<P> convexHull(std::vector<P> pts)
{
    std::sort(pts.begin(), pts.end(), [](P a, P b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (pts.size() < 3) return pts;
    std::vector<P> h(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(h[k - 1] - h[k - 2], pts[i] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(h[k - 1] - h[k - 2], pts[i - 1] - h[k - 2]) <= 0) --k;
        h[k++] = pts[i - 1];
    }
    h.resize(k - 1);
    return h;  // counter-clockwise
}

// Distance from a point inside a convex counter-clockwise polygon to its
// boundary; negative when outside.
inline double depthIn(const std::vector<P>& poly, P p)
{
    double d = kInf;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const P a = poly[i], b = poly[(i + 1) % poly.size()];
        const P n = unit(P{b.y - a.y, a.x - b.x});  // outward for counter-clockwise
        d = std::min(d, -dot(p - a, n));
    }
    return d;
}

inline double distanceToPolygon(const std::vector<P>& poly, P p)
{
    if (depthIn(poly, p) >= 0) return 0.0;
    double d = kInf;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        Elem e;
        e.a = poly[i];
        e.b = poly[(i + 1) % poly.size()];
        d = std::min(d, distanceTo(e, p));
    }
    return d;
}

// How deep a convex polygon enters the material: the deepest point of its
// boundary inside the material, or the deepest point of the material's
// boundary inside it (negative: the clearance of its boundary).
inline double penetration(const Material& m, const std::vector<P>& poly, double sample)
{
    double worst = -kInf;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const P a = poly[i], b = poly[(i + 1) % poly.size()];
        const int n = std::max(1, static_cast<int>(std::ceil(distance(a, b) / sample)));
        for (int k = 0; k < n; ++k) worst = std::max(worst, -m.signedDistance(a + (static_cast<double>(k) / n) * (b - a)));
    }
    for (const P& v : m.boundary()) worst = std::max(worst, depthIn(poly, v));
    return worst;
}

// How deep a convex polygon's boundary enters the material both regions
// hold (the part as drawn and the deformed profile: what must stay after
// grinding, relief grooves and grinding stock aside).
inline double penetrationOfBoth(const Material& a, const Material& b, const std::vector<P>& poly, double sample)
{
    double worst = -kInf;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const P p = poly[i], q = poly[(i + 1) % poly.size()];
        const int n = std::max(1, static_cast<int>(std::ceil(distance(p, q) / sample)));
        for (int k = 0; k < n; ++k) {
            const P x = p + (static_cast<double>(k) / n) * (q - p);
            worst = std::max(worst, -std::max(a.signedDistance(x), b.signedDistance(x)));
        }
    }
    return worst;
}


}  // namespace taiwa::test::lathe_oracle
