// A milling step's geometry: where it cuts (its outline or region, its
// position), how deep (the depths it cuts between), what it leaves (its
// allowances) and how (taper, incisions, step-over). It is the step's
// payload (model/step_payload.h), not a member of Step: the steps of the
// milling modules carry it (the pockets M4, M2D and CP, FACE, SIDE, AREA,
// HOLES and SURFACE), a turning step does not. A module with data of its
// own besides it (SIDE's passes, FACE's pass angle, ...) holds it as
// that struct's member `milling`; the pocket steps hold it alone.
//
// The stages read it through millingOf(step) (model/step.h), which gives an
// empty geometry (no outline, depths 0); a decomposition sets it whole, and
// a later change (tool choice) goes through editMilling(step).
#pragma once

#include "model/boxed.h"
#include "model/contour.h"
#include "model/geometry.h"

#include <optional>

namespace taiwa {

struct MillingGeometry {
    static constexpr const char* kName = "milling geometry";

    // Depths are positive, measured down from the top surface.
    // Boundary the tool edge reaches (with its corner radius): at cutDepth for
    // vertical walls; for tapered wall steps (wallTaper > 0) the outline at the
    // top surface, the wall leaning inward by depth x tan(wallTaper) below it.
    // FACE and SURFACE: the rectangle the step covers.
    Boxed<Quad> outline{};  // (model/boxed.h: an optional on the heap)
    // Steps of contour units (any outline, islands): the region whose
    // boundary the tool edge reaches, instead of `outline`; and the largest
    // tool radius that reaches every part of it (its narrowest channel and
    // smallest inside corner radius).
    Boxed<Region> region{};
    double reach = 0.0;
    double inscribed = 0.0;  // the radius of the largest circle in the region

    Point2 position{};            // pilot hole centre; otherwise the outline's centroid
    double holeDiameter = 0.0;    // pilot hole: the smallest diameter it must have (0 = not yet known); hole patterns: the diameter the step's tool makes
    double startDepth = 0.0;      // above this depth everything is air (rapid)
    double cutDepth = 0.0;        // deepest point the step cuts
    double wallTaper = 0.0;       // degrees per side of the wall this step cuts
    double wallAllowance = 0.0;   // left on the walls after this step
    double floorAllowance = 0.0;  // left on the floor after this step
    bool multiIncision = false;   // wall cut in several Z incisions (F = 2)
    // Roughing (and FACE's, SIDE's passes): the unit's radial step-over as a
    // fraction of the tool diameter, when the unit overrides the technology
    // data's.
    std::optional<double> stepOver{};

    friend bool operator==(const MillingGeometry&, const MillingGeometry&) = default;
};

}  // namespace taiwa
