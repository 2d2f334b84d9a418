// The two-path timeline (two_path_timeline.h) from one run of both paths
// (two_path_run.h): each block's times, the deadlocks and the lags of the
// cuts behind each other; where the tools stand at a moment or after each
// move (the place queries); and the one-path roughing's time by the same
// clock.
#include "verify/two_path_timeline.h"

#include "verify/two_path_run.h"

#include <algorithm>
#include <iterator>
#include <limits>

namespace taiwa {

namespace {

using detail::Clock;
using detail::CutTrace;
using detail::Op;
using detail::Run;
using turning::ZR;

// The lag of every cut behind the one before it, over the Z both cover:
// along a cut the tool's Z goes with the spindle's revolutions (feed
// per revolution), so the lag in revolutions is linear in Z between
// the ends of the stretch.
void addLags(Run& run, Timeline& tl)
{
    const auto& traces = run.traces;
    auto& revsAt = run.revsAt;
    for (auto it = traces.begin(); it != traces.end(); ++it) {
        const auto next = std::next(it);
        if (next == traces.end()) break;
        const CutTrace& a = it->second;
        const CutTrace& b = next->second;
        const double lo = std::max(std::min(a.z0, a.z1), std::min(b.z0, b.z1));
        const double hi = std::min(std::max(a.z0, a.z1), std::max(b.z0, b.z1));
        if (hi < lo) continue;
        auto along = [](double v0, double v1, const CutTrace& c, double z) {
            return c.z1 == c.z0 ? v0 : v0 + (v1 - v0) * (z - c.z0) / (c.z1 - c.z0);
        };
        const auto ra = revsAt[it->first], rb = revsAt[next->first];
        double least = std::numeric_limits<double>::max(), seconds = least;
        for (const double z : {lo, hi}) {
            least = std::min(least, along(rb.first, rb.second, b, z) - along(ra.first, ra.second, a, z));
            seconds = std::min(seconds, along(b.t0, b.t1, b, z) - along(a.t0, a.t1, a, z));
        }
        tl.lags.push_back({it->first, next->first, least, seconds});
    }
}

}  // namespace

double Timeline::seconds() const
{
    double s = 0.0;
    for (double e : pathEnd) s = std::max(s, e);
    return s;
}

double Timeline::leastLag() const
{
    double least = std::numeric_limits<double>::max();
    for (const auto& l : lags) least = std::min(least, l.revolutions);
    return least;
}

Timeline runTimeline(const BalancedCut& cut, const Machine& machine)
{
    Timeline tl;
    Run run(cut, machine);
    run.run(&tl);
    tl.pathEnd = run.ended;
    // Each block's dwell as the cut says it (run above as a dwell before the cut).
    for (const auto& path : cut.paths)
        for (const auto& b : path.blocks)
            if (const auto it = run.blocks.find(b.number); it != run.blocks.end()) it->second.dwell = b.dwellSeconds;
    for (auto& [k, b] : run.blocks)
        if (k > 0) tl.blocks.push_back(b);
    addLags(run, tl);
    return tl;
}

std::vector<ZR> toolsAt(const BalancedCut& cut, const Machine& machine, double seconds)
{
    Run run(cut, machine);
    run.run(nullptr, seconds);
    return run.pos;
}

ToolPlaces toolPlaces(const BalancedCut& cut, const Machine& machine)
{
    // Each block's first move among the single path's: the blocks cut it
    // into pieces in CB order, none lost or doubled, path 1's tail after them.
    std::vector<std::size_t> sizes(static_cast<std::size_t>(std::max(cut.blockCount, 0)) + 1, 0);
    for (const BalancedPath& p : cut.paths)
        for (const BalancedBlock& b : p.blocks) sizes.at(static_cast<std::size_t>(b.number)) = b.moves.size();
    std::vector<std::size_t> first(sizes.size(), 0);
    std::size_t count = 0;
    for (std::size_t k = 1; k < sizes.size(); ++k) {
        first[k] = count;
        count += sizes[k];
    }
    const std::size_t tailFrom = count;
    count += cut.paths.empty() ? 0 : cut.paths.front().tail.size();
    Run run(cut, machine);
    ToolPlaces places;
    places.start = run.pos;
    places.afterMove.assign(count, {});
    run.moveEnded = [&](std::size_t p, const Op& o) {
        if (o.block == 0 && p != 0) return;  // another path's tail: no move of the single path
        const std::size_t at = (o.block > 0 ? first[static_cast<std::size_t>(o.block)] : tailFrom) + static_cast<std::size_t>(o.index);
        places.afterMove.at(at) = run.pos;
    };
    run.run(nullptr);
    // A move no path ran (a deadlock stopped it): the places where the run stopped.
    for (auto& a : places.afterMove)
        if (a.empty()) a = run.pos;
    return places;
}

double singlePathSeconds(const TurnPath& path, const TurnCutting& cutting, const Machine& machine)
{
    const Clock clk{cutting, machine, cutting.maxRpm > 0 ? std::min(cutting.maxRpm, machine.maxSpindleSpeed) : machine.maxSpindleSpeed};
    double s = 0.0;
    ZR at = path.start;
    for (const auto& m : path.moves) {
        s += clk.seconds(at, m);
        at = m.end;
    }
    return s;
}

}  // namespace taiwa
