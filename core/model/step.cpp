// Step kinds by name, and the label a step shows in lists and on the sheet.
#include "model/step.h"

#include "model/translate_noop.h"

#include <array>

namespace taiwa {

const char* toString(StepKind k)
{
    switch (k) {
    case StepKind::PilotHole: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "pilot hole");
    case StepKind::Roughing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "roughing");
    case StepKind::FloorFinishing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "floor finishing");
    case StepKind::WallFinishing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "wall finishing");
    case StepKind::InclinedFaceFinishing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "inclined-face finishing");
    case StepKind::Facing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "facing");
    case StepKind::CentreDrilling: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "centre drilling");
    case StepKind::Drilling: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "drilling");
    case StepKind::TurnRoughing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "roughing");
    case StepKind::Grooving: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "grooving");
    case StepKind::TurnFinishing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "finishing");
    case StepKind::Threading: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "threading");
    case StepKind::Parting: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "parting off");
    case StepKind::Tapping: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "tapping");
    case StepKind::Reaming: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "reaming");
    case StepKind::Boring: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "boring");
    case StepKind::FaceMilling: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "face milling");
    case StepKind::SideMilling: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "side milling");
    case StepKind::AreaClearing: return TAIWA_TRANSLATE_NOOP("taiwa::msg", "area clearing");
    case StepKind::SurfaceRoughing: return "surface roughing";
    case StepKind::SurfaceFinishing: return "surface finishing";
    }
    return "";
}

const char* toKey(StepKind k)
{
    switch (k) {
    case StepKind::PilotHole: return "pilot";
    case StepKind::Roughing: return "roughing";
    case StepKind::FloorFinishing: return "floor";
    case StepKind::WallFinishing: return "wall";
    case StepKind::InclinedFaceFinishing: return "inclined";
    case StepKind::Facing: return "facing";
    case StepKind::CentreDrilling: return "centre-drill";
    case StepKind::Drilling: return "drill";
    case StepKind::TurnRoughing: return "turn-rough";
    case StepKind::Grooving: return "groove";
    case StepKind::TurnFinishing: return "turn-finish";
    case StepKind::Threading: return "thread";
    case StepKind::Parting: return "part";
    case StepKind::Tapping: return "tap";
    case StepKind::Reaming: return "ream";
    case StepKind::Boring: return "bore";
    case StepKind::FaceMilling: return "face";
    case StepKind::SideMilling: return "side";
    case StepKind::AreaClearing: return "area";
    case StepKind::SurfaceRoughing: return "surface-rough";
    case StepKind::SurfaceFinishing: return "surface-finish";
    }
    return "";
}

namespace {
std::string roman(int n)
{
    static constexpr std::array<std::pair<int, const char*>, 13> table{{{1000, "M"}, {900, "CM"}, {500, "D"},
        {400, "CD"}, {100, "C"}, {90, "XC"}, {50, "L"}, {40, "XL"}, {10, "X"}, {9, "IX"}, {5, "V"}, {4, "IV"}, {1, "I"}}};
    std::string out;
    for (const auto& [value, letters] : table)
        for (; n >= value; n -= value) out += letters;
    return out;
}
}  // namespace

std::string Step::label() const
{
    std::string s = toString(kind);
    s[0] = static_cast<char>(s[0] - 'a' + 'A');
    if (kind == StepKind::PilotHole || kind == StepKind::Facing || kind == StepKind::CentreDrilling ||
        kind == StepKind::Drilling || kind == StepKind::Parting || kind == StepKind::Tapping ||
        kind == StepKind::Reaming || kind == StepKind::Boring)
        return s;
    return s + " " + roman(number);
}

}  // namespace taiwa
