// Module M4: the 2.5-D pocket with walls parallel to the depth direction (or
// tapered by S), four corners and one corner radius. Its input as the job
// keeps it, and its decomposition (core/modules/m4/m4_decompose.cpp). The
// rest of the module is behind its door (m4_kind.cpp).
#pragma once

#include "model/geometry.h"
#include "model/job.h"
#include "model/module.h"
#include "model/step.h"
#include "model/technology.h"
#include "modules/length_fields.h"

#include <array>
#include <vector>

namespace taiwa {

struct M4Pocket {
    static constexpr const char* kName = "M4";
    static constexpr int kSinceFormatVersion = 1;  // the job format that brought it
    std::array<Point2, 4> corners{};  // P1..P4 of the final outline at the top
    double cornerRadius = 0.0;        // r1
    double depth = 0.0;               // T, measured down from the top surface
    double taper = 0.0;               // S, degrees per side, 0 = vertical
    int toolUse = 1;                  // U (Table 1)
    int wallFinish = 1;               // F (Table 2)
    int pilotHole = 0;                // H (Table 3)
    std::optional<double> stepOver;   // roughing's step-over (fraction of D) for this unit; the technology's when absent
    ToolPins tools;

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, corners, cornerRadius, depth);
    }
    friend bool operator==(const M4Pocket&, const M4Pocket&) = default;
};

// The outline roughing and floor finishing share: the cross-section at the
// roughing depth T - β2 less α2, cut with vertical walls (so that roughing
// never touches a tapered wall). Inputs in mm.
Quad m4RoughOutline(const M4Pocket& pocket, const TechnologyData& tech);

// The process steps of one M4 unit (inputs in mm and checked; tools, paths
// and times not yet chosen). `unit` is the 0-based unit index stored in each step.
std::vector<Step> decomposeM4(const M4Pocket& pocket, const TechnologyData& tech, int unit);

}  // namespace taiwa
