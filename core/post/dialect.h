// Controller dialects as data (resources/dialects/*.json, docs/machines.md): framing, sequence
// numbers, number style, comments, the words of tool changes, cycles and the
// program end. Two writers read these: gcode_writer for the G-code controls
// (syntax "iso", and "sinumerik" where Siemens' cycles and comments differ)
// and klartext_writer for HEIDENHAIN's conversational language; no dialect
// copies a writer. Templates use fmt named fields: {units}, {workOffset},
// {tool}, {number}, {name}.
#pragma once

#include "model/result.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace taiwa::post {

struct Decimals {
    int mm = 3;
    int inch = 4;
};

// The language a dialect's tape is written in: which writer writes it.
enum class Syntax {
    Iso,        // ISO G-code (FANUC, Haas, LinuxCNC)
    Sinumerik,  // Siemens ISO-mode-off G-code: ';' comments, CYCLE81/CYCLE83 called by MCALL
    Klartext,   // HEIDENHAIN conversational: L, CC/C, TOOL CALL, CYCL DEF
};

// How the station's NC view colours the dialect's tapes (the data file's
// "highlighting"): the control's own words coloured as such and never as
// addresses ("BLK FORM", "CYCL DEF", "TOOL CALL" in Klartext), and whether
// an address letter may stand apart from its number ("G 1" in ISO; in
// Klartext "TOOL CALL 10" is no L word).
struct Highlighting {
    std::vector<std::string> keywords;
    bool addressesApart = true;
};

struct Dialect {
    std::string name;
    std::string description;         // "FANUC 0i/30i-style ISO G-code"
    std::string source;              // where it was read from ("built in: dialects/fanuc.json")
    std::string macroSyntax = "linuxcnc";  // the probing cycle's macro variables: "fanuc" (#100) or "linuxcnc" (#<name>)
    Syntax syntax = Syntax::Iso;     // "iso", "sinumerik" or "klartext"
    std::string fileExtension = "nc";  // of the tape's file: "nc", "mpf" (Siemens), "h" (HEIDENHAIN)
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
    // Comments: in parentheses (never nested), or after ';' to the end of
    // the line (Siemens; HEIDENHAIN always).
    bool upperCaseComments = false;
    bool semicolonComments = false;
    // The words of the tape's units: G21/G20 (ISO), G710/G700 (Siemens, feeds too).
    std::string metricWord = "G21";
    std::string inchWord = "G20";
    // Program frame and tool change.
    std::vector<std::string> preamble;  // after the header comments
    // Work offsets: G54 and the ones after it (6: to G59; Siemens' settable
    // ones end at G57), then more by name or by range ("G505..G599"). The
    // job's offset is stated with the first move after each tool change (and
    // in the preamble where it says {workOffset}); one the controller lacks
    // is refused (workOffsetWords).
    int plainWorkOffsets = 6;
    std::vector<std::string> moreWorkOffsets;  // LinuxCNC: G59.1 G59.2 G59.3; Siemens: G505..G599
    int extendedWorkOffsets = 0;               // P1..Pn of FANUC's G54.1 P (48), Haas' G154 P; 0 none
    std::string extendedWorkOffset = "G54.1 P{n}";  // how the controller writes extended offset n
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
    // Hole patterns' cycles: right-hand tapping (F = pitch x S; "G33.1":
    // LinuxCNC's spindle-synchronised motion, written as moves to R, the
    // G33.1 with K, and back up), what comes before it (FANUC's rigid
    // tapping "M29 S{rpm}"), reaming (feed in and out), boring (spindle
    // stopped at the bottom, rapid out; LinuxCNC's G86 wants P, the dwell).
    std::string tap = "G84";
    std::string rigidTapping;
    std::string ream = "G85";
    std::string bore = "G86";
    bool boreDwell = false;             // "P0" with the boring cycle
    char dwellWord = 'P';               // G4 P<seconds> (LinuxCNC), G4 X<seconds> (FANUC), G4 F<seconds> (Siemens)
    // The lathe's stock removal cycle: FANUC 0i's two blocks (G71 U R, then
    // G71 P Q U W F) or the one block with the depth in D (Haas, FANUC 10/11).
    bool oneBlockRoughingCycle = false;
    Highlighting highlighting;
    std::string programEnd = "M30";
};

// The words that select the work offset `requested` (a job's "workOffset":
// "G55", "g55", "G54.1 P7", "G54.1P7", "G59.2") on the dialect's controller,
// written the one way ("G55", "G54.1 P7"). Throws Refusal (model/result.h),
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

// What a job asks of a dialect: a milling tape, which every dialect writes, a
// lathe tape (not in
// Klartext: HEIDENHAIN's lathe controls do not speak it) and a probing
// unit's programs (the G-code dialects with FANUC or LinuxCNC macros; not
// SINUMERIK nor Klartext, whose probing constructs the manual pages at hand
// do not confirm: docs/probing.md).
enum class Task { MillingTape, LatheTape, ProbingPrograms };
// What a job of a bar (lathe), or else with work setups to probe, or else of
// milling, asks.
inline Task taskOf(bool bar, bool probing) { return bar ? Task::LatheTape : probing ? Task::ProbingPrograms : Task::MillingTape; }
// Ok when `d` writes `task`; else the Failure refusing it, naming the
// dialects that can (for probing, and why this one cannot).
Result<void> canPost(const Dialect& d, Task task);

const Dialect& fanucDialect();
const Dialect& linuxcncDialect();

const Dialect* findDialect(const std::string& name);
// The dialect of that name; throws Refusal (model/result.h), "unknown
// dialect 'x'", for none: the posts' one look-up.
const Dialect& dialectNamed(const std::string& name);

}  // namespace taiwa::post
