// The verification's colour map: the simulated stock after the last step
// against the finished part (each unit's cavity from the job's geometry,
// model/cavity.h), cell by cell: cut into the part (a gouge), at size, or
// material left above it and how much. The station draws it on the finished
// part (viz::deviationSurface); docs/verification.md says how it is judged.
#pragma once

#include "model/plan.h"
#include "sim/height_field.h"
#include "verify/verify.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace taiwa::verify {

// What a cell of the map shows, by band.
enum class DeviationBand : std::uint8_t {
    Untouched,  // stock the job leaves as it is: outside every unit and never cut
    Gouge,      // cut below the finished part
    AtSize,     // within the verification's tolerance of the finished part
    RestThin,   // material left up to kThinRest above the part
    RestMedium, // up to kMediumRest
    RestThick,  // more
};
constexpr double kThinRest = 0.1;    // [mm]
constexpr double kMediumRest = 0.5;  // [mm]

struct DeviationMap {
    // The stock after the last step on the map's grid: the verification's
    // own, or coarser by a whole factor for a large grid (each cell the
    // lowest of the verification's cells it covers).
    sim::HeightField stock;
    // Per cell of `stock` (row-major, as its heights): how far the stock is
    // from the finished part [mm], positive where material is left,
    // negative where the part is gouged, 0 at size and where untouched.
    // A coarse cell takes its worst verification cell: the deepest gouge,
    // else the most material left.
    std::vector<float> amount;
    std::vector<DeviationBand> band;
    int factor = 1;  // verification cells per map cell along each axis
    bool empty() const { return band.empty(); }
};

// The map of a report made by verifyPlan for this plan, on at most
// `maxCells` cells; empty for a report without a stock (a lathe job, a
// skipped verification). Uses every core.
DeviationMap deviationMap(const Plan& plan, const Report& report, std::size_t maxCells = 1'000'000);

}  // namespace taiwa::verify
