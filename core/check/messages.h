// The messages of input processing that the stages share (so that the
// wording is consistent and can be translated): one function per refusal,
// each a sentence a machinist understands, quoting values in the job's length
// unit. What only one module says is in its folder (modules/<kind>/
// <kind>_messages.h; the pockets' shared codes in modules/pocket_messages.h,
// the contours' in modules/region_messages.h), built on quote() and
// toolName() here.
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
std::string stockTooLarge(const std::string& key, Len value, Len limit);
std::string unknownMaterial(const std::string& id, const std::vector<std::string>& known);
std::string stockNotPositive(const std::string& what, Len v);
std::string technologyNotPositive(const std::string& name, double shownValue, const std::string& unitText);
std::string alpha1NotBelowDepth(int unitNo, Len a1, Len depth);
std::string beta2NotBelowDepth(int unitNo, Len b2, Len depth);

// Dimensions and codes of a unit.
std::string depthNotPositive(Len depth);
std::string deeperThanStock(Len depth, Len stockHeight);
std::string lengthNotPositive(const std::string& name, Len v);

// A key of a unit's tool pins ("tools") or of the operator's speeds and
// feeds ("cutting") that is not one of the module's steps.
std::string unknownStepKey(const std::string& key, const std::string& module, const std::vector<std::string>& keys);
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

// Interference of two figures.
std::string overlap(int unitNo, int otherUnitNo, double areaMm2, LengthUnit unit);

}  // namespace taiwa::msg
