// The job: what the operator entered, exactly as typed (in the job's length
// unit), and the machining units with their module inputs. Values are kept
// even when input processing refuses them, so that nothing typed is lost.
#pragma once

#include "model/geometry.h"
#include "model/module.h"
#include "model/technology.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

enum class LengthUnit { Millimetre, Inch };
constexpr double kMillimetresPerInch = 25.4;
inline double toMm(double v, LengthUnit u) { return u == LengthUnit::Inch ? v * kMillimetresPerInch : v; }
inline double fromMm(double v, LengthUnit u) { return u == LengthUnit::Inch ? v / kMillimetresPerInch : v; }
const char* unitSymbol(LengthUnit u);  // "mm" or "in"

// Rectangular block of stock; its top face is Z = 0 of the work offset and
// (x, y) is its minimum corner in the work coordinate system.
struct Stock {
    double x = 0.0, y = 0.0;
    double width = 100.0;   // along X
    double length = 100.0;  // along Y
    double height = 30.0;   // along Z, the block spans Z = -height .. 0
    friend bool operator==(const Stock&, const Stock&) = default;
};

// Round bar stock of a lathe job: Z = 0 is the finished front face, the bar
// reaches `face` beyond it (the face stock) and `length` back from there
// toward the chuck; a bore of `bore` diameter (0: solid) runs through it.
struct BarStock {
    double diameter = 50.0;
    double length = 100.0;
    double face = 1.0;
    double bore = 0.0;
    friend bool operator==(const BarStock&, const BarStock&) = default;
};

// How a milling job's block is held, as the operator sets it up: a vice
// whose jaws grip two opposite side faces of the block from its bottom up to
// `height`. The sheet draws and states it; planning and the verification do
// not depend on it.
struct Clamping {
    enum class Grip { X, Y };  // the jaws on the faces at X min and X max, or at Y min and Y max
    Grip grip = Grip::Y;
    double height = 10.0;      // how far up the block's sides the jaws reach, from its bottom
    friend bool operator==(const Clamping&, const Clamping&) = default;
};

// Tool ids the operator pinned for some steps of a unit; any step kind not
// named here has its tool chosen automatically. Keys: "pilot", "roughing",
// "floor", "wall", "inclined".
using ToolPins = std::map<std::string, int>;

// One machining unit: a module input of any kind (core/modules/), the name
// the operator gave it, and the speeds and feeds the operator set for its
// steps by step key (the keys of tool pins: "roughing", "turn-finish").
struct MachiningUnit {
    std::string name;  // optional label the operator gave
    ModuleInput module;
    std::map<std::string, CuttingOverride> cutting{};
    friend bool operator==(const MachiningUnit&, const MachiningUnit&) = default;
};

// Lathe jobs on a two-path lathe (docs/two-path-lathe.md): how the roughing
// is balanced between the paths. Read by the export and verify only when the
// job's machine has paths; the defaults otherwise.
struct TwoPathSettings {
    double dwellRevolutions = 1.0;  // the follower's dwell behind the leader [spindle revolutions], at least 0.5
    bool waitsEverywhere = false;   // a wait at every meeting, not only where the cycle lengths differ
    std::optional<int> firstWait;   // the first wait M-code; none: the machine's waitCodes.first
    friend bool operator==(const TwoPathSettings&, const TwoPathSettings&) = default;
};

struct Job {
    // Version 2 added `dialect`, version 3 lathe jobs (bar stock, turned
    // profiles), version 4 the block's `clamping`, version 5 the `figure`
    // elements and the contour units that use them, version 6 the two-path
    // settings (`twoPath`, written only when not the defaults). A job is written in the
    // oldest version that holds it, so that a program reading version 1
    // still reads every milling job without a dialect.
    static constexpr int kFormatVersion = 6;
    static constexpr int kOldestFormatVersion = 1;
    std::string name;
    LengthUnit lengthUnit = LengthUnit::Millimetre;
    std::string material = "aluminium-6061";
    std::string machine = "vmc";
    std::string workOffset = "G54";
    // The controller dialect the job is posted for ("linuxcnc", "fanuc");
    // empty: not chosen (the command line then posts for linuxcnc, the
    // station for the dialect last chosen).
    std::string dialect;
    Stock stock;                   // milling jobs
    std::optional<BarStock> bar;   // lathe jobs: the stock is a bar (then `stock` is not used)
    std::optional<Clamping> clamping;  // milling jobs: how the block is held; absent: not given
    TechnologyOverrides technology;
    // The figure elements (points, lines, circles, contours) as the APT-like
    // text the operator reads and edits (docs/figure-elements.md), in the
    // job's length unit; contour units name its contours. Empty: none.
    std::string figure;
    // Lathe jobs: roughing as the control's own cycle (G71) where a profile
    // allows it, or always as explicit passes (controls without cycles).
    bool latheRoughingCycles = true;
    TwoPathSettings twoPath;  // lathe jobs on a two-path machine
    std::vector<MachiningUnit> units;
    friend bool operator==(const Job&, const Job&) = default;
};

// The same job with every length (stock, technology overrides, module
// inputs) passed through `convert` and marked as being in `unit`; angles,
// codes and gamma unchanged.
Job withLengths(const Job& job, LengthUnit unit, const LengthMap& convert);

// The same job with every length in mm (lengthUnit = Millimetre); angles,
// codes and gamma unchanged. The pipeline works on this copy only.
Job toMillimetres(const Job& job);

}  // namespace taiwa
