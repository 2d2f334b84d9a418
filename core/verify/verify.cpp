// The verifying simulation: the steps cut in machining order into a height
// field of the operator's resolution, every cell checked as it is lowered
// (gouge, rapid into stock, shank or holder in stock) and after each step
// and at the end (material left). The grid is cut in bands of rows, one per
// core: each band runs every move in order over its own rows, so the order
// of the cuts (which a rapid into stock depends on) is kept without locks.
// Each row of the grid is kept in tiles of 32 cells with the highest of
// their heights: a sweep passes over a tile already at or below its tip in
// one test (a cell there can neither be lowered nor touch the shank or the
// holder), so a pass that re-sweeps what the last one cut costs little and
// the work follows the material removed, not the path's length.
// The milling verifier itself is in milling_verifier.h and its files; here
// the choice of grid and the coarser grid when the work passes its bound.
// A lathe job is cut into its bar's half-section instead (verify_turning.h).
#include "verify/verify.h"
#include "verify/milling_verifier.h"
#include "verify/verify_turning.h"

#include "model/result.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>

namespace taiwa::verify {

namespace {

constexpr double kCoarsestResolution = 5.0;  // the coarsest grid --resolution takes [mm]

}  // namespace

double defaultResolution(const Plan& plan)
{
    if (plan.mmJob.bar) return kDefaultResolution;
    const Stock& s = plan.mmJob.stock;
    const double fits = std::sqrt(std::max(s.width, 0.0) * std::max(s.length, 0.0) / kDefaultCells);
    return std::max(kDefaultResolution, std::ceil(fits * 100.0 - 1e-9) / 100.0);
}

Report verifyPlan(const Plan& plan, const Options& options)
{
    if (!(options.resolution >= kFinestResolution) || !std::isfinite(options.resolution))
        throw Refusal("the resolution must be at least " + std::to_string(kFinestResolution) + " mm");
    if (plan.mmJob.bar) return verifyTurning(plan, options);
    const Stock& s = plan.mmJob.stock;
    const double cells = std::ceil(s.width / options.resolution) * std::ceil(s.length / options.resolution);
    if (cells > kMaxCells)
        throw Refusal("a " + std::to_string(options.resolution) + " mm grid over this stock has " +
                      std::to_string(static_cast<long long>(cells)) + " cells, more than " +
                      std::to_string(static_cast<long long>(kMaxCells)) + ": choose a coarser resolution");
    const unsigned threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
    // Within the bound, or on a grid twice as coarse, and so on: the cells a
    // tool's shape covers fall as the square of the cell size.
    double resolution = options.resolution;
    for (;;) {
        const bool last = resolution * 2.0 > kCoarsestResolution;
        milling::Verifier v(plan, resolution, last ? 0.0 : options.maxCellVisits, options.inPathOrder);
        Report r = v.run(threads);
        if (v.over()) {
            resolution = std::ceil(resolution * 2.0 * 100.0 - 1e-9) / 100.0;
            continue;
        }
        if (resolution != options.resolution)
            r.coarsened = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                          "verified at {:g} mm, not {:g} mm: on that grid the paths would have swept more "
                                          "than {:.3g} cells; --resolution {:g} verifies on it all the same"),
                                      resolution, options.resolution, options.maxCellVisits, options.resolution);
        return r;
    }
}

}  // namespace taiwa::verify
