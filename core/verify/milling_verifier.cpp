// The milling verifier's setup and bands (milling_verifier.h): each unit's
// cavity and each step's cutter, the grid cut in bands of rows over the
// cores, and the findings of every band merged in order. Each row of the
// grid is kept in tiles of 32 cells with the highest of their heights (see
// verify.cpp); a band's gouge limits and the units' openings are laid on its
// rows before its steps are cut.
#include "verify/milling_verifier.h"

#include "modules/registry.h"
#include "sim/large_array.h"
#include "tools/holder_shape.h"

#include <future>
#include <map>
#include <string>
#include <thread>
#include <tuple>

namespace taiwa::verify::milling {

thread_local std::uint64_t Verifier::visits_ = 0;

Verifier::Verifier(const Plan& plan, double resolution, double maxVisits, bool inPathOrder)
    : plan_(plan), res_(resolution), zStep_(std::min(0.02, resolution / 5.0)), field_(plan.mmJob.stock, resolution),
      tilesPerRow_((field_.columns() + kTile - 1) / kTile),
      tileTop_(static_cast<std::size_t>(tilesPerRow_) * field_.rows(), 0.0f),
      tileStale_(tileTop_.size(), 1), maxVisits_(maxVisits), inPathOrder_(inPathOrder)
{
    sim::assignLarge(limit_, field_.heights().size(), 0.0f);
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
            u.wallAllowance = std::min(u.wallAllowance, millingOf(s).wallAllowance);
            u.floorAllowance = std::min(u.floorAllowance, millingOf(s).floorAllowance);
            u.cornerRadius = std::max(u.cornerRadius, d.cornerRadius);
        }
    }
}

Report Verifier::run(unsigned threads)
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
    releaseCutBuffers();
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

// The gouge limit of every cell of the band: the deepest the finished
// part goes within one cell of its centre, less the tolerance.
void Verifier::limits(int row0, int row1)
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

// Openings the units start with (a cored pocket) taken out of the stock.
void Verifier::open(int row0, int row1)
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
double Verifier::band(int row0, int row1, Collector& out, std::vector<double>& removed)
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

}  // namespace taiwa::verify::milling
