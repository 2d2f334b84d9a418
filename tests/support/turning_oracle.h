// An oracle of its own for lathe tapes, judged on what LinuxCNC's rs274
// makes of them (support/rs274.h): it knows nothing of core/turning/ and
// takes from a plan only the finished part (each TURN unit's deformed
// profile, plan.turned[k].deformed.edges), the bar, the steps' kinds,
// tools, orientations, allowances and withdrawals, and the library tools'
// sizes. Everything else it computes from the canonical moves:
//
// - The tool of every move is the turret station in the spindle
//   (latheStations), shaped as: a turning insert, its nose, a circle of the
//   tool's corner radius about the nose centre = controlled point minus the
//   LinuxCNC orientation vector (2: X -r, Z -r; 3: X +r, Z -r; X a radius);
//   a grooving or parting blade, a rectangle of its width from the
//   controlled point toward -Z and away from the cut (upward outside, down
//   toward the axis inside); a drill, its point on the axis at the
//   controlled point, its body (the point angle, then the diameter)
//   toward +Z.
// - The part's material: of an outer unit, between the axis and the
//   profile, closed along the axis and at the profile's ends; of an inner
//   unit, outside the bore profile (closed at its ends out past the bar).
//   Each step's tool is judged against its own unit's material only.
// - Gouges: no feed or arc of any step (lines and arcs sampled every
//   `sample` mm; blades and drills as the polygon each straight move
//   sweeps) enters that material by more than `tolerance`.
// - Finishing: every sampled nose centre at least the nose radius from the
//   deformed profile (less the tolerance), and every element of origin
//   "original" or "moved" longer than two nose radii (not counting the
//   front face the facing cuts) touched: the nose-centre path comes to it
//   at the nose radius within the tolerance (or grooving or parting
//   blades or drills of the unit lie on all of it).
// - Roughing: the nose never nearer the profile than the step's smaller
//   finishing allowance (turn->allowanceX, allowanceZ) less the tolerance.
// - Rapids: the bar's half-section (bar.diameter / 2 from bar.face back
//   over bar.length, less bar.bore / 2) is kept as a height field on
//   columns `cell` mm apart along Z, exact in the radius: each column
//   holds the one interval of radii still there. A feed or arc removes
//   what its tool sweeps (an insert with the whole insert behind its nose:
//   the nose circle and everything above it, outside, or below it, inside;
//   a blade its rectangle; a drill its body); a rapid's tool shape may not
//   overlap what is left of any column by more than `tolerance` in radius.
// - Threading: a threading insert is judged by its nose like an insert's
//   (its flanks are not modelled), against the part less the thread: the
//   deformed profile cut down to the thread's root (the edge's radius less
//   its thread depth, the edge's thread attribute) from a pitch behind
//   the threaded edge (the run-out into its relief) to the front, since
//   the insert goes below the finished profile there by design.
// - Grooving: the last feed before the rapid retract is the withdrawal:
//   turn->withdrawal long and along the profile's outward normal where the
//   blade ended, both within the tolerance.
// - Every step cuts, each cut with the step's own tool, in G18; a tool is
//   used with one orientation (the tool table's).
// Not judged, reported: how deep an insert's whole cutting corner (the nose
// and both edges, ISO shape angle and holder approach angle) reaches into
// the part where its nose does not: into the deformed profile, and into
// what must stay after grinding (the profile as drawn, plan.turned[k].profile,
// and the deformed profile both); the planner lets the finishing insert's
// edge touch grinding stock beside allowance edges it cannot follow.
#pragma once

#include "model/geometry.h"
#include "model/plan.h"
#include "support/rs274.h"

#include <QString>

#include <string>
#include <vector>

namespace taiwa::test {

// LinuxCNC's lathe tool table for a plan's tape: one line per turret
// station, `T<station> P<station> X0 Z0 D<nose diameter in inches> Q<orientation>`
// (rs274 reads the table in inches whatever the program's units); nose
// radius from the library tool's corner radius (drills 0), orientation
// from the first step that uses the tool.
std::string latheToolTable(const Plan& plan);

// LinuxCNC tool orientation 1-4: the controlled point minus the nose centre,
// as (z, r) in a Point2 {x = z, y = r} (2: X -r, Z -r; 3: X +r, Z -r;
// 1: X -r, Z +r; 4: X +r, Z +r); any other: (0, 0).
Point2 orientationOffset(int orientation, double noseRadius);

struct LatheOracleOptions {
    double sample = 0.005;     // mm between checked points along a move
    double cell = 0.02;        // mm between the stock's columns along Z
    double tolerance = 1e-3;   // mm (an inch tape resolves 0.0001 in = 2.54 µm: judge it to 2.5 µm)
};

struct LatheVerdict {
    QStringList problems;      // one sentence each; empty: the tape passes
    double worstGouge = -1e9;  // deepest entry of any cutting move into its unit's material [mm] (negative: the closest clearance)
    double worstRapid = -1e9;  // largest overlap of a rapid with the stock left [mm]
    QString worstRapidMove;    // which rapid, where
    double closestRoughing = 1e9;  // roughing: least (nose-to-profile distance - allowance) [mm]
    int feeds = 0, rapids = 0;     // moves judged
    QStringList touched;       // "unit 1 E3 0.4000" per element checked for finishing contact
    // Not judged, for the reader: the deepest entry into the part of a
    // turning insert's whole cutting corner (nose and both edges 5 mm long,
    // the ISO shape's tip angle and the holder's approach angle), per step,
    // where it is more than the tolerance: "step 3 Finishing I 0.1234 at ...".
    QStringList insertBody;
};

// Judges an rs274 run of the plan's tape (moves in mm, or in inches: then
// converted). The plan must be a lathe job's, planned in mm.
LatheVerdict judgeLatheTape(const Plan& plan, const Rs274Result& run, const LatheOracleOptions& options = {});

}  // namespace taiwa::test
