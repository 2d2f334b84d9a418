// Module HOLES: one pattern of identical holes (a single hole, a line, a
// grid, a bolt circle, an arc), each drilled, tapped, reamed or bored; its
// steps centre drilling, drilling, then tapping, reaming or boring, each a
// canned cycle at every hole. The pattern's geometry (positions, the hole's
// depths, its figure at the top) is holes_geometry.cpp, the checks
// holes_check.cpp, the steps and their tools holes_decompose.cpp, the door
// holes_kind.cpp. docs/holes.md says what it makes and why.
#pragma once

#include "check/unit_checks.h"
#include "model/diagnostic.h"
#include "model/geometry.h"
#include "model/job.h"
#include "model/step.h"
#include "model/tool.h"
#include "modules/length_fields.h"
#include "paths/cl.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct HolePattern {
    static constexpr const char* kName = "HOLES";
    static constexpr int kSinceFormatVersion = 5;  // the job format that brought it
    std::string pattern = "single";  // "single", "line", "grid", "bolt circle", "arc"
    // single: the hole; line: the first hole; grid: the corner hole (first
    // column, first row); bolt circle, arc: the centre of the circle.
    double x = 0.0, y = 0.0;
    double angle = 0.0;         // line, grid: the rows' direction; bolt circle, arc: the first hole's angle [deg, CCW from +X]
    double pitch = 0.0;         // line: between holes; grid: between columns (along the rows)
    double pitchY = 0.0;        // grid: between rows (90° CCW from the rows)
    double radius = 0.0;        // bolt circle, arc
    double angularPitch = 0.0;  // arc: between holes [deg], counter-clockwise when positive
    int count = 1;              // line, bolt circle, arc: the holes; grid: the columns
    int rows = 1;               // grid
    std::string hole = "drilled";  // "drilled", "tapped", "reamed", "bored"
    double diameter = 0.0;      // drilled, reamed, bored: the finished diameter (tapped: its thread's)
    std::string thread;         // tapped: ISO metric coarse "M3" ... "M20"
    double depth = 0.0;         // the full-diameter depth (tapped: of the full thread), down from the top
    ToolPins tools;             // by step key: "centre-drill", "drill", "tap", "ream", "bore"

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, x, y, pitch, pitchY, radius, diameter, depth);
    }
    friend bool operator==(const HolePattern&, const HolePattern&) = default;
};

// A hole step's own data (Step::payload): the centres of the unit's holes in
// the order they are machined (each gets the step's cycle, down to
// cutDepth), and a tapping step's thread pitch [mm].
struct HoleCentres {
    static constexpr const char* kName = "HOLES centres";
    std::vector<Point2> centres;
    double threadPitch = 0.0;
    MillingGeometry milling{};  // the step's geometry (model/milling_geometry.h)
    friend bool operator==(const HoleCentres&, const HoleCentres&) = default;
};

namespace holes {

constexpr int kMaxHoles = 1000;  // a unit's holes, at most

// ISO metric coarse threads M3-M20: size, pitch and tap drill (ISO 2306,
// the nominal size less the pitch, rounded as the drill tables do).
struct Thread {
    const char* name;  // "M8"
    double size;       // nominal diameter [mm]
    double pitch;      // [mm]
    double tapDrill;   // [mm]
};
const std::vector<Thread>& threadTable();
const Thread* findThread(const std::string& name);

// The hole's depths, from its input (mm) and, for the drill, the drill
// actually chosen (its diameter and point angle; 0: not yet known, the
// bound of a 90° point and the finished diameter is used).
//   drilled: the drill's full diameter at `depth`, its point below;
//   tapped: the tap (form C, 2-3 pitches of chamfer) down to depth + 2P,
//           its drill's full diameter to depth + 3P, the point below;
//   reamed: the reamer (its 45° lead) down to depth + 0.5 mm, the
//           pre-drill's full diameter to depth + 1 mm, the point below;
//   bored:  the boring tool to depth, the pre-drill's full diameter to
//           depth + 1 mm, the point below.
constexpr double kReamLead = 0.5;      // mm
constexpr double kPreDrillBelow = 1.0; // mm
struct Depths {
    double finishDiameter = 0.0;  // tapped: the thread's size; otherwise the diameter
    double drillDiameter = 0.0;   // drilled: the diameter; tapped: the tap drill; reamed, bored: the pre-drill (0 unknown)
    double finish = 0.0;          // the tap's, reamer's or boring tool's tip (0: drilled)
    double drillFull = 0.0;       // where the drill's full diameter reaches
};
Depths depths(const HolePattern& mm);
// The drill's tip below drillFull: its point length r / tan(angle / 2); a
// 90° point (r) when the angle is not known, the longest of usual points.
double pointLength(double drillDiameter, double pointAngle);
// The deepest the hole goes, its drill point included (pre-drills taken as
// wide as the hole): what the stock must hold.
double lowestPoint(const HolePattern& mm);

// The hole centres in machining order: a line from its first hole on; a
// grid row by row, every other row backwards (no long return); a bolt
// circle and an arc counter-clockwise from the start angle (clockwise for
// a negative angular pitch). Inputs checked.
std::vector<Point2> positions(const HolePattern& mm);
// The figure at the top surface the holes take, for the interference check:
// the hole's circle (single); the rectangle around the holes (line, grid);
// the ring around the circle's holes (bolt circle; a sector of it for an
// arc), made a simple polygon with a slit. Flattened outside the circles.
std::vector<Point2> topPolygon(const HolePattern& mm);

// The step keys of a hole kind, in machining order; of every kind.
std::vector<std::string> stepKeys(const std::string& hole);
std::vector<std::string> allStepKeys();

// The step's tool path (holes_paths.cpp): a canned cycle at every hole
// (the technology data does not enter it).
ToolPath cyclesPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);

}  // namespace holes

// The input checks of one HOLES unit (in mm).
check::UnitReport checkHolePattern(const HolePattern& mm, int unitNo, const check::Context& ctx);

// The steps of one HOLES unit in machining order with their tools (inputs
// checked, in mm): centre drilling, drilling, then tapping, reaming or
// boring; a tool missing from the library is a diagnostic naming it.
std::vector<Step> planHolePattern(const HolePattern& mm, int unit, const std::vector<Tool>& library,
                                  const std::string& material, LengthUnit shown, Diagnostics& out);

}  // namespace taiwa
