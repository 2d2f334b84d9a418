// CL creation (pipeline stage 4): what every step's tool path shares — the
// path parameters, move and time estimates. Each module's door makes its
// steps' paths (ModuleKind::toolPath) with the generators of
// paths/generators.h or its own. Offsets through Clipper; arcs stay arcs.
// A path is the tool tip (flat and taper end mills: the centre of the flat
// bottom; ball end mills: the lowest point of the ball); it starts and ends
// at PathParameters::safeZ.
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

// Pocket layers are proved once per shape, tool, entry and step-over
// (pocket.cpp: a repeated pocket gets the same answer moved to its place);
// benchmarks forget what was proved to measure a first computation.
void forgetProvedLayers();

// Move estimates the modules' doors share (ModuleKind::estimateMoves, from
// a step's geometry alone, in microseconds): the Z layers of at most γ·D the
// step is cut in (one more for the start), and the rings of the finer of its
// roughing and finishing step-overs across its outline's or region's
// inscribed radius.
double estimatedLayers(const Step& step, const Tool& tool, const TechnologyData& tech);
double estimatedRings(const Step& step, const Tool& tool, const TechnologyData& tech, const PathParameters& params);

// Estimated time of a path: feed moves at their feed (plunge/ramp feed where
// marked), rapids at `rapidRate` mm/min, plus `toolChangeSeconds` is NOT
// included (the sheet adds tool changes). Minutes.
double estimateMinutes(const ToolPath& path, const SpeedsFeeds& sf, double rapidRate = 15000.0);

}  // namespace taiwa
