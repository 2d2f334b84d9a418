// Machining time as the machine moves, not as the path's length divided by
// its feed: each block accelerated and decelerated at the machine's
// acceleration (the slowest of the axes it moves, in its direction), the
// speed through a corner limited by the deviation the control allows there
// and by how far it can still stop within the blocks it looks ahead at,
// arcs by their centripetal acceleration, rapids at each axis' rate with a
// stop at their end (an in-position check), drill cycles block by block
// with their pecks. The classic trapezoid planner of CNC controls (LinuxCNC's
// trajectory planner, Grbl's junction deviation), simplified to one
// acceleration per block. docs/verification.md "Machine time".
#pragma once

#include "machine/machine.h"
#include "model/toolpath.h"

namespace taiwa {

struct TurnStep;  // model/turn_path.h

// The feeds of a step [mm/min]: cutting and plunging (ramps, plunges).
struct MotionFeeds {
    double feed = 0.0;
    double plungeFeed = 0.0;
};

// The minutes the machine takes for the path; 0 for an empty path. Needs
// the machine's acceleration (hasMotionModel).
double machineMinutes(const ToolPath& path, const MotionFeeds& feeds, const Machine& machine);

// The minutes a lathe takes for a turning step's path: each move a block in
// the XZ plane (the radius along X, Z along Z), fed at its feed per
// revolution times the spindle speed there (G97's rpm, or under G96 the
// surface speed at the block's smaller diameter, no more than the spindle
// limit), rapids at the axes' rates. The same planner as machineMinutes.
double turnMachineMinutes(const TurnStep& step, const Machine& machine);

// Whether the machine definition says enough to model its motion.
bool hasMotionModel(const Machine& machine);

}  // namespace taiwa
