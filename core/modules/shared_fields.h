// Form fields that several modules' doors share word for word (key, label,
// check fields, symbol, help line): the pockets' (M4, M2D, CP) depth T,
// corner radius r1 and codes U, F and H, and the named contours of a contour
// unit's area (CP, AREA; modules/named_region.h). Each door still lists its
// fields in its own order (ModuleKindOf::formFields); labels and help lines
// are source texts of the translation as in form_fields.h. Included by the
// modules' *_kind.cpp only.
#pragma once

#include "model/codes.h"
#include "model/translate_noop.h"
#include "modules/form_fields.h"

#include <functional>
#include <initializer_list>
#include <string>
#include <utility>

namespace taiwa::form {

// T: the depth of a pocket of module P (member `depth`).
template <class P>
FormField pocketDepth()
{
    return member<P>("depth", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "T (depth)"), {"depth"}, &P::depth)
        .described("sym-T",
                   TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Depth of the pocket, down from the top surface"));
}

// r1: the corner radius of a pocket of module P (member `cornerRadius`).
template <class P>
FormField pocketCornerRadius()
{
    return member<P>("r1", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "r1 (corner radius)"), {"cornerRadius"},
                     &P::cornerRadius)
        .described("sym-r1",
                   TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec",
                                        "Radius of the pocket's corners; the finishing end mill must fit in it"));
}

// U: the tool use of a pocket of module P (member `toolUse`), offering the
// codes the module takes.
template <class P>
FormField pocketToolUse(std::initializer_list<ToolUse> allowed)
{
    return code<P>("U", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "U (tool use)"), allowed, &P::toolUse)
        .described(TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec",
                                        "Which steps the pocket gets: roughing, floor and wall finishing, or some of them"));
}

// F: the wall finish of a pocket of module P (member `wallFinish`).
template <class P>
FormField pocketWallFinish()
{
    return code<P>("F", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "F (wall finish)"),
                   {WallFinish::SingleIncision, WallFinish::MultiIncision, WallFinish::TwoStage}, &P::wallFinish)
        .described(TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec",
                                        "How the walls are finished: at full depth, in several depths, or in two stages"));
}

// H: the pilot hole of a pocket of module P (member `pilotHole`).
template <class P>
FormField pocketPilotHole()
{
    return code<P>("H", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "H (pilot hole)"),
                   {PilotHole::Drill, PilotHole::None}, &P::pilotHole)
        .described(TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec",
                                        "Whether a hole is drilled first for the roughing end mill to go down into"));
}

// The outline of the named region of module U reached by `region` (a member
// pointer or a function of U& returning the NamedRegion's reference), its
// label and help line saying what the area is.
template <class U, class Region>
FormField regionOutline(Region region, std::string label, std::string help)
{
    return contourName<U>(TAIWA_TRANSLATE_NOOP("taiwa::msg", "outline"), std::move(label), {"outline"},
                          [region](auto& u) -> auto& { return std::invoke(region, u).outline; })
        .described("sym-outline", std::move(help));
}

// The islands of the named region of module U reached by `region`.
template <class U, class Region>
FormField regionIslands(Region region, std::string help)
{
    return contourNames<U>("islands", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Islands"), {"islands"},
                           [region](auto& u) -> auto& { return std::invoke(region, u).islands; })
        .described("sym-islands", std::move(help));
}

}  // namespace taiwa::form
