// Balanced roughing (balanced_roughing.h): analysis, round-robin, path
// conversion, waits and dwells.
#include "turning/balanced_roughing.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace taiwa::turning {

namespace {

double lengthOf(ZR a, const TurnMove& m)
{
    if (m.kind == TurnMove::Rapid || m.kind == TurnMove::Feed) return std::hypot(m.end.z - a.z, m.end.r - a.r);
    const double r = std::hypot(a.z - m.centre.z, a.r - m.centre.r);
    double sweep = std::atan2(m.end.r - m.centre.r, m.end.z - m.centre.z) - std::atan2(a.r - m.centre.r, a.z - m.centre.z);
    if (m.kind == TurnMove::ArcCW) sweep = -sweep;
    while (sweep <= 0) sweep += 2 * std::numbers::pi;
    return r * sweep;
}

TurnMove converted(const TurnMove& m, const MultiPath& mp, std::size_t to)
{
    TurnMove c = m;
    c.end = mp.fromPath1(m.end, to);
    c.centre = mp.fromPath1(m.centre, to);
    // A mirrored axis turns an arc's sense.
    if (flipsArcs(mp, to) && m.kind != TurnMove::Rapid && m.kind != TurnMove::Feed)
        c.kind = m.kind == TurnMove::ArcCW ? TurnMove::ArcCCW : TurnMove::ArcCW;
    return c;
}

}  // namespace

bool flipsArcs(const MultiPath& mp, std::size_t p)
{
    return mp.paths.at(0).zDirection * mp.paths.at(p).zDirection * mp.paths.at(0).xDirection * mp.paths.at(p).xDirection < 0;
}

AnalysedRoughing analyseRoughing(const TurnPath& path)
{
    AnalysedRoughing out;
    const auto& mv = path.moves;
    std::size_t i = 0;
    while (i < mv.size()) {
        // The approach: rapids up to the first feed; none left: the tail.
        std::size_t j = i;
        while (j < mv.size() && mv[j].kind == TurnMove::Rapid) ++j;
        if (j == mv.size()) {
            out.tail.assign(mv.begin() + static_cast<long>(i), mv.end());
            break;
        }
        BalancedBlock b;
        b.number = static_cast<int>(out.blocks.size()) + 1;
        b.cutFrom = j - i;
        ZR p = j > 0 ? mv[j - 1].end : path.start;
        // The longest feed along Z is the cut; its radius is the level.
        double longest = -1.0;
        std::size_t k = j;
        for (; k < mv.size() && mv[k].kind != TurnMove::Rapid; ++k) {
            const double len = lengthOf(p, mv[k]);
            b.cutLength += len;
            if (std::abs(mv[k].end.z - p.z) > longest) {
                longest = std::abs(mv[k].end.z - p.z);
                b.level = mv[k].end.r;
            }
            p = mv[k].end;
        }
        if (k < mv.size()) ++k;  // the return
        b.moves.assign(mv.begin() + static_cast<long>(i), mv.begin() + static_cast<long>(k));
        out.blocks.push_back(std::move(b));
        i = k;
    }
    // The stock's level: one depth of cut outside the first cut (the
    // passes' levels are evenly spaced); a single cut counts from its own.
    if (out.blocks.size() >= 2) out.stockLevel = 2 * out.blocks[0].level - out.blocks[1].level;
    else if (!out.blocks.empty()) out.stockLevel = out.blocks[0].level;
    return out;
}

BalanceSettings balanceSettings(const TwoPathSettings& job, bool meetAtEnds)
{
    BalanceSettings s;
    s.dwellRevolutions = job.dwellRevolutions;
    s.waitsEverywhere = job.waitsEverywhere;
    s.meetAtEnds = meetAtEnds;
    s.firstWait = job.firstWait;
    return s;
}

Result<BalancedCut> balanceRoughing(const TurnPath& path, const TurnCutting& cutting, const Machine& machine,
                                    const BalanceSettings& settings)
{
    if (!machine.layout.multiPath)
        return Failure{fmt::format("machine: {} has one path; a balanced cut needs a two-path lathe", machine.id)};
    const MultiPath& mp = *machine.layout.multiPath;
    if (!(settings.dwellRevolutions >= 0.5))
        return Failure{fmt::format("dwellRevolutions: {} is below half a spindle revolution; the follower would cut where "
                                   "the leader has not",
                                   settings.dwellRevolutions)};
    const int firstWait = settings.firstWait.value_or(mp.waitCodes.first);
    if (!mp.waitCodes.contains(firstWait))
        return Failure{fmt::format("waitCodes: M{} is outside the machine's wait codes M{} to M{}", firstWait,
                                   mp.waitCodes.first, mp.waitCodes.last)};
    AnalysedRoughing a = analyseRoughing(path);
    if (a.blocks.empty()) return Failure{"path: the roughing has no cut to balance"};
    const std::size_t n = mp.paths.size();

    BalancedCut bc;
    bc.cutting = cutting;
    bc.spindleLimit = cutting.maxRpm > 0 ? std::min(cutting.maxRpm, machine.maxSpindleSpeed) : machine.maxSpindleSpeed;
    bc.blockCount = static_cast<int>(a.blocks.size());
    bc.paths.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        bc.paths[p].start = mp.fromPath1(path.start, p);
        for (const auto& m : a.tail) bc.paths[p].tail.push_back(converted(m, mp, p));
    }
    auto rpmAt = [&](double level) { return cutting.rpmAt(2.0 * std::abs(level), bc.spindleLimit); };

    int nextWait = firstWait;
    const std::size_t meetings = (a.blocks.size() + n - 1) / n;
    for (std::size_t j = 0; j < meetings; ++j) {
        const std::size_t from = j * n, to = std::min(a.blocks.size(), from + n);
        // A wait where the previous meeting's cycles differ in length (so
        // the paths arrive at different times), or everywhere when asked.
        bool wait = settings.waitsEverywhere || (settings.meetAtEnds && j == 0);
        if (j > 0) {
            const auto [lo, hi] = std::minmax_element(a.blocks.begin() + static_cast<long>(from - n),
                                                      a.blocks.begin() + static_cast<long>(from),
                                                      [](const auto& x, const auto& y) { return x.cutLength < y.cutLength; });
            if (hi->cutLength - lo->cutLength > 1e-3) wait = true;
        }
        std::optional<int> code;
        if (wait) {
            if (!mp.waitCodes.contains(nextWait))
                return Failure{fmt::format("waitCodes: the balanced cut needs wait code M{}, beyond the machine's last M{}",
                                           nextWait, mp.waitCodes.last)};
            code = nextWait++;
        }
        const double leaderLevel = a.blocks[from].level;
        for (std::size_t k = from; k < to; ++k) {
            BalancedBlock b = a.blocks[k];
            const std::size_t p = k - from;
            b.path = p;
            b.wait = code;
            // The infeed from this path's previous cut (its first: from the stock).
            const double prev = k >= n ? a.blocks[k - n].level : a.stockLevel;
            b.infeed = std::abs(b.level - prev);
            if (p > 0) {
                const double rpm = std::min(rpmAt(leaderLevel), rpmAt(b.level));
                b.dwellRevolutions = settings.dwellRevolutions * static_cast<double>(p);
                b.dwellSeconds = std::ceil(b.dwellRevolutions * 60.0 / rpm * 1000.0 - 1e-9) / 1000.0;
            }
            for (auto& m : b.moves) m = converted(m, mp, p);
            bc.paths[p].blocks.push_back(std::move(b));
        }
        // The last meeting may leave a path without a block: it still
        // meets the others, before going home.
        if (code)
            for (std::size_t p = to - from; p < n; ++p) bc.paths[p].tailWait = code;
    }
    if (settings.meetAtEnds) {
        if (!mp.waitCodes.contains(nextWait))
            return Failure{fmt::format("waitCodes: the balanced cut needs wait code M{}, beyond the machine's last M{}",
                                       nextWait, mp.waitCodes.last)};
        for (auto& p : bc.paths) p.endWait = nextWait;
    }
    return bc;
}

std::optional<PlannedBalance> balancePlanRoughing(const Plan& plan, const Machine& machine)
{
    for (std::size_t k = 0; k < plan.steps.size(); ++k) {
        const Step& step = plan.steps[k];
        const TurnStep* rough = step.machiningType == MachiningType::TurnRoughing ? turnOf(step) : nullptr;
        if (!rough) continue;
        const BalanceSettings set = balanceSettings(plan.mmJob.twoPath, true);
        return PlannedBalance{k, balanceRoughing(rough->path, rough->cutting, machine, set)};
    }
    return std::nullopt;
}

}  // namespace taiwa::turning
