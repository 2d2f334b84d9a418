// The exact inward offset of a pocket region (region_offset.h): candidate
// elements (parallels of the boundary segments, arcs round the corners that
// point into the pocket), split at their mutual crossings (found by a sweep
// over their bounding boxes), the pieces whose middle lies no nearer than d
// to the boundary kept (nearest segments looked up in a grid), chained end to
// start into loops, split parallels joined again, loops sorted into pieces by
// orientation and nesting.
#include "paths/region_offset.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>

namespace taiwa::paths {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kSplitEnd = 1e-7;    // a crossing nearer than this [mm] to an element's end is that end
constexpr double kSame = 1e-9;        // crossings nearer than this [mm] along an element are one
constexpr double kKeep = 1e-7;        // a piece is kept when no nearer than d - kKeep to the boundary
constexpr double kChain = 1e-6;       // ends nearer than this [mm] meet
constexpr double kLoopGap = 1e-6;     // the largest gap allowed in an input loop

Point2 leftNormal(Point2 t) { return {-t.y, t.x}; }

double normAngle(double a)
{
    a = std::fmod(a, kTwoPi);
    return a < 0.0 ? a + kTwoPi : a;
}

// One candidate: a line from a to b, or an arc round c of radius r from
// angle a0 turning `sweep` (signed), a full circle when `closed`. Its
// parameter runs along it in mm from 0 to len().
struct Element {
    bool arc = false;
    bool closed = false;
    Point2 a{}, b{};
    Point2 c{};
    double r = 0.0, a0 = 0.0, sweep = 0.0;

    double len() const { return arc ? std::abs(sweep) * r : distance(a, b); }
    Point2 at(double s) const
    {
        if (!arc) {
            const double l = len();
            return l > 0.0 ? a + (s / l) * (b - a) : a;
        }
        const double ang = a0 + (sweep > 0.0 ? 1.0 : -1.0) * s / r;
        return {c.x + r * std::cos(ang), c.y + r * std::sin(ang)};
    }
    // The parameter of a point on (or next to) the element's curve, or a
    // negative number when it lies off the element's extent.
    double paramOf(Point2 p) const
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
};

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
            const Point2 p{e.c.x + e.r * std::cos(ang), e.c.y + e.r * std::sin(ang)};
            b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y)};
            b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y)};
        }
    }
    return b;
}

Element lineElement(Point2 a, Point2 b)
{
    Element e;
    e.a = a;
    e.b = b;
    return e;
}

Element arcElement(Point2 c, double r, double a0, double sweep, bool closed)
{
    Element e;
    e.arc = true;
    e.closed = closed;
    e.c = c;
    e.r = r;
    e.a0 = a0;
    e.sweep = sweep;
    e.a = {c.x + r * std::cos(a0), c.y + r * std::sin(a0)};
    e.b = closed ? e.a : Point2{c.x + r * std::cos(a0 + sweep), c.y + r * std::sin(a0 + sweep)};
    return e;
}

// The candidates of one loop, material on its right: each segment's
// parallel on the left at d, and an arc of radius d round each corner that
// turns right.
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

struct Split {
    double s;
    Point2 p;
};

// Each element's splits, its ends included, in order along it.
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

// The boundary segments in a grid, to find those near a point.
class Nearby {
public:
    Nearby(const std::vector<const ContourSegment*>& segs, double reach) : segs_(segs)
    {
        Box all{{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()},
                {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}};
        std::vector<Box2> boxes;
        boxes.reserve(segs.size());
        for (const auto* s : segs) {
            const Box2 b = bounds(Contour{{*s}, false});
            boxes.push_back(b);
            all.min = {std::min(all.min.x, b.min.x), std::min(all.min.y, b.min.y)};
            all.max = {std::max(all.max.x, b.max.x), std::max(all.max.y, b.max.y)};
        }
        origin_ = all.min;
        const double extent = std::max({all.max.x - all.min.x, all.max.y - all.min.y, 1e-6});
        // Cells of a quarter of the reach (no more than 256 a side): a query
        // looks at the cells its disc touches, not at a block three reaches wide.
        cell_ = std::max({reach / 4.0, extent / 256.0, 1e-6});
        nx_ = static_cast<int>((all.max.x - all.min.x) / cell_) + 1;
        ny_ = static_cast<int>((all.max.y - all.min.y) / cell_) + 1;
        cells_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), {});
        for (std::size_t k = 0; k < segs.size(); ++k) {
            const auto [x0, y0] = cellOf(boxes[k].min);
            const auto [x1, y1] = cellOf(boxes[k].max);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) cells_[index(x, y)].push_back(static_cast<std::uint32_t>(k));
        }
        seen_.assign(segs.size(), 0);
    }

    // True when some boundary segment lies nearer than `limit` to p
    // (limit <= the reach given).
    bool anyNearer(Point2 p, double limit)
    {
        ++stamp_;
        const auto [x0, y0] = cellOf({p.x - limit, p.y - limit});
        const auto [x1, y1] = cellOf({p.x + limit, p.y + limit});
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                // A cell wholly farther than the limit holds nothing nearer.
                const double cx = origin_.x + x * cell_, cy = origin_.y + y * cell_;
                const double dx = std::max({cx - p.x, 0.0, p.x - cx - cell_});
                const double dy = std::max({cy - p.y, 0.0, p.y - cy - cell_});
                if (dx * dx + dy * dy >= limit * limit) continue;
                for (std::uint32_t k : cells_[index(x, y)]) {
                    if (seen_[k] == stamp_) continue;
                    seen_[k] = stamp_;
                    if (distance(p, segs_[k]->nearest(p)) < limit) return true;
                }
            }
        return false;
    }

private:
    std::pair<int, int> cellOf(Point2 p) const
    {
        const auto clampi = [](double v, int hi) { return std::clamp(static_cast<int>(std::floor(v)), 0, hi - 1); };
        return {clampi((p.x - origin_.x) / cell_, nx_), clampi((p.y - origin_.y) / cell_, ny_)};
    }
    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(x); }

    const std::vector<const ContourSegment*>& segs_;
    Point2 origin_{};
    double cell_ = 1.0;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<std::uint32_t>> cells_;
    std::vector<std::uint32_t> seen_;
    std::uint32_t stamp_ = 0;
};

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
    Nearby nearby(boundary, d);

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

    // Chain the pieces end to start.
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

    // Counter-clockwise loops bound pieces; each clockwise one is an island
    // of the smallest piece around it.
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
        const auto& pts = polygons[i];
        int winding = 0;
        for (std::size_t k = 0; k < pts.size(); ++k) {
            const Point2 a = pts[k], b = pts[(k + 1) % pts.size()];
            const double side = cross(b - a, p - a);
            if (a.y <= p.y) {
                if (b.y > p.y && side > 0.0) ++winding;
            } else if (b.y <= p.y && side < 0.0) {
                --winding;
            }
        }
        return winding != 0;
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
    Nearby nearby(boundary, d);
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
