// A two-path lathe's programs read back (tape_readback_two_path.h): each
// through readBackLathePath against its path's steps (post/two_path_post.h's
// balancedPathJob, what it was posted from), then the waits paired.
#include "verify/tape_readback_two_path.h"

#include "machine/machine.h"
#include "post/two_path_post.h"
#include "verify/tape_readback.h"
#include "verify/tape_reader.h"
#include "verify/two_path_check.h"

#include <algorithm>
#include <string>

namespace taiwa::verify {

namespace {

std::string waitName(int code, bool fanuc)
{
    if (fanuc) return "M" + std::to_string(code);
    return code > 0 ? "M66 (meeting " + std::to_string(code) + ")" : "M66 (no meeting: its output and input disagree)";
}

// Program `program`'s waits (`other`) against path 1's (`one`, program `first`): the first
// that differs, is missing on one of them or meets nothing is a finding on
// path 1's program, or on the other's where path 1's has run out or its is
// the wait that meets nothing.
void pairWaits(Report& report, const std::vector<TapeWait>& one, const std::vector<TapeWait>& other, const std::string& first,
               const std::string& program, bool fanuc)
{
    for (std::size_t i = 0; i < std::max(one.size(), other.size()); ++i) {
        const bool inOne = i < one.size(), inOther = i < other.size();
        if (inOne && inOther && one[i].code == other[i].code && one[i].code > 0) continue;
        Finding f;
        f.kind = FindingKind::UnpairedWait;
        // Path 1's wait unless path 1 has run out of them (or its is the one that meets nothing).
        const bool onOther = !inOne || (inOther && other[i].code <= 0);
        const TapeWait& w = onOther ? other[i] : one[i];
        f.program = onOther ? program : first;
        f.line = w.line;
        f.part = waitName(w.code, fanuc);
        report.findings.push_back(f);
        return;
    }
}

}  // namespace

std::optional<TwoPathPrograms> twoPathPrograms(const Plan& plan, const PostOptions& post)
{
    auto posted = postTwoPath(plan, post);
    if (!posted || !*posted) return std::nullopt;
    return std::move(**posted);
}

void readBackTwoPath(Report& report, const Plan& plan, const TwoPathPrograms& programs, const post::Dialect& dialect,
                     const PostOptions& post)
{
    const Machine* machine = findMachine(plan.mmJob.machine);
    if (!plan.mmJob.bar || !machine || !machine->layout.multiPath) return;
    const MultiPath& layout = *machine->layout.multiPath;
    // Each program named by its file (Finding::program): STEM.p1.nc, STEM.p2.nc …
    std::vector<std::string> names;
    for (std::size_t p = 0; p < programs.programs.size(); ++p)
        names.push_back(programFile(post, ".p" + std::to_string(p + 1) + "." + dialect.fileExtension));
    std::vector<TapeReading> tapes;
    for (std::size_t p = 0; p < programs.programs.size() && p < programs.cut.paths.size(); ++p) {
        const BalancedPathJob job = balancedPathJob(programs.cut, plan.steps, programs.roughing, layout, post, p);
        PathProgram which;
        which.program = names[p];
        which.layout = &layout;
        which.path = p;
        which.stepOffset = p == 0 ? 0 : static_cast<int>(programs.roughing);
        which.waits = &layout.waitCodes;
        tapes.push_back(readBackLathePath(report, job.steps, *plan.mmJob.bar, programs.programs[p], dialect, job.options, which));
    }
    // Waits are paired only on programs read through (an unread one is a finding already).
    const bool fanuc = dialect.macroSyntax == "fanuc";
    for (std::size_t p = 1; p < tapes.size(); ++p)
        if (tapes[0].error.empty() && tapes[p].error.empty())
            pairWaits(report, tapes[0].waits, tapes[p].waits, names[0], names[p], fanuc);
}

}  // namespace taiwa::verify
