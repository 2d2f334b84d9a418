// Figure contours (figure_contour.h): the junctions of consecutive elements
// (modifiers choosing where two exist), the pieces of each element between
// its junctions run in tool-motion order, the ROUND fillets and CHAMF lines
// cut into the corners, and the corner revision of the text.
#include "figure/figure_contour.h"

#include "figure/crossings.h"
#include "figure/figure_eval.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace taiwa::figure {

const ContourCorner* EvaluatedContour::cornerAt(int segment) const
{
    for (const auto& c : corners)
        if (c.segment == segment) return &c;
    return nullptr;
}

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kOnElement = 1e-6;  // mm: an open contour's point on its element

Point2 left(Point2 a) { return {-a.y, a.x}; }
Point2 unit(Point2 v) { return (1.0 / length(v)) * v; }
double angleOf(Point2 v) { return std::atan2(v.y, v.x); }
Point2 onCircle(Point2 c, double r, double a) { return {c.x + r * std::cos(a), c.y + r * std::sin(a)}; }

// The angle from `from` to `to` turning counter-clockwise (or clockwise), in [0, 2π).
double turned(double from, double to, bool ccw)
{
    double d = std::fmod(ccw ? to - from : from - to, kTwoPi);
    if (d < 0.0) d += kTwoPi;
    return d;
}

// A length for a message: to the micrometre.
std::string mm(double v) { return formatNumber(std::round(v * 1000.0) / 1000.0); }

// An element as the chain runs it: a line (its own direction does not
// matter) or a circle turning one way.
struct Run {
    std::string name;
    Place at;
    bool circle = false;
    Line line;
    Circle c;
    bool ccw = true;
};

// Where a and b cross: none (parallel, concentric, apart), one (two lines, a
// touch) or two.
std::vector<Point2> crossings(const Run& a, const Run& b)
{
    if (!a.circle && !b.circle) {
        const auto p = lineCrossing(a.line, b.line);
        return p ? std::vector<Point2>{*p} : std::vector<Point2>{};
    }
    if (a.circle && b.circle) return circleCrossings(a.c, b.c);
    return a.circle ? lineCircleCrossings(b.line, a.c) : lineCircleCrossings(a.line, b.c);
}

// The junction of a with the next element b, the modifier written before b
// choosing where they meet twice.
Point2 junction(const Run& a, const Run& b, std::optional<Modifier> m)
{
    const auto pts = crossings(a, b);
    if (pts.empty()) {
        if (!a.circle && !b.circle) throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} are parallel: they do not meet"), a.name, b.name), placeOf(b.at));
        if (a.circle && b.circle && distance(a.c.centre, b.c.centre) <= kTolerance)
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} are concentric: they do not meet"), a.name, b.name), placeOf(b.at));
        throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} do not meet"), a.name, b.name), placeOf(b.at));
    }
    if (pts.size() == 1) return pts[0];
    if (!m)
        throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before {} to choose"),
                                  a.name, b.name, b.name), placeOf(b.at));
    const bool byX = *m == Modifier::XLarge || *m == Modifier::XSmall;
    const bool large = *m == Modifier::XLarge || *m == Modifier::YLarge;
    const double k0 = byX ? pts[0].x : pts[0].y;
    const double k1 = byX ? pts[1].x : pts[1].y;
    if (std::abs(k0 - k1) <= kTolerance)
        throw Refusal(byX ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot choose between the two junctions of {} and {}: both have the same x; use YLARGE or YSMALL"),
                                        keyword(*m), a.name, b.name)
                          : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} cannot choose between the two junctions of {} and {}: both have the same y; use XLARGE or XSMALL"),
                                        keyword(*m), a.name, b.name), placeOf(b.at));
    return ((k0 > k1) == large) ? pts[0] : pts[1];
}

// The nearest point of the element to p.
Point2 foot(const Run& r, Point2 p)
{
    if (!r.circle) return r.line.point + dot(p - r.line.point, r.line.dir) * r.line.dir;
    return r.c.centre + r.c.radius * unit(p - r.c.centre);
}

// The piece of an element between its junctions, less what corners cut off.
struct Piece {
    const Run* run = nullptr;
    Point2 a, b;       // from junction to junction
    double len = 0;    // of a→b
    Point2 start, end; // after corners
    double cutStart = 0, cutEnd = 0;
};

Point2 directionAt(const Piece& p, Point2 at)
{
    if (!p.run->circle) return unit(p.b - p.a);
    const Point2 radial = left(unit(at - p.run->c.centre));
    return p.run->ccw ? radial : -1.0 * radial;
}

// The length along an arc piece from u to v (the way it runs); a length a
// hair short of the whole circle is a point behind: 0.
double along(const Piece& p, Point2 u, Point2 v)
{
    const Point2 c = p.run->c.centre;
    const double s = p.run->c.radius * turned(angleOf(u - c), angleOf(v - c), p.run->ccw);
    return p.run->c.radius * kTwoPi - s <= kTolerance ? 0.0 : s;
}

// The point `dist` along the piece from `from`, forwards (sign 1) or backwards (-1).
Point2 walk(const Piece& p, Point2 from, double dist, double sign)
{
    if (!p.run->circle) return from + (sign * dist) * unit(p.b - p.a);
    const Circle& c = p.run->c;
    return onCircle(c.centre, c.radius, angleOf(from - c.centre) + sign * (p.run->ccw ? 1 : -1) * dist / c.radius);
}

// The element moved `dist` to the left (side 1) or right (-1) of the way it
// runs (`dir` at `at`): a line's parallel, a circle's concentric circle.
Run offset(const Run& r, double side, double dist, Point2 at, Point2 dir)
{
    Run o = r;
    if (!r.circle) o.line.point = at + (side * dist) * left(dir);
    else o.c.radius = r.c.radius - side * dist * (r.ccw ? 1.0 : -1.0);  // a CCW circle's left is inwards
    return o;
}

class Builder {
public:
    Builder(const Definition& d, const Evaluation& before) : d_(d), c_(d.contour)
    {
        for (const auto& s : c_.steps) {
            const Element* e = before.find(s.element);
            if (!e || (e->kind != Kind::Line && e->kind != Kind::Circle))
                throw std::logic_error("figure: contour element not evaluated: " + s.element);
            Run r{s.element, s.at, e->kind == Kind::Circle, e->line, e->circle, s.turn != Turn::Clockwise};
            runs_.push_back(r);
        }
        if (runs_.empty()) throw std::logic_error("figure: a contour without elements");
        if (!c_.closed()) {
            start_ = pointOn(before, c_.start, c_.startAt, runs_.front(), TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not on {}: an open contour starts on its first element"));
            end_ = pointOn(before, c_.end, c_.endAt, runs_.back(), TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is not on {}: an open contour ends on its last element"));
        }
    }

    EvaluatedContour build()
    {
        EvaluatedContour out;
        out.name = d_.name;
        out.contour.closed = c_.closed();
        const std::size_t n = runs_.size();
        if (c_.closed() && n == 1) {  // a full circle, from its point at angle 0
            const Circle& c = runs_[0].c;
            const Point2 p = onCircle(c.centre, c.radius, 0);
            out.contour.segments.push_back(ContourSegment::arc(p, p, c.centre, runs_[0].ccw));
            out.elements.push_back(runs_[0].name);
            return out;
        }
        // Junction k is where run k starts: k - 1 (the last, closed) meets k.
        std::vector<Point2> j(n + 1);
        for (std::size_t k = 0; k < n; ++k) {
            if (k == 0 && !c_.closed()) j[0] = start_;
            else j[k] = junction(runs_[(k + n - 1) % n], runs_[k], c_.steps[k].junction);
        }
        j[n] = c_.closed() ? j[0] : end_;
        for (std::size_t k = 0; k < n; ++k) pieces_.push_back(piece(k, j[k], j[k + 1]));
        // Corners in the order written; a closed contour's last is between the last and the first.
        const std::size_t corners = c_.closed() ? n : n - 1;
        std::vector<ContourSegment> cut(n);
        for (std::size_t k = 0; k < corners; ++k)
            if (c_.steps[k].corner != CornerKind::None) cut[k] = corner(k, (k + 1) % n);
        for (std::size_t k = 0; k < n; ++k) {
            const Piece& p = pieces_[k];
            if (p.len - p.cutStart - p.cutEnd > kTolerance) {
                out.contour.segments.push_back(p.run->circle ? ContourSegment::arc(p.start, p.end, p.run->c.centre,
                                                                                   p.run->ccw)
                                                             : ContourSegment::line(p.start, p.end));
                out.elements.push_back(p.run->name);
            }
            const ContourStep& s = c_.steps[k];
            if (k < corners && s.corner != CornerKind::None) {
                ContourCorner cc;
                cc.kind = s.corner == CornerKind::Round ? ContourCorner::Kind::Round : ContourCorner::Kind::Chamfer;
                cc.value = s.value;
                cc.segment = static_cast<int>(out.contour.segments.size());
                cc.line = s.valueAt.line;
                cc.column = s.valueAt.column;
                cc.between[0] = s.element;
                cc.between[1] = c_.steps[(k + 1) % n].element;
                out.corners.push_back(cc);
                out.contour.segments.push_back(cut[k]);
                out.elements.emplace_back();
            }
        }
        for (const auto& s : out.contour.segments)
            for (const Point2 q : {s.start, s.end, s.centre})
                if (!std::isfinite(q.x) || !std::isfinite(q.y))
                    throw Refusal(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its coordinates cannot be computed (a degenerate definition)"), {});
        return out;
    }

private:
    // An open contour's start or end point, on its element within kOnElement.
    static Point2 pointOn(const Evaluation& ev, const std::string& name, const Place& at, const Run& r,
                          const char* where)
    {
        const Element* e = ev.find(name);
        if (!e || e->kind != Kind::Point) throw std::logic_error("figure: contour point not evaluated: " + name);
        const Point2 p = e->point;
        const Point2 f = foot(r, p);
        if (!(distance(p, f) <= kOnElement))
            throw Refusal(fmt::format(fmt::runtime(where), name, r.name), placeOf(at));
        return f;
    }

    std::string before(std::size_t k) const
    {
        if (k == 0 && !c_.closed()) return c_.start;
        return runs_[(k + runs_.size() - 1) % runs_.size()].name;
    }
    std::string after(std::size_t k) const
    {
        if (k + 1 == runs_.size() && !c_.closed()) return c_.end;
        return runs_[(k + 1) % runs_.size()].name;
    }

    Piece piece(std::size_t k, Point2 a, Point2 b) const
    {
        Piece p;
        p.run = &runs_[k];
        p.a = p.start = a;
        p.b = p.end = b;
        if (!p.run->circle) {
            p.len = distance(a, b);
            if (p.len <= kTolerance)
                throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is of zero length between {} and {}"), p.run->name, before(k), after(k)), placeOf(p.run->at));
        } else if (distance(a, b) <= kTolerance) {  // from a point round to the same point: the whole circle
            p.b = p.end = a;
            p.len = kTwoPi * p.run->c.radius;
        } else {
            p.len = along(p, a, b);
        }
        return p;
    }

    // The fillet or chamfer between piece i and the next piece k; trims both.
    ContourSegment corner(std::size_t i, std::size_t k)
    {
        Piece& p1 = pieces_[i];
        Piece& p2 = pieces_[k];
        const ContourStep& s = c_.steps[i];
        const bool round = s.corner == CornerKind::Round;
        const std::string what =
            round ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "ROUND {} between {} and {}"), formatNumber(s.value), p1.run->name, p2.run->name)
                  : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "CHAMF {} between {} and {}"), formatNumber(s.value), p1.run->name, p2.run->name);
        const Point2 at = p1.b;
        const Point2 d1 = directionAt(p1, at), d2 = directionAt(p2, at);
        const double turn = cross(d1, d2);
        if (std::abs(turn) <= 1e-9)
            throw Refusal(dot(d1, d2) > 0
                              ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: they meet tangentially, there is no corner"), what)
                              : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {} turns back along {}, there is no corner"), what, p2.run->name,
                                            p1.run->name), placeOf(s.valueAt));
        const double side = turn > 0 ? 1.0 : -1.0;
        Point2 t1, t2, centre;
        double back = s.value, fwd = s.value;
        if (round) {
            const Run o1 = offset(*p1.run, side, s.value, at, d1), o2 = offset(*p2.run, side, s.value, at, d2);
            for (const Run* r : {p1.run, p2.run})
                if (r->circle && (r == p1.run ? o1 : o2).c.radius <= kTolerance)
                    throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} does not fit: it is not smaller than {}'s radius {}"), what, r->name,
                                              formatNumber(r->c.radius)), placeOf(s.valueAt));
            double best = HUGE_VAL;
            for (const Point2 c : crossings(o1, o2)) {
                const Point2 a = foot(*p1.run, c), b = foot(*p2.run, c);
                const double ba = p1.run->circle ? along(p1, a, at) : dot(at - a, d1);
                const double fb = p2.run->circle ? along(p2, at, b) : dot(b - at, d2);
                if (ba < -kTolerance || fb < -kTolerance || ba + fb >= best) continue;
                best = ba + fb;
                back = std::max(0.0, ba);
                fwd = std::max(0.0, fb);
                t1 = a;
                t2 = b;
                centre = c;
            }
            if (best == HUGE_VAL)
                throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} does not fit: no circle of radius {} touches both in the corner"), what,
                                          formatNumber(s.value)), placeOf(s.valueAt));
        } else {
            t1 = walk(p1, at, s.value, -1);
            t2 = walk(p2, at, s.value, 1);
        }
        const double room1 = p1.len - p1.cutStart, room2 = p2.len - p2.cutEnd;
        const bool openStart = i == 0 && !c_.closed(), openEnd = k + 1 == runs_.size() && !c_.closed();
        if (back > room1 + kTolerance)
            throw Refusal(openStart ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} does not fit: {} is {} mm long from the start {}"), what,
                                                  p1.run->name, mm(room1), c_.start)
                                    : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} does not fit: {} is {} mm long from the previous corner"), what,
                                                  p1.run->name, mm(room1)), placeOf(s.valueAt));
        if (fwd > room2 + kTolerance)
            throw Refusal(openEnd ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} does not fit: {} is {} mm long to the end {}"), what,
                                                p2.run->name, mm(room2), c_.end)
                                  : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} does not fit: {} is {} mm long to the next corner"), what,
                                                p2.run->name, mm(room2)), placeOf(s.valueAt));
        p1.end = t1;
        p1.cutEnd = back;
        p2.start = t2;
        p2.cutStart = fwd;
        return round ? ContourSegment::arc(t1, t2, centre, side > 0) : ContourSegment::line(t1, t2);
    }

    const Definition& d_;
    const ContourText& c_;
    std::vector<Run> runs_;
    std::vector<Piece> pieces_;
    Point2 start_, end_;
};

}  // namespace

std::variant<EvaluatedContour, FigureError> evaluateContour(const Definition& d, const Evaluation& before)
{
    try {
        return Builder(d, before).build();
    } catch (const Refusal& r) {  // placed at the item it concerns, else at the contour
        const bool placed = r.place().line > 0;
        return FigureError{placed ? r.place().line : d.line, placed ? r.place().column : d.column, d.name + ": " + r.message()};
    }
}

std::optional<std::string> reviseCorner(std::string_view text, const std::string& contour, int cornerIndex,
                                        double newValue)
{
    if (!(newValue > 0) || !(newValue <= kMaxNumber) || cornerIndex < 0) return std::nullopt;
    const ParseResult p = parseFigure(text);
    if (!p.ok()) return std::nullopt;
    const Place* at = nullptr;
    for (const auto& d : p.definitions) {
        if (d.method != Method::Contour || d.name != contour) continue;
        int k = 0;
        for (const auto& s : d.contour.steps)
            if (s.corner != CornerKind::None && k++ == cornerIndex) at = &s.valueAt;
    }
    if (!at) return std::nullopt;
    std::size_t offset = 0;  // of the value's line
    for (int line = 1; line < at->line; ++line) offset = text.find('\n', offset) + 1;
    offset += static_cast<std::size_t>(at->column - 1);
    std::string out(text);
    out.replace(offset, static_cast<std::size_t>(at->length), formatNumber(newValue));
    return out;
}

}  // namespace taiwa::figure
