// What a setup unit (work-centre probing, core/modules/probe/) hands on
// besides machining steps: the workpiece's centre as measured from the
// operator's touch points (for the work-offset setting block and the
// sheet), and what the probing cycle program needs to make the touches on
// the machine by itself (post/probe_program.h). All lengths in mm.
#pragma once

#include "model/geometry.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct WorkSetup {
    int unit = 0;                 // 0-based index of the unit in the job
    bool round = true;            // round (boss, bore) or rectangular (block, pocket)
    bool inside = false;          // bore or pocket: touched from inside
    std::string workOffset = "G54";  // the job's, set by the setting block and the cycle

    // From the touch points entered, when there are enough of them.
    struct Measured {
        Point2 centre;            // machine X, Y of the workpiece's centre
        std::optional<double> top;  // machine Z of the top face (touched)
        double radius = 0.0;      // round
        double width = 0.0, length = 0.0;  // rectangular, along its own axes
        double rotation = 0.0;    // rectangular: deg, counter-clockwise
        bool rotationMeasured = false;
        std::vector<double> residuals;  // per touch point [mm]
        friend bool operator==(const Measured&, const Measured&) = default;
    };
    std::optional<Measured> measured;

    // The probing cycle.
    int tool = 0;                 // the probe's tool number
    double ballRadius = 0.0;      // of its stylus ball
    double sizeX = 0.0;           // nominal diameter (round) or width along X
    double sizeY = 0.0;           // nominal length along Y (rectangular)
    double touchDepth = 0.0;      // below the top face, for the side touches
    double clearance = 0.0;       // outside the nominal outline where each touch starts
    double search = 0.0;          // how far past the nominal outline a touch looks
    double feed = 0.0;            // probing feed [mm/min]
    double maxOffCentre = 0.0;    // how far from the centre the cycle may start (half the clearance)

    friend bool operator==(const WorkSetup&, const WorkSetup&) = default;
};

}  // namespace taiwa
