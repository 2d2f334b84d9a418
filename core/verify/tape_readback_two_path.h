// The read-back of a two-path lathe's programs (docs/verification.md "Lathe
// tapes", docs/two-path-lathe.md "The programs"): the plan's balanced
// roughing posted as the export does (STEM.p1, STEM.p2 …), each program
// read by the lathe reader with its waits and dwells and each motion held
// against the steps that path's program was posted from (path 1: the job's
// steps, the roughing's passes its balanced-cut blocks; another path: its
// blocks), measured in the bar in path 1's coordinates; the findings on the
// program's own lines (Finding::program). The waits must pair: every
// program's the same meetings in the same order as path 1's, else the
// first that differs is a finding (the paths would wait for ever).
#pragma once

#include "model/plan.h"
#include "model/two_path.h"
#include "post/dialect.h"
#include "post/post.h"
#include "post/posted_job.h"
#include "verify/verify.h"

#include <optional>
#include <vector>

namespace taiwa::verify {

// The programs the export writes (post/posted_job.h postTwoPath).
using TwoPathPrograms = PostedTwoPath;

// The programs the export writes for `plan` with `post` (postTwoPath).
// Nothing when the job's machine has one path or its programs cannot be
// written (its roughing not balanced: checkTwoPath says why; a dialect that
// writes no two-path programs: the export refuses it).
std::optional<TwoPathPrograms> twoPathPrograms(const Plan& plan, const PostOptions& post);

// Adds what reading `programs` back finds (as readBack, tape_readback.h).
void readBackTwoPath(Report& report, const Plan& plan, const TwoPathPrograms& programs, const post::Dialect& dialect,
                     const PostOptions& post);

}  // namespace taiwa::verify
