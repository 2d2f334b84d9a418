// Module SIDE: side milling along a contour of the job's figure, open or
// closed: the finished wall is the contour, the material removed lies on
// the tool's side of it, within the width W, down to the depth T, in
// roughing passes leaving α2 and a finishing pass (docs/side-milling.md).
// The contour is named in the unit and resolved by the job layer as CP's
// are (job/figure_contours.h). Checks in side_check.cpp, decomposition and
// tool choice in side_decompose.cpp, the door in side_kind.cpp.
#pragma once

#include "check/unit_checks.h"
#include "model/cavity.h"
#include "model/contour.h"
#include "model/diagnostic.h"
#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "modules/length_fields.h"
#include "paths/cl.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include <cstdint>
#include <vector>

namespace taiwa {

struct SideMill {
    static constexpr const char* kName = "SIDE";
    static constexpr int kSinceFormatVersion = 5;  // the job format that brought it
    std::string contour;   // the contour of the finished wall ("K1")
    int side = 1;          // 1: the tool on the left of the contour's direction, 2: on its right
    int direction = 1;     // 1: climb, 2: conventional (M3: climb runs the tool on the left of its travel)
    double depth = 0.0;    // T, down from the top surface
    double width = 0.0;    // W: the material to remove, measured from the contour on the tool's side
    int toolUse = 1;       // U: 1 roughing and finishing, 8 finishing only, 9 roughing only
    int wallFinish = 1;    // F: 1 full depth at once, 2 in several incisions
    std::optional<double> stepOver;  // roughing's radial step as a fraction of D; the technology's when absent
    ToolPins tools;                  // "side": the end mill of every pass

    // Not in the job file: the named contour as the job's figure evaluates
    // it (mm), set by the job layer; absent until then, or when the name is
    // not a contour of the figure.
    std::optional<Contour> path;
    std::vector<std::string> figureContours;  // every contour of the figure, for the message (only when it has not `contour`)
    bool resolved = false;
    // Worked out when the contour is resolved: a closed contour with the
    // tool inside, the largest radius that reaches all of it
    // (paths::reachRadius; 0 otherwise).
    double reach = 0.0;

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, depth, width, reach, path);
    }
    friend bool operator==(const SideMill&, const SideMill&) = default;
};

// A side-milling step's own data (Step::payload): the contour the tool's
// edge runs along, open or closed, in the direction the tool travels; the
// tool on its left (true) or its right; and the distances of the tool's edge
// from the contour of the step's radial passes in the order cut (the last is
// the nearest; 0 on a finishing pass).
struct SidePasses {
    static constexpr const char* kName = "SIDE passes";
    Contour contour;
    bool toolOnLeft = true;
    std::vector<double> offsets;
    MillingGeometry milling{};  // the step's geometry (model/milling_geometry.h)
    friend bool operator==(const SidePasses&, const SidePasses&) = default;
};

namespace side {

// The contour as the tool travels along it (reversed for side and
// direction codes that run it backwards) and the tool's side of that
// travel: climb runs the tool on the left of its travel (M3), conventional
// on its right. The contour must be resolved.
struct Travel {
    Contour contour;
    bool toolOnLeft = true;
};
Travel travel(const SideMill& mm);

// The smallest radius of an arc of the contour that curves round the
// tool's side (the tool must fit into it); a large number when none.
double smallestConcaveRadius(const Contour& c, bool toolOnLeft);
// Where the contour turns towards the tool's side at a sharp corner: an end
// mill cannot reach into it.
std::optional<Point2> sharpConcaveCorner(const Contour& c, bool toolOnLeft);
// The largest tool radius the finishing pass may have (smallest concave
// radius; a closed contour with the tool inside, its reach too).
double toolRoom(const SideMill& mm);
// The arc of the contour with the smallest radius curving round the tool's
// side; nothing when none does.
const ContourSegment* tightestConcaveArc(const Contour& c, bool toolOnLeft);
// Why even the smallest end mill `tool` finds no room (issue 33): the arc
// that limits it, where, and by how much it is too large for it; with the
// tool inside a closed contour whose reach is the limit, the neck (its two
// sides) or the arc that makes the reach. `allowance`: what the step leaves
// on the wall (its tool radius plus this must fit). In the job's unit.
std::string noRoomAt(const SideMill& mm, const Tool& tool, double allowance, LengthUnit shown);

// The material side: +1 on the tool's side of the contour, -1 on the other,
// for any point (an open contour continued past its ends along the tangents
// of its first and last elements); and the distance to the contour itself.
class Sides {
public:
    Sides(const Contour& c, bool toolOnLeft);
    bool onToolSide(Point2 p) const;
    double distance(Point2 p) const;  // to the contour (not its continuations)

private:
    void makeBands();
    std::size_t band(double y) const;

    Contour contour_;
    // The contour flattened to 0.1 µm; an open one closed round its tool
    // side. The tool side is inside it (`inside_`) or outside.
    std::vector<Point2> polygon_;
    bool inside_ = true;
    // The polygon's edges (index of their first point) by horizontal band,
    // each edge in every band its y range meets: the crossing test of a
    // point looks at its band's edges only (a contour flattened to 0.1 µm
    // has thousands of edges; verification asks millions of points).
    // The bands span the contour's own height (an open contour's closing
    // chords, a kilometre long, fall into the end bands); a point below,
    // above or right of the whole polygon crosses none of it.
    std::vector<std::vector<std::uint32_t>> bands_;
    double bandsY0_ = 0.0, bandHeight_ = 1.0;
    Box2 extent_{};
};

// The step's tool path (side_paths.cpp): the contour's offsets, layer by layer and pass by pass.
ToolPath millingPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);

}  // namespace side

check::UnitReport checkSideMill(const SideMill& mm, int unitNo, const check::Context& ctx);

// The steps of one SIDE unit with their tools (inputs in mm, checked and
// resolved): roughing (Z layers down to T, radial passes from W to α2) and
// the finishing pass at the contour, each with the largest flat end mill
// that fits its room; problems as diagnostics.
std::vector<Step> planSideMill(const SideMill& mm, const TechnologyData& tech, const std::vector<Tool>& library,
                               const std::string& material, int unit, LengthUnit shown, Diagnostics& out);
// The radial passes of a roughing step: the tool edge's distances from the
// contour, outermost first, equally spaced at most `maxStep` apart, the first
// one step in from W, the last at α2.
std::vector<double> roughingOffsets(double width, double alpha2, double maxStep);

// The finished shape (model/cavity.h).
Cavity sideCavity(const SideMill& mm, const TechnologyData& tech);

}  // namespace taiwa
