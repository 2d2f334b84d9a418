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
// A lathe job is cut into its bar's half-section instead (verify_turning.h).
#include "verify/verify.h"
#include "verify/verify_parts.h"
#include "verify/verify_turning.h"

#include "machine/machine.h"
#include "model/translate_noop.h"
#include "modules/registry.h"
#include "sim/cutter_profile.h"
#include "sim/height_field.h"
#include "sim/path_samples.h"
#include "sim/sweep.h"
#include "tools/holder_shape.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <future>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <thread>
#include <tuple>

namespace taiwa::verify {

namespace {

constexpr double kGougeTolerance = 0.001;  // material removed inside the part beyond this (and the resolution) [mm]
constexpr double kTouch = 0.001;           // a rapid, a shank or a holder nearer than this touches nothing [mm]
constexpr int kBandsPerThread = 8;
constexpr int kTile = 32;  // cells of a row under one tile top
constexpr double kCoarsestResolution = 5.0;  // the coarsest grid --resolution takes [mm]

class Verifier {
public:
    Verifier(const Plan& plan, double resolution, double maxVisits)
        : plan_(plan), res_(resolution), zStep_(std::min(0.02, resolution / 5.0)), field_(plan.mmJob.stock, resolution),
          limit_(field_.heights().size(), 0.0f), tilesPerRow_((field_.columns() + kTile - 1) / kTile),
          tileTop_(static_cast<std::size_t>(tilesPerRow_) * field_.rows(), 0.0f),
          tileStale_(tileTop_.size(), 1), maxVisits_(maxVisits)
    {
        units_.resize(plan.mmJob.units.size());
        for (std::size_t u = 0; u < units_.size(); ++u) {
            const ModuleInput& m = plan.mmJob.units[u].module;
            if (!m.empty()) units_[u].cavity = moduleKind(m).cavity(m, plan.technology);
        }
        steps_.resize(plan.steps.size());
        for (std::size_t k = 0; k < plan.steps.size(); ++k) {
            const Step& s = plan.steps[k];
            const Tool* tool = s.tool ? plan.tool(s.tool->toolId) : nullptr;
            if (!s.path || !tool || tool->type == ToolType::Probe) continue;
            StepData& d = steps_[k];
            d.cuts = true;
            d.pieces = sim::sweptPieces(*s.path);
            d.cutter.emplace(*tool);
            d.cornerRadius = tool->type == ToolType::BallEndMill ? tool->radius() : tool->cornerRadius;
            d.flute = d.cutter->cuttingLength();
            const tools::HolderShape h = tools::holderShape(*tool);
            d.holderZ = std::max(tool->stickout, d.flute);
            d.holderR = h.noseDiameter / 2.0;
            // The wall passes (final, semi-finish, a taper's middle) and an inclined face's finishing.
            const MachiningType m = s.machiningType;
            const bool finishing = m == MachiningType::WallFinishing || m == MachiningType::WallSemiFinishing ||
                                   m == MachiningType::WallMiddlePass || m == MachiningType::InclinedFaceFinishing;
            if (s.unit >= 0 && s.unit < static_cast<int>(units_.size()) && finishing) {
                UnitData& u = units_[s.unit];
                u.lastFinish = static_cast<int>(k);
                u.wallAllowance = std::min(u.wallAllowance, s.wallAllowance);
                u.floorAllowance = std::min(u.floorAllowance, s.floorAllowance);
                u.cornerRadius = std::max(u.cornerRadius, d.cornerRadius);
            }
        }
    }

    Report run(unsigned threads)
    {
        Report r;
        r.resolution = res_;
        r.columns = field_.columns();
        r.rows = field_.rows();
        // More bands than threads, taken in turn: the work lies where the
        // units are, not evenly over the rows.
        const int bands = std::clamp(static_cast<int>(threads) * kBandsPerThread, 1, field_.rows());
        std::vector<Collector> found(static_cast<std::size_t>(bands));
        std::vector<std::vector<double>> removed(static_cast<std::size_t>(bands), std::vector<double>(steps_.size(), 0.0));
        std::vector<double> visits(static_cast<std::size_t>(bands), 0.0);
        std::atomic<int> next{0};
        const auto work = [&] {
            for (int b = next++; b < bands; b = next++) {
                const int row0 = field_.rows() * b / bands, row1 = field_.rows() * (b + 1) / bands - 1;
                const auto k = static_cast<std::size_t>(b);
                visits[k] = band(row0, row1, found[k], removed[k]);
            }
        };
        std::vector<std::future<void>> running;
        for (unsigned t = 1; t < threads; ++t) running.push_back(std::async(std::launch::async, work));
        work();
        for (auto& f : running) f.get();
        for (double n : visits) r.cellVisits += n;
        r.removed.assign(steps_.size(), 0.0);
        for (const auto& v : removed)
            for (std::size_t k = 0; k < v.size(); ++k) r.removed[k] += v[k] * cellArea();
        std::map<std::tuple<int, int, int, std::string>, Finding> all;
        for (const Collector& c : found) c.mergeInto(all);
        addTravelFindings(plan_, steps_, all);
        for (auto& [key, f] : all) r.findings.push_back(f);
        std::stable_sort(r.findings.begin(), r.findings.end(), [](const Finding& a, const Finding& b) {
            return std::tie(a.step, a.kind, a.move) < std::tie(b.step, b.kind, b.move);
        });
        r.stock = std::move(field_);
        return r;
    }

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
    void limits(int row0, int row1)
    {
        for (int j = row0; j <= row1; ++j)
            for (int i = 0; i < field_.columns(); ++i) limit_[field_.indexOf(i, j)] = static_cast<float>(-kGougeTolerance);
        for (const UnitData& u : units_) {
            if (!u.cavity) continue;
            forCells(*u.cavity, res_, row0, row1, [&](int i, int j, Point2 p) {
                const double z = -u.cavity->depthAt(p, res_) - kGougeTolerance;
                float& l = limit_[field_.indexOf(i, j)];
                l = std::min(l, static_cast<float>(z));
            });
        }
    }

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
    void open(int row0, int row1)
    {
        float* h = field_.data();
        for (const UnitData& u : units_) {
            if (!u.cavity || !u.cavity->openAt) continue;
            forCells(*u.cavity, 0.0, row0, row1, [&](int i, int j, Point2 p) {
                float& z = h[field_.indexOf(i, j)];
                z = std::min(z, static_cast<float>(std::max(-u.cavity->openAt(p), field_.bottom())));
            });
        }
    }

    // Runs every step over the band's rows; the cells visited.
    double band(int row0, int row1, Collector& out, std::vector<double>& removed)
    {
        visits_ = 0;
        limits(row0, row1);
        open(row0, row1);  // (every tile starts stale: its top is taken when first asked)
        for (std::size_t k = 0; k < steps_.size() && !over(); ++k) {
            if (!steps_[k].cuts) continue;
            removed[k] = cutStep(static_cast<int>(k), row0, row1, out);
            restAfterStep(static_cast<int>(k), row0, row1, out);
        }
        restAtEnd(row0, row1, out);
        return static_cast<double>(visits_);
    }

    // Cuts step k into the band's rows; the sum of the heights it took off.
    double cutStep(int k, int row0, int row1, Collector& out)
    {
        double removed = 0.0;
        const StepData& d = steps_[static_cast<std::size_t>(k)];
        const sim::CutterProfile& cutter = *d.cutter;
        const double reach = cutter.reach(), reach2 = reach * reach;
        float* h = field_.data();
        const double bottom = field_.bottom();
        std::uint64_t visits = 0;
        sim::SweepChain chain;  // where the last straight sweep ended, and its height
        std::uint64_t counted = 0;  // of `visits`, added to the job's count
        for (const sim::SweptPiece& piece : d.pieces) {
            if (maxVisits_ > 0.0 && visits > counted) {  // the bound of the work, over every band
                const auto sum = allVisits_.fetch_add(visits - counted, std::memory_order_relaxed) + (visits - counted);
                counted = visits;
                if (static_cast<double>(sum) > maxVisits_) over_.store(true, std::memory_order_relaxed);
            }
            if (over()) break;
            if (std::min(piece.from.z, piece.to.z) >= 0.0) continue;
            // The cells near one horizontal sweep at tip height z: a
            // straight piece from a to b, or the part [t0, t1] of the arc.
            const auto level = [&](double z, const auto& cellsWithin) {
                if (z >= 0.0) return;
                const bool shankLow = z + d.flute < -kTouch;
                const bool holderLow = z + d.holderZ < -kTouch;
                const double radius = holderLow ? std::max(reach, d.holderR) : reach;
                // No cell at or below the tip's height changes, nor touches
                // the shank or holder (both above the tip): skip its tile.
                const float floor = static_cast<float>(std::max(z, bottom));
                const auto runs = [&](int j, int from, int to, const auto& cells) {
                    int start = -1;  // the first cell of the run still to visit
                    for (int lo = from; lo <= to;) {
                        const int t = lo / kTile, hi = std::min(to, (t + 1) * kTile - 1);
                        if (tileTop(j, t) > floor) {
                            if (start < 0) start = lo;
                        } else if (start >= 0) {
                            cells(start, lo - 1);
                            start = -1;
                        }
                        lo = hi + 1;
                    }
                    if (start >= 0) cells(start, to);
                };
                cellsWithin(radius, runs, [&](int i, int j, double r2) {
                    const std::size_t c = field_.indexOf(i, j);
                    ++visits;
                    const double before = h[c];
                    const auto where = [&](double zz) {
                        const Point2 p = field_.centre(i, j);
                        return Point3{p.x, p.y, zz};
                    };
                    if (holderLow && before > z + d.holderZ + kTouch)
                        out.add(FindingKind::Collision, k, piece.move, TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder"), where(before), before - (z + d.holderZ));
                    if (r2 > reach2) return;
                    if (shankLow && before > z + d.flute + kTouch && before <= z + d.holderZ + kTouch)
                        out.add(FindingKind::Collision, k, piece.move, TAIWA_TRANSLATE_NOOP("taiwa::msg", "shank"), where(before), before - (z + d.flute));
                    const double after = std::max(z + cutter.heightSquared(r2), bottom);
                    const float lowered = static_cast<float>(after);  // the grid's heights are floats
                    if (lowered >= h[c]) return;
                    if (piece.rapid && before - after > kTouch)
                        out.add(FindingKind::RapidIntoStock, k, piece.move, "", where(after), before - after);
                    h[c] = lowered;
                    tileStale_[tileOf(i, j)] = 1;
                    removed += before - h[c];
                    if (h[c] < limit_[c]) {
                        const double area = before >= limit_[c] ? cellArea() : 0.0;  // each cell counted once
                        out.add(FindingKind::Gouge, k, piece.move, "", where(after), limit_[c] + kGougeTolerance - after, area);
                    }
                });
            };
            // A straight sweep; when the last one ended where it starts, at
            // the same height and without the holder low, the cells within
            // the cutter's flat bottom of its start are at that height
            // already (or lower) and are not visited again: a contour's
            // short chords would otherwise each visit a whole disc of cells.
            const auto line = [&](Point2 a, Point2 b, double z) {
                const bool holderLow = z + d.holderZ < -kTouch;
                const double skip = holderLow ? 0.0 : chain.skip(a, z, cutter.flatRadius());
                level(z, [&](double radius, const auto& runs, const auto& visit) {
                    sim::forEachCellNear(field_, a, b, radius, row0, row1, visit, skip, runs);
                });
                if (z < 0.0 && !holderLow) chain.ended(b, z);
                else chain.broken();
            };
            if (!piece.arc) {
                sim::forEachLevel(piece.from, piece.to, zStep_, line);
                continue;
            }
            chain.broken();
            // An arc exactly; a helix in parts at most zStep apart in Z, each
            // at its higher end, then its end point at its own height.
            const Point2 c = piece.centre;
            const double radius = std::hypot(piece.from.x - c.x, piece.from.y - c.y);
            const double a0 = std::atan2(piece.from.y - c.y, piece.from.x - c.x);
            const double dz = piece.to.z - piece.from.z;
            const int n = std::max(1, static_cast<int>(std::ceil(std::abs(dz) / zStep_)));
            for (int part = 0; part < n; ++part) {
                const double t0 = static_cast<double>(part) / n, t1 = static_cast<double>(part + 1) / n;
                const double z = std::max(piece.from.z + t0 * dz, piece.from.z + t1 * dz);
                level(z, [&](double reachOf, const auto& runs, const auto& visit) {
                    sim::forEachCellNearArc(field_, c, radius, a0 + t0 * piece.sweep, (t1 - t0) * piece.sweep, reachOf, row0,
                                            row1, visit, runs);
                });
            }
            if (dz != 0.0) line({piece.to.x, piece.to.y}, {piece.to.x, piece.to.y}, piece.to.z);
        }
        visits_ += visits;
        return removed;
    }

    // A roughing layer, a floor finish or a face-milling layer clears its
    // unit's cross-section at its depth, less the walls' allowance (and its
    // tool's corner radius);
    // a pilot hole reaches its depth at its centre.
    void restAfterStep(int k, int row0, int row1, Collector& out)
    {
        const Step& s = plan_.steps[static_cast<std::size_t>(k)];
        const StepData& d = steps_[static_cast<std::size_t>(k)];
        const float* h = field_.data();
        const double tolerance = kGougeTolerance + zStep_;
        if (s.machiningType == MachiningType::PilotHole) {
            const Stock& st = field_.stock();
            const int i = static_cast<int>(std::floor((s.position.x - st.x) / res_));
            const int j = static_cast<int>(std::floor((s.position.y - st.y) / res_));
            if (i < 0 || j < row0 || i >= field_.columns() || j > row1) return;
            const double allowed = -s.cutDepth + tolerance + d.cutter->height(distance(field_.centre(i, j), s.position));
            if (h[field_.indexOf(i, j)] > allowed)
                out.add(FindingKind::RestMaterial, k, -1, "", {s.position.x, s.position.y, h[field_.indexOf(i, j)]},
                        h[field_.indexOf(i, j)] - allowed + tolerance, cellArea());
            return;
        }
        const MachiningType m = s.machiningType;
        if (m != MachiningType::Roughing && m != MachiningType::FloorFinishing && m != MachiningType::FaceMilling &&
            m != MachiningType::FaceFinishing)
            return;
        if (s.unit < 0 || s.unit >= static_cast<int>(units_.size()) || !units_[s.unit].cavity) return;
        const Cavity& cav = *units_[s.unit].cavity;
        const double slack = -(s.wallAllowance / std::cos(cav.wallAngle * std::numbers::pi / 180.0) + res_ + d.cornerRadius);
        forCells(cav, 0.0, row0, row1, [&](int i, int j, Point2 p) {
            const double z = h[field_.indexOf(i, j)];
            if (z <= -s.cutDepth + tolerance) return;
            if (cav.depthAt(p, slack) < s.cutDepth - 1e-9) return;
            out.add(FindingKind::RestMaterial, k, -1, "", {p.x, p.y, z}, z + s.cutDepth, cellArea());
        });
    }

    // After the last step, a unit whose walls (or inclined faces) are
    // finished is cut down to its whole cavity, less what its finishing
    // steps leave. (A unit roughed only keeps its stairs: its layers are
    // checked one by one.)
    void restAtEnd(int row0, int row1, Collector& out)
    {
        const float* h = field_.data();
        for (const UnitData& ud : units_) {
            if (!ud.cavity || ud.lastFinish < 0) continue;
            const Cavity& cav = *ud.cavity;
            const int lastStep = ud.lastFinish;
            const double slack =
                -(ud.wallAllowance / std::cos(cav.wallAngle * std::numbers::pi / 180.0) + res_ + ud.cornerRadius);
            const double tolerance = kGougeTolerance + zStep_ + cav.surfaceTolerance;
            forCells(cav, 0.0, row0, row1, [&](int i, int j, Point2 p) {
                const double z = h[field_.indexOf(i, j)];
                const double depth = cav.depthAt(p, slack);
                if (depth <= 0.0) return;
                const double excess = z - (-depth + ud.floorAllowance);
                if (excess > tolerance) out.add(FindingKind::RestMaterial, lastStep, -1, "", {p.x, p.y, z}, excess, cellArea());
            });
        }
    }

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
    std::atomic<std::uint64_t> allVisits_{0};     // every band's visits so far (with a bound)
    std::atomic<bool> over_{false};               // past the bound: the bands stop

public:
    // The work passed Options::maxCellVisits: the report is unfinished.
    bool over() const { return over_.load(std::memory_order_relaxed); }
};

thread_local std::uint64_t Verifier::visits_ = 0;

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
        Verifier v(plan, resolution, last ? 0.0 : options.maxCellVisits);
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
