// The finished shape a milling unit cuts into the stock, as the job's
// geometry defines it (not as its tool paths cut it): the depth of the
// finished surface below the stock top at each point of the plan view. The
// verification (core/verify/) compares the simulated stock with it; every
// module with a figure in the XY plane hands one out through its door
// (ModuleKind::cavity).
#pragma once

#include "model/geometry.h"

#include <functional>

namespace taiwa {

struct Cavity {
    // Where the depth can be above zero, at the top (the opening's box).
    Point2 min{}, max{};
    double depth = 0.0;       // the deepest point [mm], the floor
    double wallAngle = 0.0;   // the steepest wall's angle from the vertical [deg] (0: vertical walls)
    // How far the finished surface may stray from the geometry by design
    // [mm]: an inclined face finished by a ball end mill leaves its scallop.
    double surfaceTolerance = 0.0;
    // The depth of the finished surface at p [mm, >= 0; 0 outside the
    // opening]. With slack s > 0: the deepest within distance s of p (the
    // cavity grown by s); s < 0: the shallowest within |s| (shrunk by |s|).
    std::function<double(Point2 p, double slack)> depthAt;
    // What is open already before the unit's steps (a cored casting, a
    // pocket roughed on another machine): the depth of the opening at p
    // (0: solid). Empty: the unit starts in solid stock.
    std::function<double(Point2 p)> openAt;
};

}  // namespace taiwa
