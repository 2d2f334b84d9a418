// Chaining pieces into contours (see dxf_chain.h): a hash grid on the ends,
// the nearest pairs within the tolerance matched first, chains walked from a
// free end (open) or round (closed), the joins closed and measured, and the
// ends left open reported when another is near.
#include "dxf/dxf_chain.h"

#include "model/translate_noop.h"
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <optional>
#include <set>

namespace taiwa::dxf::detail {

namespace {

constexpr std::size_t kMaxScan = 4096;  // ends looked at around one end: beyond, a crowd
constexpr double kExactJoin = 1e-9;     // mm: joins this close are not counted as gaps

std::string at(Point2 p) { return fmt::format("({:.3f}, {:.3f})", p.x, p.y); }

// Some of the ends of the pieces (end e: piece e / 2, its start if e is
// even) in a grid of cells as wide as the largest distance asked about. Two
// grids serve the chaining: one as fine as the gap tolerance over every end
// (the joins), one as wide as the report distance over the ends left free
// (the gaps), so that a drawing of many short segments never makes one end
// look at the thousands of ends within the report distance.
class EndGrid {
public:
    EndGrid(const std::vector<Point2>& ends, const std::vector<bool>& in, double cell) : cell_(std::max(cell, 1e-9)), ends_(ends)
    {
        cells_.reserve(ends.size());
        for (std::size_t e = 0; e < ends.size(); ++e)
            if (in[e]) cells_.emplace_back(key(ends[e]), static_cast<int>(e));
        std::sort(cells_.begin(), cells_.end());
        // Each cell's first entry, found through an open-addressed table
        // (index + 1; 0 is an empty slot).
        std::size_t cells = 0;
        for (std::size_t i = 0; i < cells_.size(); ++i) cells += i == 0 || cells_[i].first != cells_[i - 1].first;
        std::size_t size = 2;
        while (size < 2 * cells) size *= 2;
        first_.assign(size, 0);
        mask_ = size - 1;
        for (std::size_t i = 0; i < cells_.size(); ++i) {
            if (i > 0 && cells_[i].first == cells_[i - 1].first) continue;
            std::size_t slot = mix(cells_[i].first) & mask_;
            while (first_[slot] != 0) slot = (slot + 1) & mask_;
            first_[slot] = static_cast<std::uint32_t>(i + 1);
        }
    }
    Point2 end(int e) const { return ends_[static_cast<std::size_t>(e)]; }
    // Calls f(other end, distance) for the ends within `radius` of end e;
    // false when there were too many to look at.
    template <class F>
    bool near(int e, double radius, const F& f) const
    {
        const Point2 p = end(e);
        const auto [cx, cy] = cellOf(p);
        std::size_t seen = 0;
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy) {
                const unsigned long long k = pack(cx + dx, cy + dy);
                for (auto it = firstOf(k); it != cells_.end() && it->first == k; ++it) {
                    const int o = it->second;
                    if (++seen > kMaxScan) return false;
                    const double d = distance(p, end(o));
                    if (o != e && d <= radius) f(o, d);
                }
            }
        return true;
    }

private:
    std::pair<long long, long long> cellOf(Point2 p) const
    {
        const auto c = [&](double v) { return static_cast<long long>(std::clamp(std::floor(v / cell_), -1e15, 1e15)); };
        return {c(p.x), c(p.y)};
    }
    static unsigned long long pack(long long x, long long y)
    {
        return static_cast<unsigned long long>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<unsigned long long>(y);
    }
    static std::size_t mix(unsigned long long k)
    {
        k ^= k >> 33;
        k *= 0xff51afd7ed558ccdULL;
        return static_cast<std::size_t>(k ^ (k >> 33));
    }
    // The cell's first entry in cells_, or its end.
    std::vector<std::pair<unsigned long long, int>>::const_iterator firstOf(unsigned long long k) const
    {
        for (std::size_t slot = mix(k) & mask_; first_[slot] != 0; slot = (slot + 1) & mask_)
            if (cells_[first_[slot] - 1].first == k) return cells_.begin() + static_cast<std::ptrdiff_t>(first_[slot] - 1);
        return cells_.end();
    }
    unsigned long long key(Point2 p) const
    {
        const auto [x, y] = cellOf(p);
        return pack(x, y);
    }
    double cell_;
    const std::vector<Point2>& ends_;
    std::vector<std::pair<unsigned long long, int>> cells_;  // (cell, end), sorted: a cell's ends in their order
    std::vector<std::uint32_t> first_;                      // the table of each cell's first entry
    std::size_t mask_ = 0;
};

// Closes the join of a (ending) and b (starting): a line end moves to an
// arc's end so that arcs stay exact; two arcs meet half-way.
void closeJoin(ContourSegment& a, ContourSegment& b)
{
    if (a.end == b.start) return;
    if (!b.isArc()) b.start = a.end;
    else if (!a.isArc()) a.end = b.start;
    else a.end = b.start = 0.5 * (a.end + b.start);
}

int findRoot(std::vector<int>& parent, int x)
{
    while (parent[static_cast<std::size_t>(x)] != x) x = parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
    return x;
}

// The chaining in its four stages, over one set of pieces: the ends
// matched (nearest pairs first), the branches reported, the chains walked
// into contours, the gaps reported.
class Chainer {
public:
    Chainer(std::vector<Piece> pieces, double tolerance, double reportDistance)
        : pieces_(std::move(pieces)), n_(pieces_.size()), tolerance_(tolerance), reportDistance_(reportDistance),
          chained_(n_), ends_(2 * n_), crowded_(2 * n_), partner_(2 * n_, -1), parent_(2 * n_)
    {
        std::vector<bool> inGrid(2 * n_);
        for (std::size_t i = 0; i < n_; ++i) {
            chained_[i] = !pieces_[i].closedByItself;
            ends_[2 * i] = pieces_[i].segments.front().start;
            ends_[2 * i + 1] = pieces_[i].segments.back().end;
            inGrid[2 * i] = inGrid[2 * i + 1] = chained_[i];
        }
        grid_.emplace(ends_, inGrid, tolerance_);
        std::iota(parent_.begin(), parent_.end(), 0);
    }
    // The grid holds a reference to ends_: a copy would look at another's.
    Chainer(const Chainer&) = delete;
    Chainer& operator=(const Chainer&) = delete;

    ChainResult run()
    {
        match();
        reportBranches();
        walk();
        reportGaps();
        return std::move(out_);
    }

private:
    static std::size_t pieceOf(int e) { return static_cast<std::size_t>(e / 2); }
    bool selfClosable(std::size_t i) const { return pieces_[i].segments.size() > 1 || pieces_[i].segments.front().isArc(); }
    int& partner(int e) { return partner_[static_cast<std::size_t>(e)]; }

    // The pairs of ends within the tolerance, nearest first, matched
    // greedily; ends within the tolerance of each other share a root.
    void match()
    {
        struct Candidate {
            double d;
            int a, b;
        };
        std::vector<Candidate> candidates;
        for (std::size_t i = 0; i < n_; ++i)
            for (int e = static_cast<int>(2 * i); chained_[i] && e <= static_cast<int>(2 * i + 1); ++e)
                crowded_[static_cast<std::size_t>(e)] = !grid_->near(e, tolerance_, [&](int o, double d) {
                    if (o > e && (pieceOf(o) != i || selfClosable(i))) candidates.push_back({d, e, o});
                });
        std::sort(candidates.begin(), candidates.end(),
                  [](const Candidate& x, const Candidate& y) { return std::tie(x.d, x.a, x.b) < std::tie(y.d, y.a, y.b); });
        for (const Candidate& c : candidates) {
            parent_[static_cast<std::size_t>(findRoot(parent_, c.a))] = findRoot(parent_, c.b);
            if (partner(c.a) < 0 && partner(c.b) < 0) {
                partner(c.a) = c.b;
                partner(c.b) = c.a;
            }
        }
    }

    // Three or more ends within the tolerance of each other: a branch.
    void reportBranches()
    {
        // The chained ends by their cluster (its root), each cluster's in
        // their order; the branches in the order of their first ends.
        std::vector<std::pair<int, int>> byRoot;
        byRoot.reserve(2 * n_);
        for (std::size_t e = 0; e < 2 * n_; ++e)
            if (chained_[pieceOf(static_cast<int>(e))]) byRoot.emplace_back(findRoot(parent_, static_cast<int>(e)), static_cast<int>(e));
        std::sort(byRoot.begin(), byRoot.end());
        std::vector<std::pair<std::vector<int>, bool>> found;  // a branch's ends, whether a crowd
        for (std::size_t i = 0, j = 0; i < byRoot.size(); i = j) {
            while (j < byRoot.size() && byRoot[j].first == byRoot[i].first) ++j;
            const bool crowd = std::any_of(byRoot.begin() + static_cast<std::ptrdiff_t>(i), byRoot.begin() + static_cast<std::ptrdiff_t>(j),
                                           [&](const auto& x) { return crowded_[static_cast<std::size_t>(x.second)]; });
            if (j - i < 3 && !crowd) continue;
            std::vector<int> ends;
            for (std::size_t k = i; k < j; ++k) ends.push_back(byRoot[k].second);
            found.emplace_back(std::move(ends), crowd);
        }
        std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first.front() < b.first.front(); });
        for (const auto& [ends, crowd] : found) out_.branches.push_back(branch(ends, crowd));
    }

    DxfBranch branch(const std::vector<int>& ends, bool crowd) const
    {
        DxfBranch b{ends_[static_cast<std::size_t>(ends.front())], static_cast<int>(ends.size()), {}, {}};
        std::string names;
        for (int x : ends) {
            b.entities.push_back(pieces_[pieceOf(x)].source);
            if (b.entities.size() <= 4)
                names = names.empty() ? b.entities.back().text()
                                      : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}, {}"), names, b.entities.back().text());
        }
        // One whole sentence for each case, for the station's translation.
        const bool more = ends.size() > 4;
        b.message =
            crowd ? (more ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "more than {} ends meet at {} or near it: {}, …; the nearest were joined, the rest left open"),
                                        kMaxScan, at(b.at), names)
                          : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "more than {} ends meet at {} or near it: {}; the nearest were joined, the rest left open"),
                                        kMaxScan, at(b.at), names))
                  : (more ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} ends meet at {}: {}, …; the nearest were joined, the rest left open"),
                                        ends.size(), at(b.at), names)
                          : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} ends meet at {}: {}; the nearest were joined, the rest left open"),
                                        ends.size(), at(b.at), names));
        return b;
    }

    // Closes the join of a and b, counting it when it was not exact.
    void join(ContourSegment& a, ContourSegment& b)
    {
        const double d = distance(a.end, b.start);
        if (d > kExactJoin) {
            ++out_.joinsOverZero;
            if (d > out_.largestJoin) {
                out_.largestJoin = d;
                out_.largestJoinAt = a.end;
            }
        }
        closeJoin(a, b);
    }

    // The chains in the file's order, joins closed and measured.
    void walk()
    {
        std::vector<bool> visited(n_);
        for (std::size_t i = 0; i < n_; ++i) {
            if (visited[i]) continue;
            if (!chained_[i]) {
                visited[i] = true;
                DxfContour c;
                c.contour = {pieces_[i].segments, true};
                c.sources.assign(pieces_[i].segments.size(), pieces_[i].source);
                out_.contours.push_back(std::move(c));
                continue;
            }
            out_.contours.push_back(chainFrom(head(i), visited));
        }
    }

    // The end by which the chain through piece i is entered: back along the
    // partners to a piece whose entering end is free, or round to i again
    // (a closed chain).
    int head(std::size_t i)
    {
        int enter = static_cast<int>(2 * i);
        for (std::size_t steps = 0; steps < n_; ++steps) {
            const int q = partner(enter);
            if (q < 0) break;
            if (pieceOf(q) == i) return static_cast<int>(2 * i);
            enter = q ^ 1;
        }
        return enter;
    }

    DxfContour chainFrom(int enter, std::vector<bool>& visited)
    {
        DxfContour c;
        const std::size_t head = pieceOf(enter);
        bool closed = false;
        for (std::size_t steps = 0; steps <= n_; ++steps) {
            const std::size_t p = pieceOf(enter);
            visited[p] = true;
            const std::size_t first = c.contour.segments.size();
            if (enter % 2 == 0) c.contour.segments.insert(c.contour.segments.end(), pieces_[p].segments.begin(), pieces_[p].segments.end());
            else
                for (auto s = pieces_[p].segments.rbegin(); s != pieces_[p].segments.rend(); ++s) c.contour.segments.push_back(s->reversed());
            c.sources.resize(c.contour.segments.size(), pieces_[p].source);
            if (first > 0) join(c.contour.segments[first - 1], c.contour.segments[first]);
            const int next = partner(enter ^ 1);
            if (next < 0) break;
            if (pieceOf(next) == head) {
                closed = true;
                break;
            }
            if (visited[pieceOf(next)]) break;  // cannot happen with a matching; kept as a guard
            enter = next;
        }
        if (closed) join(c.contour.segments.back(), c.contour.segments.front());
        c.contour.closed = closed;
        return c;
    }

    // Gaps: each free end and the nearest other free end within the report
    // distance (never closer than the tolerance: they would have been
    // joined), found on a grid of the free ends alone.
    void reportGaps()
    {
        std::vector<bool> free(2 * n_);
        for (std::size_t e = 0; e < 2 * n_; ++e) free[e] = chained_[pieceOf(static_cast<int>(e))] && partner_[e] < 0;
        const EndGrid freeEnds(ends_, free, reportDistance_);
        std::set<std::pair<int, int>> pairs;
        for (std::size_t e = 0; e < 2 * n_; ++e) {
            const std::size_t i = pieceOf(static_cast<int>(e));
            if (!free[e] || crowded_[e]) continue;
            int best = -1;
            double bestD = 0;
            freeEnds.near(static_cast<int>(e), reportDistance_, [&](int o, double d) {
                if (pieceOf(o) == i && !selfClosable(i)) return;
                if (best < 0 || d < bestD) best = o, bestD = d;
            });
            if (best >= 0 && bestD > tolerance_) pairs.insert(std::minmax(static_cast<int>(e), best));
        }
        for (const auto& [a, b] : pairs) {
            const Point2 pa = ends_[static_cast<std::size_t>(a)], pb = ends_[static_cast<std::size_t>(b)];
            DxfGap g{pa, pb, distance(pa, pb), pieces_[pieceOf(a)].source, pieces_[pieceOf(b)].source, {}};
            g.message = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "gap of {:.4g} mm at {} between {} and {}, whose end is at {}; the gap tolerance is {:.4g} mm"),
                                    g.size, at(g.at), g.a.text(), g.b.text(), at(g.other), tolerance_);
            out_.gaps.push_back(std::move(g));
        }
        std::stable_sort(out_.gaps.begin(), out_.gaps.end(), [](const DxfGap& x, const DxfGap& y) { return x.size > y.size; });
    }

    std::vector<Piece> pieces_;
    std::size_t n_;
    double tolerance_, reportDistance_;
    std::vector<bool> chained_;    // per piece: not closed by itself
    std::vector<Point2> ends_;     // per end
    std::optional<EndGrid> grid_;  // every chained end, cells as wide as the tolerance
    std::vector<bool> crowded_;    // per end: too many ends near it to look at
    std::vector<int> partner_;     // per end: the end it is joined to, or -1
    std::vector<int> parent_;      // per end: union-find of the ends within the tolerance
    ChainResult out_;
};

}  // namespace

ChainResult chainPieces(std::vector<Piece> pieces, double tolerance, double reportDistance)
{
    return Chainer(std::move(pieces), tolerance, reportDistance).run();
}

}  // namespace taiwa::dxf::detail
