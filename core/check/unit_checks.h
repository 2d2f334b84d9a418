// Input checks shared by the modules and the job: the context of a unit's
// checks, the reporter, the depth and tool-room checks every pocket module
// uses, the interference check between figures and the unit order. A
// module's own checks live in its folder (core/modules/<kind>/); checkJob
// (job/job_check.h) runs them all.
#pragma once

#include "model/diagnostic.h"
#include "check/messages.h"
#include "model/job.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/turned.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::check {

// What every unit check needs besides the unit: all lengths in mm.
struct Context {
    LengthUnit shownUnit = LengthUnit::Millimetre;  // the job's unit, for quoting values
    std::optional<TechnologyData> tech;             // absent when the material is unknown
    const Stock* stock = nullptr;                   // nullptr when the stock itself is refused
    const std::vector<Tool>* library = nullptr;
    const BarStock* bar = nullptr;                  // lathe jobs: nullptr when the bar itself is refused
};

// Adds diagnostics of one unit (1-based unitNo, module "M4"/"M2D"), or of
// the job, quoting lengths in the job's unit.
struct Reporter {
    int unitNo;
    const char* module;
    const Context& ctx;
    Diagnostics& out;
    void unit(std::string field, std::string message)
    {
        out.push_back({Severity::Error, unitNo, module, std::move(field), std::move(message)});
    }
    void job(std::string field, std::string message)
    {
        out.push_back({Severity::Error, std::nullopt, "", std::move(field), std::move(message)});
    }
    msg::Len len(double mm) const { return {mm, ctx.shownUnit}; }
};

// Collects the diagnostics of one unit (1-based unitNo). Job-level findings
// about the unit (alpha1 or beta2 against its depth) go in with no unit.
struct UnitReport {
    Diagnostics diagnostics;
    bool figureValid = false;  // its top outline is well-formed: take part in the interference check
    // A turning unit that passed: the deformed profile its check made
    // (ModuleKind::turned), which the plan then cuts instead of deforming
    // the profile again.
    std::optional<TurnedPart> turned;
};
// The depth T of either module: positive, and no deeper than the stock
// (when the stock is valid). False when it is not positive.
bool checkDepth(double depth, Reporter& r);

// Every length and coordinate of a job lies within ±kMaxLength mm: beyond it
// a micrometre is no longer exact in a double, nor on a tape. Finite and
// within reach, else a diagnostic on `field` of the unit.
constexpr double kMaxLength = 1e6;  // mm
bool checkLength(double mm, const std::string& field, const std::string& what, Reporter& r);
// The allowances a pocket leaves against its depth T: α1 (the pilot hole
// stops α1 above the floor) when it drills one, β2 (roughing stops β2 above
// the floor) when it roughs or finishes the floor. Reported on the job's
// technology fields, naming the unit. False when one is not below T.
bool checkDepthAllowances(double depth, const TechnologyData& tech, bool drillsPilot, bool roughsToFloor, Reporter& r);

// The step-over's range, the technology data's and a unit's own alike.
constexpr double kStepOverLow = 0.01, kStepOverHigh = 0.9;
constexpr const char* kStepOverWhy =
    "roughing's radial step-over as a multiple of the tool diameter; at 0.9 and above the rings leave cusps";
// A unit's own step-over (a fraction of D): within that range, on field
// "stepOver". True when absent or within.
bool checkStepOver(const std::optional<double>& stepOver, Reporter& r);

// One corner radius that a step's tool must fit into.
struct RoomQuery {
    std::vector<std::string> stepKeys;  // pin keys of the steps using this radius ("roughing", "floor")
    std::string label;                  // how the message names the radius ("r1 - α2")
    double available = 0.0;             // the radius [mm]
    double cornerRadius = 0.0;          // r1 [mm], to say which r1 would let the smallest tool fit
    ToolType type = ToolType::FlatEndMill;
    double taper = 0.0;                 // taper end mills: the angle they must have
};
// Pinned tools too big for the radius are refused naming one that fits;
// unpinned steps need the smallest suitable library tool to fit.
void checkRoom(const RoomQuery& q, const ToolPins& pins, int unitNo, const std::string& module, const Context& ctx,
               Diagnostics& out);
// The smallest library tool of the query's type (a taper end mill: of its
// angle), the one checkRoom measures an unpinned step's room against;
// null when the library has none.
const Tool* smallestSuitable(const std::vector<Tool>& library, const RoomQuery& q);
// Pins of a step the module does not have (`keys`, its door's stepKeys())
// or of a tool id not in the library. Every unit's door runs it
// (ModuleKindOf::check) before the module's own checks, which add only
// what is the module's own (a pinned tool of the wrong type or size).
void checkPins(const ToolPins& pins, const std::vector<std::string>& keys, int unitNo, const std::string& module,
               const Context& ctx, Diagnostics& out);
// The step keys of the pocket modules (pins, speeds and feeds): "pilot",
// "roughing", "floor", "wall", "inclined".
const std::vector<std::string>& millingStepKeys();

// The figure of one unit at the top surface, for the interference check.
struct UnitFigure {
    int unit = 0;                 // 0-based
    std::string module;           // "M4"
    std::string field;            // where an overlap is reported ("corners")
    Quad outline;                 // in mm
    // A figure of any outline (contour units): the outline flattened, in
    // mm; `outline` is then the box around it. Empty for a quad.
    std::vector<Point2> polygon{};
};
// One diagnostic per overlapping pair (on the later unit, naming both), in
// the order of the later unit; at most kMaxDiagnostics of them, then a line
// saying the rest was not looked for. Figures are compared through a grid,
// only with the earlier ones in the cells they cover.
Diagnostics interferences(std::vector<UnitFigure> figures, LengthUnit shownUnit);

// Machining order of the units (0-based indices) from their centres: see
// docs/input-checks.md ("Unit order").
std::vector<int> machiningOrder(const std::vector<Point2>& centres);

}  // namespace taiwa::check
