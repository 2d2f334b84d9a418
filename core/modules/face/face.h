// Module FACE: face milling of the stock top. The whole top of the block
// (grown by a margin beyond its sides) is lowered by a depth in roughing
// layers and a finishing pass, by parallel passes one way or back and forth
// at an angle. The checks are face_check.cpp, the tool choice and the steps
// face_decompose.cpp, the door face_kind.cpp; the passes are
// paths/face_milling.cpp. docs/face-milling.md says what it makes and why.
#pragma once

#include "check/unit_checks.h"
#include "model/diagnostic.h"
#include "model/geometry.h"
#include "model/job.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "modules/length_fields.h"
#include "paths/cl.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct FaceUnit {
    static constexpr const char* kName = "FACE";
    static constexpr int kSinceFormatVersion = 5;  // the job format that brought it
    double depth = 0.0;              // stock removed from the top, down from Z0
    int toolUse = 1;                 // U: 1 roughing layers and a finishing pass, 9 roughing only
    std::optional<double> finish;    // the finishing pass's depth (U9: the allowance left); the technology's β2 when absent
    double angle = 0.0;              // direction of the passes [deg, counter-clockwise from +X]
    int pattern = 1;                 // 1 one way (climb), 2 zigzag
    std::optional<double> stepOver;  // between passes, a fraction of D; 0.75 (face mill) or the technology's when absent
    double margin = 0.0;             // how far the face reaches beyond the stock's sides
    ToolPins tools;                  // key "face"

    void convertLengths(const LengthMap& f)
    {
        convertEach(f, depth, finish, margin);
    }
    friend bool operator==(const FaceUnit&, const FaceUnit&) = default;
};

// A face-milling step's own data (Step::payload; its geometry's outline is the
// face to mill): the passes run at `angle` degrees from +X, one way or back
// and forth (zigzag).
struct FacePasses {
    static constexpr const char* kName = "FACE passes";
    double angle = 0.0;
    bool zigzag = false;
    MillingGeometry milling{};  // the step's geometry (model/milling_geometry.h)
    friend bool operator==(const FacePasses&, const FacePasses&) = default;
};

namespace face {

constexpr int kOneWay = 1, kZigzag = 2;
constexpr int kStandard = 1, kRoughOnly = 9;
constexpr double kFaceMillStepOver = 0.75;  // a face mill's default step-over [× D]
constexpr double kStepOverLow = 0.01, kStepOverHigh = 0.9;
constexpr const char* kStepKey = "face";

// The face to mill: the stock's top grown by the margin, counter-clockwise.
Quad faceOutline(const Stock& stock, double margin);
// The finishing pass's depth (U1), or the allowance roughing leaves (U9).
double finishDepth(const FaceUnit& mm, const TechnologyData& tech);
// What a tool's flutes or inserts cut at most in one layer (0: unknown, any).
double cuttingLength(const Tool& t);
// The deepest roughing layer with this tool: γ·D, no more than its cutting length.
double layerLimit(const Tool& t, const TechnologyData& tech);
// The step-over [× D]: the unit's, else 0.75 for a face mill, else the technology's.
double stepOverFor(const FaceUnit& mm, const Tool& t, const TechnologyData& tech);

// The tool for the unit's steps: the pinned one, else the largest face mill
// (else the largest flat end mill) whose cutting length takes the finishing
// pass, tools with cutting data for the material first. nullptr with
// `problem` said when none fits.
struct ToolPick {
    const Tool* tool = nullptr;
    std::string reason;   // why this one (the step's ToolChoice)
    std::string problem;  // why none, on field "tools.face"
};
ToolPick chooseTool(const FaceUnit& mm, const TechnologyData& tech, const std::vector<Tool>& library,
                    const std::string& material, LengthUnit shown);

// The step's tool path (face_paths.cpp): parallel passes across the face at the step's angle.
ToolPath millingPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& p);

}  // namespace face

// The input checks of one FACE unit (in mm).
check::UnitReport checkFace(const FaceUnit& mm, int unitNo, const check::Context& ctx);

// The steps of one FACE unit with its tool (inputs checked, in mm): roughing
// layers of at most γ·D (and the tool's cutting length) down to depth -
// finish, then the finishing pass at the depth (U1); every step the whole
// face, its passes at the unit's angle.
std::vector<Step> decomposeFace(const FaceUnit& mm, const Stock& stock, const TechnologyData& tech, const Tool& tool,
                                int unit);

}  // namespace taiwa
