// Random contour jobs and their judgement (contour_generator.h).
#include "support/contour_generator.h"

#include "figure/figure_from_contours.h"
#include "modules/cp/cp.h"
#include "modules/side/side.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::test {

namespace {

constexpr double kPi = std::numbers::pi;

// splitmix64: the same numbers on every platform for a seed.
class Random {
public:
    explicit Random(std::uint64_t seed) : s_(seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull) {}
    double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
    int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

private:
    std::uint64_t next()
    {
        std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    std::uint64_t s_;
};

Point2 unit(Point2 v) { return (1.0 / std::hypot(v.x, v.y)) * v; }
Point2 leftOf(Point2 d) { return {-d.y, d.x}; }

// The polyline's corners (all of a closed one's, an open one's inner ones)
// rounded by the radii asked for, each shrunk so that its tangent points
// stay within 0.45 of both edges.
Contour rounded(const std::vector<Point2>& v, bool closed, Random& rnd, double smallRadiusChance)
{
    const std::size_t n = v.size();
    struct Corner {
        Point2 in, out, centre;
        bool ccw = true, round = false;
    };
    std::vector<Corner> corners(n);
    for (std::size_t i = 0; i < n; ++i) {
        corners[i].in = corners[i].out = v[i];
        if (!closed && (i == 0 || i + 1 == n)) continue;
        const Point2 a = v[(i + n - 1) % n], p = v[i], b = v[(i + 1) % n];
        const Point2 u0 = unit(p - a), u1 = unit(b - p);
        const double turn = cross(u0, u1), deflection = std::atan2(std::abs(turn), dot(u0, u1));
        if (deflection < 1e-3) continue;
        double r = rnd.chance(smallRadiusChance) ? rnd.uniform(0.5, 1.3) : rnd.uniform(1.5, 10.0);
        const double room = 0.45 * std::min(distance(a, p), distance(p, b));
        r = std::min(r, room / std::tan(deflection / 2.0));
        const double t = r * std::tan(deflection / 2.0);
        Corner& c = corners[i];
        c.in = p - t * u0;
        c.out = p + t * u1;
        c.ccw = turn > 0;
        c.centre = c.in + (c.ccw ? r : -r) * leftOf(u0);
        c.round = true;
    }
    Contour out;
    out.closed = closed;
    for (std::size_t i = 0; i < n; ++i) {
        if (!closed && i == 0) continue;
        const Corner& from = corners[i - 1 < n ? i - 1 : n - 1];
        const Corner& c = corners[i];
        out.segments.push_back(ContourSegment::line(i == 0 ? corners[n - 1].out : from.out, c.in));
        if (c.round) out.segments.push_back(ContourSegment::arc(c.in, c.out, c.centre, c.ccw));
    }
    return out;
}

// A star polygon round `m`, counter-clockwise, its vertices within the box
// [lo, hi]; with a neck: two opposite vertices drawn in near the centre.
std::vector<Point2> star(Point2 m, double rMin, double rMax, Point2 lo, Point2 hi, bool neck, Random& rnd)
{
    const int n = neck ? 2 * rnd.integer(3, 4) : rnd.integer(4, 8);
    const double start = rnd.uniform(0.0, 2.0 * kPi);
    std::vector<Point2> v;
    for (int k = 0; k < n; ++k) {
        const double a = start + 2.0 * kPi * (k + rnd.uniform(-0.25, 0.25)) / n;
        double r = rnd.uniform(rMin, rMax);
        if (neck && (k == 0 || k == n / 2)) r = rnd.uniform(1.5, 7.0);
        const Point2 d{std::cos(a), std::sin(a)};
        for (const double s : {(hi.x - m.x) / d.x, (lo.x - m.x) / d.x, (hi.y - m.y) / d.y, (lo.y - m.y) / d.y})
            if (s > 0) r = std::min(r, s);
        v.push_back(m + r * d);
    }
    return v;
}

Contour circle(Point2 c, double r)
{
    Contour k;
    k.closed = true;
    k.segments = {ContourSegment::arc(c + Point2{r, 0.0}, c + Point2{r, 0.0}, c, true)};
    return k;
}

double gapBetween(const Contour& a, const Contour& b)
{
    double g = 1e300;
    for (const Point2& p : flatten(a, 1e-3)) g = std::min(g, distanceTo(b, p));
    return g;
}

void makeJob(ContourCase& c, const ModuleInput& unit)
{
    std::vector<Contour> ready;
    for (const Contour& w : c.walls) ready.push_back(figureReady(w));
    c.walls = ready;
    const FigureFromContours f = figureFromContours(c.walls);
    c.job.name = fmt::format("generated contour {}", c.seed);
    c.job.figure = f.text;
    c.job.units.push_back({"generated", unit, {}});
    // The names the figure gave the contours go into the unit.
    ModuleInput& m = c.job.units.back().module;
    if (c.module == "CP") {
        ContourPocket& p = m.as<ContourPocket>();
        p.contours.outline = f.names.at(0);
        p.contours.islands.assign(f.names.begin() + 1, f.names.end());
    } else {
        m.as<SideMill>().contour = f.names.at(0);
    }
}

ContourCase pocketCase(std::uint64_t seed, Random& rnd)
{
    ContourCase c;
    c.seed = seed;
    c.module = "CP";
    c.job.stock = Stock{0, 0, 60, 45, 20};
    c.neck = rnd.chance(0.3);
    const Contour outline = rounded(star({30, 22.5}, 9, 21, {1.5, 1.5}, {58.5, 43.5}, c.neck, rnd), true, rnd, 0.03);
    c.walls = {outline};
    const int islands = rnd.integer(0, 3);
    const Box2 box = bounds(outline);
    for (int k = 0; k < islands; ++k) {
        // The island's kind drawn once (a retry keeps it): 5 % a circle
        // touching the outline, 7 % at a narrow gap, the rest 4 mm or more
        // off every wall; at most 15 places tried.
        const double mode = rnd.uniform(0.0, 1.0);
        const double least = rnd.chance(0.07) ? 0.2 : 4.0;
        for (int tries = 0; tries < 15; ++tries) {
            const Point2 m{rnd.uniform(box.min.x, box.max.x), rnd.uniform(box.min.y, box.max.y)};
            if (!contains(outline, m)) continue;
            const double room = distanceTo(outline, m);
            const bool touch = mode < 0.05;
            if (touch && room < 2.5) continue;
            Contour island;
            if (touch) {
                island = circle(m, room);
            } else if (mode < 0.6) {
                island = circle(m, rnd.uniform(2.0, 6.0));
            } else {
                const double w = rnd.uniform(2.0, 5.0), h = rnd.uniform(2.0, 5.0), a = rnd.uniform(0.0, kPi);
                const Point2 u{std::cos(a), std::sin(a)}, n = leftOf(u);
                island = rounded({m - w * u - h * n, m + w * u - h * n, m + w * u + h * n, m - w * u + h * n}, true, rnd, 0.0);
            }
            bool fits = touch || (contains(outline, island.segments.front().start) && gapBetween(island, outline) > least);
            for (std::size_t j = 1; fits && j < c.walls.size(); ++j) fits = gapBetween(island, c.walls[j]) > least;
            if (!fits) continue;
            c.touching = c.touching || touch;
            c.walls.push_back(island);
            break;
        }
    }
    ContourPocket p;
    p.depth = std::round(rnd.uniform(1.5, 5.0) * 10.0) / 10.0;
    p.toolUse = rnd.chance(0.2) ? 9 : 1;
    p.wallFinish = rnd.chance(0.3) ? 2 : 1;
    makeJob(c, ModuleInput{p});
    c.what = fmt::format("CP: {} segments, {} islands{}{}, T {}", outline.segments.size(), c.walls.size() - 1,
                         c.neck ? ", neck" : "", c.touching ? ", one touching" : "", p.depth);
    return c;
}

ContourCase sideCase(std::uint64_t seed, Random& rnd)
{
    ContourCase c;
    c.seed = seed;
    c.module = "SIDE";
    c.job.stock = Stock{0, 0, 70, 45, 20};
    SideMill s;
    s.side = rnd.integer(1, 2);
    s.direction = rnd.integer(1, 2);
    s.depth = std::round(rnd.uniform(1.5, 7.0) * 10.0) / 10.0;
    s.width = std::round(rnd.uniform(2.0, 16.0) * 10.0) / 10.0;
    s.toolUse = rnd.chance(0.15) ? 9 : 1;
    s.wallFinish = rnd.chance(0.3) ? 2 : 1;
    Contour k;
    if (rnd.chance(0.3)) {  // a closed boss or pocket
        k = rounded(star({35, 22.5}, 8, 16, {8, 6}, {62, 39}, rnd.chance(0.2), rnd), true, rnd, 0.08);
        s.width = std::min(s.width, 5.0);
    } else {
        std::vector<Point2> v{{-10, rnd.uniform(15, 30)}};
        const int bends = rnd.integer(0, 3);
        std::vector<double> xs;
        for (int i = 0; i < bends; ++i) xs.push_back(rnd.uniform(5, 65));
        std::sort(xs.begin(), xs.end());
        for (const double x : xs)
            if (x - v.back().x > 10) v.push_back({x, rnd.uniform(12, 33)});
        v.push_back({80, rnd.uniform(15, 30)});
        k = rounded(v, false, rnd, 0.08);
        // A semicircular notch into the material in the longest straight run.
        if (rnd.chance(0.6)) {
            std::size_t longest = 0;
            for (std::size_t i = 0; i < k.segments.size(); ++i)
                if (!k.segments[i].isArc() && k.segments[i].length() > k.segments[longest].length()) longest = i;
            const ContourSegment run = k.segments[longest];
            const double r = std::min(rnd.uniform(2.0, 14.0), 0.3 * run.length());
            if (!run.isArc() && r > 1.5) {
                const Point2 u = run.startDirection(), m = run.at(0.5);
                const Point2 a = m - r * u, b = m + r * u;
                // Tool on the left of the drawn contour (side 1): the material on
                // its right, where a counter-clockwise half circle from a to b bulges.
                const std::vector<ContourSegment> notch{ContourSegment::line(run.start, a),
                                                        ContourSegment::arc(a, b, m, s.side == 1),
                                                        ContourSegment::line(b, run.end)};
                k.segments.erase(k.segments.begin() + static_cast<std::ptrdiff_t>(longest));
                k.segments.insert(k.segments.begin() + static_cast<std::ptrdiff_t>(longest), notch.begin(), notch.end());
                c.notch = true;
            }
        }
    }
    c.walls = {k};
    makeJob(c, ModuleInput{s});
    c.what = fmt::format("SIDE: {} {} segments{}, side {}, direction {}, T {}, W {}, U {}", k.closed ? "closed" : "open",
                         k.segments.size(), c.notch ? " with a notch" : "", s.side, s.direction, s.depth, s.width,
                         s.toolUse);
    return c;
}

double arcDistance(const ContourSegment& s, Point2 p)
{
    const Point2 a = s.start - s.centre, q = p - s.centre, e = s.end - s.centre;
    const double r = std::hypot(a.x, a.y), dq = std::hypot(q.x, q.y);
    const double sign = s.kind == ContourSegment::Kind::ArcCCW ? 1.0 : -1.0;
    const auto angleFromStart = [&](Point2 w) {
        double t = sign * std::atan2(cross(a, w), dot(a, w));
        return t < 0 ? t + 2.0 * kPi : t;
    };
    double sweep = angleFromStart(e);
    if (sweep < 1e-12) sweep = 2.0 * kPi;  // a full circle
    if (dq > 0 && angleFromStart(q) <= sweep) return std::abs(dq - r);
    return std::min(std::hypot(p.x - s.start.x, p.y - s.start.y), std::hypot(p.x - s.end.x, p.y - s.end.y));
}

double lineDistance(const ContourSegment& s, Point2 p)
{
    const Point2 d = s.end - s.start;
    const double l2 = dot(d, d);
    const double t = l2 > 0 ? std::clamp(dot(p - s.start, d) / l2, 0.0, 1.0) : 0.0;
    const Point2 f = s.start + t * d;
    return std::hypot(p.x - f.x, p.y - f.y);
}

}  // namespace

double wallDistance(const Contour& c, Point2 p)
{
    double best = 1e300;
    for (const ContourSegment& s : c.segments) best = std::min(best, s.isArc() ? arcDistance(s, p) : lineDistance(s, p));
    return best;
}

ContourCase generateContourCase(std::uint64_t seed)
{
    Random rnd(seed);
    return seed % 2 == 1 ? pocketCase(seed, rnd) : sideCase(seed, rnd);
}

}  // namespace taiwa::test
