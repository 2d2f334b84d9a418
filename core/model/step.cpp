// Step kinds by name, the label a step shows in lists and on the sheet, and
// a step's milling geometry (its payload's).
#include "model/step.h"

#include "model/translate_noop.h"

#include <array>
#include <stdexcept>
#include <string>

namespace taiwa {

namespace {

// Each step kind's name (lists, the sheet) and key (steps.json, tool pins).
struct StepKindWords {
    StepKind kind;
    const char* name;
    const char* key;
};
constexpr std::array<StepKindWords, 21> kStepKinds{{
    {StepKind::PilotHole, TAIWA_TRANSLATE_NOOP("taiwa::msg", "pilot hole"), "pilot"},
    {StepKind::Roughing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "roughing"), "roughing"},
    {StepKind::FloorFinishing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "floor finishing"), "floor"},
    {StepKind::WallFinishing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "wall finishing"), "wall"},
    {StepKind::InclinedFaceFinishing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "inclined-face finishing"), "inclined"},
    {StepKind::Facing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "facing"), "facing"},
    {StepKind::CentreDrilling, TAIWA_TRANSLATE_NOOP("taiwa::msg", "centre drilling"), "centre-drill"},
    {StepKind::Drilling, TAIWA_TRANSLATE_NOOP("taiwa::msg", "drilling"), "drill"},
    {StepKind::TurnRoughing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "roughing"), "turn-rough"},
    {StepKind::Grooving, TAIWA_TRANSLATE_NOOP("taiwa::msg", "grooving"), "groove"},
    {StepKind::TurnFinishing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "finishing"), "turn-finish"},
    {StepKind::Threading, TAIWA_TRANSLATE_NOOP("taiwa::msg", "threading"), "thread"},
    {StepKind::Parting, TAIWA_TRANSLATE_NOOP("taiwa::msg", "parting off"), "part"},
    {StepKind::Tapping, TAIWA_TRANSLATE_NOOP("taiwa::msg", "tapping"), "tap"},
    {StepKind::Reaming, TAIWA_TRANSLATE_NOOP("taiwa::msg", "reaming"), "ream"},
    {StepKind::Boring, TAIWA_TRANSLATE_NOOP("taiwa::msg", "boring"), "bore"},
    {StepKind::FaceMilling, TAIWA_TRANSLATE_NOOP("taiwa::msg", "face milling"), "face"},
    {StepKind::SideMilling, TAIWA_TRANSLATE_NOOP("taiwa::msg", "side milling"), "side"},
    {StepKind::AreaClearing, TAIWA_TRANSLATE_NOOP("taiwa::msg", "area clearing"), "area"},
    {StepKind::SurfaceRoughing, "surface roughing", "surface-rough"},
    {StepKind::SurfaceFinishing, "surface finishing", "surface-finish"},
}};
static_assert(kStepKinds.size() == static_cast<std::size_t>(StepKind::SurfaceFinishing) + 1, "words for every step kind");

const StepKindWords* wordsOf(StepKind k)
{
    for (const auto& w : kStepKinds)
        if (w.kind == k) return &w;
    return nullptr;
}

}  // namespace

const char* toString(StepKind k)
{
    const auto* w = wordsOf(k);
    return w ? w->name : "";
}

const char* toKey(StepKind k)
{
    const auto* w = wordsOf(k);
    return w ? w->key : "";
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

const MillingGeometry& millingOf(const Step& s)
{
    static const MillingGeometry kNone{};
    const MillingGeometry* g = s.payload.milling();
    return g ? *g : kNone;
}

MillingGeometry& editMilling(Step& s)
{
    if (s.payload.empty()) s.payload = MillingGeometry{};
    if (MillingGeometry* g = s.payload.editMilling()) return *g;
    throw std::logic_error(std::string("a step holding ") + s.payload.name() + " has no milling geometry");
}

}  // namespace taiwa
