// Every program an export writes, each posted once (docs/verification.md
// "The tape read back"): the tape, a two-path lathe's programs (STEM.p1.nc,
// STEM.p2.nc …, in place of the tape) and the probing units' programs
// (STEM.uN.setting.nc, STEM.uN.probe.nc). `taiwa export` and the station's
// export post them, the tape read-back (verify/tape_readback.h) judges them
// and the export (export/export.h) writes that very text.
#pragma once

#include "model/plan.h"
#include "model/result.h"
#include "model/two_path.h"
#include "post/dialect.h"
#include "post/post.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// A two-path lathe's programs (post/two_path_post.h): the balanced cut, the
// roughing step's index in the plan it was balanced from, and one program
// per path, path 1's first.
struct PostedTwoPath {
    BalancedCut cut;
    std::size_t roughing = 0;
    std::vector<PostedProgram> programs;
};

// A probing unit's programs (post/probe_program.h), in mm: the setting
// program (empty when the unit has no measured touches) and the probing cycle.
struct PostedProbing {
    int unit = 0;  // the job's unit (0-based): the files are STEM.u<unit + 1>.…
    std::string setting;
    std::string probe;
};

struct PostedJob {
    PostedProgram tape;  // STEM.nc (a two-path lathe's: the findings placed on it, not written)
    // A two-path lathe's programs, or why they cannot be written (no
    // roughing step, a balancing refusal, a dialect that writes none);
    // nothing: the machine has one path.
    std::optional<Result<PostedTwoPath>> twoPath;
    std::vector<PostedProbing> probing;  // one per probing unit, in the plan's order
};

// The job's programs posted with `post` (postOptions of the plan, the
// dialect, units, program number and stem). Throws as postProcess does for
// the tape.
PostedJob postJob(const Plan& plan, const PostOptions& post);
// The same around a tape already posted with `post`, the probing programs
// in `dialect` (the read-back of a tape alone: verify/tape_readback.h).
PostedJob postJob(const Plan& plan, const PostOptions& post, PostedProgram tape, const post::Dialect& dialect);

// A two-path lathe's programs posted with `post` (as postJob) from the
// plan's balanced roughing (Plan::balance: a plan from planJob with its
// tool paths); nothing for a machine of one path.
std::optional<Result<PostedTwoPath>> postTwoPath(const Plan& plan, const PostOptions& post);

// The probing units' programs in `dialect` (as the export names them, the
// O-numbers after the tape's `post.programNumber`, in mm whatever the
// job's unit). None for a dialect that writes no probing programs (the
// export refuses it before).
std::vector<PostedProbing> postProbing(const Plan& plan, const PostOptions& post, const post::Dialect& dialect);

}  // namespace taiwa
