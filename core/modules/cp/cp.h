// Module CP: the contour pocket, a 2.5-D pocket of any outline of lines and
// arcs with any number of islands, its walls vertical. The outline and the
// islands are contours of the job's figure elements (core/figure/), named in
// the unit; the job layer resolves the names into the unit's region in mm
// (job/figure_contours.h) before it is checked and planned. Its decomposition
// is cp_decompose.cpp; everything else is behind its door (cp_kind.cpp).
#pragma once

#include "check/unit_checks.h"
#include "model/contour.h"
#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
#include "modules/length_fields.h"
#include "modules/named_region.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct ContourPocket {
    static constexpr const char* kName = "CP";
    static constexpr int kSinceFormatVersion = 5;  // the job format that brought it
    // The contour of the pocket's edge at the top ("K1") and those of the
    // islands left standing in it, and (not in the job file) the region the
    // job's figure makes of them in mm, set by the job layer: `region` is
    // absent until then, or when a name is not a contour of the figure.
    NamedRegion contours;
    double depth = 0.0;                // T, measured down from the top surface
    int toolUse = 1;                   // U (Table 1): 1, 6, 8 or 9
    int wallFinish = 1;                // F (Table 2)
    std::optional<double> stepOver;    // roughing's step-over (fraction of D); the technology's when absent
    ToolPins tools;

    // Of the region, worked out once when it is resolved (paths/region.h):
    // the check's tool room and the decomposition's steps both use them.
    double reach = 0.0;
    double inscribed = 0.0;

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, depth, reach, inscribed, contours.region);
    }
    friend bool operator==(const ContourPocket&, const ContourPocket&) = default;
};

// The input checks of one CP unit (in mm).
check::UnitReport checkContourPocket(const ContourPocket& mm, int unitNo, const check::Context& ctx);

// The process steps of one CP unit (inputs in mm, checked and resolved;
// tools, paths and times not yet chosen): roughing to T - β2 leaving α2 on
// the walls and islands, floor finishing, and the wall passes of code F
// around the outline and every island.
std::vector<Step> decomposeContourPocket(const ContourPocket& pocket, const TechnologyData& tech, int unit);

// After the tool choice (cp_kind.cpp): a finishing step left without a tool
// because the end mills that pass the contour's narrowest place have flutes
// shorter than the depth (modules/pocket_tools.h, narrowForcesShortFlutes)
// is refused on the contour's field ("outline" or "islands") naming that
// place, the end mill whose flutes reach the depth and how much more room it
// needs, instead of the shortest flutes on "tools".
void nameNarrowPlaceOfShortFlutes(const ContourPocket& pocket, const std::vector<Step>& steps,
                                  const std::vector<Tool>& library, const std::string& material, LengthUnit shown,
                                  int unitNo, Diagnostics& out);

}  // namespace taiwa
