// The narrowest place of a pocket region by rolling balls (narrowest.h).
#include "paths/narrowest.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace taiwa::paths {

namespace {

constexpr std::size_t kMaxSamples = 8000;
constexpr double kTouch = 1e-3;  // mm: closer contours touch

struct Sample {
    Point2 p;
    Point2 n;  // unit inward normal (towards the pocket)
    int contour;
    int segment;
    double t;  // along the segment, 0 to 1
};

Point2 leftNormal(Point2 d) { return {-d.y, d.x}; }

Point2 directionAt(const ContourSegment& s, Point2 p)
{
    if (!s.isArc()) return s.startDirection();
    const Point2 r = p - s.centre;
    const double l = std::hypot(r.x, r.y);
    const Point2 u = l > 0 ? (1.0 / l) * r : Point2{1.0, 0.0};
    return s.kind == ContourSegment::Kind::ArcCCW ? leftNormal(u) : -1.0 * leftNormal(u);
}

std::vector<Contour*> contoursOf(Region& r)
{
    std::vector<Contour*> out{&r.outer};
    for (Contour& i : r.islands) out.push_back(&i);
    return out;
}

// The nearest point of a contour to p.
Point2 nearestOn(const Contour& c, Point2 p)
{
    Point2 best = c.start();
    double bestD = std::numeric_limits<double>::infinity();
    for (const ContourSegment& s : c.segments) {
        const Point2 q = s.nearest(p);
        if (const double d = distance(p, q); d < bestD) bestD = d, best = q;
    }
    return best;
}

bool sameCircle(const ContourSegment& a, const ContourSegment& b)
{
    return a.isArc() && b.isArc() && a.kind == b.kind && distance(a.centre, b.centre) < 1e-6 &&
           std::abs(a.radius() - b.radius()) < 1e-6;
}

}  // namespace

std::optional<NarrowestPlace> narrowestPlace(const Region& given, double spacing)
{
    Region region = normalised(given);  // the pocket on the left of every contour
    const std::vector<Contour*> contours = contoursOf(region);
    double total = 0.0;
    for (const Contour* c : contours) total += length(*c);
    if (!(total > 0.0)) return std::nullopt;
    const double h = std::max(spacing, total / static_cast<double>(kMaxSamples));

    std::vector<Sample> samples;
    for (std::size_t k = 0; k < contours.size(); ++k)
        for (std::size_t i = 0; i < contours[k]->segments.size(); ++i) {
            const ContourSegment& s = contours[k]->segments[i];
            const int n = std::max(2, static_cast<int>(std::ceil(s.length() / h)));
            for (int j = 0; j < n; ++j) {
                const Point2 p = s.at((j + 0.5) / n);
                samples.push_back({p, leftNormal(directionAt(s, p)), static_cast<int>(k), static_cast<int>(i), (j + 0.5) / n});
            }
        }

    // The smallest ball: for each p, the tightest q.
    double best = std::numeric_limits<double>::infinity();
    std::size_t bp = 0, bq = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        const Sample& p = samples[i];
        for (std::size_t j = 0; j < samples.size(); ++j) {
            if (j == i) continue;
            const Point2 d = samples[j].p - p.p;
            const double dd = dot(d, d);
            if (dd > 4.0 * best * best) continue;  // its ball is at least |d| / 2
            const double proj = dot(d, p.n);
            if (proj <= 1e-9 * std::sqrt(dd)) continue;
            if (const double r = dd / (2.0 * proj); r < best) best = r, bp = i, bq = j;
        }
    }
    if (!std::isfinite(best)) return std::nullopt;

    const Sample& p = samples[bp];
    const Sample& q = samples[bq];
    NarrowestPlace out;
    if (p.contour == q.contour) {
        const Contour& c = *contours[static_cast<std::size_t>(p.contour)];
        const ContourSegment& sp = c.segments[static_cast<std::size_t>(p.segment)];
        const ContourSegment& sq = c.segments[static_cast<std::size_t>(q.segment)];
        out.first = out.second = p.contour;
        if (sp.kind == ContourSegment::Kind::ArcCCW && (p.segment == q.segment || sameCircle(sp, sq))) {
            out.kind = NarrowestPlace::Kind::InsideArc;
            out.a = sp.at(0.5);
            out.b = sp.centre;
            out.width = out.reach = sp.radius();
            return out;
        }
        out.kind = NarrowestPlace::Kind::Neck;
        out.a = p.p;
        out.b = sq.nearest(p.p);
        out.width = distance(out.a, out.b);
        out.reach = 0.5 * out.width;
        return out;
    }
    // Two contours: the island named first, their exact narrowest gap.
    out.first = std::max(p.contour, q.contour);
    out.second = std::min(p.contour, q.contour);
    const Contour& from = *contours[static_cast<std::size_t>(out.first)];
    const Contour& to = *contours[static_cast<std::size_t>(out.second)];
    double gap = std::numeric_limits<double>::infinity();
    const Sample* nearest = nullptr;
    for (const Sample& s : samples) {
        if (s.contour != out.first) continue;
        if (const double d = distanceTo(to, s.p); d < gap) gap = d, out.a = s.p, nearest = &s;
    }
    if (nearest) {  // refined along its segment, a sample's width either side (the distance is unimodal there)
        const ContourSegment& seg = from.segments[static_cast<std::size_t>(nearest->segment)];
        const double step = 1.0 / std::max(2.0, std::ceil(seg.length() / h));
        double lo = std::max(0.0, nearest->t - step), hi = std::min(1.0, nearest->t + step);
        for (int i = 0; i < 100 && hi - lo > 1e-12; ++i) {
            const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
            if (distanceTo(to, seg.at(m1)) < distanceTo(to, seg.at(m2))) hi = m2;
            else lo = m1;
        }
        if (const Point2 refined = seg.at(0.5 * (lo + hi)); distanceTo(to, refined) < gap) gap = distanceTo(to, refined), out.a = refined;
    }
    for (const ContourSegment& s : from.segments)  // the segment ends too: a corner may be the nearest
        if (const double d = distanceTo(to, s.start); d < gap) gap = d, out.a = s.start;
    out.b = nearestOn(to, out.a);
    out.width = distance(out.a, out.b);
    out.reach = 0.5 * out.width;
    out.kind = out.width < kTouch ? NarrowestPlace::Kind::Touch : NarrowestPlace::Kind::Gap;
    return out;
}

double smallestIslandGap(const Region& region, double spacing)
{
    double gap = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < region.islands.size(); ++k) {
        const Contour& island = region.islands[k];
        std::vector<Point2> points;
        for (const ContourSegment& s : island.segments) {
            const int n = std::max(1, static_cast<int>(std::ceil(s.length() / spacing)));
            for (int j = 0; j < n; ++j) points.push_back(s.at(static_cast<double>(j) / n));
        }
        const auto against = [&](const Contour& other) {
            for (const Point2& p : points) gap = std::min(gap, distanceTo(other, p));
        };
        against(region.outer);
        for (std::size_t j = k + 1; j < region.islands.size(); ++j) against(region.islands[j]);
    }
    return gap;
}

}  // namespace taiwa::paths
