// Verification by simulation: every step's path cut into the stock with the
// tool's real shape, on a height field finer than the preview's (default
// 0.05 mm) for a milling job, on the bar's exact half-section for a lathe
// job (the insert's outline; verify_turning.h), and what a verifier finds on the way: gouges into the finished
// part (the job's geometry, model/cavity.h, not the paths), material left
// where a step was meant to clear it, rapids into stock, the shank or the
// holder running into stock, and paths longer than the machine's travel.
// `taiwa verify` prints the report, `taiwa export` refuses a tape with a
// gouge, a collision or beyond the travel. docs/verification.md tells how and why.
#pragma once

#include "model/plan.h"
#include "post/post.h"
#include "sim/height_field.h"

#include <string>
#include <vector>

namespace taiwa::verify {

enum class FindingKind {
    Gouge,           // material removed inside the finished part
    Collision,       // the shank or the holder in stock (`part` says which)
    RapidIntoStock,  // a G0 that cuts
    TravelLimit,     // the paths span more than an axis travels
    RestMaterial,    // material left where the step (or the unit) should have cleared it
    // The posted tape read back (tape_readback.h):
    UnplannedMove,   // a motion on the tape that the plan does not have (`part`: "rapid", "feed" or "arc")
    UnreadTape,      // a tape line its dialect's reader does not understand (`part`: why); the rest is unchecked
    UnpairedWait,    // a two-path lathe's wait the other path's program does not meet at its turn (`part`: the wait)
};
// "gouge", "collision", "rapid-into-stock", "travel-limit", "rest-material",
// "unplanned-move", "unread-tape", "unpaired-wait"
const char* toKey(FindingKind k);

struct Finding {
    FindingKind kind = FindingKind::Gouge;
    int step = -1;      // index into plan.steps (machining order); -1: the whole job
    int move = -1;      // index into the step's path; -1: the step as a whole
    int line = 0;       // 1-based line of the tape where the move is written; 0: not placed (placeOnTape)
    // The program `line` is on when it is not the one tape: its file as the
    // export names it, a two-path lathe's "STEM.p2.nc", a probing unit's
    // "STEM.u1.probe.nc" ("p2.nc", "u1.probe.nc" without a stem); empty: the tape.
    std::string program;
    // The worst point [mm]: milling, a cell's centre and its height after
    // the move; a lathe job, {x: the diameter (as the tape writes X), y: 0, z}.
    Point3 position{};
    // Gouge depth, height of material (lathe: its thickness), depth of the
    // rapid into stock (or of the unplanned move), overlap, excess [mm].
    double size = 0.0;
    // Rest material and gouges: the plan-view area of the cells found
    // (lathe: the area of the half-section) [mm²].
    double area = 0.0;
    std::string part;   // collisions: "shank" or "holder"; travel limits: the axis "x", "y", "z"
    // A gouge, a collision (a rapid into stock is one, at rapid speed), a
    // travel limit, a tape that cannot be read back or a move the plan does
    // not have that goes into stock: the tape must not run. Material left,
    // and a move the plan does not have that stays out of the stock, are
    // reported only.
    bool fatal() const
    {
        return kind != FindingKind::RestMaterial && !(kind == FindingKind::UnplannedMove && !(size > 0.0));
    }
    friend bool operator==(const Finding&, const Finding&) = default;
};

// The verification's cell size unless the operator chooses one [mm], and
// the most cells it takes by default: a larger stock is verified on the
// finest grid within that many cells (defaultResolution), so that a job
// of a thousand pockets on a 1.2 m plate verifies in seconds, not minutes.
constexpr double kDefaultResolution = 0.05;
constexpr double kDefaultCells = 16e6;

struct Options {
    // The cell size [mm]; a lathe job: arcs and the nose flattened within a
    // tenth of it, outlines sampled at it, a gouge deeper than 1 µm and it.
    double resolution = kDefaultResolution;
    unsigned threads = 0;      // 0: every core (a lathe job runs on one: it takes milliseconds)
    // The most cells the tools' shapes may be swept over (Report::cellVisits)
    // on this grid: past it the verification stops and starts again on a
    // grid twice as coarse, until it fits (Report::coarsened says so). The
    // work of a verification is then bounded whatever the paths' step-over
    // and layer depth; 0: no bound (a resolution the operator chose).
    double maxCellVisits = 0.0;
    // Every piece of every path cut in the path's order: the reference
    // the faster order is held against (tests, bench_verify). By default a
    // run of pieces going down that gouges nothing is cut from its end
    // (verify/milling_cut.cpp), which leaves the same heights and findings.
    bool inPathOrder = false;
};

// The bound of the verification's work when the operator chose no cell
// size: about 10 s of a two-core machine (docs/verification.md).
constexpr double kDefaultCellVisits = 1e9;

struct Report {
    std::vector<Finding> findings;  // by step, then kind, then move
    double resolution = 0.0;        // the cell size used
    int columns = 0, rows = 0;      // of the height field (0 for a lathe job)
    // Per step: the volume it cut [mm³] (lathe: the half-section it took
    // off, turned about the axis).
    std::vector<double> removed;
    double cellVisits = 0.0;        // cells the tool's shapes were swept over (the benchmark's count; 0 on a lathe)
    sim::HeightField stock;         // after the last step (empty for a lathe job)
    // A lathe job: the bar's half-section after the last step, closed loops
    // in (z, r), holes clockwise.
    std::vector<std::vector<turning::ZR>> section;
    // Not every job is simulated: a lathe job without a turning step is
    // not (then `skipped` says why and there are no findings).
    std::string skipped;
    // The grid is coarser than Options::resolution asked, because on that
    // grid the work would have passed Options::maxCellVisits: one sentence
    // saying so; empty otherwise.
    std::string coarsened;
    bool fatal() const;
    int count(FindingKind k) const;
};

// The smallest cell the verification takes [mm], and the most cells (a
// 200 x 200 mm stock at 0.02 mm; past it the command asks for a coarser
// resolution instead of running out of memory).
constexpr double kFinestResolution = 0.005;
constexpr double kMaxCells = 100e6;

// The cell size the verification takes for this plan unless the operator
// chooses one: kDefaultResolution, or for a stock that would need more than
// kDefaultCells of them the finest cell (in whole hundredths of a mm) that
// stays within that many. A lathe job: kDefaultResolution.
double defaultResolution(const Plan& plan);

// Simulates the plan's steps in order and checks them. The plan must have
// its paths (PlanOptions::withToolPaths). Throws Refusal (model/result.h)
// for a resolution out of range or a grid beyond kMaxCells.
Report verifyPlan(const Plan& plan, const Options& options = {});

// Fills each finding's tape line from a program posted from the same plan.
void placeOnTape(Report& report, const PostedProgram& program);

// One finding in words, lengths in the job's unit: "step 3 (Roughing II,
// unit 2): gouge 0.520 mm deep at X12.300 Y4.100 Z-10.520, move 57, tape
// line 312"; on a lathe "at X24.600 Z-10.520", X a diameter; on a program
// other than the tape "…, in part.p2.nc at line 14".
std::string describe(const Finding& f, const Plan& plan);

}  // namespace taiwa::verify
