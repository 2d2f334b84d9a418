// Turning inserts as the shop names them: the ISO 1832 code ("CNMG 120408")
// read into its shape, clearance, tolerance, type, cutting-edge length,
// inscribed circle, thickness and nose radius. Refusals say which letter or
// digits are wrong.
#pragma once

#include "model/result.h"

#include <string>

namespace taiwa {

struct InsertCode {
    std::string code;       // normalised: "CNMG 120408" (with a chip breaker "CNMG 120408-PM")
    char shape = 'C';       // C D K R S T V W
    double tipAngle = 0.0;  // the insert's corner angle [deg]: C 80, D 55, V 35, T 60, S 90, W 80, K 55; round 0
    char clearance = 'N';   // N = 0°, B 5°, C 7°, P 11°, …
    double clearanceAngle = 0.0;
    char tolerance = 'M';
    char type = 'G';
    double edgeLength = 0.0;   // cutting edge length [mm] (the size digits; a round insert's diameter)
    double inscribedCircle = 0.0;  // IC [mm]
    double thickness = 0.0;    // [mm]
    double noseRadius = 0.0;   // [mm]; 0 for a sharp corner and a round insert ("M0")
    std::string chipBreaker;   // "PM", "MF", … or empty
};

Result<InsertCode> parseInsertCode(const std::string& text);

}  // namespace taiwa
