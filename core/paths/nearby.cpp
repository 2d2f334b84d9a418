// The boundary's tree of chords for nearness queries (nearby.h).
#include "paths/nearby.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::paths::offset {

namespace {

// The distance from p to the segment from a to b.
double toChord(Point2 p, Point2 a, Point2 b)
{
    const Point2 ab = b - a, ap = p - a;
    const double l2 = ab.x * ab.x + ab.y * ab.y;
    const double t = l2 > 0.0 ? std::clamp((ap.x * ab.x + ap.y * ab.y) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * ab);
}

// How far a segment strays from its own chord: 0 for a line; an arc's
// sagitta, or its diameter past a half circle (its ends then bulge beyond
// the chord's span).
double stray(const ContourSegment& s)
{
    if (!s.isArc()) return 0.0;
    const double half = 0.5 * std::abs(s.sweep());
    return half <= 0.5 * std::numbers::pi ? s.radius() * (1.0 - std::cos(half)) : 2.0 * s.radius();
}

}  // namespace

Nearby::Nearby(const std::vector<const ContourSegment*>& segs) : segs_(segs)
{
    nodes_.reserve(2 * segs.size());
    if (!segs.empty()) build(0, static_cast<std::uint32_t>(segs.size()));
}

std::uint32_t Nearby::build(std::uint32_t first, std::uint32_t count)
{
    const auto at = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({segs_[first]->start, segs_[first + count - 1]->end, 0.0, first, count, 0});
    if (count == 1) {
        nodes_[at].thick = stray(*segs_[first]);
        return at;
    }
    const std::uint32_t half = count / 2;
    build(first, half);
    const std::uint32_t second = build(first + half, count - half);
    // Each half lies within its thickness of its own chord, and a chord
    // within the larger of its ends' distances of this one.
    const Node& n = nodes_[at];
    double thick = 0.0;
    for (const std::uint32_t c : {at + 1, second}) {
        const Node& h = nodes_[c];
        thick = std::max(thick, std::max(toChord(h.a, n.a, n.b), toChord(h.b, n.a, n.b)) + h.thick);
    }
    nodes_[at].thick = thick;
    nodes_[at].second = second;
    return at;
}

bool Nearby::anyNearer(Point2 p, double limit) const
{
    visited_ = 0;
    if (nodes_.empty()) return false;
    // A run whose chord is farther than its thickness plus the limit (and a
    // nanometre, for rounding) holds nothing nearer. The nearer half first.
    const double reach = limit + 1e-9;
    const auto bound = [&](std::uint32_t i) { return toChord(p, nodes_[i].a, nodes_[i].b) - nodes_[i].thick; };
    std::uint32_t stack[64];
    int top = 0;
    if (bound(0) < reach) stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        ++visited_;
        if (n.count == 1) {
            if (distance(p, segs_[n.first]->nearest(p)) < limit) return true;
            continue;
        }
        const std::uint32_t l = static_cast<std::uint32_t>(&n - nodes_.data()) + 1, r = n.second;
        const double bl = bound(l), br = bound(r);
        const bool leftFirst = bl <= br;
        if ((leftFirst ? br : bl) < reach) stack[top++] = leftFirst ? r : l;
        if ((leftFirst ? bl : br) < reach) stack[top++] = leftFirst ? l : r;
    }
    return false;
}

}  // namespace taiwa::paths::offset
