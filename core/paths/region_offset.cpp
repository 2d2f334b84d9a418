// The exact inward offset of a pocket region (region_offset.h): candidate
// elements (parallels of the boundary segments, arcs round the corners that
// point into the pocket), split at their mutual crossings (found by a sweep
// over their bounding boxes), the pieces whose middle lies no nearer than d
// to the boundary kept (nearest segments looked up in a grid), chained end to
// start into loops, split parallels joined again, loops sorted into pieces by
// orientation and nesting.
#include "paths/region_offset.h"

#include "model/winding.h"
#include "paths/nearby.h"
#include "paths/offset_candidates.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>

namespace taiwa::paths {

namespace {

using offset::Element;
using offset::kSame;
using offset::Nearby;
using offset::Split;

constexpr double kKeep = 1e-7;     // a piece is kept when no nearer than d - kKeep to the boundary
constexpr double kChain = 1e-6;    // ends nearer than this [mm] meet
constexpr double kLoopGap = 1e-6;  // the largest gap allowed in an input loop

// A kept piece of an element, from split k to split k + 1.
struct Piece {
    std::size_t elem;
    std::size_t k;
    Point2 start, end;
    bool used = false;
};

ContourSegment toSegment(const Element& e, Point2 a, Point2 b)
{
    return e.arc ? ContourSegment::arc(a, b, e.c, e.sweep > 0.0) : ContourSegment::line(a, b);
}

std::int64_t key(double v) { return static_cast<std::int64_t>(std::floor(v / kChain)); }

struct KeyHash {
    std::size_t operator()(const std::pair<std::int64_t, std::int64_t>& k) const
    {
        return std::hash<std::int64_t>()(k.first * 73856093LL ^ k.second * 19349663LL);
    }
};

// The kept pieces chained end to start into closed loops; the consecutive
// pieces of one element joined again, so that a line stays one line and a
// full circle one circle.
Result<std::vector<Contour>> chainLoops(std::vector<Piece>& pieces, const std::vector<Element>& elems,
                                        const std::vector<std::vector<Split>>& splits)
{
    std::unordered_map<std::pair<std::int64_t, std::int64_t>, std::vector<std::size_t>, KeyHash> starts;
    for (std::size_t i = 0; i < pieces.size(); ++i) starts[{key(pieces[i].start.x), key(pieces[i].start.y)}].push_back(i);
    const auto following = [&](const Piece& p) -> std::size_t {
        std::size_t best = pieces.size();
        double bestGap = kChain;
        // Prefer the element's own next piece, then the nearest start.
        const std::int64_t kx = key(p.end.x), ky = key(p.end.y);
        for (std::int64_t y = ky - 1; y <= ky + 1; ++y)
            for (std::int64_t x = kx - 1; x <= kx + 1; ++x) {
                const auto it = starts.find({x, y});
                if (it == starts.end()) continue;
                for (std::size_t j : it->second) {
                    if (pieces[j].used) continue;
                    const double gap = distance(pieces[j].start, p.end);
                    if (gap < bestGap || (gap <= bestGap && pieces[j].elem == p.elem)) {
                        best = j;
                        bestGap = gap;
                    }
                }
            }
        return best;
    };
    std::vector<Contour> result;
    for (std::size_t first = 0; first < pieces.size(); ++first) {
        if (pieces[first].used) continue;
        std::vector<std::size_t> chain{first};
        pieces[first].used = true;
        for (;;) {
            const Piece& last = pieces[chain.back()];
            if (distance(last.end, pieces[first].start) < kChain) break;
            const std::size_t next = following(last);
            if (next == pieces.size()) return Failure{"the offset of the region does not close into loops (do its loops cross?)"};
            pieces[next].used = true;
            chain.push_back(next);
        }
        // Join the consecutive pieces of one element again: start at a piece
        // that does not continue the one before it (none: a full circle).
        const auto joins = [&](std::size_t a, std::size_t b) {
            const Piece &pa = pieces[a], &pb = pieces[b];
            if (pa.elem != pb.elem) return false;
            return pb.k == pa.k + 1 || (elems[pa.elem].closed && pa.k + 2 == splits[pa.elem].size() && pb.k == 0);
        };
        const std::size_t n = chain.size();
        std::size_t begin = n;
        for (std::size_t m = 0; m < n && begin == n; ++m)
            if (!joins(chain[(m + n - 1) % n], chain[m])) begin = m;
        Contour c;
        c.closed = true;
        if (begin == n) {
            const Piece& a = pieces[chain.front()];
            c.segments.push_back(toSegment(elems[a.elem], a.start, a.start));
        } else {
            std::rotate(chain.begin(), chain.begin() + static_cast<std::ptrdiff_t>(begin), chain.end());
            std::size_t runStart = chain.front();
            for (std::size_t m = 0; m < n; ++m) {
                if (m + 1 < n && joins(chain[m], chain[m + 1])) continue;
                c.segments.push_back(toSegment(elems[pieces[runStart].elem], pieces[runStart].start, pieces[chain[m]].end));
                if (m + 1 < n) runStart = chain[m + 1];
            }
        }
        // Close the tiny gaps: each segment ends where the next starts.
        for (std::size_t m = 0; m < c.segments.size(); ++m) c.segments[m].end = c.segments[(m + 1) % c.segments.size()].start;
        c = withoutDegenerateSegments(c);
        if (!c.empty()) result.push_back(std::move(c));
    }

    return result;
}

// Counter-clockwise loops bound pieces of the tool-centre area, largest
// first; each clockwise one is an island of the smallest piece around it.
std::vector<Region> regionsOf(std::vector<Contour> result)
{
    std::vector<Region> out;
    std::vector<Contour> islands;
    for (auto& c : result) {
        if (signedArea(c) > 0.0) out.push_back(Region{std::move(c), {}});
        else islands.push_back(std::move(c));
    }
    std::sort(out.begin(), out.end(), [](const Region& a, const Region& b) { return signedArea(a.outer) > signedArea(b.outer); });
    // Each outer loop flattened once (islands never touch the loops round
    // them, so 0.1 µm chords decide), looked at only when its box holds the
    // island's probe point.
    std::vector<std::vector<Point2>> polygons(out.size());
    std::vector<Box2> boxes(out.size());
    for (std::size_t i = 0; i < out.size(); ++i) boxes[i] = bounds(out[i].outer);
    const auto inside = [&](std::size_t i, Point2 p) {
        if (out.size() == 1) return true;
        if (p.x < boxes[i].min.x || p.x > boxes[i].max.x || p.y < boxes[i].min.y || p.y > boxes[i].max.y) return false;
        if (polygons[i].empty()) polygons[i] = flatten(out[i].outer, 1e-4);
        return windingNumber(polygons[i], p) != 0;
    };
    for (auto& c : islands) {
        const Point2 probe = c.segments.front().at(0.5);
        for (std::size_t i = out.size(); i-- > 0;)  // smallest first
            if (inside(i, probe)) {
                out[i].islands.push_back(std::move(c));
                break;
            }
    }
    return out;
}
}  // namespace

Result<std::vector<Region>> offsetRegion(const Region& input, double d)
{
    if (!(d >= 0.0) || !std::isfinite(d)) return Failure{"the offset of a region must be a finite distance of zero or more"};
    Region region = normalised(input);
    region.outer = withoutDegenerateSegments(region.outer);
    for (auto& i : region.islands) i = withoutDegenerateSegments(i);
    std::vector<const Contour*> loops{&region.outer};
    for (const auto& i : region.islands) loops.push_back(&i);
    for (const auto* l : loops) {
        if (l->empty()) return Failure{"a loop of the region to offset is empty"};
        Contour closed = *l;
        closed.closed = true;
        if (largestGap(closed) > kLoopGap) return Failure{"a loop of the region to offset does not close"};
    }
    if (d == 0.0) return std::vector<Region>{region};

    std::vector<Element> elems;
    for (const auto* l : loops) addCandidates(*l, d, elems);
    const auto splits = splitAll(elems);

    std::vector<const ContourSegment*> boundary;
    for (const auto* l : loops)
        for (const auto& s : l->segments) boundary.push_back(&s);
    Nearby nearby(boundary);

    std::vector<Piece> pieces;
    for (std::size_t i = 0; i < elems.size(); ++i) {
        const auto& sp = splits[i];
        for (std::size_t k = 0; k + 1 < sp.size(); ++k) {
            if (sp[k + 1].s - sp[k].s < kSame) continue;
            const Point2 mid = elems[i].at(0.5 * (sp[k].s + sp[k + 1].s));
            if (nearby.anyNearer(mid, d - kKeep)) continue;
            pieces.push_back({i, k, sp[k].p, sp[k + 1].p});
        }
    }

    auto chained = chainLoops(pieces, elems, splits);
    if (!chained) return chained.failure();
    return regionsOf(std::move(*chained));
}

bool rollsAround(const Region& input, double d, double tolerance)
{
    if (!(d > 0.0) || !std::isfinite(d)) return false;
    Region region = normalised(input);
    region.outer = withoutDegenerateSegments(region.outer);
    for (auto& i : region.islands) i = withoutDegenerateSegments(i);
    std::vector<const Contour*> loops{&region.outer};
    for (const auto& i : region.islands) loops.push_back(&i);
    std::vector<Element> elems;
    for (const auto* l : loops) {
        if (l->empty()) return false;
        // An arc curving round the pocket tighter than d has no parallel:
        // the cutter stays out of it, leaving a sliver (d - r)(1/cos(φ/2) - 1)
        // thick over its sweep φ; more than twice the tolerance is not swept.
        for (const auto& s : l->segments) {
            if (s.kind != ContourSegment::Kind::ArcCCW || s.radius() > d) continue;
            const double half = std::min(0.5 * std::abs(s.sweep()), 0.5 * std::numbers::pi - 1e-9);
            if (distance(s.start, s.end) < 1e-9 || (d - s.radius()) * (1.0 / std::cos(half) - 1.0) > 2.0 * tolerance)
                return false;
        }
        addCandidates(*l, d, elems);
    }
    const auto splits = splitAll(elems);
    std::vector<const ContourSegment*> boundary;
    for (const auto* l : loops)
        for (const auto& s : l->segments) boundary.push_back(&s);
    Nearby nearby(boundary);
    for (std::size_t i = 0; i < elems.size(); ++i) {
        const auto& sp = splits[i];
        for (std::size_t k = 0; k + 1 < sp.size(); ++k) {
            if (sp[k + 1].s - sp[k].s < kSame) continue;
            if (nearby.anyNearer(elems[i].at(0.5 * (sp[k].s + sp[k + 1].s)), d - tolerance)) return false;
        }
    }
    return true;
}

std::vector<Contour> loopsOf(const std::vector<Region>& pieces)
{
    std::vector<Contour> loops;
    for (const auto& p : pieces) {
        loops.push_back(p.outer);
        loops.insert(loops.end(), p.islands.begin(), p.islands.end());
    }
    return loops;
}

}  // namespace taiwa::paths
