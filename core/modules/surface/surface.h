// Module SURFACE: a 3-D surface machined from above (seed 002, second and
// sixth abstracts; docs/surfaces.md). The surface is ruled between two space
// curves, each given as points in space or as two plane projections sharing
// an axis; both curves are divided into N pieces for the roughing surface
// and M > N for the finishing surface. Roughing by Z levels leaves an
// allowance; finishing by parallel paths holds a scallop height; both stop
// where they meet an optional boundary surface. One ball end mill, chosen by
// the surface's smallest concave radius, cuts both. The geometry is
// core/occt/surface_*; here are the door (surface_kind.cpp), the checks and
// the steps (surface_plan.cpp) and the paths (surface_paths.cpp).
#pragma once

#include "model/cavity.h"

#include "check/unit_checks.h"
#include "model/diagnostic.h"
#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "modules/length_fields.h"
#include "model/toolpath.h"
#include "paths/cl.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// One plane projection of a curve: the plane ("XY", "YZ" or "ZX") and the
// curve in its two coordinates in that order: as points, or as an open
// contour of the job's figure (its lines and arcs, the figure's X and Y
// being the plane's two coordinates), whose points the mm unit gets when
// the figure is evaluated (ModuleKind::resolveContours), its arcs to 0.1 µm.
struct SurfaceProjection {
    std::string plane;
    std::vector<Point2> points;
    std::string contour;  // a figure contour's name ("K1"); empty: `points` as given
    // Why `contour` gives no points (the figure has no such contour, or it
    // is closed), for the check to refuse on the curve; never in the file.
    std::string contourProblem;
    friend bool operator==(const SurfaceProjection&, const SurfaceProjection&) = default;
};

namespace surfacemod {
// How far a contour projection's points stray from its arcs [mm]: a tenth of
// the micrometre the surface is held to.
constexpr double kContourTolerance = 1e-4;
}  // namespace surfacemod

// A space curve as the operator gives it: points in space, or (when
// `points` is empty) two projections sharing an axis.
struct SurfaceCurve {
    std::vector<Point3> points;
    std::vector<SurfaceProjection> projections;
    bool smooth = true;  // a smooth curve through the points, else straight lines
    friend bool operator==(const SurfaceCurve&, const SurfaceCurve&) = default;
};

struct SurfaceUnit {
    static constexpr const char* kName = "SURFACE";
    static constexpr int kSinceFormatVersion = 5;
    SurfaceCurve curve1, curve2;         // Z in the work system, the stock top at 0
    int n = 4;                           // roughing pieces
    std::optional<int> m;                // finishing pieces; from curveStep when absent
    std::optional<double> curveStep;     // the step along the curves that gives M
    double scallop = 0.01;               // finishing's scallop height
    double allowance = 0.3;              // left by roughing, along the normal
    std::vector<std::vector<Point3>> boundary;  // a cutting boundary surface as paths; none when empty
    // The surface itself as point-sequence paths (a STEP face set sampled
    // by `taiwa import --surface`, occt/surface_step.h), in place of the
    // curves: roughing and finishing both machine it, N and M unused.
    std::vector<std::vector<Point3>> surface;
    ToolPins tools;                      // key "surface": a ball end mill
    // The form's text of a curve or the boundary that does not read, kept
    // for the check to refuse on its field (the values stay as they were);
    // never in the job file. Lengths in it are not converted.
    std::string curve1Bad, curve2Bad, boundaryBad;

    void convertLengths(const LengthMap& f)
    {
        for (SurfaceCurve* c : {&curve1, &curve2}) {
            convertEach(f, c->points);
            for (SurfaceProjection& pr : c->projections) convertEach(f, pr.points);
        }
        convertEach(f, curveStep, scallop, allowance, boundary, surface);
    }
    friend bool operator==(const SurfaceUnit&, const SurfaceUnit&) = default;
};

// A surface step's own data (Step::payload): the surface (roughing's with N
// pieces or finishing's with M) and the boundary as point paths, and what
// the paths are made with.
struct SurfacePaths {
    static constexpr const char* kName = "SURFACE paths";
    std::vector<std::vector<Point3>> surface;
    // Roughing's: the finishing surface, which it stays off by the allowance
    // too (the N surface's chords may pass under the M surface).
    std::vector<std::vector<Point3>> finished;
    std::vector<std::vector<Point3>> boundary;
    double scallop = 0.0;        // finishing
    double allowance = 0.0;      // roughing
    double concaveRadius = 0.0;  // the smallest concave radius (infinity: none)
    double step = 0.5;           // along a path [mm]
    MillingGeometry milling{};  // the step's geometry (model/milling_geometry.h)
    friend bool operator==(const SurfacePaths&, const SurfacePaths&) = default;
};

namespace surfacemod {

constexpr const char* kStepKey = "surface";

// The unit's surfaces as point paths (across the rulings, about 1 mm
// apart), or the field and message that refuse it.
struct Built {
    std::vector<std::vector<Point3>> roughing, finishing;
    int m = 0;
    std::string field, problem;  // problem empty: built
};
Built buildSurfaces(const SurfaceUnit& mm, LengthUnit shown);

// The curves and the boundary as the form shows and reads them
// (surface_text.cpp): a curve "x, y, z; x, y, z" or "XY: a, b; a, b / ZX:
// a, b; a, b", "/ lines" at the end for straight lines between its points;
// the boundary's paths "x, y, z; ... / x, y, z; ..." (empty: none).
// nullopt: the text does not read.
std::string formatCurve(const SurfaceCurve& c);
std::optional<SurfaceCurve> parseCurve(const std::string& text);
std::string formatBoundary(const std::vector<std::vector<Point3>>& paths);
std::optional<std::vector<std::vector<Point3>>> parseBoundary(const std::string& text);

// The ball end mill for the surface: the pinned one, else the largest whose
// radius is less than the smallest concave radius `rho`.
struct ToolPick {
    const Tool* tool = nullptr;
    std::string reason, problem;
};
ToolPick chooseTool(const SurfaceUnit& mm, double rho, const std::string& where, const std::vector<Tool>& library,
                    LengthUnit shown);

// The step's tool path (surface_paths.cpp): the surface tessellated once,
// the nose points by the drop-cutter, stopped at the boundary, linked.
ToolPath surfacePath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);

// The finished part for the verification (model/cavity.h): the material
// under the finishing surface, its depth at a point the surface's height
// there (past the surface's edges, nothing judged), grown or shrunk by
// `slack` times the steepest facet's slope; nothing when the unit builds
// no surface.
std::optional<Cavity> surfaceCavity(const SurfaceUnit& u);

}  // namespace surfacemod

check::UnitReport checkSurface(const SurfaceUnit& mm, int unitNo, const check::Context& ctx);
// The unit's two steps (checked, in mm): Z-level roughing over the N
// surface leaving the allowance, then parallel finishing over the M surface
// at the scallop height, one ball end mill for both.
std::vector<Step> planSurface(const SurfaceUnit& mm, const TechnologyData& tech, const std::vector<Tool>& library,
                              int unit, LengthUnit shown, Diagnostics& out);


}  // namespace taiwa
