// A cutting tool of the shop's library, and the record of why a step got it.
#pragma once

#include "model/local_name.h"
#include "model/shared_text.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

enum class ToolType {
    CentreDrill,
    Drill,
    FlatEndMill,
    BallEndMill,
    TaperEndMill,
    FaceMill,
    TurningInsert,
    Grooving,
    Threading,
    Probe,
    // Hole patterns (module HOLES): a machine tap (its pitch is the
    // TurningSpec's pitchMin = pitchMax), a reamer, a boring tool set to
    // its bore (the diameter).
    Tap,
    Reamer,
    BoringBar,
};
const char* toString(ToolType t);                     // "flat end mill"
const char* toKey(ToolType t);                        // "flat_end_mill" (database, JSON)
std::optional<ToolType> toolTypeFromKey(const std::string& key);

// Cutting data of one tool for one material.
struct CuttingData {
    std::string material;       // material id of the technology table
    double surfaceSpeed = 0.0;  // vc [m/min]
    double feedPerTooth = 0.0;  // fz [mm/tooth], for drills feed per revolution
    double plungeFactor = 0.5;  // plunge / ramp feed as a fraction of the feed
    friend bool operator==(const CuttingData&, const CuttingData&) = default;
};

// What a lathe tool adds to a tool (types TurningInsert, Grooving,
// Threading): the insert as the shop names it (ISO 1832, parsed by
// tools/insert_code.h), the holder, and for blades and threading inserts
// their own limits. Zero or empty where it does not apply.
struct TurningSpec {
    std::string insertCode;      // "CNMG 120408"; the nose radius is the tool's cornerRadius
    double approachAngle = 0.0;  // the holder's approach (lead) angle κr [deg]: 95, 93, 107.5
    std::string hand;            // "right", "left" or "neutral"
    bool inside = false;         // a boring bar (inner profiles)
    double minBore = 0.0;        // boring bars: the smallest bore it enters [mm]
    double width = 0.0;          // grooving and parting blades [mm]
    double maxDepth = 0.0;       // grooving blades: the deepest groove [mm]
    double maxDiameter = 0.0;    // parting blades: the largest diameter parted off [mm]
    double pitchMin = 0.0, pitchMax = 0.0;  // threading inserts [mm]; a tap (milling): its pitch, both the same
    double threadAngle = 0.0;    // threading inserts: 60 (metric), 55 (Whitworth) [deg]
    bool empty() const { return *this == TurningSpec{}; }
    friend bool operator==(const TurningSpec&, const TurningSpec&) = default;
};

struct Tool {
    int id = 0;                  // the library's id; also the T number
    std::string name;            // as the tape, the sheet and the command line name it
    LocalNames names;            // the name in other languages, for the station (none: `name` in every language)
    ToolType type = ToolType::FlatEndMill;
    double diameter = 0.0;       // [mm], at the tip for taper end mills; inserts: the inscribed circle, blades: the width
    double cornerRadius = 0.0;   // corner or nose radius [mm]
    double taperAngle = 0.0;     // degrees per side (taper end mills)
    double pointAngle = 118.0;   // drills [deg]
    double fluteLength = 0.0;    // [mm]
    double stickout = 0.0;       // length out of the holder [mm]
    std::string holder;
    // The holder's nose (collet nut, shrink-fit sleeve) the verification
    // keeps clear of the stock [mm]; 0: read from the holder's name
    // (tools/holder_shape.h).
    double holderDiameter = 0.0;
    double holderLength = 0.0;
    int flutes = 2;
    bool centreCutting = true;   // end mills: can ramp or plunge into solid material (face mills cannot)
    double lifeMinutes = 0.0;    // cutting time a fresh tool lasts
    double usedMinutes = 0.0;    // cutting time already spent
    std::vector<CuttingData> cutting;  // turning tools: feedPerTooth is the feed per revolution [mm/rev]
    TurningSpec turning;               // lathe tools
    double radius() const { return diameter / 2.0; }
    double remainingLife() const { return lifeMinutes - usedMinutes; }
    const CuttingData* cuttingFor(const std::string& material) const;
    friend bool operator==(const Tool&, const Tool&) = default;
};

// Why a step got its tool, in words for the sheet and the step list.
struct ToolChoice {
    int toolId = 0;
    SharedText reason;  // why this tool (shared by the steps with the same reason)
    friend bool operator==(const ToolChoice&, const ToolChoice&) = default;
};

// The tool of that id in `library`; nullptr when there is none.
const Tool* findTool(const std::vector<Tool>& library, int id);

// One rule for every fit of a tool (input checks, tool choice, the paths
// that take the tool, a drill of a bore's size): a size fits into a room when
// it exceeds it by no more than kFitTolerance, 1 µm, half the tape's
// resolution in mm — so that a tool fitting exactly by the documented rule is
// not refused for the rounding of the arithmetic, nor for a value typed in
// inch to five decimals (r 6 mm is 0.23622 in, 12 nm short of 6 mm); a taper
// end mill is "of that angle" within kAngleTolerance.
constexpr double kFitTolerance = 1e-3;    // mm
constexpr double kAngleTolerance = 1e-6;  // degrees
inline bool fitsInto(double size, double room) { return size <= room + kFitTolerance; }
inline bool sameAngle(double a, double b) { return a - b <= kAngleTolerance && b - a <= kAngleTolerance; }

}  // namespace taiwa
