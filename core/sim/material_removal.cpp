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
    const double flat = std::max(0.0, cutter.flatRadius());
    // Where the last sweep ended, and at what height. When the next starts
    // there at the same height, the cells within the flat bottom's radius of
    // its start were lowered to that height (or lower) by it already and are
    // not visited again (as verify/verify.cpp does): the short chords of a
    // flattened arc would otherwise each visit a whole disc of cells. Cells
    // are only ever lowered, so the field is the same cell for cell.
    bool hasLast = false;
    Point3 last{};
    for (const PathPiece& piece : flattenPath(path, tolerance)) {
        if (std::min(piece.from.z, piece.to.z) >= 0.0) {  // the tip above the top never reaches material
            hasLast = false;
            continue;
        }
        forEachLevel(piece.from, piece.to, kZStep, [&](Point2 a, Point2 b, double z) {
            if (z >= 0.0) {
                hasLast = false;
                return;
            }
            const double skip = hasLast && last.z == z && last.x == a.x && last.y == a.y ? flat : 0.0;
            forEachCellNear(
                field, a, b, reach, 0, field.rows() - 1,
                [&](int i, int j, double r2) { field.lower(i, j, z + cutter.heightSquared(r2)); }, skip);
            last = Point3{b.x, b.y, z};
            hasLast = true;
        });
    }
}

}  // namespace taiwa::sim
