// The readers of the Haas, SINUMERIK and HEIDENHAIN Klartext tapes for the
// outside check in tests/test_rs274_dialects.cpp: the core's tape reader
// (verify/tape_reader.h, the one the verification reads tapes back with;
// what it accepts is written there), its motions turned into the canonical
// moves (support/rs274.h) that LinuxCNC's rs274 reports for the same
// motion, so that a dialect's tape can be compared move by move with the
// linuxcnc tape run through rs274.
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

// A Haas (`sinumerik` false) or SINUMERIK (`sinumerik` true) tape, read as
// the shipped dialect of that name.
DialectMoves readIsoTape(const std::string& text, bool sinumerik);
// A HEIDENHAIN Klartext program.
DialectMoves readKlartext(const std::string& text);

}  // namespace taiwa::test
