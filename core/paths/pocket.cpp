// Pocket clearing (roughing and floor finishing): equal Z layers, the entry
// (pilot hole or ramp), contour-parallel rings from the inside out, and the
// cleanup of whatever the rings leave, found and proved with Clipper.
#include "paths/generators.h"

#include "paths/contour.h"
#include "paths/coverage.h"
#include "paths/entry.h"
#include "paths/path_builder.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <unordered_map>

namespace taiwa::paths {

namespace {

constexpr int kCleanupRounds = 6;

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }

// Offsets (from the step outline) of the centre rings, innermost first: the
// outermost is exactly the tool radius, the innermost where the outline
// collapses (a point or a line, cut too), evenly spaced at most `stepOver`
// apart.
std::vector<double> ringOffsets(const Quad& outline, double radius, double stepOver)
{
    const double deepest = std::max(radius, maxOffset(outline) - 1e-4);
    const int gaps = static_cast<int>(std::ceil((deepest - radius) / stepOver - 1e-9));
    std::vector<double> d;
    for (int k = gaps; k >= 0; --k) d.push_back(radius + (deepest - radius) * k / std::max(gaps, 1));
    return d;
}

// Equal layers of at most maxDepth from start to end depth (positive).
std::vector<double> layerDepths(double start, double end, double maxDepth)
{
    const int n = std::max(1, static_cast<int>(std::ceil((end - start) / maxDepth - 1e-9)));
    std::vector<double> z;
    for (int k = 1; k < n; ++k) z.push_back(start + (end - start) * k / n);
    z.push_back(end);  // exactly the cut depth, no rounding
    return z;
}

// One layer at height z after the entry: the rings, each linked to the next
// by a straight feed from the middle of its first side to the middle of the
// next ring's (the centre region is convex: a straight link stays inside
// it), then the cleanup visits.
void appendRings(PathBuilder& b, const Quad& outline, const std::vector<double>& offsets,
                 const std::vector<Point2>& cleanup, double z, bool ccw)
{
    for (const double d : offsets) {
        const Quad centre = centreQuad(outline, d);
        b.feed(at(contourStart(centre, ccw).point, z));
        appendContour(b, centre, z, ccw);
    }
    for (const auto& c : cleanup) b.feed(at(c, z));
}

// The cleanup visits of one layer (see clear()): what the proof that the
// layer clears the outline finds, and adds, until it finds nothing.
std::vector<Point2> proveLayer(const Quad& outline, double R, const Entry& entry, const std::vector<double>& offsets,
                               const PathParameters& p)
{
    std::vector<Point2> cleanup;
    const Quad centres = centreQuad(outline, R);
    for (int round = 0;; ++round) {
        PathBuilder probe(at(entry.point, 0.0));
        appendEntry(probe, entry, 0.0, p.rampAngle, p.climb);
        appendRings(probe, outline, offsets, cleanup, 0.0, p.climb);
        const auto more = cleanupPoints(outline, centres, probe.take(), R);
        if (more.empty()) break;
        if (round == kCleanupRounds) throw std::logic_error("pocket layer not cleared");
        cleanup.insert(cleanup.end(), more.begin(), more.end());
    }
    return cleanup;
}

// The proof is most of a pocket's path time, and shops repeat pockets
// (patterns, arrays, families of parts): it is done about the outline's
// first corner, a pure function of the shape, the tool, the entry and the
// step-over there, and remembered. A pocket of the same shape elsewhere
// gets the same answer moved to its place, the one it would have computed:
// the cache changes no result, only how often it is computed (so the
// output does not depend on which thread came first).
struct ProofKey {
    Quad outline;       // about its first corner
    Point2 position;    // the step's position, about that corner
    double R, hole, stepOver;
    PathParameters params;
    bool operator==(const ProofKey& o) const
    {
        return outline.corners == o.outline.corners && outline.cornerRadius == o.outline.cornerRadius &&
               position == o.position && R == o.R && hole == o.hole && stepOver == o.stepOver && params == o.params;
    }
};
struct ProofKeyHash {
    std::size_t operator()(const ProofKey& k) const
    {
        std::size_t h = 0;
        const auto mix = [&h](double v) { h = h * 1'000'003u ^ std::hash<double>{}(v); };
        for (const Point2 c : k.outline.corners) mix(c.x), mix(c.y);
        mix(k.outline.cornerRadius), mix(k.position.x), mix(k.position.y), mix(k.R), mix(k.hole), mix(k.stepOver);
        return h;
    }
};

constexpr std::size_t kRemembered = 4096;  // shapes; forgotten all at once beyond
std::mutex provedMutex;
std::unordered_map<ProofKey, std::vector<Point2>, ProofKeyHash> proved;

std::vector<Point2> cleanupVisits(const Quad& outline, double R, double hole, Point2 position, double stepOver,
                                  const PathParameters& p)
{
    const Point2 origin = outline.corners[0];
    ProofKey key{outline, position - origin, R, hole, stepOver, p};
    for (auto& c : key.outline.corners) c = c - origin;
    std::optional<std::vector<Point2>> known;
    {
        std::lock_guard lock(provedMutex);
        if (const auto it = proved.find(key); it != proved.end()) known = it->second;
    }
    if (!known) {
        // Proved outside the lock: two threads may prove one shape at once,
        // and get the same answer.
        const auto offsets = ringOffsets(key.outline, R, stepOver);
        if (ringsClearRectangle(key.outline, R, offsets)) {
            known.emplace();  // proved by geometry (coverage.cpp): no visits
        } else {
            const Entry entry = chooseEntry(key.outline, R, hole, key.position);
            known = proveLayer(key.outline, R, entry, offsets, p);
        }
        std::lock_guard lock(provedMutex);
        if (proved.size() >= kRemembered) proved.clear();
        proved.emplace(key, *known);
    }
    std::vector<Point2> local = std::move(*known);
    for (auto& c : local) c = c + origin;
    return local;
}

// `hole`: the diameter of the pilot hole drilled at the step's position to enter
// through (roughing), 0 for none.
ToolPath clear(const Step& step, const Tool& tool, const std::vector<double>& depths, double stepOver, double hole,
               const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    if (!g.outline) throw std::logic_error("pocket step without an outline");
    const double R = tool.radius();
    if (!fitsInto(R, g.outline->cornerRadius)) throw std::logic_error("pocket corner radius smaller than the tool radius");
    // A tool within the fit tolerance of the corner radius runs it as its own.
    const Quad outline{counterClockwise(g.outline->corners), std::max(g.outline->cornerRadius, R)};
    if (maxOffset(outline) < R - 1e-9) throw std::logic_error("pocket narrower than the tool");
    if (!(stepOver > 0.0 && stepOver < 2 * R)) throw std::logic_error("step-over must lie between 0 and D");

    const Entry entry = chooseEntry(outline, R, hole, g.position);
    const auto offsets = ringOffsets(outline, R, stepOver);

    // Prove that one layer clears the outline with what it cuts at its own
    // depth (the entry's last turn or line, the rings, the cleanup; the ramp
    // above the layer does not count), and add cleanup visits for what it
    // leaves until it leaves nothing.
    const std::vector<Point2> cleanup = cleanupVisits(outline, R, hole, g.position, stepOver, p);

    PathBuilder b(at(entry.point, p.safeZ));
    b.rapid(at(entry.point, -g.startDepth + p.clearance));
    for (const double d : depths) {
        // Back to the entry point across the layer just cleared.
        appendEntry(b, entry, -d, p.rampAngle, p.climb);
        appendRings(b, outline, offsets, cleanup, -d, p.climb);
    }
    b.rapid(at({b.at().x, b.at().y}, p.safeZ));
    return b.take();
}

}  // namespace

ToolPath pocketRoughing(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p)
{
    const MillingGeometry& g = millingOf(step);
    const auto depths = layerDepths(g.startDepth, g.cutDepth, tech.gamma * tool.diameter);
    return clear(step, tool, depths, g.stepOver.value_or(tech.stepOver) * tool.diameter, g.holeDiameter, p);
}

ToolPath floorFinishing(const Step& step, const Tool& tool, const PathParameters& p)
{
    return clear(step, tool, {millingOf(step).cutDepth}, p.finishStepOver * tool.diameter, 0.0, p);
}

}  // namespace taiwa::paths

namespace taiwa {

void forgetProvedLayers()
{
    std::lock_guard lock(paths::provedMutex);
    paths::proved.clear();
}

}  // namespace taiwa
