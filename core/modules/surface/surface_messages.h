// The messages of SURFACE, the 3-D surface ruled between two space curves:
// its curves and projections, N and M, the face set's paths, the height
// field, the checks and the ball end mill; the sentences of input processing
// that only this module says, kept in its folder. The geometry's own
// refusals (core/occt/surface_*.cpp) are marked where they are made, the
// curve's name before them by surface::curveRefusal ("curve 2: …").
#pragma once

#include "check/messages.h"

#include <string>

namespace taiwa::msg {

// A curve's name in the refusals: "curve 1", "curve 2".
const char* surfaceCurveName(int which);
// A projection given as a figure contour: none of that name, or a closed one.
std::string surfaceNoContour(const std::string& contour, const std::string& openContours);
std::string surfaceContourClosed(const std::string& contour);
// A curve's points or projections.
std::string surfaceCurveOnePoint(const std::string& curve);
std::string surfaceCurveNeither(const std::string& curve);
std::string surfaceProjectionPlane(const std::string& curve, int projection, const std::string& plane);
// A projection's problem after the curve's name (1 or 2; surface::curveRefusal).
std::string surfaceProjectionProblem(int curve, int projection, const std::string& problem);
std::string surfaceCurveUnread(const std::string& curve, const std::string& text);
// The surface as paths (a STEP face set).
std::string surfaceTooFewPaths();
std::string surfacePathPoints(std::size_t path, std::size_t points, std::size_t first);
// N and M.
std::string surfaceNBelowOne(int n);
std::string surfaceNoM();
std::string surfaceNNotBelowM(int n, int m);
// Machined from above.
std::string surfaceAboveTop(Len top);
std::string surfaceThroughBottom(Len low, Len stockHeight);
// The checks of the form's other fields.
std::string surfaceScallopNotPositive(Len scallop);
std::string surfaceAllowanceNegative(Len allowance);
std::string surfaceBoundaryUnread(const std::string& text);
std::string surfaceBoundaryNoSurface();
std::string surfaceBoundaryMissesSurface();
// The ball end mill; `rho` and `where`: the smallest concave radius and the
// place it is (rho infinite: the surface has no concave bend).
std::string surfacePinnedNotBall(const Tool& pinned);
std::string surfacePinnedTooLarge(const Tool& pinned, Len radius, Len rho, const std::string& where,
                                  const Tool* smaller);
std::string surfaceNoBall(Len rho, const std::string& where);
std::string surfacePinnedByOperator();
std::string surfaceToolReason(const Tool& chosen, Len rho, const std::string& where);

}  // namespace taiwa::msg
