// Module AREA: area clearing by drawn passes (seed 002, seventh abstract).
// The area is a closed contour of the job's figure with islands, as CP's
// pocket; the operator draws the passes in it as points the tool centre goes
// through in order, each pass a straight strip one tool wide, and names the
// tool's diameter the strips were drawn for. The tape follows the passes in
// their order, layer by layer down to the depth; what the strips leave
// unswept is shown and reported (paths/drawn_passes.h). Door: area_kind.cpp;
// checks area_check.cpp; steps and tool area_plan.cpp.
#pragma once

#include "check/unit_checks.h"
#include "model/contour.h"
#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
#include "modules/length_fields.h"
#include "modules/named_region.h"
#include "paths/cl.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// The work of an AREA unit's checks, refused beyond (area_check.cpp): the
// passes times the area's segments (the excursion test), and the pairs of
// strips whose boxes overlap (the crossings of the unswept area's union).
constexpr double kMaxAreaPassSegments = 2e7;
constexpr std::size_t kMaxAreaStripPairs = 50'000;

// The pairs of strips of radius `radius` round the passes through `points`
// whose boxes overlap, counted by a sweep over the boxes; past `stopAt` the
// count stops (stopAt + 1).
std::size_t overlappingStripPairs(const std::vector<Point2>& points, double radius, std::size_t stopAt);

struct AreaClearing {
    static constexpr const char* kName = "AREA";
    static constexpr int kSinceFormatVersion = 5;  // the job format that brought it
    NamedRegion area;             // outline and islands, from the figure
    std::vector<Point2> points;   // the passes: the tool centre goes from each point to the next
    double depth = 0.0;           // T, down from the top surface
    double diameter = 0.0;        // the tool diameter the passes were drawn for (the strips' width)
    ToolPins tools;               // key "area": a flat end mill of that diameter
    // Not in the job file: the form's text of the points when it did not
    // read as points (the check refuses it; `points` keeps the last good ones).
    std::string badPoints;

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, points, depth, diameter, area.region);
    }
    friend bool operator==(const AreaClearing&, const AreaClearing&) = default;
};

// An area-clearing step's own data (Step::payload): the points the tool
// centre goes through in the order the operator drew them (each pass runs
// from one point to the next), within the step's region.
struct DrawnPoints {
    static constexpr const char* kName = "AREA passes";
    std::vector<Point2> points;
    MillingGeometry milling{};  // the step's geometry (model/milling_geometry.h)
    friend bool operator==(const DrawnPoints&, const DrawnPoints&) = default;
};

// The points as the form shows and reads them: "10, 20; 60, 20; 60, 35".
std::string formatPoints(const std::vector<Point2>& points);
// Nothing when `text` is not pairs of numbers separated by ';'.
std::optional<std::vector<Point2>> parsePoints(const std::string& text);

// A tool the passes can be cut with: a centre-cutting flat end mill of the
// diameter they were drawn for (the check and the tool choice alike).
bool cutsDrawnPasses(const Tool& t, double diameter);

// The input checks of one AREA unit (in mm).
check::UnitReport checkAreaClearing(const AreaClearing& mm, int unitNo, const check::Context& ctx);

// The step of one AREA unit (checked, in mm): the passes in layers of at
// most γ·D down to T; then its tool, a centre-cutting flat end mill of the
// unit's diameter (a pin may name it). Problems become diagnostics.
std::vector<Step> planAreaClearing(const AreaClearing& mm, const TechnologyData& tech, const std::vector<Tool>& library,
                                   const std::string& material, int unit, Diagnostics& out);

// The step's tool path (area_paths.cpp): the drawn passes layer by layer.
ToolPath areaClearingPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);

}  // namespace taiwa
