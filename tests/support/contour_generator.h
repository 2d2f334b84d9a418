// Random contour jobs for the proof by generation of the contour units
// (issue 33): seeded, reproducible outlines of lines and arcs — rounded star
// polygons (convex and concave fillets), some pinched into a neck, with
// round and rounded-square islands at random gaps (some touching) for CP;
// open runs with rounded bends and a semicircular notch into the material,
// and closed bosses and pockets, for SIDE. Each case is a job whose figure
// is written from the exact contours (figure/figure_from_contours.h), planned with the
// default library and judged from outside: the product's verification,
// LinuxCNC's rs274 on the linuxcnc tape, and the tool centre's distance to
// every wall computed here (exact lines and arcs, not the product's offset
// code), at least R − 1 µm on the plan's paths, and on the tape less its
// rounding to 3 decimals (1.5 µm more). A refusal must name a field the module has and
// say something. test_contour_generator replays a few hundred seeds,
// bench/bench_contour_generator.cpp 10,000.
#pragma once

#include "model/contour.h"
#include "model/job.h"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace taiwa::test {

struct ContourCase {
    std::uint64_t seed = 0;
    std::string module;          // "CP" or "SIDE"
    Job job;                     // in mm, ready to plan
    std::vector<Contour> walls;  // the finished walls exactly (CP: outline then islands; SIDE: its contour)
    std::string what;            // the case in words ("CP: 6 corners, neck, 2 islands (one touching)")
    bool neck = false, touching = false, notch = false;
};
ContourCase generateContourCase(std::uint64_t seed);

struct ContourOutcome {
    bool planned = false;
    std::string refusedOn, refusal;  // the first error's field and message
    bool clean = false;              // planned, no fatal finding of the verification
    int restMaterial = 0;            // findings of material left (reported, not a failure)
    bool tapeRun = false, tapeAccepted = false;
    double clMargin = 1e300;         // smallest (centre's distance to a wall − R) on the plan's paths (≥ −1 µm)
    double wallMargin = 1e300;       // the same on the tape's moves as rs274 reads them (≥ −1 µm less the tape's rounding)
    std::string failure;             // empty unless the case fails: why, in words
    double planSeconds = 0.0, verifySeconds = 0.0, tapeSeconds = 0.0;
    std::string tape;                // the posted tape until runTapes has run it
};

// Plans, verifies, measures the plan's tool centre against the walls and
// posts the linuxcnc tape (ContourOutcome::tape); when `withTape`, runs it
// too (runTapes).
ContourOutcome runContourCase(const ContourCase& c, bool withTape);
// Runs the posted tapes of planned cases through rs274 as one program (each
// tape's end left out but the last's, its steps renumbered on: one rs274
// for many; a program refused is run again tape by tape to find which) and
// measures the tool centre of each case's moves against its walls.
void runTapes(const std::vector<std::pair<const ContourCase*, ContourOutcome*>>& batch);

// The counts of a run.
struct ContourTally {
    int cases = 0, planned = 0, refused = 0, clean = 0, tapes = 0, tapesAccepted = 0, withRest = 0;
    int necks = 0, touching = 0, notches = 0;
    std::map<std::string, int> byModule, refusedOn;
    std::map<std::string, std::string> refusalExample;
    std::vector<std::string> failing;  // "seed 12 (CP: ...): why"
    double smallestMargin = 1e300, smallestClMargin = 1e300;
    double planSeconds = 0.0, verifySeconds = 0.0, tapeSeconds = 0.0;
    void add(const ContourCase& c, const ContourOutcome& o);
    std::string summary() const;
};

// The distance from p to the contour's lines and arcs, computed here.
double wallDistance(const Contour& c, Point2 p);

}  // namespace taiwa::test
