// One contour written as figure definitions (contour_writer.h): its points
// in the order the contour runs, its circles and lines, the junctions
// (where the two elements cross, which of the crossings the modifier names,
// tangent where an intersection would move too far with the rounding), and
// the check that the written elements still meet where the contour turns.
#include "figure/contour_writer.h"

#include "figure/crossings.h"
#include "figure/figure_eval.h"
#include "model/result.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace taiwa::figure {

namespace {

// v to the nearest multiple of 1/scale (scale a power of ten): the double
// nearest that decimal, which formatNumber writes with no more digits.
double rounded(double v, double scale)
{
    const double r = std::round(v * scale) / scale;
    return r == 0.0 ? 0.0 : r;  // no "-0"
}
Point2 rounded(Point2 p, double scale) { return {rounded(p.x, scale), rounded(p.y, scale)}; }
std::string at(Point2 p) { return fmt::format("({:.3f}, {:.3f})", p.x, p.y); }

// Where two evaluated elements cross, as the contour evaluation finds it
// (figure_contour.cpp; both through crossings.h): one point where they
// touch within figure::kTolerance, two where they cross, none where they
// miss.
std::vector<Point2> crossings(const figure::Element& a, const figure::Element& b)
{
    const bool ac = a.kind == figure::Kind::Circle, bc = b.kind == figure::Kind::Circle;
    if (ac && bc) return circleCrossings(a.circle, b.circle);
    return ac ? lineCircleCrossings(b.line, a.circle) : lineCircleCrossings(a.line, b.circle);
}

// True when the junction of a and b (b starting where a ends) is better
// written as tangent (TANTO) than as an intersection: making it exactly
// tangent moves it by about r·θ, intersecting after rounding by about
// grid/θ (θ the angle between the two at the junction, r the smaller
// radius); tangent where the first is the smaller.
bool tangentJunction(const ContourSegment& a, const ContourSegment& b, double grid)
{
    if (!a.isArc() && !b.isArc()) return false;
    const double r = std::min(a.isArc() ? a.radius() : HUGE_VAL, b.isArc() ? b.radius() : HUGE_VAL);
    const double theta = std::abs(std::asin(std::clamp(cross(a.endDirection(), b.startDirection()), -1.0, 1.0)));
    return theta * theta * r <= grid;
}

class ContourWriter {
public:
    ContourWriter(Namer& names, const Contour& c, double scale) : names_(names), c_(c), scale_(scale) {}

    // The contour's definitions in order: points, circles, lines, CONTOUR.
    std::vector<Definition> build()
    {
        const auto& s = c_.segments;
        const std::size_t n = s.size();
        if (n == 0) throw Refusal(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it has no segments"));
        if (c_.closed && n == 1 && !s[0].isArc())
            throw Refusal(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a closed contour of one line"));
        // Junction k is where segment k starts: from segment k - 1 (closed: the last).
        tangent_.assign(n, false);
        for (std::size_t k = 0; k < n; ++k)
            if (hasJunction(k)) tangent_[k] = tangentJunction(s[(k + n - 1) % n], s[k], 1.0 / scale_);
        linesMeet();

        // Points, in the order the contour runs; circles; lines: each made
        // in its place in `defs_` (a circle's centre and a line's ends are
        // points made before it).
        defs_.reserve(2 * n + 3);  // a closed contour's n points, its n lines or circles and the CONTOUR
        pointNames_.reserve(n + 2);
        centres_.reserve(n);
        if (!c_.closed) start_ = point(s.front().start);
        for (std::size_t k = 0; k < n; ++k) {
            if (s[k].isArc()) {
                centres_.push_back(point(s[k].centre));
                continue;
            }
            centres_.emplace_back();
            // (A line tangent at both ends to the one other segment is
            // drawn from its start: line().)
            if (!tangentAtStart(k) || (n == 2 && tangentAtEnd(k))) point(s[k].start);
            if (!tangentAtEnd(k)) point(s[k].end);
        }
        if (!c_.closed) end_ = point(s.back().end);
        const std::size_t points = defs_.size();
        elements_.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            if (s[k].isArc()) elements_[k] = circle(k);
        for (std::size_t k = 0; k < n; ++k)
            if (!s[k].isArc()) elements_[k] = line(k);
        if (defs_.size() != points + n) throw std::logic_error("dxf figure: a point made after the points");

        std::vector<Definition> out = std::move(defs_);
        Definition k = contour(out);
        out.push_back(std::move(k));
        return out;
    }

private:
    bool hasJunction(std::size_t k) const { return c_.closed ? c_.segments.size() > 1 : k > 0; }
    bool tangentAtStart(std::size_t k) const { return hasJunction(k) && tangent_[k]; }
    bool tangentAtEnd(std::size_t k) const
    {
        const std::size_t n = c_.segments.size();
        return hasJunction((k + 1) % n) && (c_.closed || k + 1 < n) && tangent_[(k + 1) % n];
    }

    std::string point(Point2 p)
    {
        if (!(std::abs(p.x) <= figure::kMaxNumber && std::abs(p.y) <= figure::kMaxNumber))
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it reaches {}, beyond the ±1000000 mm the figure text can write"), at(p)));
        const Point2 q = rounded(p, scale_);
        const auto key = std::make_pair(std::llround(q.x * scale_), std::llround(q.y * scale_));
        if (const auto it = pointNames_.find(key); it != pointNames_.end()) return it->second;
        Definition d;
        d.name = names_.next('P');
        d.method = Method::PointXY;
        d.numbers = {q.x, q.y};
        pointNames_.emplace(key, d.name);
        std::string name = d.name;
        defs_.push_back(std::move(d));
        return name;
    }
    std::string pointAt(Point2 p) const
    {
        const Point2 q = rounded(p, scale_);
        return pointNames_.at(std::make_pair(std::llround(q.x * scale_), std::llround(q.y * scale_)));
    }

    // CIRCLE/CENTER, P, RADIUS, r. Where neither end is tangent the radius
    // is the mean distance of the rounded ends from the rounded centre, so
    // that the intersections fall on the rounded ends; else the arc's own.
    std::string circle(std::size_t k)
    {
        const ContourSegment& s = c_.segments[k];
        const bool whole = c_.closed && c_.segments.size() == 1;
        double r = s.radius();
        if (!whole && !tangentAtStart(k) && !tangentAtEnd(k)) {
            const Point2 c = rounded(s.centre, scale_);
            r = 0.5 * (distance(c, rounded(s.start, scale_)) + distance(c, rounded(s.end, scale_)));
        }
        r = rounded(r, scale_);
        if (!(r > 0.0))
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the arc around {} has a radius of {:g} mm, which rounds to nothing"),
                                      at(s.centre), s.radius()));
        if (r > figure::kMaxNumber) throw Refusal(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an arc's radius is beyond the 1000000 mm the figure text can write"));
        Definition d;
        d.name = names_.next('C');
        d.method = Method::CircleCenterRadius;
        d.refs = {centres_[k]};
        d.numbers = {r};
        std::string name = d.name;
        defs_.push_back(std::move(d));
        return name;
    }

    // LINE/P1, P2; tangent at one end LINE/P, LEFT|RIGHT, TANTO, C from the
    // other end; at both LINE/LEFT|RIGHT, TANTO, C1, LEFT|RIGHT, TANTO, C2.
    std::string line(std::size_t k)
    {
        const auto& segs = c_.segments;
        const std::size_t n = segs.size();
        const ContourSegment& s = segs[k];
        const std::size_t before = (k + n - 1) % n, after = (k + 1) % n;
        const auto side = [](Point2 from, Point2 towards, Point2 p) {
            return cross(towards - from, p - from) > 0 ? Modifier::Left : Modifier::Right;
        };
        Definition d;
        d.name = names_.next('L');
        const bool atStart = tangentAtStart(k), atEnd = tangentAtEnd(k);
        if (atStart && atEnd && elements_[before] != elements_[after]) {
            const Point2 c1 = segs[before].centre, c2 = segs[after].centre;
            d.method = Method::LineTwoCircles;
            d.refs = {elements_[before], elements_[after]};
            d.modifiers = {side(c1, c2, s.start), side(c2, c2 + (c2 - c1), s.end)};
        } else if (atEnd) {
            d.method = Method::LinePointTangent;
            d.refs = {point(s.start), elements_[after]};
            d.modifiers = {side(s.start, segs[after].centre, s.end)};
        } else if (atStart) {
            d.method = Method::LinePointTangent;
            d.refs = {point(s.end), elements_[before]};
            d.modifiers = {side(s.end, segs[before].centre, s.start)};
        } else {
            d.method = Method::LineTwoPoints;
            d.refs = {pointAt(s.start), pointAt(s.end)};
        }
        std::string name = d.name;
        defs_.push_back(std::move(d));
        return name;
    }

    // Two lines through their rounded points that no longer cross: the
    // evaluation would refuse the CONTOUR (figure_contour.cpp), so a
    // polygon of many short sides (a circle of 200,000 LINEs) is refused
    // at once, before any statement is made.
    void linesMeet() const
    {
        const auto& segs = c_.segments;
        const std::size_t n = segs.size();
        const auto through = [&](std::size_t k) { return lineThrough(rounded(segs[k].start, scale_), rounded(segs[k].end, scale_)); };
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t before = (k + n - 1) % n;
            if (!hasJunction(k) || segs[before].isArc() || segs[k].isArc()) continue;
            if (tangentAtStart(before) || tangentAtEnd(k)) continue;  // a line tangent to a circle: not through two points
            if (!lineCrossing(through(before), through(k)))
                throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "two of its lines no longer meet at {} once written to {:g} mm"),
                                          at(segs[k].start), 1.0 / scale_));
        }
    }

    Definition contour(const std::vector<Definition>& elements)
    {
        const auto& segs = c_.segments;
        const std::size_t n = segs.size();
        // The junction modifiers need the evaluated elements only where a
        // circle meets: a contour of lines alone is not evaluated here (the
        // attempt reads its whole text back and evaluates it all the same).
        arcs_ = std::any_of(segs.begin(), segs.end(), [](const ContourSegment& s) { return s.isArc(); });
        const figure::Evaluation ev = arcs_ ? figure::evaluate(elements) : figure::Evaluation{};
        if (arcs_ && !ev.ok()) throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its elements cannot be evaluated: {}"), ev.errors.front().message));
        Definition d;
        d.name = names_.next('K');
        d.method = Method::Contour;
        d.contour.start = start_;
        d.contour.end = end_;
        if (!start_.empty()) d.refs.push_back(start_);
        for (std::size_t k = 0; k < n; ++k) {
            figure::ContourStep step;
            step.element = elements_[k];
            if (segs[k].isArc())
                step.turn = segs[k].kind == ContourSegment::Kind::ArcCCW ? figure::Turn::CounterClockwise
                                                                          : figure::Turn::Clockwise;
            if (hasJunction(k)) step.junction = modifier(ev, elements_[(k + n - 1) % n], elements_[k], segs[k].start);
            d.contour.steps.push_back(step);
            d.refs.push_back(step.element);
        }
        if (!end_.empty()) d.refs.push_back(end_);
        return d;
    }

    // The modifier that picks `junction` of the two crossings of a and b;
    // none where they cross once (two lines, a touch).
    std::optional<Modifier> modifier(const figure::Evaluation& ev, const std::string& a, const std::string& b,
                                     Point2 junction) const
    {
        if (!arcs_) return std::nullopt;  // two lines cross once
        const figure::Element* ea = ev.find(a);
        const figure::Element* eb = ev.find(b);
        if (!ea || !eb) throw std::logic_error("dxf figure: element not evaluated");
        if (ea->kind != figure::Kind::Circle && eb->kind != figure::Kind::Circle) return std::nullopt;
        const auto two = crossings(*ea, *eb);
        if (two.empty())
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its elements {} and {} no longer meet at {} once written to {:g} mm"), a, b,
                                      at(junction), 1.0 / scale_));
        if (two.size() == 1) return std::nullopt;
        const bool first = distance(two[0], junction) <= distance(two[1], junction);
        const Point2 mine = first ? two[0] : two[1], other = first ? two[1] : two[0];
        const double dx = std::abs(mine.x - other.x), dy = std::abs(mine.y - other.y);
        if (std::max(dx, dy) <= figure::kTolerance)
            throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} and {} cross twice at {} within {:g} mm in x and in y: XLARGE, XSMALL, YLARGE and YSMALL cannot choose between the two"),
                                      a, b, at(junction), figure::kTolerance));
        if (dx >= dy) return mine.x > other.x ? Modifier::XLarge : Modifier::XSmall;
        return mine.y > other.y ? Modifier::YLarge : Modifier::YSmall;
    }

    Namer& names_;
    const Contour& c_;
    double scale_;  // numbers to the nearest 1/scale_ mm
    std::vector<bool> tangent_;
    struct KeyHash {
        std::size_t operator()(const std::pair<long long, long long>& k) const
        {
            return std::hash<long long>()(k.first) * 1000003u ^ std::hash<long long>()(k.second);
        }
    };
    std::unordered_map<std::pair<long long, long long>, std::string, KeyHash> pointNames_;
    std::vector<Definition> defs_;  // points, circles, lines, in this order
    std::vector<std::string> centres_;   // per segment: an arc's centre point
    std::vector<std::string> elements_;  // per segment: its line or circle
    std::string start_, end_;            // an open contour's points
    bool arcs_ = false;                  // whether any segment is an arc
};

}  // namespace

std::vector<Definition> contourDefinitions(Namer& names, const Contour& c, double scale)
{
    return ContourWriter(names, c, scale).build();
}

}  // namespace taiwa::figure
