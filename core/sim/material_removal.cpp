// Sweeping a cutter profile over the height field.
#include "sim/material_removal.h"

#include "sim/cutter_profile.h"
#include "sim/path_samples.h"
#include "sim/sweep.h"

#include <algorithm>
#include <cmath>

namespace taiwa::sim {

namespace {

constexpr double kZStep = 0.02;  // largest Z change within one swept piece [mm]

}  // namespace

void cut(HeightField& field, const ToolPath& path, const Tool& tool)
{
    const CutterProfile cutter(tool);
    const double tolerance = std::min(0.01, field.cellSize() / 10.0);
    const double reach = cutter.reach();
    // A sweep that starts where the last ended, at the same height, skips the
    // cells its flat bottom cut already (SweepChain, as verify/milling_cut.cpp):
    // the short chords of a flattened arc would otherwise each visit a whole
    // disc of cells.
    SweepChain chain;
    for (const PathPiece& piece : flattenPath(path, tolerance)) {
        if (std::min(piece.from.z, piece.to.z) >= 0.0) {  // the tip above the top never reaches material
            chain.broken();
            continue;
        }
        forEachLevel(piece.from, piece.to, kZStep, [&](Point2 a, Point2 b, double z) {
            if (z >= 0.0) {
                chain.broken();
                return;
            }
            forEachCellNear(
                field, a, b, reach, 0, field.rows() - 1,
                [&](int i, int j, double r2) { field.lower(i, j, z + cutter.heightSquared(r2)); },
                chain.skip(a, z, cutter.flatRadius()));
            chain.ended(b, z);
        });
    }
}

}  // namespace taiwa::sim
