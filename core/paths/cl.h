// CL creation (pipeline stage 4): the tool path of every step, computed from
// the step's geometry and its tool. Offsets through Clipper; arcs stay arcs.
#pragma once

#include "model/step.h"
#include "model/technology.h"
#include "model/tool.h"
#include "model/toolpath.h"
#include "tools/cutting.h"

namespace taiwa {

struct PathParameters {
    // Roughing's radial step-over is technology data (TechnologyData::stepOver).
    double finishStepOver = 0.3;   // floor finishing step-over (fine), fraction of the tool diameter
    double safeZ = 5.0;            // rapid height above the stock top [mm]
    double clearance = 1.0;        // feed starts this far above the material [mm]
    double peckWhenDeeperThan = 3.0;  // drilling pecks when depth > this x drill diameter
    double peckDepth = 1.0;        // peck as a fraction of the drill diameter
    double rampAngle = 3.0;        // helical ramp-in angle without a pilot hole [deg]
    bool climb = true;             // climb milling (conventional when false)
    double leadRadius = 0.0;       // lead-in/out arc radius, 0 = derived from the tool
    friend bool operator==(const PathParameters&, const PathParameters&) = default;
};

// The tool path of one step. Z layers of at most gamma x D for roughing.
// The path is the tool tip (flat and taper end mills: the centre of the flat
// bottom; ball end mills: the lowest point of the ball); it starts and ends
// at params.safeZ. A ROUGHING step whose holeDiameter > 0 tells that a pilot
// hole of that diameter was drilled at step.position: the tool plunges into
// it when the hole is at least as wide as the tool and lies where the tool
// centre may go; otherwise (and always without a hole) it ramps in.
// Throws std::logic_error only for a step the checks should have refused
// (no outline, a tool that does not fit) or for a layer it failed to clear.
ToolPath makeToolPath(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);

// Pocket layers are proved once per shape, tool, entry and step-over
// (pocket.cpp: a repeated pocket gets the same answer moved to its place);
// benchmarks forget what was proved to measure a first computation.
void forgetProvedLayers();

// About how many moves makeToolPath would make for the step, from its
// geometry alone (layers x rings or passes), computed in microseconds: the
// pipeline refuses a plan whose paths would not fit its move budget before
// computing any of them.
double estimateMoves(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);

// Estimated time of a path: feed moves at their feed (plunge/ramp feed where
// marked), rapids at `rapidRate` mm/min, plus `toolChangeSeconds` is NOT
// included (the sheet adds tool changes). Minutes.
double estimateMinutes(const ToolPath& path, const SpeedsFeeds& sf, double rapidRate = 15000.0);

}  // namespace taiwa
