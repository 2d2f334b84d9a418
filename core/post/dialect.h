// Controller dialects as data (resources/dialects/*.json, docs/machines.md): framing, sequence
// numbers, number style, comments, the words of tool changes, cycles and the
// program end. The one writer (gcode_writer) reads these; no dialect copies
// the writer. Templates use fmt named fields: {units}, {workOffset}, {tool},
// {number}, {name}.
#pragma once

#include "model/result.h"

#include <cstddef>
#include <string>
#include <vector>

namespace taiwa::post {

struct Decimals {
    int mm = 3;
    int inch = 4;
};

struct Dialect {
    std::string name;
    std::string description;         // "FANUC 0i/30i-style ISO G-code"
    std::string source;              // where it was read from ("built in: dialects/fanuc.json")
    std::string macroSyntax = "linuxcnc";  // the probing cycle's macro variables: "fanuc" (#100) or "linuxcnc" (#<name>)
    // Framing.
    bool percentFraming = false;     // '%' leader and trailer lines
    std::string programNumberLine;   // "O{number:04d} ({name})"; empty: none
    // Blocks.
    bool sequenceNumbers = false;    // N word on every block
    int sequenceStart = 10;
    int sequenceIncrement = 10;
    int sequenceMax = 99999;         // wraps to sequenceStart beyond this
    std::size_t maxLineLength = 255; // longer comments are cut, longer blocks refused
    // Numbers.
    bool decimalPointAlways = false; // "X10." (FANUC) rather than "X10"
    Decimals lengthDecimals{3, 4};
    Decimals feedDecimals{1, 2};
    // Comments: always in parentheses, never nested.
    bool upperCaseComments = false;
    // Program frame and tool change.
    std::vector<std::string> preamble;  // after the header comments
    // Work offsets beyond G54..G59, which every controller has. The job's
    // offset is stated with the first move after each tool change (and in
    // the preamble where it says {workOffset}); one the controller lacks is
    // refused (workOffsetWords).
    std::vector<std::string> moreWorkOffsets;  // LinuxCNC: G59.1 G59.2 G59.3
    int extendedWorkOffsets = 0;               // G54.1 P1..Pn (FANUC: 48); 0 none
    std::vector<std::string> retract;   // to the machine's safe height (tool change, end)
    std::string toolChange = "T{tool} M6";
    std::string lengthOffset = "G43 H{tool}";
    bool lengthOffsetWithZ = false;     // "G43 H1 Z5." in one block (FANUC) or "G43 H1" alone
    std::string spindleClockwise = "M3";
    std::string spindleCounterClockwise = "M4";
    std::string spindleStop = "M5";
    std::string coolantOn = "M8";
    std::string coolantOff = "M9";
    // Canned drilling cycles.
    std::string drill = "G81";
    std::string peckDrill = "G83";      // peck depth in Q
    std::string cycleCancel = "G80";
    std::string cycleRetract = "G98";   // back to the initial level after each hole
    char dwellWord = 'P';               // G4 P<seconds> (LinuxCNC) or G4 X<seconds> (FANUC)
    std::string programEnd = "M30";
};

// The words that select the work offset `requested` (a job's "workOffset":
// "G55", "g55", "G54.1 P7", "G54.1P7", "G59.2") on the dialect's controller,
// written the one way ("G55", "G54.1 P7"). Throws std::invalid_argument,
// saying what the controller offers, for one it does not have.
std::string workOffsetWords(const Dialect& dialect, const std::string& requested);

// Reads one dialect definition (format taiwa-dialect, version 1); every
// problem names `source`, the line and the key.
Result<Dialect> readDialect(const std::string& text, const std::string& source);
// The dialects this program posts: the shipped definitions
// (resources/dialects/*.json, compiled in), each replaced or joined by the
// shop's own files in ~/.config/taiwa/dialects; read once.
const std::vector<Dialect>& dialectLibrary();
// The shop's files that were left out, one sentence each.
const std::vector<std::string>& dialectLibraryProblems();

const Dialect& fanucDialect();
const Dialect& linuxcncDialect();

const Dialect* findDialect(const std::string& name);

}  // namespace taiwa::post
