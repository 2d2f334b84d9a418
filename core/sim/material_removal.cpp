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
    for (const PathPiece& piece : flattenPath(path, tolerance)) {
        if (std::min(piece.from.z, piece.to.z) >= 0.0) continue;  // the tip above the top never reaches material
        forEachLevel(piece.from, piece.to, kZStep, [&](Point2 a, Point2 b, double z) {
            if (z >= 0.0) return;
            forEachCellNear(field, a, b, reach, 0, field.rows() - 1,
                            [&](int i, int j, double r2) { field.lower(i, j, z + cutter.heightSquared(r2)); });
        });
    }
}

}  // namespace taiwa::sim
