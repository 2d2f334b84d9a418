// Figure evaluation (figure_eval.h): the geometry of every definition
// method, in plain doubles, with the refusals of definitions that give no
// element or more than the modifiers can choose between.
#include "figure/figure_eval.h"

#include "figure/crossings.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

namespace taiwa::figure {

namespace {

// The item of that name: through the index when it covers every item, else
// by a look along them.
template <class T>
const T* findNamed(const std::vector<T>& items, const std::unordered_map<std::string, std::size_t>& index,
                   const std::string& name)
{
    if (index.size() == items.size()) {
        const auto it = index.find(name);
        return it == index.end() ? nullptr : &items[it->second];
    }
    for (const auto& item : items)
        if (item.name == name) return &item;
    return nullptr;
}

}  // namespace

const Element* Evaluation::find(const std::string& name) const { return findNamed(elements, elementIndex, name); }

const EvaluatedContour* Evaluation::findContour(const std::string& name) const
{
    return findNamed(contours, contourIndex, name);
}

namespace {

Point2 left(Point2 a) { return {-a.y, a.x}; }  // a turned +90°

std::string num(double v) { return formatNumber(v); }

constexpr const char* kCoincide = TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} coincide: no circle through three points");

// Of two candidates, the one the modifier names; a tie is refused.
Point2 choose(Point2 a, Point2 b, Modifier m, const std::string& what)
{
    const bool byX = m == Modifier::XLarge || m == Modifier::XSmall;
    const bool large = m == Modifier::XLarge || m == Modifier::YLarge;
    const double ka = byX ? a.x : a.y;
    const double kb = byX ? b.x : b.y;
    if (std::abs(ka - kb) <= kTolerance) {
        if (length(a - b) <= kTolerance) return a;  // one candidate (touching): nothing to choose
        throw Refusal(byX ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot choose between the two {}: both have the same x; use YLARGE or YSMALL"),
                                        keyword(m), what)
                          : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot choose between the two {}: both have the same y; use XLARGE or XSMALL"),
                                        keyword(m), what));
    }
    return ((ka > kb) == large) ? a : b;
}

// The unit normal of `l` pointing to the side the modifier names (XLARGE:
// towards +x...); refused for a line along the axis the modifier compares.
Point2 sideNormal(const Line& l, Modifier m, const std::string& lineName)
{
    const Point2 n = left(l.dir);
    const bool byX = m == Modifier::XLarge || m == Modifier::XSmall;
    const bool large = m == Modifier::XLarge || m == Modifier::YLarge;
    const double k = byX ? n.x : n.y;
    if (std::abs(k) <= 1e-12)
        throw Refusal(byX ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} names no side of {}: it is parallel to the X axis; use YLARGE or YSMALL"),
                                        keyword(m), lineName)
                          : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} names no side of {}: it is parallel to the Y axis; use XLARGE or XSMALL"),
                                        keyword(m), lineName));
    return ((k > 0) == large) ? n : -1.0 * n;
}

Point2 intersectLines(const Line& a, const Line& b, const std::string& an, const std::string& bn)
{
    const auto p = lineCrossing(a, b);
    if (!p) throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} are parallel: they do not intersect"), an, bn));
    return *p;
}

// Both intersections of a line and a circle (equal when it touches).
std::pair<Point2, Point2> intersectLineCircle(const Line& l, const Circle& c, const std::string& what)
{
    const Point2 foot = l.point + dot(c.centre - l.point, l.dir) * l.dir;
    const double h = length(c.centre - foot);
    if (h > c.radius + kTolerance) throw Refusal(what);
    const double half = std::sqrt(std::max(0.0, c.radius * c.radius - h * h));
    return {foot + half * l.dir, foot - half * l.dir};
}

std::pair<Point2, Point2> intersectCircles(const Circle& a, const Circle& b, const std::string& an, const std::string& bn)
{
    const Point2 d = b.centre - a.centre;
    const double dist = length(d);
    if (dist <= kTolerance) throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} are concentric: they do not intersect"), an, bn));
    if (dist > a.radius + b.radius + kTolerance || dist < std::abs(a.radius - b.radius) - kTolerance)
        throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} do not meet"), an, bn));
    const Point2 e = (1.0 / dist) * d;
    const double along = (dist * dist + a.radius * a.radius - b.radius * b.radius) / (2 * dist);
    const double h = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
    const Point2 base = a.centre + along * e;
    return {base + h * left(e), base - h * left(e)};
}

// The direction at `deg` degrees from +X, exact at multiples of 90°.
Point2 direction(double deg)
{
    const double r = std::fmod(deg, 360.0);
    const double a = r < 0 ? r + 360.0 : r;
    if (a == 0) return {1, 0};
    if (a == 90) return {0, 1};
    if (a == 180) return {-1, 0};
    if (a == 270) return {0, -1};
    const double rad = a * std::numbers::pi / 180.0;
    return {std::cos(rad), std::sin(rad)};
}

class Evaluator {
public:
    Element element(const Definition& d)
    {
        Element e;
        e.name = d.name;
        e.kind = d.kind();
        switch (d.method) {
        case Method::PointXY: e.point = {d.numbers.at(0), d.numbers.at(1)}; break;
        case Method::PointCenter: e.point = circle(d.refs.at(0)).centre; break;
        case Method::PointIntof: e.point = intof(d); break;
        case Method::LineTwoPoints: {
            const Point2 a = point(d.refs.at(0));
            const Point2 b = point(d.refs.at(1));
            const double len = length(b - a);
            if (len <= kTolerance)
                throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} coincide: no line through them"), d.refs[0], d.refs[1]));
            e.line = lineThrough(a, b);
            break;
        }
        case Method::LineAtAngle: e.line = {point(d.refs.at(0)), direction(d.numbers.at(0))}; break;
        case Method::LineParallel: {
            const Line& l = line(d.refs.at(0));
            const Point2 n = sideNormal(l, d.modifiers.at(0), d.refs[0]);
            e.line = {l.point + d.numbers.at(0) * n, l.dir};
            break;
        }
        case Method::LinePointTangent: e.line = tangentFromPoint(d); break;
        case Method::LineTwoCircles: e.line = tangentToCircles(d); break;
        case Method::CircleCenterRadius: e.circle = {point(d.refs.at(0)), d.numbers.at(0)}; break;
        case Method::CircleThreePoints: e.circle = throughThree(d); break;
        case Method::CircleTwoLines: {
            const double r = d.numbers.at(0);
            const Line a = offset(line(d.refs.at(0)), d.modifiers.at(0), d.refs[0], r);
            const Line b = offset(line(d.refs.at(1)), d.modifiers.at(1), d.refs[1], r);
            e.circle = {intersectLines(a, b, d.refs[0], d.refs[1]), r};
            break;
        }
        case Method::CircleLineCircle: e.circle = tangentLineCircle(d); break;
        case Method::Contour: throw std::logic_error("figure: a contour is not an element");
        }
        return e;
    }

    // The elements evaluated so far are looked up in the evaluation being
    // made (its index), not in a copy of their own.
    explicit Evaluator(const Evaluation& known) : known_(known) {}

private:
    const Element& get(const std::string& n) const
    {
        const Element* e = known_.find(n);
        if (!e) throw std::logic_error("figure: element not evaluated: " + n);
        return *e;
    }
    Point2 point(const std::string& n) const { return get(n).point; }
    const Line& line(const std::string& n) const { return get(n).line; }
    const Circle& circle(const std::string& n) const { return get(n).circle; }

    static Line offset(const Line& l, Modifier m, const std::string& name, double dist)
    {
        return {l.point + dist * sideNormal(l, m, name), l.dir};
    }

    Point2 intof(const Definition& d) const
    {
        const Element& a = get(d.refs.at(0));
        const Element& b = get(d.refs.at(1));
        if (a.kind == Kind::Line && b.kind == Kind::Line) return intersectLines(a.line, b.line, d.refs[0], d.refs[1]);
        std::pair<Point2, Point2> two;
        if (a.kind == Kind::Circle && b.kind == Kind::Circle)
            two = intersectCircles(a.circle, b.circle, d.refs[0], d.refs[1]);
        else if (a.kind == Kind::Line)
            two = intersectLineCircle(a.line, b.circle, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} do not meet"), d.refs[0], d.refs[1]));
        else
            two = intersectLineCircle(b.line, a.circle, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} do not meet"), d.refs[0], d.refs[1]));
        return choose(two.first, two.second, d.modifiers.at(0),
                      fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "intersections of {} and {}"), d.refs[0], d.refs[1]));
    }

    // LINE/P, LEFT|RIGHT, TANTO, C: looking from P to the centre, the tangent
    // touching the circle's left (right) side; its direction from P to the
    // point of contact. The ray to the centre turned by asin(r/D).
    Line tangentFromPoint(const Definition& d) const
    {
        const Point2 p = point(d.refs.at(0));
        const Circle& c = circle(d.refs.at(1));
        const Point2 toC = c.centre - p;
        const double dist = length(toC);
        if (dist < c.radius - kTolerance || dist <= kTolerance)
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is inside {}: no tangent from it"), d.refs[0], d.refs[1]));
        const Point2 u = (1.0 / dist) * toC;
        const double t = std::sqrt(std::max(0.0, dist * dist - c.radius * c.radius));
        const double s = d.modifiers.at(0) == Modifier::Left ? 1.0 : -1.0;
        const double cosA = t / dist;
        const double sinA = c.radius / dist;
        return {p, cosA * u + (s * sinA) * left(u)};
    }

    // LINE/S1, TANTO, C1, S2, TANTO, C2: looking from C1's centre to C2's,
    // the tangent touching C1 on side S1 and C2 on side S2. With m the unit
    // normal from C1's centre to its point of contact, m·u = (r1 ∓ r2)/D
    // (same sides / opposite sides), m's component along u's left normal
    // signed by S1. Directed from C1 towards C2.
    Line tangentToCircles(const Definition& d) const
    {
        const Circle& c1 = circle(d.refs.at(0));
        const Circle& c2 = circle(d.refs.at(1));
        const Point2 between = c2.centre - c1.centre;
        const double dist = length(between);
        if (dist <= kTolerance) throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} are concentric: no common tangent"), d.refs[0], d.refs[1]));
        const bool same = d.modifiers.at(0) == d.modifiers.at(1);
        const double a = (same ? c1.radius - c2.radius : c1.radius + c2.radius) / dist;
        if (std::abs(a) > 1.0 + 1e-12)
            throw Refusal(same ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} lie one inside the other: no tangent on the same side of both"),
                                             d.refs[0], d.refs[1])
                               : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} overlap: no tangent crossing between them"), d.refs[0], d.refs[1]));
        const double b = std::sqrt(std::max(0.0, 1.0 - a * a));
        const double s = d.modifiers[0] == Modifier::Left ? 1.0 : -1.0;
        const Point2 u = (1.0 / dist) * between;
        const Point2 m = a * u + (s * b) * left(u);
        return {c1.centre + c1.radius * m, s * Point2{m.y, -m.x}};
    }

    static Circle throughThreeCheck(Point2 a, Point2 b, Point2 c, const Definition& d)
    {
        const std::string& n0 = d.refs[0];
        const std::string& n1 = d.refs[1];
        const std::string& n2 = d.refs[2];
        if (length(b - a) <= kTolerance) throw Refusal(fmt::format(kCoincide, n0, n1));
        if (length(c - a) <= kTolerance) throw Refusal(fmt::format(kCoincide, n0, n2));
        if (length(c - b) <= kTolerance) throw Refusal(fmt::format(kCoincide, n1, n2));
        const Point2 ab = b - a;
        const Point2 ac = c - a;
        const double det = 2 * cross(ab, ac);
        if (std::abs(det) <= 1e-12 * length(ab) * length(ac))
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}, {} and {} lie on one line: no circle through them"), n0, n1, n2));
        // Centre relative to a: solves 2 ab·o = |ab|², 2 ac·o = |ac|².
        const double ab2 = dot(ab, ab);
        const double ac2 = dot(ac, ac);
        const Point2 o{(ac.y * ab2 - ab.y * ac2) / det, (ab.x * ac2 - ac.x * ab2) / det};
        return {a + o, length(o)};
    }

    Circle throughThree(const Definition& d) const
    {
        return throughThreeCheck(point(d.refs.at(0)), point(d.refs.at(1)), point(d.refs.at(2)), d);
    }

    // CIRCLE/S1, L, S2, OUT|IN, C, RADIUS, r: the centre lies on L's
    // parallel at r on side S1 and on the circle about C's centre of radius
    // rc + r (OUT: touching C from outside) or rc − r (IN: inside C); of the
    // two such centres, the one S2 names.
    Circle tangentLineCircle(const Definition& d) const
    {
        const double r = d.numbers.at(0);
        const Line l = offset(line(d.refs.at(0)), d.modifiers.at(0), d.refs[0], r);
        const Circle& c = circle(d.refs.at(1));
        const bool out = d.modifiers.at(2) == Modifier::Out;
        if (!out && r >= c.radius - kTolerance)
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "radius {} is not smaller than {}'s radius {}: no circle inside it"), num(r), d.refs[1],
                                      num(c.radius)));
        const Circle locus{c.centre, out ? c.radius + r : c.radius - r};
        const auto two = intersectLineCircle(
            l, locus,
            out ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no circle of radius {} on the {} side of {} touches {} from outside (the radius is too small or the side is wrong)"),
                              num(r), keyword(d.modifiers[0]), d.refs[0], d.refs[1])
                : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no circle of radius {} on the {} side of {} touches {} from inside (the radius is too small or the side is wrong)"),
                              num(r), keyword(d.modifiers[0]), d.refs[0], d.refs[1]));
        return {choose(two.first, two.second, d.modifiers.at(1), TAIWA_TRANSLATE_NOOP("taiwa::msg", "centres")), r};
    }

    const Evaluation& known_;
};

bool finite(const Element& e)
{
    const auto ok = [](Point2 v) { return std::isfinite(v.x) && std::isfinite(v.y); };
    switch (e.kind) {
    case Kind::Point: return ok(e.point);
    case Kind::Line: return ok(e.line.point) && ok(e.line.dir);
    case Kind::Circle: return ok(e.circle.centre) && std::isfinite(e.circle.radius);
    case Kind::Contour: return false;
    }
    return false;
}

}  // namespace

Evaluation evaluate(const std::vector<Definition>& definitions)
{
    Evaluation out;
    out.elements.reserve(definitions.size());
    out.elementIndex.reserve(definitions.size());
    Evaluator ev(out);
    std::set<std::string> missing;  // refused, or defined from a refused element
    for (const auto& d : definitions) {
        if (std::any_of(d.refs.begin(), d.refs.end(), [&](const std::string& r) { return missing.count(r) > 0; })) {
            missing.insert(d.name);
            continue;
        }
        if (d.method == Method::Contour) {
            auto c = evaluateContour(d, out);
            if (auto* error = std::get_if<FigureError>(&c)) out.errors.push_back(std::move(*error));
            else {
                out.contourIndex.emplace(std::get<EvaluatedContour>(c).name, out.contours.size());
                out.contours.push_back(std::move(std::get<EvaluatedContour>(c)));
            }
            continue;
        }
        try {
            Element e = ev.element(d);
            if (!finite(e)) throw Refusal(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its coordinates cannot be computed (a degenerate definition)"));
            out.elementIndex.emplace(e.name, out.elements.size());
            out.elements.push_back(std::move(e));
        } catch (const Refusal& r) {  // of the element being evaluated (model/result.h)
            missing.insert(d.name);
            out.errors.push_back(FigureError{d.line, d.column, d.name + ": " + r.message()});
        }
    }
    return out;
}

std::vector<std::string> definedFrom(const std::vector<Definition>& definitions, const std::string& name)
{
    std::set<std::string> changed{name};
    std::vector<std::string> out;
    for (const auto& d : definitions) {
        if (d.name == name) continue;
        if (std::any_of(d.refs.begin(), d.refs.end(), [&](const std::string& r) { return changed.count(r) > 0; })) {
            changed.insert(d.name);
            out.push_back(d.name);
        }
    }
    return out;
}

}  // namespace taiwa::figure
