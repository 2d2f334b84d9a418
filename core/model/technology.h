// Technology data ("external file data" of the spec): the allowances and the
// depth-of-cut coefficient registered per material, overridable per job.
#pragma once

#include "model/local_name.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// Turning defaults of a material (docs/turning.md): roughing's depth of cut
// per pass (radius), the finishing allowance it leaves across the axis
// (radius) and along it, the lift after each pass, the clearance of
// approaches, and grooving's withdrawal along the surface normal (seed 002).
struct TurningTechnology {
    double depthOfCut = 2.0;
    double allowanceX = 0.2, allowanceZ = 0.1;  // across the axis (radius), along it
    double retract = 0.5;
    double clearance = 2.0;
    double withdrawal = 0.3;
    friend bool operator==(const TurningTechnology&, const TurningTechnology&) = default;
};

// The operator's spindle speed and feed for the steps of one kind of a unit,
// in place of the tool's cutting data: S as the tape says it (rpm; a
// turning step under constant surface speed: m/min) and F (per minute on
// a mill, per revolution on a lathe, in the job's length unit). The
// plunge feed follows F in proportion, as the control's feed override does.
// A milling tool's spindle speed and feeds in a material (tools/cutting.h
// computes them from its cutting data).
struct SpeedsFeeds {
    double rpm = 0.0;         // S
    double feed = 0.0;        // mm/min for contouring (drills: mm/min of the feed into the hole)
    double plungeFeed = 0.0;  // mm/min for plunges and ramps
    friend bool operator==(const SpeedsFeeds&, const SpeedsFeeds&) = default;
};

struct CuttingOverride {
    std::optional<double> speed;  // S
    std::optional<double> feed;   // F
    bool empty() const { return !speed && !feed; }
    friend bool operator==(const CuttingOverride&, const CuttingOverride&) = default;
};

struct TechnologyData {
    double alpha1 = 1.0;  // pilot hole stops alpha1 above the pocket floor [mm]
    double alpha2 = 0.3;  // wall allowance left by roughing [mm]
    double alpha3 = 0.1;  // wall allowance left by the semi-finish pass (F = 3) [mm]
    double beta2 = 0.2;   // floor allowance left by roughing [mm]
    double gamma = 0.5;   // roughing layer depth = gamma x tool diameter [-]
    double stepOver = 0.45;  // roughing's radial step-over = stepOver x tool diameter [-]
    TurningTechnology turning{};
    friend bool operator==(const TechnologyData&, const TechnologyData&) = default;
};

// The per-job overrides: only the values the job sets, in the job's units.
struct TechnologyOverrides {
    std::optional<double> alpha1, alpha2, alpha3, beta2, gamma, stepOver;
    bool empty() const { return !alpha1 && !alpha2 && !alpha3 && !beta2 && !gamma && !stepOver; }
    friend bool operator==(const TechnologyOverrides&, const TechnologyOverrides&) = default;
};

// One material of the shipped table (resources/technology/materials.json).
struct MaterialTechnology {
    std::string id;           // e.g. "aluminium-6061"
    std::string description;  // e.g. "Aluminium alloy 6061-T6"
    LocalNames names;         // the description in other languages ("ja": "アルミニウム合金 6061-T6"), for the station
    TechnologyData data;      // in mm
    friend bool operator==(const MaterialTechnology&, const MaterialTechnology&) = default;
};

class TechnologyTable {
public:
    // The table shipped with the program (compiled in from resources/).
    static const TechnologyTable& builtIn();
    // Parse a table in the format of resources/technology/materials.json.
    // Throws Refusal (model/result.h) naming the material and field on bad input.
    static TechnologyTable fromJson(const std::string& text);

    const MaterialTechnology* find(const std::string& id) const;
    const std::vector<MaterialTechnology>& materials() const { return materials_; }

private:
    std::vector<MaterialTechnology> materials_;
};

// Table value with the job's overrides applied (both in mm).
TechnologyData effective(const TechnologyData& base, const TechnologyOverrides& mmOverrides);

}  // namespace taiwa
