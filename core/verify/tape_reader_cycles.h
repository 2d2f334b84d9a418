// The drilling cycles of the tape reader (tape_reader_iso.h): ISO's G81-G86
// canned cycles and SINUMERIK's CYCLE81/83/84/85/86 (a call read into its
// parameters, what this reader does not support refused), their moves
// made on the reader's machine as the controls expand them. Internal to
// core/verify/.
#pragma once

#include "verify/tape_reader_machine.h"

#include <optional>
#include <string>

namespace taiwa::verify::tape {

// A SINUMERIK cycle called modally: CYCLE81, 83, 84, 85 or 86.
struct SinumerikCycle {
    int number = 81;
    double rtp = 0, rfp = 0, sdis = 0, dp = 0;
    double fdep = 0, dam = 0;          // CYCLE83: the first depth (absolute), each further peck
    double pit = 0, sst = 0, sst1 = 0; // CYCLE84: the pitch, the speeds in and out
    double ffr = 0, rff = 0;           // CYCLE85: the feeds in and out
};

// The call "CYCLE8x(...)" read; refuse() (Unread) for anything else.
SinumerikCycle sinumerikCycle(const std::string& call);

// The called cycle's moves at `to`, the position just reached.
void runCalledCycle(Machine& m, const SinumerikCycle& c, const Point3& to);

// ISO's G98 canned cycle `code` (81, 83, 84, 85, 86) at `hole`, from R
// `r` to Z `bottom`, G83 pecking by `q`: its moves made on the machine.
void runCannedCycle(Machine& m, int code, const Point3& hole, double r, double bottom, std::optional<double> q);

}  // namespace taiwa::verify::tape
