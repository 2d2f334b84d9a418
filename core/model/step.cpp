// Step kinds by name, and the label a step shows in lists and on the sheet.
#include "model/step.h"

#include <array>

namespace taiwa {

const char* toString(StepKind k)
{
    switch (k) {
    case StepKind::PilotHole: return "pilot hole";
    case StepKind::Roughing: return "roughing";
    case StepKind::FloorFinishing: return "floor finishing";
    case StepKind::WallFinishing: return "wall finishing";
    case StepKind::InclinedFaceFinishing: return "inclined-face finishing";
    case StepKind::Facing: return "facing";
    case StepKind::CentreDrilling: return "centre drilling";
    case StepKind::Drilling: return "drilling";
    case StepKind::TurnRoughing: return "roughing";
    case StepKind::Grooving: return "grooving";
    case StepKind::TurnFinishing: return "finishing";
    case StepKind::Threading: return "threading";
    case StepKind::Parting: return "parting off";
    case StepKind::Tapping: return "tapping";
    case StepKind::Reaming: return "reaming";
    case StepKind::Boring: return "boring";
    case StepKind::FaceMilling: return "face milling";
    case StepKind::SideMilling: return "side milling";
    case StepKind::AreaClearing: return "area clearing";
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
