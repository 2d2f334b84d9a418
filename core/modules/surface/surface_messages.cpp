// The wording of surface_messages.h: the messages of SURFACE, the 3-D
// surface ruled between two space curves.
#include "modules/surface/surface_messages.h"

#include "model/tool.h"
#include "model/translate_noop.h"
#include "occt/surface_curves.h"

#include <fmt/format.h>

#include <cmath>

namespace taiwa::msg {

const char* surfaceCurveName(int which)
{
    return which == 1 ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "curve 1") : TAIWA_TRANSLATE_NOOP("taiwa::msg", "curve 2");
}

std::string surfaceNoContour(const std::string& contour, const std::string& openContours)
{
    const std::string open = openContours.empty() ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "none") : openContours;
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the figure has no contour {}; its open contours: {}"),
                       contour, open);
}

std::string surfaceContourClosed(const std::string& contour)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "contour {} is closed; a projection runs from one end to the other"),
        contour);
}

std::string surfaceCurveOnePoint(const std::string& curve)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has one point; give two or more [x, y, z]"), curve);
}

std::string surfaceCurveNeither(const std::string& curve)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} has neither points [x, y, z] nor two projections (XY, YZ or ZX)"),
        curve);
}

std::string surfaceProjectionPlane(const std::string& curve, int projection, const std::string& plane)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: projection {} is in plane \"{}\"; give XY, YZ or ZX"),
                       curve, projection, plane);
}

std::string surfaceProjectionProblem(int curve, int projection, const std::string& problem)
{
    return surface::curveRefusal(
        curve, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "projection {}: {}"), projection, problem));
}

std::string surfaceCurveUnread(const std::string& curve, const std::string& text)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                            "{} \"{}\" does not read: give points \"x, y, z; x, y, z\" or two "
                                            "projections \"XY: a, b; a, b / ZX: a, b; a, b\""),
                       curve, text);
}

std::string surfaceTooFewPaths()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the surface needs at least 2 paths of 2 points or more");
}

std::string surfacePathPoints(std::size_t path, std::size_t points, std::size_t first)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "path {} has {} points; every path has as many as the first ({})"), path,
        points, first);
}

std::string surfaceNBelowOne(int n)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "N {} must be 1 or more: the roughing surface needs pieces"),
                       n);
}

std::string surfaceNoM()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                "give M (the finishing surface's pieces) or the step along the curves that implies it");
}

std::string surfaceNNotBelowM(int n, int m)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "N {} is not less than M {}: the finishing surface must be "
                                                          "divided more finely than the roughing surface (N < M)"),
                       n, m);
}

std::string surfaceAboveTop(Len top)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the surface rises to Z {} above the stock top (Z 0); the "
                                                          "surface is cut into the stock from above"),
                       quote(top));
}

std::string surfaceThroughBottom(Len low, Len stockHeight)
{
    return fmt::format(
        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the surface goes down to Z {}, through the stock's bottom (height {})"),
        quote(low), quote(stockHeight));
}

std::string surfaceScallopNotPositive(Len scallop)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the scallop height {} must be greater than 0"),
                       quote(scallop));
}

std::string surfaceAllowanceNegative(Len allowance)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the allowance {} must be 0 or more"), quote(allowance));
}

std::string surfaceBoundaryUnread(const std::string& text)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the boundary \"{}\" does not read: give paths of points "
                                                          "\"x, y, z; x, y, z\" separated by \"/\""),
                       text);
}

std::string surfaceBoundaryNoSurface()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                "the boundary makes no surface: give two or more paths with the same number of points");
}

std::string surfaceBoundaryMissesSurface()
{
    return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the boundary surface never meets the surface: no path would stop at it; "
                                              "move it onto the surface or leave it out");
}

std::string surfacePinnedNotBall(const Tool& pinned)
{
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is pinned for \"surface\" but is not a ball end mill"),
                       toolName(pinned));
}

std::string surfacePinnedTooLarge(const Tool& pinned, Len radius, Len rho, const std::string& where,
                                  const Tool* smaller)
{
    if (smaller)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                "{} is pinned for \"surface\" but its radius {} is not less than the "
                                                "surface's smallest concave radius {} ({}); {} would fit"),
                           toolName(pinned), quote(radius), quote(rho), where, toolName(*smaller));
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} is pinned for \"surface\" but its radius {} is not less "
                                                          "than the surface's smallest concave radius {} ({}), and the "
                                                          "library has no smaller ball end mill"),
                       toolName(pinned), quote(radius), quote(rho), where);
}

std::string surfaceNoBall(Len rho, const std::string& where)
{
    if (!std::isfinite(rho.mm))
        return TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool library has no ball end mill; add one");
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool library has no ball end mill with a radius less "
                                                          "than the surface's smallest concave radius {} ({}); add a "
                                                          "smaller one"),
                       quote(rho), where);
}

std::string surfacePinnedByOperator() { return TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned by the operator"); }

std::string surfaceToolReason(const Tool& chosen, Len rho, const std::string& where)
{
    if (!std::isfinite(rho.mm))
        return fmt::format(
            TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest ball end mill (Ø{:g} mm); the surface has no concave bend"),
            chosen.diameter);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                            "largest ball end mill (Ø{:g} mm) under the smallest concave radius {} ({})"),
                       chosen.diameter, quote(rho), where);
}

}  // namespace taiwa::msg
