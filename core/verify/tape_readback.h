// The posted tape judged as written: read back through its dialect's reader
// (tape_reader.h) and every motion on it held against the plan. A motion
// must be the planned move its line was written for (the end point within
// 1.5 units of the tape's last decimal, the kind, the arc's centre and turn,
// the feed rate to half a unit of F), a canned cycle's motions must stay in
// their hole, and the frame's own moves (the approach after a tool change,
// the retract to the safe height) must go where the post sends them. Any
// other motion (a shop's word that moves, a post's bug) is a finding at its
// tape line saying what it does, fatal when it goes into stock; a tape the
// reader cannot follow is a fatal finding at the line where it stops. A
// two-path lathe's programs are read back each on its own lines, and their
// waits paired (tape_readback_two_path.h).
// docs/verification.md "The tape read back".
#pragma once

#include "model/plan.h"
#include "model/setup.h"
#include "post/dialect.h"
#include "post/post.h"
#include "post/posted_job.h"
#include "verify/verify.h"

namespace taiwa {
struct MultiPath;      // machine/lathe_kinds.h
struct WaitCodeRange;
}  // namespace taiwa

namespace taiwa::verify {

struct TapeReading;  // tape_reader.h

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
// A two-path lathe's programs are posted apart (post/two_path_post.h):
// for such a job `program` is not read, its programs are (readBackTwoPath,
// tape_readback_two_path.h).
// A milling job's probing units' programs are read back by readBackProbing
// (below).
void readBack(Report& report, const Plan& plan, const PostedProgram& program, const post::Dialect& dialect,
              const PostOptions& post);

// The same of every program of an export, posted once (post/posted_job.h)
// and written by the export as it is: the tape, a two-path lathe's
// programs and the probing units' programs handed over are the ones read
// back (the readBack above posts the other programs itself, in `dialect`).
void readBack(Report& report, const Plan& plan, const PostedJob& posted, const post::Dialect& dialect,
              const PostOptions& post);

// A program's file as the export names it (Finding::program): the stem
// and `suffix` ("part" and ".p2.nc": "part.p2.nc"; no stem: "p2.nc").
std::string programFile(const PostOptions& post, const std::string& suffix);

// readBack of a lathe job (tape_readback_lathe.cpp), which readBack calls.
void readBackLathe(Report& report, const Plan& plan, const PostedJob& posted, const post::Dialect& dialect,
                   const PostOptions& post);

// Which of a two-path lathe's programs a lathe tape is
// (tape_readback_two_path.cpp); the default: a one-path lathe's one tape.
struct PathProgram {
    std::string program;                   // Finding::program: "STEM.p1.nc", "STEM.p2.nc" …; empty: the tape
    const MultiPath* layout = nullptr;     // its coordinates into path 1's, where the bar is measured
    std::size_t path = 0;
    int stepOffset = 0;                    // its steps' indices into the plan's (another path's one step: the roughing)
    const WaitCodeRange* waits = nullptr;  // the control's wait codes (readLatheTape)
};

// A lathe tape read back against `steps` (what `program` was posted from,
// with `post`), the material the bar's (Report::section, else `bar`); the
// reading returned (its waits).
TapeReading readBackLathePath(Report& report, const std::vector<Step>& steps, const BarStock& bar, const PostedProgram& program,
                              const post::Dialect& dialect, const PostOptions& post, const PathProgram& which);

// readBack of a milling job's probing units (tape_readback_probe.cpp),
// which readBack calls: each unit's setting program (when it has measured
// touches) and probing cycle (`programs`, posted by postProbing as export
// posts them) read back against the unit's nominal part; the findings name
// the program (Finding::program: "STEM.u1.probe.nc", "u1.probe.nc" without
// a stem) and its line. A dialect that writes no probing programs has none.
void readBackProbing(Report& report, const Plan& plan, const std::vector<PostedProbing>& programs,
                     const post::Dialect& dialect, const PostOptions& post);

// The findings of reading back one unit's probing cycle `text` (in
// `dialect`), `program` its file, `stockHeight` [mm] where the table is
// below the top face: the touches made on the unit's nominal part, its
// rapids out of it (grown by the stylus ball) and at the cycle's places,
// each touch's target and point of touch the planned ones.
std::vector<Finding> probingFindings(const WorkSetup& setup, double stockHeight, const std::string& text,
                                     const post::Dialect& dialect, const std::string& program);

// The same of a unit's setting program: its motions at the machine's top,
// the last one to the measured centre, and no probing move.
std::vector<Finding> settingFindings(const WorkSetup& setup, double stockHeight, const std::string& text,
                                     const post::Dialect& dialect, const std::string& program);

// The reading's "unread tape" finding, where the reader stopped (none when
// it read the tape through), on `program` (Finding::program): the milling
// and the lathe read-back end so.
void addUnreadTape(Report& report, const TapeReading& tape, const std::string& program = {});

}  // namespace taiwa::verify
