// Readers of the Haas, SINUMERIK and HEIDENHAIN Klartext tapes Taiwa writes,
// for the outside check in tests/test_rs274_dialects.cpp: each turns a tape
// back into the canonical moves (support/rs274.h) that LinuxCNC's rs274
// reports for the same motion, so that a dialect's tape can be compared
// move by move with the linuxcnc tape run through rs274.
// They are strict: a word, block or construct they do not understand is an
// error naming the line, never skipped. What they accept:
// - readIsoTape, Haas: '%' framing, "O01000 (NAME)", N numbers, comments in
//   parentheses, G0 G1 G2 G3 (I J centre from the start), G17 G20 G21 G40
//   G49 G54-G59 G154 P G80 G90 G94, "G43 H<tool> [Z]" (H must be the tool in
//   the spindle, and no Z move after M06 before it), "G28 G91 Z0." (machine
//   retract: no move) then G90, "G98 G81|G83|G84|G85|G86 X Y Z R [Q] [F]"
//   modal until G80 (drilling, pecking with Q, rigid tapping at F = pitch x
//   S, reaming, boring; expanded as rs274 expands G81 G83 G85 G86, tapping
//   as the linuxcnc tape's G0 to R, G33.1 and G0 up), G4 P, T M06, S
//   M3/M4/M5, M8 M9 M30; X Y Z I J R Q F must carry a decimal point
//   (without one a Haas reads least increments).
// - readIsoTape, SINUMERIK: ';' comments, N numbers, G710/G700 (inch,
//   feeds too), G641 ADIS=, G0 G1 G2 G3 (I J incremental), G17 G40 G90 G94,
//   G54-G57 G505-G599, "G0 SUPA Z0 [D0]" (machine retract: no move; D0
//   required while a D is in force, else the tool tip, not the spindle,
//   goes to machine Z0), T M6, D1 (the length offset), D0, S M3/M4/M5, M8 M9 M30, F alone, G4 F (a dwell),
//   "MCALL CYCLE81(RTP,RFP,SDIS,DP)", "CYCLE83(RTP,RFP,SDIS,DP,,FDEP,,DAM,
//   0,0,1,1)" (chip removal), "CYCLE84(RTP,RFP,SDIS,DP,,0,3,,PIT,POSS,SST,
//   SST1)", "CYCLE85(RTP,RFP,SDIS,DP,,0,FFR,RFF)" and "CYCLE86(RTP,RFP,
//   SDIS,DP,,0,3,0,0,0,POSS)" called after every positioning block until a
//   bare MCALL.
// - readKlartext: consecutive block numbers from 0, BEGIN/END PGM name
//   MM|INCH, ';' comments, BLK FORM 0.1/0.2, CYCL DEF 247 (Q339), TOOL CALL
//   [n] Z [S], L X Y Z (signed, absolute) [R0] [FMAX|F] [M..] (M91: machine
//   retract, no move; M99: call the cycle in force after the move), CC X Y,
//   C X Y DR±, CP IPA± [IZ±] DR± (a helix about CC; |IPA| 360 a full turn),
//   CYCL DEF 200 DRILLING (Q202 < |Q201|: pecking), 201 REAMING, 202 BORING
//   (Q214 0: no lift; Q208=MAX out at rapid, as the TNC displays it: FMAX
//   or any other word as a cycle parameter is refused), 207 RIGID TAPPING NEW (at Q239 x the TOOL CALL's S),
//   no dwells in them; CYCL DEF 9.0/9.1 DWELL, bare M blocks (M3 M4 M5 M8
//   M9 M30).
// Coordinates the tape has not set yet (before the first move down after the
// first tool change) are NaN. A pecking cycle comes back down in rapid to
// rs274's 0.010 inch (0.254 mm) above the last peck: the real controls take
// that distance from a machine setting, not from the tape. What a cycle
// does beyond this (dwells, degression, chip breaking, relative depths,
// left-hand tapping, a lift off the wall) is refused rather than guessed.
#pragma once

#include "support/rs274.h"

#include <string>
#include <vector>

namespace taiwa::test {

struct DialectMoves {
    std::vector<CanonMove> moves;  // as rs274 reports them, in the tape's units
    std::vector<int> lines;        // the tape line (1-based) of each move
    bool inches = false;           // the tape's units
    int dwells = 0;                // dwell blocks
    std::string error;             // "line 12: ..." when the tape is refused (moves then stop there)
};

// A Haas (`sinumerik` false) or SINUMERIK (`sinumerik` true) tape.
DialectMoves readIsoTape(const std::string& text, bool sinumerik);
// A HEIDENHAIN Klartext program.
DialectMoves readKlartext(const std::string& text);

}  // namespace taiwa::test
