// LinuxCNC's standalone interpreter as the outside judge of our G-code: runs
// `rs274 -g` on a program with fresh copies of tests/data/rs274/tools.tbl and
// params.var in a temporary folder and parses its canonical machining calls
// back into moves, in the program's units (mm after G21, inch after G20).
// What rs274 does and expects is written up in docs/post-processors.md.
// Lathe programs (G18): rs274 prints X as a radius even under G7, and the
// arcs in the XZ plane; a lathe needs a tool table of its own (nose radius
// and orientation), passed as text.
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
    // Arcs: the centre in the plane's two axes, in the order rs274 prints
    // them: (x, y) in G17; (z, x) in G18 (x the radius on a lathe).
    Point2 centre{};
    int rotation = 0;  // arcs: -1 clockwise, +1 counter-clockwise, ±(1 + n) with n extra full turns
                       // (in G18 as seen with Z to the right and X up: -1 is G2, +1 G3)
    int plane = 17;    // the plane selected when the move was made: 17 (XY) or 18 (XZ)
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

// `toolTable`: the tool table's text (lengths and diameters in inches, as
// rs274 reads them whatever the program's units); empty: a copy of
// tests/data/rs274/tools.tbl.
Rs274Result runRs274(const std::string& ngc, const std::string& toolTable = {});

// Points along an arc move, at most `step` apart (its end included), in
// either plane (the axis of the plane's normal interpolated linearly).
std::vector<Point3> sampleArc(const CanonMove& arc, double step);

}  // namespace taiwa::test
