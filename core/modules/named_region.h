// An area of a contour unit given by names of the job's figure: a closed
// outline and the closed islands in it (CP's pocket, AREA's area). Reading
// the names from the job file and writing them, resolving them against the
// evaluated figure, checking the contours (known, closed, not crossing
// themselves, inside the stock, islands inside the outline and apart,
// optionally no sharp inside corner), the resolved outline's box and
// polygon, the cavity's box and the default figure's rectangle are shared
// here.
#pragma once

#include "check/unit_checks.h"
#include "io/json_fields.h"
#include "io/unit_keys.h"
#include "model/cavity.h"
#include "model/contour.h"
#include "model/geometry.h"
#include "model/job.h"
#include "model/module.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct NamedRegion {
    std::string outline;               // "K1"
    std::vector<std::string> islands;  // "K2", "K3"

    // Not in the job file: what resolve() finds in the figure (mm). `region`
    // is absent until then, or when a name is not a contour of the figure
    // (listed in `unknown`).
    std::optional<Region> region;
    std::vector<std::string> unknown;
    std::vector<std::string> figureContours;  // every contour the figure defines, to name in messages (only when a name is unknown)
    std::vector<bool> closedContours;         // outline, then islands
    bool resolved = false;

    // Takes the named contours from the figure's table.
    void resolve(const ContourTable& table);
    friend bool operator==(const NamedRegion&, const NamedRegion&) = default;
};

// The most segments a named region may have, outline and islands together
// as the figure evaluates them, and the most islands: the checks (crossing,
// islands apart) and the sizing (paths/region.h) are near-linear up to here
// and refused beyond, before any of them runs (docs/input-checks.md).
constexpr std::size_t kMaxRegionSegments = 20'000;
constexpr std::size_t kMaxRegionIslands = 100;
// True when `region` is within both.
bool regionWithinLimits(const Region& region);

// The names of a unit's "outline" and "islands" in the job file, not yet
// resolved; an islands value that is not an array, or an item that is not
// a name, is reported on its field ("islands", "islands[2]"), and no
// islands key is none.
NamedRegion readNamedRegion(const io::ObjectFields& f);
// ... written: "outline", then "islands" when there are any.
void writeNamedRegion(const NamedRegion& n, nlohmann::ordered_json& u);
// The named region at member `m` of unit U as an entry of U's job-file table
// (io/unit_keys.h): the keys "outline" and "islands".
template <class U>
io::UnitKey<U> namedRegionKeys(NamedRegion U::*m)
{
    return io::keys::custom<U>(
        {"outline", "islands"}, [m](const io::ObjectFields& f, U& u) { u.*m = readNamedRegion(f); },
        [m](const U& u, nlohmann::ordered_json& j) { writeNamedRegion(u.*m, j); });
}

// A resolved region's outline as a unit's door gives it: the box around it
// (topOutline) and the outline flattened to 1 µm (topPolygon); nothing
// while the region is unresolved.
std::optional<Quad> regionBox(const std::optional<Region>& region);
std::vector<Point2> regionPolygon(const std::optional<Region>& region);

// The cavity a contour unit cuts down to `depth` within a resolved region
// (ModuleKind::cavity): the box around its outline and the depth, with the
// signed distance from the region (normalised) for the unit's own depthAt
// and openAt, which it sets.
struct RegionCavity {
    Cavity cavity;
    std::shared_ptr<const RegionDistance> distance;
};
RegionCavity regionCavity(const Region& region, double depth);

// The figure text of a default contour unit's rectangle over the middle of
// `stock` (0.2 to 0.6 of its width and length, to 1 µm): the corners P1
// and P2 and the sides L1 ... L4, counter-clockwise from the bottom side,
// each line ending in a newline; the caller names the contour.
std::string middleRectangleFigure(const Stock& stock);

// Scales a region's points and centres (mm <-> inch).
void convertRegionLengths(Region& region, const LengthMap& f);

// The checks of the named contours on fields "outline" and "islands"; `what`
// names the outline in messages ("pocket", "area"). True when the region is
// well-formed.
bool checkNamedRegion(const NamedRegion& n, check::Reporter& r, const char* what, bool refuseSharpInsideCorners);

}  // namespace taiwa
