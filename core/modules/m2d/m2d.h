// Module M2D: the geometric 3-D pocket whose two walls at the ends of L1 are
// inclined (θ1, θ2), the other two vertical. Its input as the job keeps it,
// its cross-section at a depth and its decomposition. The rest of the module
// is behind its door (m2d_kind.cpp).
#pragma once

#include "model/geometry.h"
#include "model/job.h"
#include "model/module.h"
#include "model/step.h"
#include "model/technology.h"
#include "modules/length_fields.h"
#include "modules/pocket_tools.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct M2DPocket {
    static constexpr const char* kName = "M2D";
    static constexpr int kSinceFormatVersion = 1;  // the job format that brought it
    Point2 corner{};               // (X1, Y1): reference corner of the top opening
    double lengthX = 0.0;          // L1, top opening along X
    double lengthY = 0.0;          // L2, top opening along Y
    double depth = 0.0;            // T
    double theta1 = 0.0;           // left wall angle from the vertical [deg]
    std::optional<double> theta2{};  // right wall angle; equals theta1 when absent
    double cornerRadius = 0.0;     // r1 of the vertical corners
    int toolUse = 1;               // U: 1 or 9 only
    int pilotHole = 0;             // H
    double scallop = 0.01;         // scallop height of the inclined-face finish
    std::optional<double> stepOver{};  // roughing's step-over (fraction of D) for this unit; the technology's when absent
    ToolPins tools{};
    double rightAngle() const { return theta2.value_or(theta1); }

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, corner, lengthX, lengthY, depth, cornerRadius, scallop);
    }
    friend bool operator==(const M2DPocket&, const M2DPocket&) = default;
};

// The pocket's cross-section at a depth (vertical corners keep r1).
Quad m2dCrossSection(const M2DPocket& pocket, double depth);

// The process steps of one M2D unit. The roughing layer count depends on the
// roughing tool's diameter D: n = round-half-up((T - beta2) / (gamma * D)).
std::vector<Step> decomposeM2D(const M2DPocket& pocket, const TechnologyData& tech, double roughingToolDiameter,
                               int unit);

// The roughing tool, chosen before the decomposition (the layer count
// depends on its diameter): the largest end mill that fits the narrowest
// layer and the corners less α2, reaching one layer deep.
ToolPick chooseM2DRoughingTool(const M2DPocket& mmPocket, const TechnologyData& tech, const std::vector<Tool>& library,
                               const std::string& material);

}  // namespace taiwa
