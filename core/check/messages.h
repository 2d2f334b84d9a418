// Every message of input processing, in one place (so that the wording is
// consistent and can be translated): one function per refusal, each a
// sentence a machinist understands, quoting values in the job's length unit.
#pragma once

#include "model/job.h"
#include "model/tool.h"

#include <string>
#include <vector>

namespace taiwa::msg {

// A length to quote: the value in mm, shown in the job's unit ("12.5 mm", "0.4921 in").
struct Len {
    double mm;
    LengthUnit unit;
};
std::string quote(Len v);
std::string quoteDeg(double deg);  // "5°"
std::string toolName(const Tool& t);  // "T12 (flat end mill Ø6 mm)", always in mm like the library

// Job level.
std::string notFinite(const std::string& what);
// "the coordinate X of P1 is 1e+10 mm; every length must lie within ±1000000 mm ..."
std::string beyondReach(const std::string& what, Len value, Len limit);
// "γ is 1e-09; it must lie between 0.05 and 2 (...)"
std::string technologyOutOfRange(const std::string& name, double shownValue, double low, double high,
                                 const std::string& unitText, const std::string& why);
std::string scallopTooSmall(Len scallop, Len smallest);
std::string stockTooLarge(const std::string& key, Len value, Len limit);
std::string unknownMaterial(const std::string& id, const std::vector<std::string>& known);
std::string stockNotPositive(const std::string& what, Len v);
std::string technologyNotPositive(const std::string& name, double shownValue, const std::string& unitText);
std::string alpha3NotBelowAlpha2(Len a3, Len a2);
std::string alpha1NotBelowDepth(int unitNo, Len a1, Len depth);
std::string beta2NotBelowDepth(int unitNo, Len b2, Len depth);

// Area clearing by drawn passes (AREA).
std::string pointsUnreadable(const std::string& typed);
std::string tooFewPoints(std::size_t count);
std::string pointOutsideStock(std::size_t index, Len x, Len y);
std::string passSamePoint(int pass);
std::string passLeavesArea(int pass, Len x, Len y, Len by, const std::string& outline);  // pass 0: the start point
std::string diameterNotPositive(Len d);
std::string noToolOfDiameter(Len d, const std::vector<double>& diametersMm, LengthUnit unit);
std::string pinnedDiameterDiffers(const Tool& pinned, Len d);
std::string unswept(double areaMm2, int pieces, double largestMm2, Len x, Len y, LengthUnit unit);

// Dimensions and codes of a unit.
std::string depthNotPositive(Len depth);
std::string deeperThanStock(Len depth, Len stockHeight);
std::string lengthNotPositive(const std::string& name, Len v);
std::string radiusNegative(Len r1);
std::string outsideStock(const std::string& figure);
std::string duplicateCorner(int first, int second, Len x, Len y);
std::string selfIntersecting();
std::string notConvex();
std::string radiusOverHalfSide(Len r1, Len shortestSide);
std::string radiusOverInscribed(Len r1, Len inscribed);
std::string radiusOverHalfL2(Len r1, Len l2);
std::string taperOutOfRange(double taper);
std::string taperClosesPocket(double taper, Len meetDepth);
std::string thetaOutOfRange(const std::string& name, double theta);
std::string floorVanishes(Len floorWidth, Len needed, Len shortBy);
std::string scallopNotPositive(Len scallop);
std::string toolUseUndefined(int code);
std::string toolUseUnknown(int code);
std::string toolUseNotForM2D(int code);
std::string wallFinishUnknown(int code);
std::string pilotHoleUnknown(int code);

// Tools.
std::string unknownPinKey(const std::string& key);
// The operator's speeds and feeds of a unit's steps ("cutting").
std::string unknownCuttingKey(const std::string& key, const std::string& module, const std::vector<std::string>& keys);
std::string noCuttingSteps(const std::string& module);
std::string cuttingValueOutOfRange(const std::string& what, double value, const std::string& unit, double low,
                                   double high, const std::string& why);
std::string toolNotInLibrary(int id);
std::string noToolOfType(const std::string& typeName);
std::string noTaperTool(double taper, const std::vector<double>& anglesInLibrary);
// `label` names the radius ("r1 - α2"); `neededR1` is the r1 the smallest tool would need.
std::string noRoomForTool(const std::string& label, Len available, const Tool& smallest, Len neededR1);
std::string pinnedToolTooBig(const std::string& step, const Tool& pinned, const std::string& label, Len available,
                             const Tool* fitting);

// Contour units (CP): their contours, named from the job's figure.
std::string contourNotNamed(const std::string& role);                 // role: "outline"
std::string contourUnknown(const std::string& name, const std::vector<std::string>& known);
std::string contourOpen(const std::string& name, const std::string& what, const std::string& role);  // what: "pocket"
std::string contourCrossesItself(const std::string& name);
std::string islandOutside(const std::string& island, const std::string& what, const std::string& outline);
std::string islandsOverlap(const std::string& a, const std::string& b);
std::string sharpInsideCorner(const std::string& name, Len x, Len y);
std::string toolUseNotForContours(int code);

// Side milling (SIDE): its contour, codes, width and room.
std::string sideContourNotNamed();
std::string sideCodeUnknown(const std::string& code, int value, const std::string& allowed);
std::string sideWidthNotAboveAllowance(Len width, Len alpha2);
std::string sidePinKeyUnknown(const std::string& key);
std::string sideNoTool(const std::string& step, const std::string& why);
std::string sideChannelTooNarrow(const std::string& name, const std::string& tool, Len x, Len y);

// Interference of two figures.
std::string overlap(int unitNo, int otherUnitNo, double areaMm2, LengthUnit unit);

}  // namespace taiwa::msg
