// The 1,000-unit job the benchmarks share: M4 pockets with every code mix
// and a 3 deg taper on every third, an M2D pocket every fifth unit, on a
// 40 x 25 grid where neighbours in a row touch (the interference check sees
// touching figures, which it must accept).
#pragma once

#include "model/job.h"

#include <algorithm>
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"

namespace taiwa::bench {

constexpr int kUnits = 1000;

// `units` units (the shared 1,000 by default), 40 to a row up to 1,600 units,
// then a square grid (at most ~110,000 units fit the largest stock). With
// `distinct`, no two pockets have the same size (each up to 4 mm narrower,
// still inside its 30 mm cell): nothing proved for one serves another.
inline Job bigJob(int units = kUnits, bool distinct = false)
{
    Job job;
    job.name = "bench-decompose";
    int columns = 40;
    while (columns * columns < units * 40 / 25 && columns < 333) ++columns;
    const int rows = (units + columns - 1) / columns;
    job.stock = {0, 0, columns * 30.0, std::max(25, rows) * 30.0 + 10, 40};
    const int codes[][3] = {{1, 1, 0}, {1, 2, 9}, {1, 3, 0}, {6, 1, 0}, {7, 3, 9}, {8, 2, 9}, {9, 1, 0}};
    for (int i = 0; i < units; ++i) {
        // Pitch 30 mm along X with 30 mm wide figures: neighbours in a row touch.
        const double x = (i % columns) * 30.0, y = 5 + (i / columns) * 30.0;
        const double narrower = distinct ? (i % 997) * 0.004 : 0.0;
        if (i % 5 == 4) {
            M2DPocket m;
            m.corner = {x, y};
            m.lengthX = 30 - narrower;
            m.lengthY = 20;
            m.depth = 6;
            m.theta1 = 10;
            m.theta2 = 20;
            m.cornerRadius = 4;
            job.units.push_back({"", m});
            continue;
        }
        const auto* c = codes[i % 7];
        M4Pocket m;
        m.corners = {{{x, y}, {x + 30 - narrower, y}, {x + 30 - narrower, y + 20}, {x, y + 20}}};
        m.cornerRadius = 5;
        m.depth = 8;
        m.taper = (i % 3 == 0) ? 3.0 : 0.0;
        m.toolUse = c[0];
        m.wallFinish = c[1];
        m.pilotHole = c[2];
        job.units.push_back({"", m});
    }
    return job;
}

}  // namespace taiwa::bench
