// The milling verifier: the stock as a height field, cut in
// bands of rows, one per core, each running every move in order over its
// own rows. Its setup and bands are in milling_verifier.cpp, the cutting of
// one step with its checks (gouge, rapid into stock, shank or holder in
// stock) in milling_cut.cpp, the material left after a step and at the end
// in milling_rest.cpp. Internal to core/verify.
#pragma once

#include "model/cavity.h"
#include "model/plan.h"
#include "sim/height_field.h"
#include "verify/verify.h"
#include "verify/verify_parts.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <vector>

namespace taiwa::verify::milling {

constexpr double kGougeTolerance = 0.001;  // material removed inside the part beyond this (and the resolution) [mm]
constexpr double kTouch = 0.001;           // a rapid, a shank or a holder nearer than this touches nothing [mm]
constexpr int kBandsPerThread = 8;
constexpr int kTile = 32;  // cells of a row under one tile top

// Gives back what this thread's cutting keeps from step to step (the
// station's thread runs a band too, and lives on).
void releaseCutBuffers();

class Verifier {
    friend class StepCut;  // the cutting of one step (milling_cut.cpp)

public:
    // Each unit's cavity and each cutting step's cutter; maxVisits bounds
    // the cells the bands may visit (0: no bound, see over()); inPathOrder:
    // no run of pieces cut backwards (Options::inPathOrder).
    Verifier(const Plan& plan, double resolution, double maxVisits, bool inPathOrder = false);

    // Cuts every step in `threads` threads: the findings, the material each
    // step removed and the stock as left.
    Report run(unsigned threads);

private:
    double cellArea() const { return res_ * res_; }

    std::size_t tileOf(int i, int j) const { return static_cast<std::size_t>(j) * tilesPerRow_ + i / kTile; }

    // The highest cell of tile t of row j, taken anew when a cell of it was
    // lowered since (a tile is only read and written by its row's band).
    float tileTop(int j, int t)
    {
        const std::size_t k = static_cast<std::size_t>(j) * tilesPerRow_ + t;
        if (tileStale_[k]) {
            const float* h = field_.data() + field_.indexOf(t * kTile, j);
            const int n = std::min(kTile, field_.columns() - t * kTile);
            tileTop_[k] = *std::max_element(h, h + n);
            tileStale_[k] = 0;
        }
        return tileTop_[k];
    }

    // The gouge limit of every cell of the band: the deepest the finished
    // part goes within one cell of its centre, less the tolerance.
    void limits(int row0, int row1);

    // Visits the band's cells within `margin` of the cavity's box.
    template <class Visit>
    void forCells(const Cavity& c, double margin, int row0, int row1, Visit&& visit) const
    {
        const Stock& s = field_.stock();
        const auto col = [&](double x) { return static_cast<int>(std::floor((x - s.x) / res_)); };
        const auto row = [&](double y) { return static_cast<int>(std::floor((y - s.y) / res_)); };
        const int i0 = std::max(0, col(c.min.x - margin)), i1 = std::min(field_.columns() - 1, col(c.max.x + margin));
        const int j0 = std::max(row0, row(c.min.y - margin)), j1 = std::min(row1, row(c.max.y + margin));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) visit(i, j, field_.centre(i, j));
    }

    // Openings the units start with (a cored pocket) taken out of the stock.
    void open(int row0, int row1);

    // Runs every step over the band's rows; the cells visited.
    double band(int row0, int row1, Collector& out, std::vector<double>& removed);

    // Cuts step k into the band's rows; the sum of the heights it took off.
    double cutStep(int k, int row0, int row1, Collector& out);

    // A roughing layer, a floor finish or a face-milling layer clears its
    // unit's cross-section at its depth, less the walls' allowance (and its
    // tool's corner radius);
    // a pilot hole reaches its depth at its centre.
    void restAfterStep(int k, int row0, int row1, Collector& out);

    // After the last step, a unit whose walls (or inclined faces) are
    // finished is cut down to its whole cavity, less what its finishing
    // steps leave. (A unit roughed only keeps its stairs: its layers are
    // checked one by one.)
    void restAtEnd(int row0, int row1, Collector& out);

    const Plan& plan_;
    double res_;
    double zStep_;
    sim::HeightField field_;
    std::vector<float> limit_;
    int tilesPerRow_;
    std::vector<float> tileTop_;             // the highest cell of each tile (row-major, tilesPerRow_ a row)
    std::vector<std::uint8_t> tileStale_;    // a cell of the tile lowered since its top was taken
    std::vector<UnitData> units_;
    std::vector<StepData> steps_;
    static thread_local std::uint64_t visits_;
    double maxVisits_;                            // 0: no bound
    bool inPathOrder_;
    std::atomic<std::uint64_t> allVisits_{0};     // every band's visits so far (with a bound)
    std::atomic<bool> over_{false};               // past the bound: the bands stop

public:
    // The work passed Options::maxCellVisits: the report is unfinished.
    bool over() const { return over_.load(std::memory_order_relaxed); }
};

}  // namespace taiwa::verify::milling
