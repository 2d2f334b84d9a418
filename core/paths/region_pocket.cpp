// Clearing a pocket of any outline with islands (contour units' roughing and
// floor finishing): equal Z layers; in each, contour-parallel rings of the
// tool centre made by Clipper from the flattened region, deepest ring first
// (inside out); a ring is entered by ramping along itself, and linked to the
// next by a straight feed when that link stays in the cleared region, else
// by lifting to the safe height. See docs/toolpaths.md ("Contour pockets").
#include "paths/generators.h"
#include "paths/region.h"
#include "paths/region_offset.h"

#include "model/clipper_scale.h"
#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <stdexcept>

namespace taiwa::paths {

namespace {

using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kChord = 1e-4;  // mm between an arc of the region and its chords (0.1 µm: rings keep α2 to the tape's µm)

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }

// What the reach and the inscribed circle are measured on: they are tool
// sizes, for which a micrometre of chord does not matter.
constexpr double kSizingChord = 1e-3;

Paths regionPaths(const Region& r, double chord = kChord)
{
    Paths out;
    out.push_back(toClipper(flatten(r.outer, chord)));
    for (const auto& i : r.islands) out.push_back(toClipper(flatten(i, chord)));
    // Outer counter-clockwise, islands clockwise: Clipper's orientation.
    for (std::size_t k = 0; k < out.size(); ++k)
        if (ClipperLib::Orientation(out[k]) != (k == 0)) ClipperLib::ReversePath(out[k]);
    return out;
}

// The region shrunk by d (islands grown by d), round joins.
Paths inset(const Paths& region, double d, double chord = kChord)
{
    ClipperLib::ClipperOffset o(2.0, chord * kClipperScale);
    o.AddPaths(region, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths out;
    o.Execute(out, -d * kClipperScale);
    ClipperLib::CleanPolygons(out, 1.0);
    std::erase_if(out, [](const Path& p) { return p.size() < 3; });
    return out;
}

bool insideAll(const Paths& domain, Point2 q)
{
    // Inside the outer loops and outside the holes: winding of all of them.
    int winding = 0;
    const ClipperLib::IntPoint ip = toClipper(q);
    for (const auto& p : domain) {
        const int in = ClipperLib::PointInPolygon(ip, p);
        if (in == 0) continue;
        winding += ClipperLib::Orientation(p) ? 1 : -1;
    }
    return winding > 0;
}

struct Loop {
    std::vector<Point2> points;  // closed, the first point not repeated
    int level = 0;
};

double perimeter(const Loop& l)
{
    double d = 0.0;
    for (std::size_t i = 0; i < l.points.size(); ++i) d += distance(l.points[i], l.points[(i + 1) % l.points.size()]);
    return d;
}

bool insideLoop(const Loop& l, Point2 q)
{
    return ClipperLib::PointInPolygon(toClipper(q), toClipper(l.points)) == 1;
}

Point2 centroid(const Loop& l)
{
    Point2 c{};
    for (const Point2 q : l.points) c = c + q;
    return (1.0 / static_cast<double>(l.points.size())) * c;
}

// The point of the loop nearest to q: the index of the vertex to start at.
std::size_t nearestVertex(const Loop& l, Point2 q)
{
    std::size_t best = 0;
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < l.points.size(); ++i)
        if (const double e = distance(l.points[i], q); e < d) d = e, best = i;
    return best;
}

// Walks the loop from vertex `from` around once at height z (or ramping from
// the builder's height down to z over `rampLength`, then once around).
void runLoop(PathBuilder& b, const Loop& l, std::size_t from, double z, double rampLength)
{
    const std::size_t n = l.points.size();
    if (rampLength > 0.0) {
        const double z0 = b.at().z;
        double walked = 0.0;
        std::size_t i = from;
        while (walked < rampLength) {
            const std::size_t j = (i + 1) % n;
            const double seg = distance(l.points[i], l.points[j]);
            if (walked + seg >= rampLength) {
                const double t = (rampLength - walked) / std::max(seg, 1e-12);
                b.feed(at(l.points[i] + t * (l.points[j] - l.points[i]), z), FeedKind::Ramp);
                // Back to the loop's vertex to start the level round from.
                b.feed(at(l.points[j], z));
                from = j;
                break;
            }
            walked += seg;
            b.feed(at(l.points[j], z0 + (z - z0) * walked / rampLength), FeedKind::Ramp);
            i = j;
        }
    }
    for (std::size_t k = 1; k <= n; ++k) b.feed(at(l.points[(from + k) % n], z));
}

struct Clearing {
    double stepOver;  // mm
    bool singleLayer;
};

ToolPath clearRegion(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p,
                     const Clearing& how)
{
    const MillingGeometry& g = millingOf(step);
    if (!g.region) throw std::logic_error("contour step without a region");
    const double R = tool.radius();
    const double s = std::clamp(how.stepOver, 1e-3, 0.9 * R);  // below R: every point within R of a ring
    const Paths region = regionPaths(*g.region);
    const double first = R + g.wallAllowance;
    const Paths domain = inset(region, first);
    if (domain.empty()) throw std::logic_error("the tool does not fit into the contour region");

    // The rings by level, the outermost (level 0) exactly at the allowance.
    std::vector<Loop> loops;
    // Each inner ring from the one outside it: a small offset of a smooth
    // ring is fast where one large offset of a detailed outline is not (a
    // 2,000-element gear took minutes). Only the first ring sets the
    // allowance; the inner ones may each lose the chords' sliver, far
    // inside the 0.1 R the step-over keeps in hand.
    Paths ring = domain;
    for (int level = 0;; ++level) {
        if (level > 0) ring = inset(ring, s, kSizingChord);
        if (ring.empty()) break;
        for (const auto& path : ring) {
            Loop l;
            l.level = level;
            for (const auto& ip : path) l.points.push_back(fromClipper(ip));
            if (!p.climb) std::reverse(l.points.begin(), l.points.end());
            loops.push_back(std::move(l));
        }
        if (level > 100000) throw std::logic_error("contour clearing does not converge");
    }
    std::stable_sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.level > b.level; });

    // Layers: equal, at most gamma x D deep (floor finishing: one).
    const double top = g.startDepth, bottom = g.cutDepth;
    int layers = 1;
    if (!how.singleLayer) {
        const double maxDepth = std::max(tech.gamma * tool.diameter, 1e-3);
        layers = std::max(1, static_cast<int>(std::ceil((bottom - top) / maxDepth - 1e-9)));
    }
    const double rampSlope = std::tan(std::clamp(p.rampAngle, 0.5, 45.0) * std::numbers::pi / 180.0);

    PathBuilder b(at(loops.front().points.front(), p.safeZ));
    for (int layer = 1; layer <= layers; ++layer) {
        const double above = top + (bottom - top) * (layer - 1) / layers;  // what the layer before left
        const double z = layer == layers ? -bottom : -(top + (bottom - top) * layer / layers);
        bool inside = false;  // at depth z in a cleared place
        for (const Loop& l : loops) {
            const std::size_t from = nearestVertex(l, {b.at().x, b.at().y});
            const Point2 target = l.points[from];
            bool link = false;
            if (inside) {
                const Point2 here{b.at().x, b.at().y};
                link = distance(here, target) <= 1.05 * s;
                for (int k = 1; link && k < 16; ++k) link = insideAll(domain, here + (k / 16.0) * (target - here));
            }
            if (link) {
                b.feed(at(target, z));
                runLoop(b, l, from, z, 0.0);
                continue;
            }
            // Lift, go over, come down above the layer and ramp in: on a
            // helix round the middle of a ring too short to ramp along (the
            // innermost, a few tenths long), else along the ring itself.
            if (b.at().z < p.safeZ) b.rapid(at({b.at().x, b.at().y}, p.safeZ));
            const double approach = -above + p.clearance;
            const double ringLength = perimeter(l);
            const Point2 middle = centroid(l);
            // Inside the ring at level L, a point is at least L step-overs
            // inside the first ring: room for a helix of that radius.
            const double helix = std::min(0.5 * R, 0.95 * l.level * s);
            if (ringLength < 2.0 * std::numbers::pi * 0.5 * R && helix > 0.05 * R && insideLoop(l, middle)) {
                const Point2 start = middle + Point2{helix, 0.0};
                b.rapid(at(start, p.safeZ));
                b.rapid(at(start, approach));
                const double drop = approach - z;
                const int halves = std::max(2, static_cast<int>(std::ceil(drop / (std::numbers::pi * helix * rampSlope))));
                for (int k = 1; k <= halves; ++k) {
                    const Point2 to = middle + Point2{k % 2 ? -helix : helix, 0.0};
                    b.arc(p.climb, at(to, approach - drop * k / halves), middle, FeedKind::Ramp);
                }
                // A level turn at the depth, in two halves, back to where the ramp ended.
                const Point2 ended = middle + Point2{halves % 2 ? -helix : helix, 0.0};
                b.arc(p.climb, at(2.0 * middle - ended, z), middle);
                b.arc(p.climb, at(ended, z), middle);
                b.feed(at(target, z));
                runLoop(b, l, from, z, 0.0);
            } else {
                b.rapid(at(target, p.safeZ));
                b.rapid(at(target, approach));
                runLoop(b, l, from, z, (approach - z) / rampSlope);
            }
            inside = true;
        }
    }
    b.rapid(at({b.at().x, b.at().y}, p.safeZ));
    return b.take();
}

}  // namespace

double reachRadius(const Region& r, double inscribed)
{
    // A radius reaches everywhere when the cutter rolling along the whole
    // boundary stays inside to kLost (paths/region_offset.h): what it leaves
    // out is then no thicker than the chords' slivers.
    constexpr double kLost = 2e-3;  // mm: twice the chords' 1 µm
    const auto reaches = [&](double radius) { return rollsAround(r, radius, kLost); };
    // Small radii first, doubling: most contours are limited by a small
    // corner or channel, and a small radius is the cheapest to test.
    const double most = std::min(inscribed, kMaxReach);
    if (!(most > 0.0)) return 0.0;
    double lo = 0.0, hi = std::min(0.125, most);
    while (reaches(hi)) {
        lo = hi;
        if (hi >= most) return most;
        hi = std::min(2.0 * hi, most);
    }
    for (int it = 0; it < 32 && hi - lo > 1e-3; ++it) {
        const double mid = 0.5 * (lo + hi);
        (reaches(mid) ? lo : hi) = mid;
    }
    return lo;
}

double inscribedRadius(const Region& input)
{
    // The pole of inaccessibility (Mapbox's polylabel): square cells over the
    // box, the most promising first (its centre's distance to the boundary
    // plus its half diagonal bounds every point in it); a cell that cannot
    // beat the best centre found by more than the precision is not split.
    const Region r = normalised(input);
    if (r.outer.empty()) return 0.0;
    const Box2 box = bounds(r.outer);
    const double w = box.max.x - box.min.x, h = box.max.y - box.min.y;
    const double size = std::min(w, h);
    if (!(size > 0.0) || !std::isfinite(size)) return 0.0;
    const double precision = std::max(1e-3, 1e-5 * std::max(w, h));
    const RegionDistance signedDistance(r);  // negative inside
    struct Cell {
        Point2 c;
        double half, d, bound;
        bool operator<(const Cell& o) const { return bound < o.bound; }
    };
    const auto cell = [&](Point2 c, double half) {
        const double d = -signedDistance(c);
        return Cell{c, half, d, d + half * std::numbers::sqrt2};
    };
    std::priority_queue<Cell> queue;
    const double tile = std::max(size, std::sqrt(w * h / 1000.0));  // a thin strip: no more than about 1,000 tiles
    for (double x = box.min.x; x < box.max.x; x += tile)
        for (double y = box.min.y; y < box.max.y; y += tile) queue.push(cell({x + tile / 2, y + tile / 2}, tile / 2));
    Cell best = cell(0.5 * (box.min + box.max), 0.0);
    // Each cell costs a distance along every segment: a long ridge (a slot)
    // would split many; past 5·10⁷ segment distances (at most 40,000 cells)
    // the best so far is the answer (a lower bound, within the cells' size
    // of the radius).
    std::size_t segments = r.outer.segments.size();
    for (const auto& i : r.islands) segments += i.segments.size();
    const auto maxCells = static_cast<int>(std::clamp<std::size_t>(50'000'000 / std::max<std::size_t>(segments, 1), 2'000, 40'000));
    for (int n = 0; !queue.empty() && n < maxCells; ++n) {
        const Cell c = queue.top();
        queue.pop();
        if (c.d > best.d) best = c;
        if (c.bound - best.d <= precision) continue;
        const double q = c.half / 2;
        for (const Point2 o : {Point2{-q, -q}, Point2{q, -q}, Point2{-q, q}, Point2{q, q}}) queue.push(cell(c.c + o, q));
    }
    return std::max(best.d, 0.0);
}

ToolPath regionRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    return clearRegion(step, tool, tech, p, {millingOf(step).stepOver.value_or(tech.stepOver) * tool.diameter, false});
}

ToolPath regionFloorFinishing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    return clearRegion(step, tool, tech, p, {p.finishStepOver * tool.diameter, true});
}

}  // namespace taiwa::paths
