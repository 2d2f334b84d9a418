// The lathe tape oracle (turning_oracle.h): its own geometry of lines and
// arcs in the (z, r) half-plane, a Point2 with x = z and y = r throughout.
#include "support/turning_oracle.h"

#include "model/turned.h"
#include "post/lathe_post.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <optional>

namespace taiwa::test {

namespace {

using P = Point2;  // x: z along the axis, y: r the radius
constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

P zrOf(const turning::ZR& p) { return {p.z, p.r}; }
P unit(P v)
{
    const double l = length(v);
    return l > 0 ? P{v.x / l, v.y / l} : P{0, 0};
}

QString mm(double v) { return QString::number(v, 'f', 4); }
// A point as the tape writes it: X a diameter.
QString where(P p) { return QString("X%1 Z%2").arg(mm(2 * p.y), mm(p.x)); }

// ---- elements: lines and arcs ---------------------------------------------

struct Elem {
    bool arc = false;
    P a, b, c;
    double radius = 0.0;
    bool ccw = false;
    std::string id;  // the deformed edge's; empty for the material's closing lines
    turning::Origin origin = turning::Origin::Original;
};

double normAngle(double a)
{
    a = std::fmod(a, 2 * kPi);
    return a < 0 ? a + 2 * kPi : a;
}
double angleOf(P v) { return std::atan2(v.y, v.x); }

// Signed sweep of an arc from a to b (positive counter-clockwise).
double sweepOf(const Elem& e)
{
    const double ta = angleOf(e.a - e.c), tb = angleOf(e.b - e.c);
    return e.ccw ? normAngle(tb - ta) : -normAngle(ta - tb);
}

bool withinSweep(const Elem& e, P p)
{
    const double ta = angleOf(e.a - e.c), t = angleOf(p - e.c), s = sweepOf(e);
    return s >= 0 ? normAngle(t - ta) <= s + 1e-12 : normAngle(ta - t) <= -s + 1e-12;
}

P nearestOn(const Elem& e, P p)
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

double distanceTo(const Elem& e, P p) { return distance(p, nearestOn(e, p)); }

double lengthOf(const Elem& e) { return e.arc ? e.radius * std::abs(sweepOf(e)) : distance(e.a, e.b); }

// The direction of travel at a point of the element.
P tangentAt(const Elem& e, P q)
{
    if (!e.arc) return unit(e.b - e.a);
    const P v = unit(q - e.c);
    return e.ccw ? P{-v.y, v.x} : P{v.y, -v.x};
}

// Points along the element, at most `tol` off it (arcs: chords), its start
// included, its end not.
void flattenInto(const Elem& e, double tol, std::vector<P>& out)
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

Shape shapeOf(const Tool& t, int orientation)
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
std::vector<P> insertCorner(const Shape& s, P c, double reach)
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
std::vector<P> outline(const Shape& s, P p, double rTop, double zBack)
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

std::vector<P> convexHull(std::vector<P> pts)
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
double depthIn(const std::vector<P>& poly, P p)
{
    double d = kInf;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const P a = poly[i], b = poly[(i + 1) % poly.size()];
        const P n = unit(P{b.y - a.y, a.x - b.x});  // outward for counter-clockwise
        d = std::min(d, -dot(p - a, n));
    }
    return d;
}

double distanceToPolygon(const std::vector<P>& poly, P p)
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
double penetration(const Material& m, const std::vector<P>& poly, double sample)
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
double penetrationOfBoth(const Material& a, const Material& b, const std::vector<P>& poly, double sample)
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

// ---- the stock -------------------------------------------------------------

// The bar's half-section as columns along Z, each the interval of radii
// [lo, hi] still there (empty when hi <= lo). Outside tools take from the
// top of a column, inside tools and drills from its bottom: every tool
// shape here is one whole side of its cutting edge.
class Stock {
public:
    Stock(const BarStock& bar, double cell) : cell_(cell)
    {
        const double back = bar.face - bar.length;
        z0_ = back - 10.0;
        const auto n = static_cast<std::size_t>(std::ceil((bar.length + 20.0) / cell));
        lo_.assign(n, kInf);
        hi_.assign(n, -kInf);
        for (std::size_t i = 0; i < n; ++i) {
            const double z = centre(i);
            if (z >= back && z <= bar.face) {
                lo_[i] = bar.bore / 2.0;
                hi_[i] = bar.diameter / 2.0;
            }
        }
    }

    void cut(const Shape& s, P a, P b)
    {
        sweep(s, a, b, [&](std::size_t i, double v) {
            if (s.inner) lo_[i] = std::max(lo_[i], v);
            else hi_[i] = std::min(hi_[i], v);
        });
    }

    // The deepest overlap (in radius) of the shape swept from a to b with
    // what is left, and the Z where it is.
    double overlap(const Shape& s, P a, P b, double* atZ) const
    {
        double worst = -kInf;
        sweep(s, a, b, [&](std::size_t i, double v) {
            if (hi_[i] <= lo_[i]) return;
            const double o = s.inner ? std::min(v, hi_[i]) - lo_[i] : hi_[i] - std::max(v, lo_[i]);
            if (o > worst) {
                worst = o;
                if (atZ) *atZ = centre(i);
            }
        });
        return worst;
    }

private:
    double centre(std::size_t i) const { return z0_ + (static_cast<double>(i) + 0.5) * cell_; }

    // Calls f(column, value) for every column the shape's sweep from a to b
    // (reference points) reaches: outside tools, the lowest radius it takes
    // there (it takes everything above); inside ones the highest.
    template <class F>
    void sweep(const Shape& s, P a, P b, F&& f) const
    {
        double zMin = std::min(a.x, b.x), zMax = std::max(a.x, b.x);
        if (s.kind == Shape::Insert) {
            zMin -= s.nose;
            zMax += s.nose;
        } else if (s.kind == Shape::Blade) {
            zMin -= s.width;
        } else if (s.kind == Shape::Drill) {
            zMax = z0_ + cell_ * static_cast<double>(lo_.size());
        } else {
            return;
        }
        const double first = std::floor((zMin - z0_) / cell_ - 0.5), last = std::ceil((zMax - z0_) / cell_ - 0.5);
        const double count = static_cast<double>(lo_.size());
        for (double k = std::max(first, 0.0); k <= std::min(last, count - 1); k += 1.0) {
            const auto i = static_cast<std::size_t>(k);
            if (const auto v = value(s, a, b, centre(i))) f(i, *v);
        }
    }

    static std::optional<double> value(const Shape& s, P a, P b, double z)
    {
        const bool lower = !s.inner;
        const P d = b - a;
        std::optional<double> best;
        const auto take = [&](double v) { best = !best ? v : lower ? std::min(*best, v) : std::max(*best, v); };
        switch (s.kind) {
        case Shape::Insert: {
            // The capsule the nose sweeps: both end discs and the offset side.
            const double r = s.nose;
            for (const P c : {a, b}) {
                const double dz = z - c.x;
                if (std::abs(dz) <= r) {
                    const double h = std::sqrt(std::max(0.0, r * r - dz * dz));
                    take(lower ? c.y - h : c.y + h);
                }
            }
            const double l = length(d);
            if (l > 1e-12 && std::abs(d.x) > 1e-12) {
                P n{-d.y / l, d.x / l};
                if ((lower && n.y > 0) || (!lower && n.y < 0)) n = -1.0 * n;
                const double t = (z - a.x - r * n.x) / d.x;
                if (t >= 0 && t <= 1) take(a.y + t * d.y + r * n.y);
            }
            break;
        }
        case Shape::Blade: {
            // The rectangle covers [p.z - width, p.z]: the column while p.z is in [z, z + width].
            double t0 = 0, t1 = 1;
            if (std::abs(d.x) < 1e-12) {
                if (a.x < z - 1e-12 || a.x > z + s.width + 1e-12) return std::nullopt;
            } else {
                const double ta = (z - a.x) / d.x, tb = (z + s.width - a.x) / d.x;
                t0 = std::max(0.0, std::min(ta, tb));
                t1 = std::min(1.0, std::max(ta, tb));
                if (t0 > t1) return std::nullopt;
            }
            take(a.y + t0 * d.y);
            take(a.y + t1 * d.y);
            break;
        }
        case Shape::Drill: {
            const double zTip = std::min(a.x, b.x);
            if (z < zTip) return std::nullopt;
            take(std::max(a.y, b.y) + std::min(s.radius, (z - zTip) * s.tanHalf));
            break;
        }
        case Shape::None: break;
        }
        return best;
    }

    double z0_ = 0.0, cell_ = 0.02;
    std::vector<double> lo_, hi_;
};

int orientationFor(const Plan& plan, int toolId)
{
    for (const auto& s : plan.steps)
        if (s.tool && s.tool->toolId == toolId && s.turn) return s.turn->orientation;
    return 0;
}

const Tool* libraryTool(const Plan& plan, int id)
{
    if (const Tool* t = plan.tool(id)) return t;
    return findTool(plan.tools, id);
}

}  // namespace

Point2 orientationOffset(int orientation, double r)
{
    // LinuxCNC's lathe tool orientations: the controlled (imaginary tip)
    // point from the nose centre, X a radius; 9 (and a zero radius) is the
    // centre itself.
    switch (orientation) {
    case 1: return {r, -r};   // X -r, Z +r
    case 2: return {-r, -r};  // X -r, Z -r: outside, cutting toward the chuck
    case 3: return {-r, r};   // X +r, Z -r: boring toward the chuck
    case 4: return {r, r};    // X +r, Z +r
    default: return {0, 0};   // 5-8 (tip on an axis) are not modelled: no plan uses them with a nose radius
    }
}

std::string latheToolTable(const Plan& plan)
{
    std::string out;
    for (const auto& [station, id] : latheStations(plan.steps)) {
        const Tool* t = libraryTool(plan, id);
        const bool drill = t && (t->type == ToolType::Drill || t->type == ToolType::CentreDrill);
        const double nose = t && !drill ? t->cornerRadius : 0.0;
        char line[160];
        std::snprintf(line, sizeof line, "T%d P%d X0 Z0 D%.6f Q%d ;library T%d\n", station, station, 2.0 * nose / 25.4,
                      orientationFor(plan, id), id);
        out += line;
    }
    return out;
}

LatheVerdict judgeLatheTape(const Plan& plan, const Rs274Result& run, const LatheOracleOptions& o)
{
    LatheVerdict v;
    if (!plan.mmJob.bar) {
        v.problems << "not a lathe job: no bar stock";
        return v;
    }
    const BarStock& bar = *plan.mmJob.bar;
    const double k = run.inches ? 25.4 : 1.0;
    const auto zr = [&](const Point3& p) { return P{k * p.z, k * p.x}; };
    const double rTop = bar.diameter / 2.0 + 5.0;

    std::map<int, Shape> shapes;  // by turret station
    for (const auto& [station, id] : latheStations(plan.steps)) {
        const Tool* t = libraryTool(plan, id);
        if (!t) {
            v.problems << QString("station %1: library tool T%2 is not in the plan").arg(station).arg(id);
            continue;
        }
        shapes[station] = shapeOf(*t, orientationFor(plan, id));
        const int q = shapes[station].orientation;
        if (shapes[station].kind == Shape::Insert && t->cornerRadius > 0 && (q < 1 || q > 4))
            v.problems << QString("station %1: T%2 has a nose radius and orientation %3, which the oracle does not model").arg(station).arg(id).arg(q);
        if (shapes[station].kind == Shape::None)
            v.problems << QString("station %1: T%2 %3 is no lathe tool").arg(station).arg(id).arg(QString::fromStdString(t->name));
    }
    for (const auto& s : plan.steps)
        if (s.tool && s.turn && s.turn->orientation != orientationFor(plan, s.tool->toolId))
            v.problems << QString("%1 uses T%2 with orientation %3, the tool table has %4")
                              .arg(QString::fromStdString(s.label())).arg(s.tool->toolId).arg(s.turn->orientation)
                              .arg(orientationFor(plan, s.tool->toolId));

    std::map<int, Material> materials, drawn;  // by unit: the deformed profile's material, the part as drawn
    for (const auto& part : plan.turned)
        if (!part.deformed.edges.empty() && !part.profile.edges.empty()) {
            materials.emplace(part.unit, Material(part, bar));
            drawn.emplace(part.unit, Material(part, bar, true));
        }
    double zBack = -kInf;
    for (const auto& [u, m] : materials) zBack = std::max(zBack, m.zFront() + 10.0);
    zBack = std::max(zBack, bar.face + 10.0);

    Stock stock(bar, o.cell);
    const std::size_t nSteps = plan.steps.size();
    std::vector<std::vector<P>> noseCentres(nSteps);              // finishing and facing: every sampled nose centre
    std::vector<std::vector<std::vector<P>>> toolSweeps(nSteps);   // grooving, parting, drilling: each cut's swept outline
    std::vector<int> cuts(nSteps, 0);
    int reported = 0;
    const auto problem = [&](const QString& s) {
        if (++reported <= 40) v.problems << s;
        else if (reported == 41) v.problems << "(more problems left out)";
    };

    for (std::size_t i = 0; i < run.moves.size(); ++i) {
        const CanonMove& m = run.moves[i];
        const P a = zr(m.start), b = zr(m.end);
        const auto st = shapes.find(m.tool);
        const Shape none;
        const Shape& s = st == shapes.end() ? none : st->second;
        const QString at = QString("move %1 (step %2, station T%3) %4 to %5").arg(i).arg(m.step).arg(m.tool).arg(where(a), where(b));

        if (m.kind == CanonMove::Traverse) {
            ++v.rapids;
            double z = 0;
            const double ov = stock.overlap(s, s.ref(a), s.ref(b), &z);
            if (ov > v.worstRapid) {
                v.worstRapid = ov;
                v.worstRapidMove = QString("%1, at Z%2").arg(at, mm(z));
            }
            if (ov > o.tolerance) problem(QString("rapid into stock not yet cut: %1 overlaps the stock left by %2 mm at Z%3").arg(at, mm(ov), mm(z)));
            continue;
        }
        if (m.plane != 18) problem(QString("cut outside G18: %1").arg(at));
        if (m.step < 1 || m.step > static_cast<int>(nSteps)) {
            problem(QString("cut outside any step: %1").arg(at));
            continue;
        }
        const std::size_t si = static_cast<std::size_t>(m.step - 1);
        const Step& step = plan.steps[si];
        ++cuts[si];
        ++v.feeds;
        if (!step.tool || s.id != step.tool->toolId)
            problem(QString("%1 cuts with library T%2, the step's tool is T%3").arg(at).arg(s.id).arg(step.tool ? step.tool->toolId : 0));
        if (s.kind == Shape::None) continue;

        // The move as reference points (nose centres for inserts): a line
        // its two ends, an arc as chords; and sampled every `sample` mm.
        std::vector<P> path{s.ref(a)};
        if (m.kind == CanonMove::Arc) {
            for (const auto& q : sampleArc(m, o.sample / k)) path.push_back(s.ref(zr(q)));
        } else {
            path.push_back(s.ref(b));
        }
        std::vector<P> pts{path.front()};
        for (std::size_t j = 0; j + 1 < path.size(); ++j) {
            const int n = std::max(1, static_cast<int>(std::ceil(distance(path[j], path[j + 1]) / o.sample)));
            for (int q = 1; q <= n; ++q) pts.push_back(path[j] + (static_cast<double>(q) / n) * (path[j + 1] - path[j]));
        }

        const auto mat = materials.find(step.unit);
        if (mat == materials.end()) {
            problem(QString("%1: unit %2 has no turned profile").arg(at).arg(step.unit + 1));
        } else if (s.kind == Shape::Insert) {
            const Material& part = mat->second;
            const bool roughing = step.kind == StepKind::TurnRoughing;
            const bool finishing = step.kind == StepKind::TurnFinishing;
            const bool threading = step.kind == StepKind::Threading;
            const double allowance = roughing && step.turn ? std::min(step.turn->allowanceX, step.turn->allowanceZ) : 0.0;
            double worst = -kInf, closest = kInf, nearest = kInf;
            P worstAt{}, closestAt{}, nearestAt{};
            for (const P& c : pts) {
                const double sd = threading ? part.threadedDistance(c) : part.signedDistance(c);
                if (s.nose - sd > worst) {
                    worst = s.nose - sd;
                    worstAt = c;
                }
                if (roughing && sd - s.nose - allowance < closest) {
                    closest = sd - s.nose - allowance;
                    closestAt = c;
                }
                if (finishing) {
                    const double d = part.profileDistance(c);
                    if (d < nearest) {
                        nearest = d;
                        nearestAt = c;
                    }
                }
                if (finishing || step.kind == StepKind::Facing) noseCentres[si].push_back(c);
            }
            if (finishing && nearest < s.nose - o.tolerance)
                problem(QString("finishing nose centre %1 mm from the profile, less than the nose radius %2: %3, nearest at nose centre Z%4 R%5")
                            .arg(mm(nearest), mm(s.nose), at, mm(nearestAt.x), mm(nearestAt.y)));
            v.worstGouge = std::max(v.worstGouge, worst);
            if (worst > o.tolerance)
                problem(QString("gouge of %1 mm into unit %2's part by %3 (nose R%4): %5, deepest at nose centre Z%6 R%7")
                            .arg(mm(worst)).arg(step.unit + 1).arg(QString::fromStdString(step.label()), mm(s.nose), at, mm(worstAt.x), mm(worstAt.y)));
            // The whole cutting corner, for the reader.
            double body = -kInf, bodyDrawn = -kInf;
            for (std::size_t j = 0; j + 1 < path.size(); ++j) {
                std::vector<P> both = insertCorner(s, path[j], 5.0);
                if (both.empty()) break;
                const auto more = insertCorner(s, path[j + 1], 5.0);
                both.insert(both.end(), more.begin(), more.end());
                const auto hull = convexHull(both);
                body = std::max(body, penetration(part, hull, 0.05));
                bodyDrawn = std::max(bodyDrawn, penetrationOfBoth(part, drawn.at(step.unit), hull, 0.05));
            }
            if (body > std::max(worst, 0.0) + o.tolerance)
                v.insertBody << QString("step %1 %2: %3 mm into the deformed profile, %4 mm into the finished part (as drawn, less relief grooves); %5")
                                    .arg(m.step).arg(QString::fromStdString(step.label()), mm(body), mm(bodyDrawn), at);
            if (roughing) {
                v.closestRoughing = std::min(v.closestRoughing, closest);
                if (closest < -o.tolerance)
                    problem(QString("roughing leaves less than its allowance %1 mm: the nose comes %2 mm closer, %3, at nose centre Z%4 R%5")
                                .arg(mm(allowance), mm(-closest), at, mm(closestAt.x), mm(closestAt.y)));
            }
        } else {
            const Material& part = mat->second;
            for (std::size_t j = 0; j + 1 < path.size(); ++j) {
                std::vector<P> both = outline(s, path[j], rTop, zBack);
                const auto more = outline(s, path[j + 1], rTop, zBack);
                both.insert(both.end(), more.begin(), more.end());
                const auto hull = convexHull(both);
                const double pen = penetration(part, hull, o.sample);
                v.worstGouge = std::max(v.worstGouge, pen);
                if (pen > o.tolerance)
                    problem(QString("gouge of %1 mm into unit %2's part by %3 (%4): %5")
                                .arg(mm(pen)).arg(step.unit + 1).arg(QString::fromStdString(step.label()), QString::fromStdString(s.name), at));
                toolSweeps[si].push_back(hull);
            }
            if (s.kind == Shape::Drill && (std::abs(a.y) > 1e-6 || std::abs(b.y) > 1e-6))
                problem(QString("a drill off the axis: %1").arg(at));
        }
        for (std::size_t j = 0; j + 1 < path.size(); ++j) stock.cut(s, path[j], path[j + 1]);
    }

    // Every step cuts.
    for (std::size_t si = 0; si < nSteps; ++si)
        if (cuts[si] == 0) problem(QString("step %1 %2 cuts nothing").arg(si + 1).arg(QString::fromStdString(plan.steps[si].label())));

    // Finishing touches every element it must; the facing the front face.
    for (const auto& [unitIndex, part] : materials) {
        std::vector<P> finish, facing;
        double rFinish = 0, rFacing = 0;
        std::vector<const std::vector<P>*> blades;
        for (std::size_t si = 0; si < nSteps; ++si) {
            const Step& s = plan.steps[si];
            if (s.unit != unitIndex || !s.tool) continue;
            const Tool* t = libraryTool(plan, s.tool->toolId);
            if (s.kind == StepKind::TurnFinishing) {
                finish.insert(finish.end(), noseCentres[si].begin(), noseCentres[si].end());
                rFinish = t ? t->cornerRadius : 0;
            } else if (s.kind == StepKind::Facing) {
                facing.insert(facing.end(), noseCentres[si].begin(), noseCentres[si].end());
                rFacing = t ? t->cornerRadius : 0;
            } else {
                for (const auto& h : toolSweeps[si]) blades.push_back(&h);
            }
        }
        if (finish.empty()) continue;
        for (std::size_t ei = 0; ei < part.profile().size(); ++ei) {
            const Elem& e = part.profile()[ei];
            if (e.origin != turning::Origin::Original && e.origin != turning::Origin::Moved) continue;
            const bool front = part.onFrontFace(ei);
            const std::vector<P>& path = front ? facing : finish;
            const double rn = front ? rFacing : rFinish;
            if (front && path.empty()) continue;
            if (lengthOf(e) <= 2.0 * rn) continue;
            double d = kInf;
            for (const P& c : path) d = std::min(d, distanceTo(e, c));
            // A blade or drill finishes the element when it lies on all of it:
            // the farthest point of the element from every such cut.
            double blade = kInf;
            if (!front && !blades.empty()) {
                std::vector<P> corners, pts;
                flattenInto(e, 1e-4, corners);
                corners.push_back(e.b);
                for (std::size_t j = 0; j + 1 < corners.size(); ++j) {
                    const int n = std::max(1, static_cast<int>(std::ceil(distance(corners[j], corners[j + 1]) / 0.02)));
                    for (int q = 0; q < n; ++q) pts.push_back(corners[j] + (static_cast<double>(q) / n) * (corners[j + 1] - corners[j]));
                }
                pts.push_back(e.b);
                blade = 0.0;
                for (const P& p : pts) {
                    double nearest = kInf;
                    for (const auto* h : blades) nearest = std::min(nearest, distanceToPolygon(*h, p));
                    blade = std::max(blade, nearest);
                }
            }
            const bool touched = std::abs(d - rn) <= o.tolerance || blade <= o.tolerance;
            v.touched << QString("unit %1 %2 %3 %4").arg(unitIndex + 1).arg(QString::fromStdString(e.id), mm(d - rn), blade < kInf ? mm(blade) : "-");
            if (!touched)
                problem(QString("unit %1: %2 (%3, %4 mm long) is not %5 at the nose radius: the nearest nose centre is %6 mm from it, "
                                "not the nose radius %7%8")
                            .arg(unitIndex + 1).arg(QString::fromStdString(e.id), QString::fromLatin1(turning::toKey(e.origin)), mm(lengthOf(e)),
                                 QString::fromLatin1(front ? "faced" : "finished"),
                                 mm(d), mm(rn), blade < kInf ? QString("; blades and drills stay up to %1 mm off it").arg(mm(blade)) : QString()));
        }
    }

    // Grooving: withdrawn along the outward normal by the withdrawal.
    for (std::size_t si = 0; si < nSteps; ++si) {
        const Step& s = plan.steps[si];
        if (s.kind != StepKind::Grooving || !s.turn) continue;
        const QString name = QString("step %1 %2").arg(si + 1).arg(QString::fromStdString(s.label()));
        std::optional<std::size_t> last;
        for (std::size_t i = 0; i < run.moves.size(); ++i)
            if (run.moves[i].step == static_cast<int>(si + 1) && run.moves[i].kind != CanonMove::Traverse) last = i;
        if (!last) continue;  // said above: cuts nothing
        const CanonMove& w = run.moves[*last];
        if (w.kind != CanonMove::Feed || *last + 1 >= run.moves.size() || run.moves[*last + 1].kind != CanonMove::Traverse) {
            problem(name + ": its last cut is not a straight feed followed by a rapid");
            continue;
        }
        const auto mat = materials.find(s.unit);
        const auto st = shapes.find(w.tool);
        if (mat == materials.end() || st == shapes.end()) continue;
        const P a = zr(w.start), b = zr(w.end);
        const double width = st->second.width;
        const P mid{a.x - width / 2.0, a.y};
        std::size_t nearest = 0;
        double dn = kInf;
        for (std::size_t ei = 0; ei < mat->second.profile().size(); ++ei) {
            const double d = distanceTo(mat->second.profile()[ei], mid);
            if (d < dn) {
                dn = d;
                nearest = ei;
            }
        }
        const P q = nearestOn(mat->second.profile()[nearest], mid);
        const P n = mat->second.airNormal(nearest, q);
        const P move = b - a;
        const double len = length(move), off = std::abs(cross(move, n)), along = dot(move, n);
        if (std::abs(len - s.turn->withdrawal) > o.tolerance || off > o.tolerance || along <= 0)
            problem(QString("%1: the withdrawal %2 to %3 is %4 mm long (the step's withdrawal %5 mm), %6 mm off the outward normal "
                            "(%7, %8) of %9")
                        .arg(name, where(a), where(b), mm(len), mm(s.turn->withdrawal), mm(off), mm(n.x), mm(n.y),
                             QString::fromStdString(mat->second.profile()[nearest].id)));
    }
    return v;
}

}  // namespace taiwa::test
