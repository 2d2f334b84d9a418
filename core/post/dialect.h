// Controller dialects as data (interfaces.md "Dialects"): framing, sequence
// numbers, number style, comments, tool change and retract blocks. The one
// writer (gcode_writer) reads these; no dialect copies the writer.
#pragma once

#include <string>
#include <vector>

namespace taiwa::post {

struct Dialect {
    std::string name;
    bool percentFraming = false;          // '%' leader and trailer lines
    bool programNumber = false;           // "O1000 (NAME)" line
    bool sequenceNumbers = false;         // N words on every block
    int sequenceIncrement = 10;
    bool decimalPointAlways = false;      // "X10." (FANUC) rather than "X10"
    bool upperCaseComments = false;
    std::vector<std::string> preamble;    // blocks after the header; {UNITS} = G20/G21
    std::vector<std::string> retract;     // blocks that send Z to the machine's safe height
    bool lengthOffsetWithFirstZ = false;  // "G43 H1 Z5." (FANUC) vs a lone "G43 H1"
    std::string cycleRetractMode;         // "G98" before canned cycles, or empty
};

const Dialect* findDialect(const std::string& name);
const std::vector<Dialect>& dialects();

}  // namespace taiwa::post
