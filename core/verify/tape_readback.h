// The posted tape judged as written: read back through its dialect's reader
// (tape_reader.h) and every motion on it held against the plan. A motion
// must be the planned move its line was written for (the end point within
// 1.5 units of the tape's last decimal, the kind, the arc's centre and turn,
// the feed rate to half a unit of F), a canned cycle's motions must stay in
// their hole, and the frame's own moves (the approach after a tool change,
// the retract to the safe height) must go where the post sends them. Any
// other motion (a shop's word that moves, a post's bug) is a finding at its
// tape line saying what it does, fatal when it goes into stock; a tape the
// reader cannot follow is a fatal finding at the line where it stops.
// docs/verification.md "The tape read back".
#pragma once

#include "model/plan.h"
#include "post/dialect.h"
#include "post/post.h"
#include "verify/verify.h"

namespace taiwa::verify {

struct TapeReading;  // tape_reader.h

// Whether the tape postProcess makes of `plan` is read back: a milling
// job's and a one-path lathe's (a two-path lathe's programs are posted
// apart, post/two_path_post.h, and not read back).
bool readsBack(const Plan& plan);

// The most findings of the tape's own one read-back adds (a word that moves
// repeats at every tool change; a post's bug could repeat at every move).
constexpr int kMaxTapeFindings = 50;

// Adds to `report` what reading `program` back finds. `program` was posted
// from `plan`'s steps with `post`, in `dialect`'s language (the dialect the
// post used, passed in so that one not in the library can be judged). The
// material left in the report (Report::stock) tells how deep a motion goes
// into stock; without it (a reused report) the stock block as it was before
// the first cut does. A lathe job's tape is read by readLatheTape and held
// against its turning steps (tape_readback_lathe.cpp); the material there
// is the bar's half-section (Report::section, else the bar as it was).
// Nothing is done for a job readsBack refuses.
void readBack(Report& report, const Plan& plan, const PostedProgram& program, const post::Dialect& dialect,
              const PostOptions& post);

// readBack of a lathe job (tape_readback_lathe.cpp), which readBack calls.
void readBackLathe(Report& report, const Plan& plan, const PostedProgram& program, const post::Dialect& dialect,
                   const PostOptions& post);

// The reading's "unread tape" finding, where the reader stopped (none when
// it read the tape through): the milling and the lathe read-back end so.
void addUnreadTape(Report& report, const TapeReading& tape);

}  // namespace taiwa::verify
