// LinuxCNC's standalone interpreter as the outside judge of our G-code: runs
// `rs274 -g` on a program with fresh copies of tests/data/rs274/tools.tbl and
// params.var in a temporary folder and parses its canonical machining calls
// back into moves, in the program's units (mm after G21, inch after G20).
// What rs274 does and expects is written up in docs/post-processors.md.
#pragma once

#include "model/geometry.h"
#include "model/toolpath.h"

#include <QString>
#include <QStringList>

#include <string>
#include <vector>

namespace taiwa::test {

struct CanonMove {
    enum Kind { Traverse, Feed, Arc } kind = Traverse;
    Point3 start{};    // where the move began (the previous move's end)
    Point3 end{};      // in the program's units
    Point2 centre{};   // arcs
    int rotation = 0;  // arcs: -1 clockwise, +1 counter-clockwise, ±(1 + n) with n extra full turns
    double feed = 0.0; // feeds and arcs: the feed rate in force (units per minute)
    int step = 0;      // from the last "STEP k: ..." comment, 1-based; 0 before any
    int tool = 0;      // tool in the spindle
};

struct Rs274Result {
    bool ok = false;        // exit code 0 and no error printed
    int exitCode = -1;
    QString out, err;       // everything rs274 printed
    QString errors;         // rs274's complaint when not ok
    QStringList canon;      // every canonical call line
    bool inches = false;    // the units of the canonical calls at the end of the program
    std::vector<CanonMove> moves;
    int dwells = 0;         // DWELL calls
};

Rs274Result runRs274(const std::string& ngc);

// Points along an arc move, at most `step` apart (its end included).
std::vector<Point3> sampleArc(const CanonMove& arc, double step);

}  // namespace taiwa::test
