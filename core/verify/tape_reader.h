// The reader of the milling tapes Taiwa writes, in every dialect's language:
// the tape turned back into the machine's motions, the canned cycles
// expanded, each motion with the tape line that makes it. The verification
// runs the posted tape back through it (tape_readback.h: every motion must
// be a planned one), and the outside check of the dialects
// (tests/test_rs274_dialects.cpp) compares what it reads with LinuxCNC's
// rs274 on the linuxcnc tape. docs/verification.md "The tape read back".
// It is strict: a word, block or construct it does not understand stops the
// reading with an error naming the line, never skipped. What it accepts:
// - ISO (FANUC, Haas, LinuxCNC; the dialect says which framing, program
//   number and decimal points): '%' framing when the dialect frames,
//   "O01000 (NAME)" when it numbers, N numbers, comments in parentheses,
//   G0 G1 G2 G3 (I J centre from the start), G17 G20 G21 G40 G49 G54-G59
//   G59.1-G59.3 G54.1 P G154 P G64 P G80 G90 G94, "G43 H<tool> [Z]" (H must
//   be the tool in the spindle, and no Z move after M6 before it when the
//   dialect has a length offset), "G28 G91 Z0." and "G53 G0 Z0" (machine
//   retracts: no move) then G90, "G98 G81|G83|G84|G85|G86 X Y Z R [Q] [P]
//   [F]" modal until G80 (drilling, pecking with Q, rigid tapping at F =
//   pitch x S, reaming, boring; expanded as rs274 expands G81 G83 G85 G86,
//   tapping as G33.1), LinuxCNC's "G33.1 Z K" (down at K x S and back up),
//   G4 with the dialect's dwell word, T M6, S M3/M4/M5, M8 M9 M29 M30; with
//   decimalPointAlways X Y Z I J R Q F must carry a decimal point (without
//   one a FANUC or a Haas reads least increments).
// - SINUMERIK: ';' comments, N numbers, G710/G700 (inch, feeds too), G641
//   ADIS=, G0 G1 G2 G3 (I J incremental), G17 G40 G90 G94, G54-G57
//   G505-G599, "G0 SUPA Z0 [D0]" (machine retract: no move; D0 required
//   while a D is in force, else the tool tip, not the spindle, goes to
//   machine Z0), T M6, D1 (the length offset), D0, S M3/M4/M5, M8 M9 M30,
//   F alone, G4 F (a dwell), "MCALL CYCLE81(RTP,RFP,SDIS,DP)",
//   "CYCLE83(RTP,RFP,SDIS,DP,,FDEP,,DAM,0,0,1,1)" (chip removal),
//   "CYCLE84(RTP,RFP,SDIS,DP,,0,3,,PIT,POSS,SST,SST1)",
//   "CYCLE85(RTP,RFP,SDIS,DP,,0,FFR,RFF)" and
//   "CYCLE86(RTP,RFP,SDIS,DP,,0,3,0,0,0,POSS)" called after every
//   positioning block until a bare MCALL.
// - HEIDENHAIN Klartext: consecutive block numbers from 0, BEGIN/END PGM
//   name MM|INCH, ';' comments, BLK FORM 0.1/0.2, CYCL DEF 247 (Q339), TOOL
//   CALL [n] Z [S], L X Y Z (signed, absolute) [R0] [FMAX|F] [M..] (M91:
//   machine retract, no move; M99: call the cycle in force after the move),
//   CC X Y, C X Y DR±, CP IPA± [IZ±] DR± (a helix about CC; |IPA| 360 a
//   full turn), CYCL DEF 200 DRILLING (Q202 < |Q201|: pecking), 201
//   REAMING, 202 BORING (Q214 0: no lift; Q208=MAX out at rapid), 207
//   RIGID TAPPING NEW (at Q239 x the TOOL CALL's S), no dwells in them;
//   CYCL DEF 9.0/9.1 DWELL, bare M blocks (M3 M4 M5 M8 M9 M30).
// Coordinates the tape has not set yet (before the first move down after
// the first tool change) are NaN. A pecking cycle comes back down in rapid
// to rs274's 0.010 inch (0.254 mm) above the last peck: the real controls
// take that distance from a machine setting, not from the tape. What a
// cycle does beyond this (dwells, degression, chip breaking, relative
// depths, left-hand tapping, a lift off the wall) is refused rather than
// guessed. Lathe tapes are read by readLatheTape (below); probing programs,
// which compute their moves on the control, by readProbingProgram
// (tape_reader_probe.h).
#pragma once

#include "machine/lathe_kinds.h"
#include "model/geometry.h"
#include "model/toolpath.h"
#include "post/dialect.h"

#include <string>
#include <vector>

namespace taiwa::verify {

// One motion of the machine, as LinuxCNC's rs274 reports it for the same
// motion (its canonical calls), in the tape's units. On a lathe tape X is
// the diameter the tape writes, Y is 0, an arc's centre is (X, Z) and its
// turn as drawn with Z right and X up (G2 clockwise), the feed is per
// revolution, and a Cycle is a control's turning cycle (TapeCycle).
struct TapeMotion {
    enum Kind { Traverse, Feed, Arc, Cycle } kind = Traverse;
    Point3 start{};     // where it began (the previous motion's end)
    Point3 end{};
    Point2 centre{};    // arcs (XY; a lathe's (X, Z))
    int rotation = 0;   // arcs: -1 clockwise, +1 counter-clockwise, ±(1 + n) with n extra full turns
    double feed = 0.0;  // feeds and arcs: the feed rate in force (units per minute; a lathe's per revolution, a thread's lead)
    bool synchronised = false;  // a lathe's G33 threading pass: the feed is the lead, locked to the spindle
    int cycle = -1;     // a Cycle: its index in TapeReading::cycles
    int step = 0;       // from the last "STEP k: ..." comment, 1-based; 0 before any
    int tool = 0;       // the tool in the spindle
    int line = 0;       // the tape line (1-based) that makes it
};

// A lathe control's cycle as the tape states it, not expanded into its
// passes (tape_reader_lathe_cycles.cpp): its words and the box its motions
// stay within, X diameters as on the tape, in the tape's units.
struct TapeCycle {
    enum Kind { Roughing, Threading } kind = Roughing;
    // Roughing (G71): the contour it roughs to, from the cycle's start:
    // each point reached by a line (turn 0) or an arc (turn -1 G2, +1 G3,
    // its centre (cx, cz)).
    struct Point {
        double x = 0.0, z = 0.0;
        int turn = 0;
        double cx = 0.0, cz = 0.0;
    };
    std::vector<Point> contour;
    Point3 start{};             // where the tool stood when it was called (X, 0, Z)
    double depth = 0.0;         // roughing: the depth of a pass; threading: the thread's (radius)
    double allowanceX = 0.0;    // roughing: left across the axis (radius, negative in a bore)
    double allowanceZ = 0.0;    // along it (NaN: not on the tape, LinuxCNC's G71)
    double retract = 0.0;       // roughing: the lift after a pass (radius; 0 where the control's setting gives it)
    double feed = 0.0;          // roughing: per revolution; threading: the pitch
    double rootX = 0.0;         // threading: the root's diameter
    double zEnd = 0.0;          // threading: where the thread ends
    double firstDepth = 0.0;    // threading: the first pass's depth (radius)
    double crestX = -1.0;       // threading: the crest's diameter where the tape says it (LinuxCNC), else -1
    int springPasses = -1;      // threading: where the tape says it, else -1
    double xLow = 0.0, xHigh = 0.0, zLow = 0.0, zHigh = 0.0;  // the box its motions stay within
};

// A wait of a two-path lathe's program (readLatheTape with its wait codes):
// its line, and what it meets on the other path: FANUC's wait M code, or
// LinuxCNC's meeting number k (output 0 set to k's parity and the other
// path's awaited at the same; -1 when they disagree: it meets nothing).
struct TapeWait {
    int line = 0;
    int code = 0;
};

struct TapeReading {
    std::vector<TapeMotion> motions;
    std::vector<TapeCycle> cycles;  // a lathe tape's cycles (TapeMotion::cycle)
    bool inches = false;  // the tape's units
    int dwells = 0;       // dwell blocks
    std::vector<TapeWait> waits;  // a two-path lathe's program's, in order
    // When the reader stops at a line it does not understand: "line 12:
    // why [the line]" and that line (motions then stop there).
    std::string error;
    int errorLine = 0;
};

// A milling tape of `dialect` (its syntax, framing, numbering and words).
TapeReading readTape(const std::string& text, const post::Dialect& dialect);

// A lathe tape of `dialect` (ISO: FANUC, Haas, LinuxCNC; SINUMERIK),
// strict as readTape (tape_reader_lathe.h says what it accepts). With
// `twoPath` (the wait codes of a two-path lathe's control), one path's
// program of a balanced cut (post/two_path_post.h): its waits and dwells
// too, the waits listed in TapeReading::waits.
TapeReading readLatheTape(const std::string& text, const post::Dialect& dialect, const WaitCodeRange* twoPath = nullptr);

}  // namespace taiwa::verify
