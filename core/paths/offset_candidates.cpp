// The candidates of an exact offset and their splits (offset_candidates.h).
#include "paths/offset_candidates.h"

#include <algorithm>
#include <numbers>

namespace taiwa::paths::offset {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

Point2 leftNormal(Point2 t) { return {-t.y, t.x}; }

// The point at angle `ang` on the circle round c of radius r.
Point2 onCircle(Point2 c, double r, double ang) { return {c.x + r * std::cos(ang), c.y + r * std::sin(ang)}; }

double normAngle(double a)
{
    a = std::fmod(a, kTwoPi);
    return a < 0.0 ? a + kTwoPi : a;
}

}  // namespace

Point2 Element::at(double s) const
{
    if (!arc) {
        const double l = len();
        return l > 0.0 ? a + (s / l) * (b - a) : a;
    }
    return onCircle(c, r, a0 + (sweep > 0.0 ? 1.0 : -1.0) * s / r);
}

double Element::paramOf(Point2 p) const
{
    const double l = len();
    if (!arc) {
        const double s = l > 0.0 ? dot(p - a, b - a) / l : 0.0;
        if (s < -kSplitEnd || s > l + kSplitEnd) return -1.0;
        return std::clamp(s, 0.0, l);
    }
    const double ang = std::atan2(p.y - c.y, p.x - c.x);
    const double turned = normAngle(sweep > 0.0 ? ang - a0 : a0 - ang);
    if (closed) return turned * r;
    double s = turned * r;
    if (s > l + kSplitEnd) {
        // Just before the start, seen the other way round.
        if ((kTwoPi - turned) * r <= kSplitEnd) return 0.0;
        return -1.0;
    }
    return std::min(s, l);
}

namespace {

struct Box {
    Point2 min{}, max{};
};

Box boxOf(const Element& e)
{
    if (!e.arc) return {{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y)}, {std::max(e.a.x, e.b.x), std::max(e.a.y, e.b.y)}};
    Box b{{std::min(e.a.x, e.b.x), std::min(e.a.y, e.b.y)}, {std::max(e.a.x, e.b.x), std::max(e.a.y, e.b.y)}};
    for (int q = 0; q < 4; ++q) {
        const double ang = q * std::numbers::pi / 2.0;
        const double turned = normAngle(e.sweep > 0.0 ? ang - e.a0 : e.a0 - ang);
        if (e.closed || turned <= std::abs(e.sweep)) {
            const Point2 p = onCircle(e.c, e.r, ang);
            b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y)};
            b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y)};
        }
    }
    return b;
}

Element lineElement(Point2 a, Point2 b) { return {.a = a, .b = b}; }

Element arcElement(Point2 c, double r, double a0, double sweep, bool closed)
{
    const Point2 a = onCircle(c, r, a0);
    return {.arc = true, .closed = closed, .a = a, .b = closed ? a : onCircle(c, r, a0 + sweep), .c = c, .r = r, .a0 = a0,
            .sweep = sweep};
}

}  // namespace

void addCandidates(const Contour& loop, double d, std::vector<Element>& out)
{
    const std::size_t n = loop.segments.size();
    for (std::size_t i = 0; i < n; ++i) {
        const ContourSegment& s = loop.segments[i];
        if (!s.isArc()) {
            const Point2 off = d * leftNormal(s.startDirection());
            out.push_back(lineElement(s.start + off, s.end + off));
        } else {
            const bool ccw = s.kind == ContourSegment::Kind::ArcCCW;
            const double r = s.radius() + (ccw ? -d : d);  // the centre lies on the left of a counter-clockwise arc
            const bool full = distance(s.start, s.end) < 1e-9;
            if (r > 1e-9)
                out.push_back(arcElement(s.centre, r, std::atan2(s.start.y - s.centre.y, s.start.x - s.centre.x),
                                         full ? (ccw ? kTwoPi : -kTwoPi) : s.sweep(), full));
        }
        // The corner at the end of this segment.
        const ContourSegment& next = loop.segments[(i + 1) % n];
        const Point2 t1 = s.endDirection(), t2 = next.startDirection();
        const double turn = std::atan2(cross(t1, t2), dot(t1, t2));  // left positive
        if (turn >= -1e-12) continue;
        const Point2 v = s.end, n1 = leftNormal(t1);
        out.push_back(arcElement(v, d, std::atan2(n1.y, n1.x), turn, false));
    }
}

namespace {

// Where two elements cross (at most two points).
std::vector<Point2> crossings(const Element& e, const Element& f)
{
    std::vector<Point2> pts;
    if (!e.arc && !f.arc) {
        const Point2 r = e.b - e.a, s = f.b - f.a;
        const double den = cross(r, s);
        if (std::abs(den) <= 1e-14 * length(r) * length(s)) return pts;  // parallel
        const double t = cross(f.a - e.a, s) / den;
        pts.push_back(e.a + t * r);
        return pts;
    }
    if (e.arc != f.arc) {
        const Element& l = e.arc ? f : e;
        const Element& c = e.arc ? e : f;
        const Point2 r = l.b - l.a, g = l.a - c.c;
        const double A = dot(r, r), B = 2.0 * dot(g, r), C = dot(g, g) - c.r * c.r;
        const double disc = B * B - 4.0 * A * C;
        if (A <= 0.0 || disc < 0.0) return pts;
        const double q = std::sqrt(disc);
        pts.push_back(l.a + ((-B - q) / (2.0 * A)) * r);
        if (q > 0.0) pts.push_back(l.a + ((-B + q) / (2.0 * A)) * r);
        return pts;
    }
    const Point2 v = f.c - e.c;
    const double dd = length(v);
    if (dd < 1e-12 || dd > e.r + f.r || dd < std::abs(e.r - f.r)) return pts;
    const double a = (e.r * e.r - f.r * f.r + dd * dd) / (2.0 * dd);
    const double h = std::sqrt(std::max(0.0, e.r * e.r - a * a));
    const Point2 u = (1.0 / dd) * v, m = e.c + a * u, w = leftNormal(u);
    pts.push_back(m + h * w);
    if (h > 0.0) pts.push_back(m - h * w);
    return pts;
}

}  // namespace

std::vector<std::vector<Split>> splitAll(const std::vector<Element>& elems)
{
    const std::size_t n = elems.size();
    std::vector<std::vector<Split>> splits(n);
    std::vector<Box> boxes(n);
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) {
        boxes[i] = boxOf(elems[i]);
        order[i] = i;
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return boxes[a].min.x < boxes[b].min.x; });
    const auto interior = [](const Element& e, double s) {
        return e.closed || (s > kSplitEnd && s < e.len() - kSplitEnd);
    };
    for (std::size_t oi = 0; oi < n; ++oi) {
        const std::size_t i = order[oi];
        for (std::size_t oj = oi + 1; oj < n && boxes[order[oj]].min.x <= boxes[i].max.x + kSplitEnd; ++oj) {
            const std::size_t j = order[oj];
            if (boxes[j].min.y > boxes[i].max.y + kSplitEnd || boxes[j].max.y < boxes[i].min.y - kSplitEnd) continue;
            for (const Point2 p : crossings(elems[i], elems[j])) {
                const double si = elems[i].paramOf(p), sj = elems[j].paramOf(p);
                if (si < 0.0 || sj < 0.0) continue;
                if (interior(elems[i], si)) splits[i].push_back({si, p});
                if (interior(elems[j], sj)) splits[j].push_back({sj, p});
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        auto& sp = splits[i];
        const Element& e = elems[i];
        if (e.closed) {
            // A full circle starts again wherever it is cut; its own start
            // is no cut.
            sp.erase(std::remove_if(sp.begin(), sp.end(), [&](const Split& x) { return x.s <= kSplitEnd || x.s >= e.len() - kSplitEnd; }),
                     sp.end());
        }
        sp.push_back({0.0, e.a});
        sp.push_back({e.len(), e.b});
        std::sort(sp.begin(), sp.end(), [](const Split& x, const Split& y) { return x.s < y.s; });
        std::vector<Split> unique;
        for (const auto& x : sp) {
            if (!unique.empty() && x.s - unique.back().s < kSame) {
                if (x.s == e.len()) unique.back() = x;  // the end itself wins
                continue;
            }
            unique.push_back(x);
        }
        sp = std::move(unique);
    }
    return splits;
}

}  // namespace taiwa::paths::offset
