// The reader of the probing programs (post/probe_program.h): the setting
// program and the probing cycle run as the control runs them, their
// parameters evaluated (tape_params.h), their conditionals followed
// (LinuxCNC's o-word if/else/endif and "(abort, ...)", FANUC's IF [...]
// GOTO n, GOTO n and the #3000 alarm) and their probing moves (G38.2-G38.5,
// G31) stopped where a touch callback says the stylus touches, the results
// written where the control writes them (#5061-#5063, LinuxCNC's #5070),
// the current position kept in #5420-#5422 (LinuxCNC) or #5041-#5043
// (FANUC), the work offsets in #5221... and G10 L2 / L20 setting them. It is
// strict as the tape readers are: anything else stops the reading at its
// line. docs/verification.md "The tape read back".
#pragma once

#include "post/dialect.h"
#include "verify/tape_reader.h"

#include <functional>
#include <optional>

namespace taiwa::verify {

// Where a probing move from `from` to `to` (machine coordinates, the
// program's units) touches; none: it touches nothing on its way.
using ProbeTouch = std::function<std::optional<Point3>(const Point3& from, const Point3& to)>;

struct ProbeReading {
    TapeReading tape;       // the motions in machine coordinates (a Z at the machine's home: NaN)
    std::vector<int> probes;  // the motions (indices) that probe
    std::vector<Point3> targets;  // where each of those was sent
    std::string stop;       // an abort or alarm the program stopped at ("" when it ran to its end)
    int stopLine = 0;
};

// The program `text` of `dialect` (ISO; FANUC's macros when its
// macroSyntax is "fanuc"), started with the tool tip at `start` (machine
// coordinates, mm) with every work offset `offsets` (X Y Z, mm).
ProbeReading readProbingProgram(const std::string& text, const post::Dialect& dialect, const Point3& start,
                                const ProbeTouch& touch, const Point3& offsets = {});

}  // namespace taiwa::verify
