// Contours to figure elements (job/dxf_figure.h): the merging of collinear
// lines and of arcs on one circle, the points, circles and lines of each
// contour (tangent lines as TANTO, so that a tangent junction stays one
// point whatever the rounding), the modifiers that choose each junction, and
// the check that reads every contour's text back.
#include "job/dxf_figure.h"

#include "model/translate_noop.h"

#include "figure/figure_eval.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <unordered_set>
#include <utility>
#include <vector>

namespace taiwa {

namespace {

using figure::Definition;
using figure::Method;
using figure::Modifier;

constexpr double kMerge = 1e-7;  // mm: collinear lines, arcs on one circle
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// v to the nearest multiple of 1/scale (scale a power of ten): the double
// nearest that decimal, which formatNumber writes with no more digits.
double rounded(double v, double scale)
{
    const double r = std::round(v * scale) / scale;
    return r == 0.0 ? 0.0 : r;  // no "-0"
}
Point2 rounded(Point2 p, double scale) { return {rounded(p.x, scale), rounded(p.y, scale)}; }
std::string at(Point2 p) { return fmt::format("({:.3f}, {:.3f})", p.x, p.y); }
char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
std::string upper(std::string s)
{
    for (char& c : s) c = upper(c);
    return s;
}

// ------------------------------------------------------------ merging

bool sameCircle(const ContourSegment& a, const ContourSegment& b)
{
    return a.isArc() && a.kind == b.kind && distance(a.centre, b.centre) <= kMerge &&
           std::abs(a.radius() - b.radius()) <= kMerge && std::abs(a.sweep()) + std::abs(b.sweep()) <= kTwoPi + 1e-12;
}

bool collinear(const ContourSegment& a, const ContourSegment& b)
{
    if (a.isArc() || b.isArc()) return false;
    const Point2 chord = b.end - a.start;
    const double len = length(chord);
    if (len <= kMerge || dot(a.end - a.start, b.end - b.start) <= 0.0) return false;
    return std::abs(cross(chord, a.end - a.start)) / len <= kMerge;
}

std::optional<ContourSegment> joined(const ContourSegment& a, const ContourSegment& b)
{
    if (collinear(a, b)) return ContourSegment::line(a.start, b.end);
    if (!sameCircle(a, b)) return std::nullopt;
    ContourSegment s = ContourSegment::arc(a.start, b.end, a.centre, a.kind == ContourSegment::Kind::ArcCCW);
    if (distance(s.start, s.end) <= 1e-9) s.end = s.start;  // round to where it started: the whole circle
    return s;
}

// ------------------------------------------------------------ naming

class Namer {
public:
    explicit Namer(const FigureNaming& n) : prefix_(upper(n.prefix))
    {
        const bool ok = prefix_.empty() ||
                        (isLetter(prefix_[0]) && std::all_of(prefix_.begin(), prefix_.end(), [](char c) {
                             return isLetter(c) || isDigit(c);
                         }));
        if (!ok) throw std::logic_error("figure names: the prefix '" + n.prefix + "' is not letters and digits");
        for (const auto& t : n.taken) taken_.insert(upper(t));
    }
    std::string next(char kind)
    {
        for (;;) {
            std::string name = prefix_ + kind + std::to_string(++count_[kind]);
            if (taken_.insert(name).second) {
                added_.push_back(name);
                return name;
            }
        }
    }

    // The names given since the last mark, to be taken back or given again:
    // a contour is written up to four times (more decimals each time) and
    // only one of its attempts keeps its names. Taking back costs what the
    // attempt added, never a copy of every name so far (which made many
    // contours quadratic).
    struct Given {
        std::vector<std::string> names;
        std::map<char, int> count;
    };
    void mark() { added_.clear(), countAtMark_ = count_; }
    Given takeBack()
    {
        Given g{std::move(added_), count_};
        for (const auto& name : g.names) taken_.erase(name);
        added_.clear();
        count_ = countAtMark_;
        return g;
    }
    void giveAgain(const Given& g)
    {
        for (const auto& name : g.names) taken_.insert(name);
        count_ = g.count;
    }

private:
    std::string prefix_;
    std::unordered_set<std::string> taken_;
    std::vector<std::string> added_;
    std::map<char, int> count_, countAtMark_;
};

// ------------------------------------------------------------ junctions

// Where two evaluated elements cross, as the contour evaluation finds it
// (core/figure/figure_contour.cpp): one point where they touch within
// figure::kTolerance, two where they cross, none where they miss.
std::vector<Point2> crossings(const figure::Element& a, const figure::Element& b)
{
    const double tol = figure::kTolerance;
    const bool ac = a.kind == figure::Kind::Circle, bc = b.kind == figure::Kind::Circle;
    const auto left = [](Point2 v) { return Point2{-v.y, v.x}; };
    if (ac && bc) {
        const Point2 d = b.circle.centre - a.circle.centre;
        const double dist = length(d), ra = a.circle.radius, rb = b.circle.radius;
        if (dist <= tol || dist > ra + rb + tol || dist < std::abs(ra - rb) - tol) return {};
        const Point2 e = (1.0 / dist) * d;
        const double along = std::clamp((dist * dist + ra * ra - rb * rb) / (2 * dist), -ra, ra);
        const Point2 base = a.circle.centre + along * e;
        if (std::abs(dist - (ra + rb)) <= tol || std::abs(dist - std::abs(ra - rb)) <= tol) return {base};
        const double h = std::sqrt(std::max(0.0, ra * ra - along * along));
        return {base + h * left(e), base - h * left(e)};
    }
    const figure::Element& l = ac ? b : a;
    const figure::Element& c = ac ? a : b;
    const Point2 foot = l.line.point + dot(c.circle.centre - l.line.point, l.line.dir) * l.line.dir;
    const double h = length(c.circle.centre - foot);
    if (h > c.circle.radius + tol) return {};
    if (std::abs(h - c.circle.radius) <= tol) return {foot};
    const double half = std::sqrt(c.circle.radius * c.circle.radius - h * h);
    return {foot + half * l.line.dir, foot - half * l.line.dir};
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

// ------------------------------------------------------------ one contour

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

        // Points, in the order the contour runs; circles; lines.
        if (!c_.closed) start_ = point(s.front().start);
        for (std::size_t k = 0; k < n; ++k) {
            if (s[k].isArc()) {
                centres_.push_back(point(s[k].centre));
                continue;
            }
            centres_.emplace_back();
            if (!tangentAtStart(k)) point(s[k].start);
            if (!tangentAtEnd(k)) point(s[k].end);
        }
        if (!c_.closed) end_ = point(s.back().end);
        elements_.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            if (s[k].isArc()) elements_[k] = circle(k);
        for (std::size_t k = 0; k < n; ++k)
            if (!s[k].isArc()) elements_[k] = line(k);

        std::vector<Definition> out = std::move(points_);
        out.reserve(out.size() + circles_.size() + lines_.size() + 1);
        out.insert(out.end(), std::make_move_iterator(circles_.begin()), std::make_move_iterator(circles_.end()));
        out.insert(out.end(), std::make_move_iterator(lines_.begin()), std::make_move_iterator(lines_.end()));
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
        points_.push_back(std::move(d));
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
        circles_.push_back(std::move(d));
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
        lines_.push_back(std::move(d));
        return name;
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
    std::map<std::pair<long long, long long>, std::string> pointNames_;
    std::vector<Definition> points_, circles_, lines_;
    std::vector<std::string> centres_;   // per segment: an arc's centre point
    std::vector<std::string> elements_;  // per segment: its line or circle
    std::string start_, end_;            // an open contour's points
    bool arcs_ = false;                  // whether any segment is an arc
};

// The largest distance of `got`'s ends and centres from `want`'s, segment by
// segment; infinite when the segments differ in number or kind.
double deviation(const Contour& got, const Contour& want)
{
    if (got.closed != want.closed || got.segments.size() != want.segments.size())
        return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    for (std::size_t i = 0; i < got.segments.size(); ++i) {
        const ContourSegment &g = got.segments[i], &w = want.segments[i];
        if (g.kind != w.kind) return std::numeric_limits<double>::infinity();
        worst = std::max({worst, distance(g.start, w.start), distance(g.end, w.end)});
        if (g.isArc()) worst = std::max(worst, distance(g.centre, w.centre));
    }
    return worst;
}

std::string describe(const Contour& c)
{
    int lines = 0, arcs = 0;
    for (const auto& s : c.segments) ++(s.isArc() ? arcs : lines);
    const auto count = [](int k, const char* one, const char* many) {
        return std::to_string(k) + " " + (k == 1 ? one : many);
    };
    if (c.closed && c.segments.size() == 1 && arcs == 1) return "closed, a full circle";
    return std::string(c.closed ? "closed, " : "open, ") + count(lines, "line", "lines") + ", " +
           count(arcs, "arc", "arcs");
}

}  // namespace

std::set<std::string> figureNames(std::string_view text)
{
    std::set<std::string> out;
    std::size_t i = 0;
    while (i < text.size()) {
        const std::size_t eol = std::min(text.find('\n', i), text.size());
        std::size_t j = i;
        while (j < eol && (text[j] == ' ' || text[j] == '\t')) ++j;
        std::string name;
        if (j < eol && isLetter(text[j]))
            while (j < eol && (isLetter(text[j]) || isDigit(text[j]))) name += upper(text[j++]);
        while (j < eol && (text[j] == ' ' || text[j] == '\t')) ++j;
        if (!name.empty() && j < eol && text[j] == '=') out.insert(name);
        i = eol + 1;
    }
    return out;
}

Contour figureReady(const Contour& c)
{
    const Contour in = withoutDegenerateSegments(c);
    Contour out;
    out.closed = in.closed;
    for (const auto& s : in.segments) {
        if (!out.segments.empty())
            if (const auto j = joined(out.segments.back(), s)) {
                out.segments.back() = *j;
                continue;
            }
        out.segments.push_back(s);
    }
    if (out.closed && out.segments.size() > 1)
        if (const auto j = joined(out.segments.back(), out.segments.front())) {
            out.segments.front() = *j;
            out.segments.pop_back();
        }
    if (out.closed && out.segments.size() == 1 && out.segments[0].isArc()) {
        ContourSegment& s = out.segments[0];
        s.start = s.end = Point2{s.centre.x + s.radius(), s.centre.y};
    }
    return out;
}

namespace {

// One contour written with its numbers to the nearest 1/scale mm and read
// back: its definitions and how far their contour comes back from `c`.
struct Attempt {
    std::vector<Definition> definitions;
    std::string text;
    double deviation = 0;
    double scale = 0;
};

Attempt attempt(Namer& names, const Contour& c, double scale)
{
    Attempt a;
    a.scale = scale;
    a.definitions = ContourWriter(names, c, scale).build();
    a.text = figure::writeFigure(a.definitions);
    // Read back what was written and evaluate it, as the job will.
    const figure::ParseResult read = figure::parseFigure(a.text);
    if (!read.ok()) throw std::logic_error("dxf figure: written text refused: " + read.error->text());
    const figure::Evaluation ev = figure::evaluate(read.definitions);
    if (!ev.ok()) throw Refusal(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its text is refused: {}"), ev.errors.front().message));
    a.deviation = deviation(ev.contours.at(0).contour, c);
    return a;
}

}  // namespace

FigureFromContours figureFromContours(const std::vector<Contour>& contours, const FigureNaming& naming)
{
    FigureFromContours out;
    Namer names(naming);
    int number = 0;
    for (const Contour& given : contours) {
        ++number;
        const Contour c = figureReady(given);
        names.mark();
        // To 1e-6 mm; where a junction amplifies the rounding beyond
        // kFigureRoundTrip, the contour's numbers get more decimals.
        std::optional<Attempt> best;
        Namer::Given bestNames;
        std::string why;  // why it is not written to 1e-6 mm
        for (const double scale : {1e6, 1e7, 1e8, 1e9}) {
            try {
                Attempt a = attempt(names, c, scale);
                if (why.empty() && a.deviation > kFigureRoundTrip)
                    why = std::isinf(a.deviation) ? std::string(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its text gives back other segments"))
                                                  : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it comes back {:.7f} mm from the drawing"), a.deviation);
                const bool better = !best || a.deviation < best->deviation;
                Namer::Given taken = names.takeBack();
                if (better) best = std::move(a), bestNames = std::move(taken);
                if (best->deviation <= kFigureRoundTrip) break;
            } catch (const Refusal& r) {  // a contour that cannot be written; caught per contour
                names.takeBack();
                if (why.empty()) why = r.message();
            }
        }
        if (!best || !(best->deviation <= kFigureUsable)) {
            out.refusals.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "contour {} is left out: {}"), number, why));
            out.text += fmt::format("$$ contour {} ({}) left out: {}\n", number, describe(c), why);
            out.names.emplace_back();
            out.deviations.push_back(0.0);
            continue;
        }
        names.giveAgain(bestNames);
        const std::string name = best->definitions.back().name;
        if (best->deviation > kFigureRoundTrip)
            out.notes.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "contour {} ({}) comes back {:.7f} mm from the drawing"), number, name,
                                            best->deviation));
        else if (best->scale > 1e6)
            out.notes.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "contour {} ({}) is written to {} mm: to 0.000001 mm {}"), number, name,
                                            figure::formatNumber(1.0 / best->scale), why));
        out.text += fmt::format("$$ contour {}: {}\n", number, describe(c)) + best->text;
        out.names.push_back(name);
        out.deviations.push_back(best->deviation);
    }
    return out;
}

std::string figureTextFromContours(const std::vector<Contour>& contours, const FigureNaming& naming)
{
    return figureFromContours(contours, naming).text;
}

}  // namespace taiwa
