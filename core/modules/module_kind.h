// The door of a machining module: everything the job file, the input checks,
// the planning and the station ask of one module kind, in one table. Each kind
// lives in core/modules/<kind>/ and is registered by one line in
// core/modules/registry.cpp; nothing outside its folder names its input
// struct. docs/modules.md says how a module is added.
//
// Implementations derive from ModuleKindOf<T> and receive their own input
// struct T (see model/module.h) instead of the type-erased ModuleInput. What
// the module says to the operator (palette words, form fields, the field an
// overlap is reported on) is its description file's,
// core/modules/<kind>/<kind>.module.json (modules/module_text.h).
#pragma once

#include "check/unit_checks.h"
#include "machine/machine.h"
#include "model/cavity.h"
#include "model/contour.h"
#include "io/json_fields.h"
#include "io/unit_keys.h"
#include "model/diagnostic.h"
#include "model/geometry.h"
#include "model/job.h"
#include "model/module.h"
#include "model/setup.h"
#include "model/sketch.h"
#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/turned.h"
#include "modules/form_binding.h"
#include "modules/module_text.h"
#include "paths/cl.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace taiwa {

// What planning one unit needs besides the unit itself; all lengths in mm.
struct UnitPlanContext {
    const TechnologyData& tech;
    const std::vector<Tool>& library;
    const std::string& material;
    int unit = 0;  // 0-based index of the unit in the job, stored in its steps
    const Job* job = nullptr;          // the whole job in mm (a lathe unit looks at the bar and the other units)
    const Machine* machine = nullptr;  // the job's machine, when known
    LengthUnit shownUnit = LengthUnit::Millimetre;  // messages quote lengths in it
    const TurnedPart* turned = nullptr;  // a turning unit: what its turned() made, for plan() to cut
};

// Area clearing by drawn passes (AREA): what the station's Figure tab draws
// and edits of such a unit, lengths in the job's unit. The area is named by
// contours of the job's figure, which the tab evaluates itself.
struct DrawnPasses {
    std::vector<Point2> points;  // the tool centre goes from each to the next
    double radius = 0.0;         // half the strips' width (the tool's radius)
    std::string outline;
    std::vector<std::string> islands;
};

class ModuleKind {
public:
    virtual ~ModuleKind() = default;

    // "M4": in the job file, in messages, in widget names (lower case).
    virtual const char* name() const = 0;
    // The palette button's words, "Add M4 pocket" (source text of the
    // translation, context "taiwa::ui::ModulePalette").
    virtual const char* paletteText() const = 0;
    // The module's drawing as a Qt resource path (":/modules/m4.svg").
    virtual const char* drawing() const = 0;
    // The job file format version that brought the module: a job holding a
    // unit of it is written in that version or a later one.
    virtual int formatVersion() const = 0;
    // True for a setup unit that sets the job's work offset (probing): its
    // programs must be posted in a dialect that writes probing programs.
    virtual bool setsWorkOffset() const { return false; }

    // A new unit of this kind for the station's "Add", inside the stock.
    virtual ModuleInput makeDefault(const Stock& stock) const = 0;

    // Job file: the unit's own keys (beside "module" and "name").
    virtual ModuleInput read(const io::ObjectFields& unit) const = 0;
    virtual void write(const ModuleInput& m, nlohmann::ordered_json& unit) const = 0;

    // Input checks of one unit (lengths in mm, quoted in the job's unit).
    virtual check::UnitReport check(const ModuleInput& mm, int unitNo, const check::Context& ctx) const = 0;

    // Top-view outline at the stock top for the interference check, the unit
    // order and the preview; nullopt for a unit with no figure in the XY plane.
    virtual std::optional<Quad> topOutline(const ModuleInput& mm) const = 0;
    // A figure of any outline (contour units) gives the box around it as
    // its topOutline and the outline itself here, flattened to 1 µm; empty
    // for a figure that is its quad.
    virtual std::vector<Point2> topPolygon(const ModuleInput& /*mm*/) const { return {}; }
    // The field an overlap is reported on ("corners").
    virtual const char* outlineField() const = 0;
    // The same unit moved by `delta` in XY (the station places a new or
    // duplicated unit in free stock); a unit without a figure stays as it is.
    virtual void moveBy(ModuleInput& m, Point2 delta) const = 0;

    // Decomposition, tool choice and whatever the module must settle between
    // them (M2D: the roughing tool before the layers); problems become
    // diagnostics of the unit. Inputs are checked and in mm.
    virtual std::vector<Step> plan(const ModuleInput& mm, const UnitPlanContext& ctx, Diagnostics& out) const = 0;

    // The tool path of one of the unit's milling steps (paths/cl.h: the tool
    // tip, from and back to the safe height), made by the module's own
    // generators from the step's geometry. Turning steps come with their
    // paths (their TurnStep, model/turn_path.h) and a unit without milling
    // steps has none to make: the default throws std::logic_error. Throws
    // std::logic_error too for a step the checks should have refused.
    virtual ToolPath toolPath(const Step& step, const Tool& tool, const TechnologyData& tech,
                              const PathParameters& params) const;
    // About how many moves toolPath would make for the step, from its
    // geometry alone, in microseconds: the pipeline refuses a plan whose
    // paths would not fit its move budget before computing any of them.
    virtual double estimateMoves(const Step& /*step*/, const Tool& /*tool*/, const TechnologyData& /*tech*/,
                                 const PathParameters& /*params*/) const
    {
        return 10;
    }
    // What one of the step's moves costs the export (its path, verification,
    // tape and read-back), counted in moves of a pocket: the budget weighs
    // each step's estimate by it, so that one budget bounds every module's
    // time and memory alike. 1 by default; more for a module whose moves
    // cost more (SURFACE's nose points: a drop-cutter each, and a ball's
    // whole disc swept in the verification for each short move).
    virtual double workPerMove() const { return 1.0; }
    // The unit's field that drives its moves most, named when a plan would
    // not fit the move budget (the unit `mm`, in mm; `step` its step with the
    // most moves): by default "stepOver" when the step has the unit's own
    // step-over, else "depth" (the layers).
    virtual std::string movesField(const ModuleInput& /*mm*/, const Step& step) const
    {
        return millingOf(step).stepOver ? "stepOver" : "depth";
    }
    // The order of the unit's own steps: true when `later` must wait for
    // `earlier` (both steps of one unit of this kind). The job-wide order
    // (tools/step_order.cpp) keeps these and otherwise saves tool changes.
    // By default the steps of one kind follow their numbers.
    virtual bool stepWaitsFor(const Step& later, const Step& earlier) const
    {
        return later.kind == earlier.kind && earlier.number < later.number;
    }
    // The step's own data the module adds to its entry in STEM.steps.json
    // (after its depths and outline; lengths in `u` through io::stepLength).
    // Nothing by default.
    virtual void describeStep(const Step& /*step*/, LengthUnit /*u*/, nlohmann::ordered_json& /*entry*/) const {}
    // True for a unit whose steps come before every other unit's (FACE:
    // the top is faced first, the others' depths being measured from it).
    virtual bool cutsBeforeOtherUnits() const { return false; }

    // The station's form, top to bottom (the tab order).
    virtual const std::vector<FormField>& fields() const = 0;
    // Contour units: the contours the unit names are given to it from the
    // job's evaluated figure (name -> contour in mm, closed or open), before
    // it is checked and planned. Nothing for other modules.
    virtual void resolveContours(ModuleInput& /*mm*/, const ContourTable& /*contours*/) const {}
    // Contour units: figure-element text defining the contours makeDefault's
    // unit names, inside `stock` (in the job's unit: the text is in it too),
    // for a job that has no figure yet. Empty for other modules.
    virtual std::string defaultFigure(const Stock& /*stock*/) const { return {}; }
    // Drawn passes (AREA): the unit's points and strip radius for the Figure
    // tab, and the points set from the tab (false: the module has none).
    virtual std::optional<DrawnPasses> drawnPasses(const ModuleInput& /*unit*/) const { return std::nullopt; }
    virtual bool setDrawnPoints(ModuleInput& /*unit*/, std::vector<Point2> /*points*/) const { return false; }
    // What a setup unit hands on besides steps (probing: the measured centre
    // and the probing cycle); nothing for machining units. Inputs are checked
    // and in mm.
    virtual std::optional<WorkSetup> setup(const ModuleInput& /*mm*/, const UnitPlanContext& /*ctx*/) const
    {
        return std::nullopt;
    }
    // The keys of the steps a unit of this kind may have (tool pins and the
    // operator's speeds and feeds use them): "roughing", "turn-finish".
    // None: the unit has no cutting steps (probing).
    virtual std::vector<std::string> stepKeys() const { return {}; }
    // The steps whose S is a surface speed in m/min (constant surface
    // speed on a lathe), not rpm.
    virtual bool surfaceSpeedStep(const std::string& /*key*/) const { return false; }

    // The finished shape the unit cuts into the stock (model/cavity.h), from
    // its geometry, for the verification; nothing for a unit that cuts no
    // cavity from the top (probing, turning). Inputs are checked and in mm.
    virtual std::optional<Cavity> cavity(const ModuleInput& /*mm*/, const TechnologyData& /*tech*/) const
    {
        return std::nullopt;
    }

    // The kind of machine the module runs on: milling modules on a mill,
    // turning modules on a lathe.
    virtual MachineKind machineKind() const { return MachineKind::Mill; }
    // What a turning unit hands on besides steps: its profile and the
    // deformed profile to cut. Inputs are checked and in mm.
    virtual std::optional<TurnedPart> turned(const ModuleInput& /*mm*/, const UnitPlanContext& /*ctx*/) const
    {
        return std::nullopt;
    }
    // A turning unit's profile table (the station's profile editor, STEP
    // import); nullptr for other modules. setTurnedProfile replaces it and
    // says whether the module has one.
    virtual const turning::TurnedProfile* turnedProfile(const ModuleInput& /*m*/) const { return nullptr; }
    virtual bool setTurnedProfile(ModuleInput& /*m*/, const turning::TurnedProfile& /*p*/) const { return false; }
    // The unit's live figure for the station's form (model/sketch.h), from
    // the unit as the job holds it (lengths in `unit`); nothing for modules
    // whose form shows their fixed drawing only.
    virtual std::optional<Sketch> sketch(const ModuleInput& /*unit*/, LengthUnit /*unit*/,
                                         const std::vector<Tool>& /*library*/) const
    {
        return std::nullopt;
    }
    // The free-form surface a milling step machines, for the 3-D view
    // (viz/scene_surface.cpp): point paths of equal length in mm, each
    // path's points beside the next path's; empty for a step with none
    // (SURFACE's finishing step gives its finishing surface).
    virtual std::vector<std::vector<Point3>> machinedSurface(const Step& /*step*/) const { return {}; }
};

// Adapter: implementations work on their own input struct.
template <class T>
class ModuleKindOf : public ModuleKind {
public:
    using CheckFunction = check::UnitReport (*)(const T& unit, int unitNo, const check::Context& ctx);
    using PathFunction = ToolPath (*)(const Step& step, const Tool& tool, const TechnologyData& tech,
                                      const PathParameters& params);

    // keys: the unit's job-file table (io/unit_keys.h), which reads and
    // writes the unit; checks: the unit's own input checks; paths: the tool
    // path of one of its milling steps (toolPath). A module whose unit is a
    // grammar of its own (TURN's profile table) passes no table and
    // overrides readInput and writeInput; one whose checks need more than
    // the unit passes no check and overrides checkInput; one whose steps
    // come with their paths (TURN) passes no path function.
    explicit ModuleKindOf(const io::UnitKeys<T>* keys = nullptr, CheckFunction checks = nullptr,
                          PathFunction paths = nullptr)
        : keys_(keys), check_(checks), paths_(paths)
    {
    }

    const char* name() const final { return T::kName; }
    int formatVersion() const final { return T::kSinceFormatVersion; }
    // The module's description file's (core/modules/<kind>/<kind>.module.json).
    const char* paletteText() const final { return description().palette.c_str(); }
    const char* outlineField() const final { return description().outlineField.c_str(); }
    // core/modules/<kind>/<kind>.svg, a resource of the station.
    const char* drawing() const final
    {
        static const std::string path = ":/modules/" + folder() + ".svg";
        return path.c_str();
    }
    ModuleInput read(const io::ObjectFields& unit) const final { return readInput(unit); }
    void write(const ModuleInput& m, nlohmann::ordered_json& unit) const final { writeInput(m.as<T>(), unit); }
    // The pins of steps the module has, of tools the library has, for
    // every module (check::checkPins); then the module's own checks.
    check::UnitReport check(const ModuleInput& mm, int unitNo, const check::Context& ctx) const final
    {
        const T& m = mm.as<T>();
        check::UnitReport report = checkInput(m, unitNo, ctx);
        if constexpr (requires { m.tools; }) {
            Diagnostics pins;
            check::checkPins(m.tools, stepKeys(), unitNo, T::kName, ctx, pins);
            report.diagnostics.insert(report.diagnostics.begin(), pins.begin(), pins.end());
        }
        return report;
    }
    std::optional<Quad> topOutline(const ModuleInput& mm) const final { return outline(mm.as<T>()); }
    void moveBy(ModuleInput& m, Point2 delta) const final { move(m.as<T>(), delta); }
    std::vector<Step> plan(const ModuleInput& mm, const UnitPlanContext& ctx, Diagnostics& out) const final
    {
        return planInput(mm.as<T>(), ctx, out);
    }
    ToolPath toolPath(const Step& step, const Tool& tool, const TechnologyData& tech,
                      const PathParameters& params) const final
    {
        return paths_ ? paths_(step, tool, tech, params) : ModuleKind::toolPath(step, tool, tech, params);
    }
    // The description file's fields, each bound by the door (ownField) or
    // by the job-file table (form::boundForm); made once per module kind,
    // so a field the door binds must not keep the door (its `this`).
    const std::vector<FormField>& fields() const final
    {
        static const std::vector<FormField> fs =
            form::boundForm(description().fields, keys_, [this](const form::FieldText& t) { return ownField(t); });
        return fs;
    }

protected:
    virtual T readInput(const io::ObjectFields& unit) const { return keys().read(unit); }
    virtual void writeInput(const T& m, nlohmann::ordered_json& unit) const { keys().write(m, unit); }
    virtual check::UnitReport checkInput(const T& mm, int unitNo, const check::Context& ctx) const
    {
        if (!check_) throw std::logic_error(std::string("module ") + T::kName + " has no input check");
        return check_(mm, unitNo, ctx);
    }
    virtual std::optional<Quad> outline(const T& mm) const = 0;
    virtual void move(T& m, Point2 delta) const = 0;
    virtual std::vector<Step> planInput(const T& mm, const UnitPlanContext& ctx, Diagnostics& out) const = 0;
    // A field of the form that the door binds itself, asked first for every
    // field: one the job file holds in a grammar of its own (M4's corners,
    // PROBE's touches), or one the door shows otherwise than the table
    // would (HOLES' pattern and hole, texts offered as codes); nullopt: the
    // job-file table binds it by its key.
    virtual std::optional<FormField> ownField(const form::FieldText& /*t*/) const { return std::nullopt; }

private:
    // The module's folder under core/modules/: its name in lower case.
    static std::string folder()
    {
        std::string f = T::kName;
        for (char& c : f) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return f;
    }
    static const form::ModuleText& description()
    {
        static const form::ModuleText text = form::shippedModuleText(folder());
        return text;
    }
    const io::UnitKeys<T>& keys() const
    {
        if (!keys_) throw std::logic_error(std::string("module ") + T::kName + " has neither a job-file table nor a reader");
        return *keys_;
    }
    const io::UnitKeys<T>* keys_;
    CheckFunction check_;
    PathFunction paths_;
};

// The one instance of a module kind, for its `<kind>Module()` function.
template <class Kind>
const ModuleKind& moduleInstance()
{
    static const Kind kind;
    return kind;
}

}  // namespace taiwa
