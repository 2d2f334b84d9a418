// The job: what the operator entered, exactly as typed (in the job's length
// unit), and the machining units with their module inputs. Values are kept
// even when input processing refuses them, so that nothing typed is lost.
#pragma once

#include "model/geometry.h"
#include "model/technology.h"

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <variant>
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

// Module M4: 2.5-D pocket with walls parallel to the depth direction.
struct M4Pocket {
    std::array<Point2, 4> corners{};  // P1..P4 of the final outline at the top
    double cornerRadius = 0.0;        // r1
    double depth = 0.0;               // T, measured down from the top surface
    double taper = 0.0;               // S, degrees per side, 0 = vertical
    int toolUse = 1;                  // U (Table 1)
    int wallFinish = 1;               // F (Table 2)
    int pilotHole = 0;                // H (Table 3)
    ToolPins tools;
    friend bool operator==(const M4Pocket&, const M4Pocket&) = default;
};

// Module M2D: geometric 3-D pocket, the two walls at the ends of L1 inclined.
struct M2DPocket {
    Point2 corner{};             // (X1, Y1): reference corner of the top opening
    double lengthX = 0.0;        // L1, top opening along X
    double lengthY = 0.0;        // L2, top opening along Y
    double depth = 0.0;          // T
    double theta1 = 0.0;         // left wall angle from the vertical [deg]
    std::optional<double> theta2;  // right wall angle; equals theta1 when absent
    double cornerRadius = 0.0;   // r1 of the vertical corners
    int toolUse = 1;             // U: 1 or 9 only
    int pilotHole = 0;           // H
    double scallop = 0.01;       // scallop height of the inclined-face finish
    ToolPins tools;
    double rightAngle() const { return theta2.value_or(theta1); }
    friend bool operator==(const M2DPocket&, const M2DPocket&) = default;
};

using ModuleInput = std::variant<M4Pocket, M2DPocket>;

// Module name as written in the job file and messages: "M4", "M2D".
const char* moduleName(const ModuleInput& m);

struct MachiningUnit {
    std::string name;  // optional label the operator gave
    ModuleInput module;
    friend bool operator==(const MachiningUnit&, const MachiningUnit&) = default;
};

struct Job {
    static constexpr int kFormatVersion = 1;
    std::string name;
    LengthUnit lengthUnit = LengthUnit::Millimetre;
    std::string material = "aluminium-6061";
    std::string machine = "vmc";
    std::string workOffset = "G54";
    Stock stock;
    TechnologyOverrides technology;
    std::vector<MachiningUnit> units;
    friend bool operator==(const Job&, const Job&) = default;
};

// The same job with every length (stock, technology overrides, module
// inputs) passed through `convert` and marked as being in `unit`; angles,
// codes and gamma unchanged.
Job withLengths(const Job& job, LengthUnit unit, const std::function<double(double)>& convert);

// The same job with every length in mm (lengthUnit = Millimetre); angles,
// codes and gamma unchanged. The pipeline works on this copy only.
Job toMillimetres(const Job& job);

}  // namespace taiwa
