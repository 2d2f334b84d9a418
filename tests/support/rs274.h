// LinuxCNC's standalone interpreter as the outside judge of our G-code: runs
// `rs274 -g` on a program with a fresh tool table and parameter file and
// parses its canonical machining calls back into moves.
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
    Point3 end{};      // in the program's units (mm for G21)
    Point2 centre{};   // arcs
    int rotation = 0;  // arcs: -1 clockwise, +1 counter-clockwise (LinuxCNC's sign)
    int step = 0;      // from the last "STEP k: ..." comment, 1-based; 0 before any
    int tool = 0;      // tool in the spindle
};

struct Rs274Result {
    bool ok = false;
    QString errors;     // rs274's complaint when not ok
    QStringList canon;  // every canonical call line
    std::vector<CanonMove> moves;
};

Rs274Result runRs274(const std::string& ngc);

// Points along an arc move, at most `step` mm apart (its end included).
std::vector<Point3> sampleArc(const CanonMove& arc, double step);

}  // namespace taiwa::test
