// What a turning step is cut with: its tool path in the XZ half-plane (the
// programmed point of the tool as the lathe's post-processor writes it), the
// stretch of it that the control compensates for the nose radius (G41/G42),
// the roughing cycle the control may run instead of the explicit passes
// (FANUC G71 P/Q, LinuxCNC G71 with an o-subroutine), and the speeds:
// constant surface speed with its spindle limit, feed per revolution.
// Made by the TURN module (core/modules/turn/turn_plan.h), written by core/post/lathe_post.cpp.
//
// Conventions (model/turned.h): z along the spindle axis, r the radius; the
// post-processor prints X as a diameter. An arc's sense is as drawn in the
// profile view (Z right, X up): ArcCW is G2 in G18, ArcCCW G3.
#pragma once

#include "model/toolpath.h"
#include "model/turned.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct Step;

struct TurnMove {
    enum Kind { Rapid, Feed, ArcCW, ArcCCW };
    Kind kind = Rapid;
    turning::ZR end{};     // programmed point
    turning::ZR centre{};  // arcs
    FeedKind feed = FeedKind::Cut;  // Plunge: the plunge feed (grooving, drilling, entries)
    friend bool operator==(const TurnMove&, const TurnMove&) = default;
};

// Which side of the programmed contour the nose's centre runs on.
enum class NoseCompensation { Off, Left, Right };  // G40, G41, G42

// A roughing cycle of the control: the finished contour (nose-radius
// compensation is the control's business: the contour is the part's, not
// the nose centre's), the depth of cut, the allowance it leaves for
// finishing and the retract after each pass. The programmed point is at
// `start` when the cycle is called.
struct TurnCycle {
    std::vector<turning::Segment> contour;  // from its first point in -Z (outer) or +Z (inner) order, lines and arcs
    turning::ZR start{};
    double depthOfCut = 0.0;   // per pass, radius
    double allowanceX = 0.0;   // finishing allowance across the axis, radius
    double allowanceZ = 0.0;   // along the axis
    double retract = 0.0;      // lift after each pass, radius
    bool inner = false;        // a bore: the passes go outward
    friend bool operator==(const TurnCycle&, const TurnCycle&) = default;
};

struct TurnPath {
    turning::ZR start{};          // programmed point before the first move
    std::vector<TurnMove> moves;  // explicit moves (also for a cycle: what it cuts, for time and preview)
    // Moves [compFrom, compTo) run with nose-radius compensation on: the
    // move at compFrom is the entry (G41/G42 stated with it), the move at
    // compTo the exit (G40 with it); both are straight and leave the part.
    NoseCompensation comp = NoseCompensation::Off;
    int compFrom = -1, compTo = -1;
    std::optional<TurnCycle> cycle;  // roughing the control may run
    friend bool operator==(const TurnPath&, const TurnPath&) = default;
};

// The speeds and cutting data of a turning step, settled at planning.
struct TurnCutting {
    bool constantSurfaceSpeed = true;  // G96 (false: G97 at `rpm`, drilling on centre)
    double surfaceSpeed = 0.0;   // vc [m/min]
    double maxRpm = 0.0;         // the spindle limit under G96 [rpm]
    double rpm = 0.0;            // G97 [rpm]
    double feedPerRev = 0.0;     // [mm/rev]
    double plungeFeedPerRev = 0.0;
    // The spindle speed where the tool cuts at `diameter` [mm] [rpm]: G97's
    // `rpm`, or under G96 the surface speed there, no more than `limit`
    // (at the axis: `limit`).
    double rpmAt(double diameter, double limit) const;
    friend bool operator==(const TurnCutting&, const TurnCutting&) = default;
};

// A threading step's cycle (docs/turning.md "Threading"), what the tapes'
// G76 say: the drive line (the programmed point before the cycle, above
// the thread's crest by `clearance`), the thread's end, pitch and depth,
// the first pass's depth and the passes the depths make. Depths are on the
// radius, from the crest; pass k (1-based) cuts to min(firstDepth √k, depth)
// (constant chip area), the passes while that is below the depth, then one
// at the full depth and `springPasses` more there. Each pass enters along
// the compound angle (Z shifted by its depth × tan(compoundAngle)).
struct TurnThread {
    double pitch = 0.0;          // [mm], the feed per revolution of every pass
    double depth = 0.0;          // on the radius [mm]
    double firstDepth = 0.0;     // the first pass's [mm]
    double crestR = 0.0;         // the thread's crest (the row's radius) [mm]
    double clearance = 0.0;      // drive line above the crest [mm]
    double zStart = 0.0;         // the drive point's Z, the run-in in front of the thread
    double zEnd = 0.0;           // where the thread ends (the run-out included)
    double compoundAngle = 29.5; // [deg]
    int springPasses = 1;
    std::vector<double> passDepths;  // cumulative depth of each pass, the last ones at `depth`
    friend bool operator==(const TurnThread&, const TurnThread&) = default;
};

// What a turning step adds to a step: its payload (model/step.h,
// model/step_payload.h), made by the TURN module and read by the lathe's
// post, the verification, the sheet and the step table through turnOf.
struct TurnStep {
    static constexpr const char* kName = "TURN step";
    turning::ProfileSide side = turning::ProfileSide::Outer;
    int orientation = 3;          // the tool's tip orientation (LinuxCNC tool table Q, FANUC T)
    turning::ZR tipFromCentre{};  // programmed (imaginary tip) point minus the nose centre
    double depthOfCut = 0.0;      // roughing, facing: per pass [mm]
    double allowanceX = 0.0;      // left for finishing across the axis (radius) [mm]
    double allowanceZ = 0.0;      // along the axis [mm]
    double withdrawal = 0.0;      // grooving: the move along the surface normal at the groove's end [mm] (seed 002)
    std::string region;           // what the step cuts, in words ("E3.groove1", "Ø30-Ø46 front")
    TurnCutting cutting;
    TurnPath path;
    std::optional<TurnThread> thread;  // threading: the cycle the path runs
    friend bool operator==(const TurnStep&, const TurnStep&) = default;
};

// The step's turning data, or nullptr for a step that is not turned.
const TurnStep* turnOf(const Step& s);

// Length of a turning path, split into cutting and rapid travel [mm].
PathLength turnPathLength(const TurnPath& p);
// Minutes the path takes at its cutting data: feed per revolution at the
// spindle speed each move's diameter gets (surface speed capped by the
// limit), rapids at `rapidMmPerMin`.
double turnMinutes(const TurnPath& p, const TurnCutting& c, double rapidMmPerMin);

}  // namespace taiwa
