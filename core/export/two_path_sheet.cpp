// The sheet's two-path sections (two_path_sheet.h): each step's path, and
// the balanced roughing's timeline as a Gantt-style table.
#include "export/two_path_sheet.h"

#include "machine/machine.h"
#include "model/turn_path.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace taiwa {

namespace {

constexpr double kSame = 1e-9;  // [s] two times this close are one

}  // namespace

std::vector<TimelineStretch> timelineStretches(const Timeline& t, std::size_t path)
{
    std::vector<const TimelineBlock*> blocks;
    for (const auto& b : t.blocks)
        if (b.path == path) blocks.push_back(&b);
    std::sort(blocks.begin(), blocks.end(), [](const auto* a, const auto* b) { return a->start < b->start; });
    std::vector<TimelineStretch> out;
    const auto add = [&](TimelineStretch s) {
        if (s.to > s.from + kSame || s.kind == TimelineStretch::Wait) out.push_back(std::move(s));
    };
    using S = TimelineStretch;
    for (const TimelineBlock* b : blocks) {
        const int n = b->number;
        const double in = b->wait ? b->waitTo : b->start;
        if (b->wait) {
            add({b->start, b->waitFrom, S::In, n, 0, 0.0, fmt::format("CB{} in", n)});
            add({b->waitFrom, b->waitTo, S::Wait, n, *b->wait, 0.0, fmt::format("M{} wait", *b->wait)});
        }
        add({in, b->cutStart, S::In, n, 0, b->dwell,
             b->dwell > 0 ? fmt::format("CB{} in, dwell {:.3f} s", n, b->dwell) : fmt::format("CB{} in", n)});
        add({b->cutStart, b->cutEnd, S::Cut, n, 0, 0.0, fmt::format("CB{} cut", n)});
        add({b->cutEnd, b->end, S::Out, n, 0, 0.0, fmt::format("CB{} out", n)});
    }
    const double last = blocks.empty() ? 0.0 : blocks.back()->end;
    if (path < t.pathEnd.size()) add({last, t.pathEnd[path], S::Tail, 0, 0, 0.0, "tail, end wait"});
    return out;
}


sheet::Table timelineTable(const Timeline& t, std::size_t paths)
{
    sheet::Table table;
    table.headers = {"From s", "To s"};
    table.numeric = {true, true};
    table.widths = {1.2, 1.2};
    for (std::size_t p = 0; p < paths; ++p) {
        table.headers.push_back(fmt::format("Path {}", p + 1));
        table.numeric.push_back(false);
        table.widths.push_back(3.0);
    }
    std::vector<std::vector<TimelineStretch>> of;
    std::vector<double> times;
    for (std::size_t p = 0; p < paths; ++p) {
        of.push_back(timelineStretches(t, p));
        for (const auto& s : of.back()) times.insert(times.end(), {s.from, s.to});
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return b - a <= kSame; }), times.end());
    const auto row = [&](double from, double to, const std::vector<std::string>& cells) {
        std::vector<std::string> r{fmt::format("{:.2f}", from), fmt::format("{:.2f}", to)};
        r.insert(r.end(), cells.begin(), cells.end());
        // A stretch in which no path changes what it does: one row.
        if (!table.rows.empty() && std::equal(cells.begin(), cells.end(), table.rows.back().begin() + 2) &&
            table.rows.back()[1] == r[0])
            table.rows.back()[1] = r[1];
        else
            table.rows.push_back(std::move(r));
    };
    for (std::size_t k = 0; k < times.size(); ++k) {
        // The waits met at once (no time held) at this instant: a row of their own.
        std::vector<std::string> met(paths);
        bool any = false;
        for (std::size_t p = 0; p < paths; ++p)
            for (const auto& s : of[p])
                if (s.kind == TimelineStretch::Wait && s.to - s.from <= kSame && std::abs(s.from - times[k]) <= kSame) met[p] = s.what, any = true;
        if (any) table.rows.push_back([&] {
            std::vector<std::string> r{fmt::format("{:.2f}", times[k]), fmt::format("{:.2f}", times[k])};
            for (auto& m : met) r.push_back(m.empty() ? "" : m.substr(0, m.find(' ')) + " met");
            return r;
        }());
        if (k + 1 == times.size()) break;
        const double mid = (times[k] + times[k + 1]) / 2;
        std::vector<std::string> cells(paths, "-");
        for (std::size_t p = 0; p < paths; ++p)
            for (const auto& s : of[p])
                if (s.from <= mid && mid < s.to) cells[p] = s.what;
        row(times[k], times[k + 1], cells);
    }
    return table;
}

std::optional<BalancedRoughing> balancedRoughing(const Plan& plan)
{
    const Machine* machine = findMachine(plan.mmJob.machine);
    if (!plan.mmJob.bar || !machine || !machine->layout.multiPath) return std::nullopt;
    BalancedRoughing out;
    out.step = plan.steps.size();
    const std::optional<PlannedBalance>& balance = plan.balance;
    if (!balance) return out;
    out.step = balance->step;
    out.cut = balance->cut;
    if (!*out.cut) return out;
    const TurnStep& rough = *turnOf(plan.steps[out.step]);
    out.timeline = runTimeline(**out.cut, *machine);
    out.onePathSeconds = singlePathSeconds(rough.path, rough.cutting, *machine);
    return out;
}

std::vector<sheet::Section> twoPathSheet(const Plan& plan)
{
    const std::optional<BalancedRoughing> balanced = balancedRoughing(plan);
    if (!balanced) return {};
    const MultiPath& mp = *findMachine(plan.mmJob.machine)->layout.multiPath;
    std::vector<sheet::Section> out;
    sheet::Section paths;
    paths.heading = "Paths";
    paths.table.headers = {"No.", "Step", "Path"};
    paths.table.numeric = {true, false, false};
    paths.table.widths = {1, 4, 12};
    const std::size_t rough = balanced->step;
    const auto& cut = balanced->cut;
    for (std::size_t k = 0; k < plan.steps.size(); ++k) {
        std::string where = fmt::format("1 ({})", mp.paths[0].name);
        if (k == rough && cut && *cut) {
            where.clear();
            for (std::size_t p = 0; p < (**cut).paths.size(); ++p) {
                std::string blocks;
                for (const auto& b : (**cut).paths[p].blocks) blocks += (blocks.empty() ? "CB" : ", CB") + std::to_string(b.number);
                where += fmt::format("{}{} ({}): {}", p ? "; " : "", p + 1, mp.paths[p].name, blocks.empty() ? "no block" : blocks);
            }
        }
        paths.table.rows.push_back({std::to_string(k + 1), plan.steps[k].label(), where});
    }
    paths.note = "Path 1's program (STEM.p1) runs every step; path 2's (STEM.p2) its blocks of the balanced roughing, "
                 "meeting path 1 before the first cut and after the last.";
    if (rough == plan.steps.size()) paths.note = "No roughing step to balance between the paths: nothing is exported.";
    else if (!*cut) paths.note = "The roughing does not balance (" + cut->error() + "): nothing is exported.";
    out.push_back(std::move(paths));
    if (!balanced->timeline) return out;

    const Timeline& t = *balanced->timeline;
    sheet::Section gantt;
    gantt.heading = "Balanced roughing on the timeline";
    gantt.table = timelineTable(t, (**cut).paths.size());
    for (std::size_t p = 0; p < mp.paths.size(); ++p) gantt.table.headers[2 + p] += " " + mp.paths[p].name;
    const double one = balanced->onePathSeconds;
    std::string deadlocks;
    for (const auto& d : t.deadlocks) deadlocks += (deadlocks.empty() ? "" : "; ") + d.why;
    gantt.note = fmt::format("Roughing on {} paths {:.2f} s against {:.2f} s on one (ratio {:.3f}); the follower at least {:.2f} "
                             "spindle revolutions behind the cut above (set: {:g}); deadlocks: {}.",
                             (**cut).paths.size(), t.seconds(), one, one > 0 ? t.seconds() / one : 0.0,
                             t.lags.empty() ? 0.0 : t.leastLag(), plan.mmJob.twoPath.dwellRevolutions,
                             deadlocks.empty() ? "none" : deadlocks);
    out.push_back(std::move(gantt));
    return out;
}

}  // namespace taiwa
