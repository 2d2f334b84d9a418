// The two-path job's programs and timeline for the station (two_path_shown.h).
#include "ui/two_path_shown.h"

#include "machine/machine.h"
#include "pipeline/pipeline.h"
#include "post/two_path_post.h"
#include "ui/core_messages.h"
#include "viz/palette.h"

#include <QCoreApplication>

#include <algorithm>
#include <array>

namespace taiwa::ui {

namespace {

// The shipped machines' path names (resources/machines/*.json "paths[i].name").
constexpr const char* kPathNames = "taiwa::PathNames";
[[maybe_unused]] constexpr std::array kShippedPathNames{
    QT_TRANSLATE_NOOP("taiwa::PathNames", "upper turret"),
    QT_TRANSLATE_NOOP("taiwa::PathNames", "lower turret"),
};

}  // namespace

QString localPathName(const std::string& name) { return QCoreApplication::translate(kPathNames, name.c_str()); }

QColor turretColour(std::size_t path)
{
    static constexpr viz::Rgb kColours[] = {viz::palette::kTool, viz::palette::kTool2, viz::palette::kTool3};
    const viz::Rgb c = kColours[std::min(path, std::size(kColours) - 1)];
    return QColor(c.r, c.g, c.b);
}

std::optional<std::pair<std::size_t, int>> TwoPathShown::blockOfMove(int step, int move) const
{
    if (!balanced.cut || !*balanced.cut || step != static_cast<int>(balanced.step) || move < 0) return std::nullopt;
    for (const BalancedPath& p : (**balanced.cut).paths)
        for (const BalancedBlock& b : p.blocks) {
            const int from = blockStart[static_cast<std::size_t>(b.number)];
            if (move >= from && move < from + static_cast<int>(b.moves.size())) return std::pair{b.path, b.number};
        }
    return std::nullopt;
}

int TwoPathShown::cutMoveOf(int block) const
{
    if (!balanced.cut || !*balanced.cut) return -1;
    for (const BalancedPath& p : (**balanced.cut).paths)
        for (const BalancedBlock& b : p.blocks)
            if (b.number == block) return blockStart[static_cast<std::size_t>(block)] + static_cast<int>(b.cutFrom);
    return -1;
}

std::optional<TwoPathShown> twoPathShown(const Plan& plan, const std::string& dialect, const std::string& stem)
{
    std::optional<BalancedRoughing> balanced = balancedRoughing(plan);
    if (!balanced) return std::nullopt;
    TwoPathShown out;
    out.balanced = std::move(*balanced);
    const MultiPath& mp = *findMachine(plan.mmJob.machine)->layout.multiPath;
    for (const LathePath& p : mp.paths) out.pathNames.push_back(p.name);
    out.tools.resize(mp.paths.size());
    for (const Step& s : plan.steps)
        if (s.tool && std::find(out.tools[0].begin(), out.tools[0].end(), s.tool->toolId) == out.tools[0].end())
            out.tools[0].push_back(s.tool->toolId);
    const auto& cut = out.balanced.cut;
    if (!cut) return out;  // no roughing step: no programs, no error of the balancing
    if (!*cut) {
        out.error = coreMessage(cut->error());
        return out;
    }
    const Step& rough = plan.steps[out.balanced.step];
    for (std::size_t p = 1; p < mp.paths.size(); ++p)
        if (rough.tool) out.tools[p].push_back(rough.tool->toolId);
    // Each block's first move among the single path's: the blocks cut it
    // into pieces in CB order, none lost or doubled, the tail after them.
    const BalancedCut& bc = **cut;
    out.places = toolPlaces(bc, *findMachine(plan.mmJob.machine));
    for (const LathePath& p : mp.paths) out.sides.push_back(p.xDirection == mp.paths.front().xDirection ? 1 : -1);
    std::vector<const BalancedBlock*> byNumber(static_cast<std::size_t>(bc.blockCount) + 1, nullptr);
    for (const BalancedPath& p : bc.paths)
        for (const BalancedBlock& b : p.blocks) byNumber[static_cast<std::size_t>(b.number)] = &b;
    out.blockStart.assign(byNumber.size(), 0);
    int at = 0;
    for (std::size_t n = 1; n < byNumber.size(); ++n) {
        out.blockStart[n] = at;
        at += byNumber[n] ? static_cast<int>(byNumber[n]->moves.size()) : 0;
    }
    try {
        out.programs = postBalancedCut(bc, plan.steps, out.balanced.step, mp, plan.tools,
                                       postOptions(plan, dialect, std::nullopt, 1000, stem));
    } catch (const Refusal& e) {
        out.error = coreMessage(e.what());
        return out;
    }
    // The lines' sources as the plan's: path 1's steps are the job's, the
    // other paths' program is the roughing step alone; a roughing move is
    // the single path's of its block (the tail: the single path's tail).
    const int here = static_cast<int>(out.balanced.step);
    const int tailFrom = at;
    for (std::size_t p = 0; p < out.programs.size(); ++p) {
        std::vector<int> single;  // the path's own moves, in order, as the single path's
        for (const BalancedBlock& b : bc.paths[p].blocks)
            for (std::size_t i = 0; i < b.moves.size(); ++i) single.push_back(out.blockStart[static_cast<std::size_t>(b.number)] + static_cast<int>(i));
        for (std::size_t i = 0; i < bc.paths[p].tail.size(); ++i) single.push_back(tailFrom + static_cast<int>(i));
        for (BlockSource& l : out.programs[p].lines) {
            if (p > 0 && l.step >= 0) l.step = here;
            if (l.step == here && l.move >= 0)
                l.move = static_cast<std::size_t>(l.move) < single.size() ? single[static_cast<std::size_t>(l.move)] : -1;
        }
    }
    return out;
}

}  // namespace taiwa::ui
