// Matching library tools to what a step asks of them.
#include "tools/tool_fit.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <cmath>

namespace taiwa::tools {

namespace {

// The first thing that keeps `t` from the step, or None. Tool choice asks
// this of every library tool for every step: no words are made for it.
enum class Misfit { None, Type, Material, Taper, CornerRadius, CentreCutting, TooLarge, TooSmall, Flutes, Stickout };

Misfit misfit(const Tool& t, const Fit& f, const std::string& material)
{
    if (t.type != f.type) return Misfit::Type;
    if (!t.cuttingFor(material)) return Misfit::Material;
    if (f.type == ToolType::TaperEndMill && !sameAngle(t.taperAngle, f.taperAngle)) return Misfit::Taper;
    if (f.cornerRadius > 0 && !fitsInto(t.radius(), f.cornerRadius)) return Misfit::CornerRadius;
    if (f.centreCutting && !t.centreCutting) return Misfit::CentreCutting;
    if (!fitsInto(t.diameter, f.maxDiameter)) return Misfit::TooLarge;
    if (!fitsInto(f.minDiameter, t.diameter)) return Misfit::TooSmall;
    if (t.fluteLength > 0 && !fitsInto(f.depth, t.fluteLength)) return Misfit::Flutes;
    if (t.stickout > 0 && !fitsInto(f.reach, t.stickout)) return Misfit::Stickout;
    return Misfit::None;
}

}  // namespace

std::string whyNot(const Tool& t, const Fit& f, const std::string& material)
{
    switch (misfit(t, f, material)) {
    case Misfit::None: return {};
    case Misfit::Type:
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it is a {}, the step needs a {}"), toString(t.type),
                           toString(f.type));
    case Misfit::Material: return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "it has no cutting data for {}"), material);
    case Misfit::Taper:
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its taper is {:g} deg per side, the wall's is {:g}"),
                           t.taperAngle, f.taperAngle);
    case Misfit::CornerRadius:
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "its radius {:g} mm is larger than the corner radius {:g} mm"),
            t.radius(), f.cornerRadius);
    case Misfit::CentreCutting:
        return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                    "it does not cut at its centre, so it cannot ramp in without a pilot hole");
    case Misfit::TooLarge:
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "its diameter {:g} mm is too large for the pocket"),
                           t.diameter);
    case Misfit::TooSmall:
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "its diameter {:g} mm is smaller than the {:g} mm needed"), t.diameter,
            f.minDiameter);
    case Misfit::Flutes:
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "its flutes ({:g} mm) are shorter than the depth {:g} mm"),
            t.fluteLength, f.depth);
    case Misfit::Stickout:
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "its stick-out ({:g} mm) is shorter than the depth {:g} mm"), t.stickout,
            f.reach);
    }
    return {};
}

bool fits(const Tool& t, const Fit& f, const std::string& material) { return misfit(t, f, material) == Misfit::None; }

const Tool* largestFitting(const std::vector<Tool>& library, const Fit& f, const std::string& material)
{
    const Tool* best = nullptr;
    for (const auto& t : library)
        if (fits(t, f, material) && (!best || t.diameter > best->diameter)) best = &t;
    return best;
}

const Tool* smallestFitting(const std::vector<Tool>& library, const Fit& f, const std::string& material)
{
    const Tool* best = nullptr;
    for (const auto& t : library)
        if (fits(t, f, material) && (!best || t.diameter < best->diameter)) best = &t;
    return best;
}

std::string noFitMessage(const std::vector<Tool>& library, const Fit& f, const std::string& material,
                         const std::string& what)
{
    const Tool* smallest = nullptr;
    for (const auto& t : library)
        if (t.type == f.type && (f.type != ToolType::TaperEndMill || sameAngle(t.taperAngle, f.taperAngle)) &&
            (!smallest || t.diameter < smallest->diameter))
            smallest = &t;
    if (!smallest) {
        if (f.type == ToolType::TaperEndMill)
            return fmt::format(
                TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                     "no taper end mill of {:g} deg per side in the tool library for the {}"),
                f.taperAngle, what);
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "no {} in the tool library for the {}"), toString(f.type),
                           what);
    }
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "no {} in the tool library fits the {}: T{} ({}) is the nearest, but {}"),
        toString(f.type), what, smallest->id, smallest->name, whyNot(*smallest, f, material));
}

}  // namespace taiwa::tools
