// The programs of a balanced cut (two_path_post.h): each path's blocks
// posted by the lathe post as explicit passes, the waits and dwells put in
// before each cut.
#include "post/two_path_post.h"

#include "post/dialect.h"
#include "post/lathe_post.h"
#include "post/number_format.h"
#include "post/tape_image.h"

#include <fmt/format.h>

#include <optional>
#include <stdexcept>

namespace taiwa {

BalancedPathJob balancedPathJob(const BalancedCut& cut, const std::vector<Step>& steps, std::size_t roughing,
                                const MultiPath& layout, const PostOptions& options, std::size_t p)
{
    const BalancedPath& bp = cut.paths[p];
    BalancedPathJob job;
    Step s = steps[roughing];
    TurnStep ts = *turnOf(s);
    ts.path = {};
    ts.path.start = bp.start;
    // Where each block's cut starts among the path's moves.
    for (const auto& b : bp.blocks) {
        job.cuts.emplace_back(ts.path.moves.size() + b.cutFrom, &b);
        ts.path.moves.insert(ts.path.moves.end(), b.moves.begin(), b.moves.end());
    }
    job.tailFrom = ts.path.moves.size();
    ts.path.moves.insert(ts.path.moves.end(), bp.tail.begin(), bp.tail.end());
    s.payload = ts;
    PostOptions& o = job.options;
    o = options;
    o.programNumber = options.programNumber + static_cast<int>(p);
    o.programName = fmt::format("Path {} {}: {}", p + 1, layout.paths[p].name, options.programName);
    o.fileStem = fmt::format("{}.p{}", options.fileStem, p + 1);
    o.turningCycles = false;
    // The tool change point on the path's own side.
    const turning::ZR change = layout.fromPath1({options.latheChangeZ, options.latheChangeX / 2.0}, p);
    o.latheChangeZ = change.z;
    o.latheChangeX = 2.0 * change.r;
    // Path 1 runs the whole job; the others their blocks.
    if (p == 0) {
        job.steps = steps;
        job.steps[roughing] = std::move(s);
        job.step = roughing;
    } else {
        job.steps = {std::move(s)};
    }
    return job;
}

std::vector<PostedProgram> postBalancedCut(const BalancedCut& cut, const std::vector<Step>& steps, std::size_t roughingIndex,
                                           const MultiPath& layout, const std::vector<Tool>& library,
                                           const PostOptions& options)
{
    if (roughingIndex >= steps.size()) throw std::logic_error("post-processor: the balanced cut's step is not among the steps");
    const post::Dialect* d = &post::dialectNamed(options.dialect);
    const bool fanuc = d->macroSyntax == "fanuc" && d->syntax == post::Syntax::Iso;
    const bool linuxcnc = d->macroSyntax == "linuxcnc" && d->syntax == post::Syntax::Iso;
    if (!fanuc && !linuxcnc)
        throw Refusal("post-processor: " + d->name + " writes no two-path programs (FANUC's family and LinuxCNC do)");
    if (!turnOf(steps[roughingIndex])) throw std::logic_error("post-processor: the balanced cut's step is not a turning step");
    const auto dwellNumber = [&](double s) { return post::formatNumber(s, 3, d->decimalPointAlways); };
    std::vector<PostedProgram> out;
    for (std::size_t p = 0; p < cut.paths.size(); ++p) {
        const BalancedPath& bp = cut.paths[p];
        const BalancedPathJob job = balancedPathJob(cut, steps, roughingIndex, layout, options, p);
        const auto& cuts = job.cuts;
        const std::size_t tailFrom = job.tailFrom;
        const PostOptions& o = job.options;
        const PostedProgram posted = postLathe(job.steps, library, o);
        const int here = static_cast<int>(job.step);

        // The waits and dwells, each before the first line of its cut's move.
        int meeting = 0;
        auto syncLines = [&](std::optional<int> code, double dwell) {
            std::vector<std::string> lines;
            if (code && fanuc) {
                lines.push_back(fmt::format("M{}", *code));
            } else if (code) {
                ++meeting;
                lines.push_back(fmt::format("(wait M{}: meeting {} of the paths)", *code, meeting));
                lines.push_back(meeting % 2 ? "M64 P0" : "M65 P0");
                lines.push_back(fmt::format("M66 P0 {} Q{}", meeting % 2 ? "L3" : "L4", post::formatInteger(kLinuxcncWaitTimeout)));
                lines.push_back(fmt::format("o{} if [#5399 LT 0]", 200 + meeting));
                lines.push_back("  (MSG, the other path did not come: stopped)");
                lines.push_back("  M2");
                lines.push_back(fmt::format("o{} endif", 200 + meeting));
            }
            if (dwell > 0) lines.push_back(fanuc ? "G04 X" + dwellNumber(dwell) : "G4 P" + dwellNumber(dwell));
            return lines;
        };
        PostedProgram prog;
        auto emit = [&](const std::vector<std::string>& lines, BlockSource from) {
            for (const auto& l : lines) {
                prog.nc += l + '\n';
                prog.lines.push_back(from);
            }
        };
        std::size_t nextCut = 0, lineStart = 0;
        bool tailDone = !bp.tailWait, endDone = !bp.endWait, seenStep = false;
        for (std::size_t i = 0; i < posted.lines.size(); ++i) {
            const std::size_t lineEnd = posted.nc.find('\n', lineStart);
            const std::string text = posted.nc.substr(lineStart, lineEnd - lineStart);
            lineStart = lineEnd + 1;
            const BlockSource src = posted.lines[i];
            const bool inMoves = src.step == here && src.move >= 0;
            while (nextCut < cuts.size() && inMoves && static_cast<std::size_t>(src.move) >= cuts[nextCut].first) {
                const BalancedBlock& b = *cuts[nextCut].second;
                emit(syncLines(b.wait, b.dwellSeconds), src);
                ++nextCut;
            }
            // The last meeting of a path without a block there: before its
            // tail, or before the program's end when the tail wrote nothing.
            if (!tailDone && nextCut == cuts.size() &&
                ((inMoves && static_cast<std::size_t>(src.move) >= tailFrom) || (src.step != here && seenStep))) {
                emit(syncLines(bp.tailWait, 0.0), src);
                tailDone = true;
            }
            // After the roughing, all paths meet before path 1 goes on.
            if (!endDone && src.step != here && seenStep) {
                emit(syncLines(bp.endWait, 0.0), src);
                endDone = true;
            }
            seenStep = seenStep || src.step == here;
            prog.nc += text + '\n';
            prog.lines.push_back(src);
        }
        if (!endDone) throw std::logic_error("two-path post: path " + std::to_string(p + 1) + "'s end wait has no place");
        if (!tailDone) throw std::logic_error("two-path post: path " + std::to_string(p + 1) + "'s last wait has no place");
        prog.tapeImage = post::tapeImage(prog.nc, o.programName, d->name, options.machine);
        out.push_back(std::move(prog));
    }
    return out;
}

}  // namespace taiwa
