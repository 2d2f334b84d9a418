// A process step: one machining operation of one unit, as the decomposition
// makes it (kind, number, machining type, and what its module makes), later
// given its tool, its cutting data, its tool path and its time by the
// tool-choice and CL stages. Step holds what every stage reads of every
// step; what the module makes (a milling step's outline, depths and
// allowances, an inclined face of M2D, a turning step's path and speeds,
// SIDE's passes, ...) is the step's payload (model/step_payload.h).
#pragma once

#include "model/boxed.h"
#include "model/milling_geometry.h"
#include "model/step_payload.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/toolpath.h"

#include <optional>
#include <string>

namespace taiwa {

enum class StepKind {
    PilotHole,
    Roughing,
    FloorFinishing,
    WallFinishing,
    InclinedFaceFinishing,
    // Turning (model/turn_path.h): in the order a bar is cut.
    Facing,
    CentreDrilling,
    Drilling,
    TurnRoughing,
    TurnFinishing,
    Grooving,
    Threading,
    Parting,
    // Hole patterns (module HOLES) besides CentreDrilling and Drilling: the
    // finishing of a hole after its drill.
    Tapping,
    Reaming,
    Boring,
    // Contour units besides the contour pocket: face milling of the stock
    // top (module FACE), side milling along a contour (module SIDE), area
    // clearing along passes the operator drew (module AREA).
    FaceMilling,
    SideMilling,
    AreaClearing,
    // 3-D surfaces (module SURFACE): Z-level roughing, parallel finishing.
    SurfaceRoughing,
    SurfaceFinishing,
};
const char* toString(StepKind k);  // "roughing"
const char* toKey(StepKind k);     // "roughing" as in steps.json and tool pins ("pilot", "floor", "wall", "inclined";
                                   // turning: "facing", "centre-drill", "drill", "turn-rough", "turn-finish", "groove", "thread", "part")

// Machining-type code attached to every step for the post-processor
// (seed: "attached with a predetermined machining type code"):
// 10 pilot hole, 20 roughing, 30 floor finishing, 40 wall finishing,
// 41 wall semi-finish, 42 taper-wall middle pass, 50 inclined-face finishing;
// turning: 60 facing, 61 centre drilling, 62 drilling, 70 roughing,
// 71 finishing, 72 grooving, 73 parting, 74 threading; hole patterns: 61
// centre drilling, 62 drilling as on the lathe, 63 tapping, 64 reaming,
// 65 boring; 80 face milling, 81 face finishing, 85 side milling, 86 side
// finishing, 90 area clearing by drawn passes; 95 surface roughing, 96
// surface finishing.
enum class MachiningType : int {
    PilotHole = 10,
    Roughing = 20,
    FloorFinishing = 30,
    WallFinishing = 40,
    WallSemiFinishing = 41,
    WallMiddlePass = 42,
    InclinedFaceFinishing = 50,
    Facing = 60,
    CentreDrilling = 61,
    Drilling = 62,
    TurnRoughing = 70,
    TurnFinishing = 71,
    Grooving = 72,
    Parting = 73,
    Threading = 74,
    Tapping = 63,
    Reaming = 64,
    Boring = 65,
    FaceMilling = 80,
    FaceFinishing = 81,
    SideMilling = 85,
    SideFinishing = 86,
    AreaClearing = 90,
    SurfaceRoughing = 95,
    SurfaceFinishing = 96,
};

struct Step {
    int unit = 0;                 // index of the unit in the job (0-based)
    std::string module;           // "M4", "M2D"
    StepKind kind = StepKind::Roughing;
    int number = 1;               // 1-based within the unit and kind: roughing I, II, ...
    MachiningType machiningType = MachiningType::Roughing;

    // What the step's module makes (model/step_payload.h): a milling step's
    // geometry (model/milling_geometry.h: outline or region, position,
    // depths, allowances, taper, step-over; millingOf(step) reads it), alone
    // or with the module's own data — SIDE's contour and passes, FACE's pass
    // angle, AREA's drawn points, HOLES' centres, M2D's inclined face,
    // SURFACE's paths, each struct in its module's folder (M2D's in
    // modules/inclined_face.h, beside the pocket modules' shared code). A
    // turning step's TurnStep (model/turn_path.h: side, speeds, the path in
    // XZ; turnOf(step) reads it) is its payload too, and then `path` stays
    // empty: milling's stages pass it by.
    StepPayload payload{};

    // Filled by the later stages; absent until then, never faked.
    std::optional<ToolChoice> tool{};
    Boxed<ToolPath> path{};
    std::optional<double> minutes{};  // estimated machining time: length over feed, rapids at one rate
    // The time as the machine moves (acceleration, corners, look-ahead;
    // machine/motion_time.h), when the job's machine says how it moves.
    std::optional<double> machineMinutes{};
    // The operator's S and F for this step (its unit's `cutting` for its
    // kind; F in mm per minute, or per revolution on a lathe), in place of
    // the tool's cutting data.
    CuttingOverride cutting{};
    // A milling step's S and F, bound once by planJob from its tool's
    // cutting data and the operator's values (tools/cutting.h
    // stepSpeedsFeeds); the paths' times, the post, the sheet and the step
    // table read them. Absent for a tool with no cutting data for the
    // material, and for turning steps (theirs are in their TurnStep).
    std::optional<SpeedsFeeds> speeds{};

    std::string label() const;  // "Roughing II" ("Pilot hole", "Wall finishing I", ...)
    friend bool operator==(const Step&, const Step&) = default;
};

// A step's milling geometry (its payload's, model/milling_geometry.h); an
// empty one (no outline or region, depths and allowances 0) for a step
// without: a turning step.
const MillingGeometry& millingOf(const Step& s);
// The step's milling geometry to change (tool choice): a step with no payload
// is given an empty one, which a payload set later replaces. Throws
// std::logic_error for a step whose payload has none (a turning step's). Take
// it anew for each change: a payload a copy shares is cloned first.
MillingGeometry& editMilling(Step& s);

}  // namespace taiwa
