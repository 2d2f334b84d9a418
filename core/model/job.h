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

// Tool ids the operator pinned for some steps of a unit; any step kind not
// named here has its tool chosen automatically. Keys: "pilot", "roughing",
// "floor", "wall", "inclined".
using ToolPins = std::map<std::string, int>;

// One machining unit: a module input of any kind (core/modules/) and the
// name the operator gave it.
struct MachiningUnit {
    std::string name;  // optional label the operator gave
    ModuleInput module;
    friend bool operator==(const MachiningUnit&, const MachiningUnit&) = default;
};

struct Job {
    // Version 2 added `dialect`. A job is written as version 1 when it has
    // none, so that a program reading version 1 still reads it.
    static constexpr int kFormatVersion = 2;
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
    Stock stock;
    TechnologyOverrides technology;
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
