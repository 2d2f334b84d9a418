// A cutting tool of the shop's library, and the record of why a step got it.
#pragma once

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

struct Tool {
    int id = 0;                  // the library's id; also the T number
    std::string name;
    ToolType type = ToolType::FlatEndMill;
    double diameter = 0.0;       // [mm], at the tip for taper end mills
    double cornerRadius = 0.0;   // corner or nose radius [mm]
    double taperAngle = 0.0;     // degrees per side (taper end mills)
    double pointAngle = 118.0;   // drills [deg]
    double fluteLength = 0.0;    // [mm]
    double stickout = 0.0;       // length out of the holder [mm]
    std::string holder;
    int flutes = 2;
    bool centreCutting = true;   // end mills: can ramp or plunge into solid material (face mills cannot)
    double lifeMinutes = 0.0;    // cutting time a fresh tool lasts
    double usedMinutes = 0.0;    // cutting time already spent
    std::vector<CuttingData> cutting;
    double radius() const { return diameter / 2.0; }
    double remainingLife() const { return lifeMinutes - usedMinutes; }
    const CuttingData* cuttingFor(const std::string& material) const;
    friend bool operator==(const Tool&, const Tool&) = default;
};

// Why a step got its tool, in words for the sheet and the step list.
struct ToolChoice {
    int toolId = 0;
    std::string reason;
    friend bool operator==(const ToolChoice&, const ToolChoice&) = default;
};

// The tool of that id in `library`; nullptr when there is none.
const Tool* findTool(const std::vector<Tool>& library, int id);

// One rule for every fit of a tool (input checks and tool choice alike): a
// size fits into a room when it exceeds it by no more than kFitTolerance, so
// that a tool fitting exactly by the documented rule is not refused for a
// rounding error of the arithmetic; a taper end mill is "of that angle"
// within kAngleTolerance.
constexpr double kFitTolerance = 1e-6;    // mm
constexpr double kAngleTolerance = 1e-6;  // degrees
inline bool fitsInto(double size, double room) { return size <= room + kFitTolerance; }
inline bool sameAngle(double a, double b) { return a - b <= kAngleTolerance && b - a <= kAngleTolerance; }

}  // namespace taiwa
