// The lathe post-processor (docs/post-processors.md "Lathe"): turning steps
// (model/turn_path.h) to a lathe program in the dialect's framing, blocks
// and numbers: G18, X as a diameter (LinuxCNC G7), feed per revolution,
// constant surface speed under the spindle limit (FANUC G50 S then G96;
// LinuxCNC G96 D S), tool change with offset by turret station (FANUC
// T0101; LinuxCNC T1 M6 G43), nose-radius compensation G41/G42 on the
// finishing contour, and roughing as the control's own cycle where the step
// has one and the job allows it (FANUC G71 with P/Q blocks; LinuxCNC G71
// with the contour as an o-subroutine) or as the explicit passes.
#pragma once

#include "post/post.h"

#include <functional>
#include <memory>

namespace taiwa {

namespace post {
class LatheSink;
}

// Steps in machining order, each a turning step with its tool. Throws
// as postProcess does.
PostedProgram postLathe(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library, const PostOptions& options);

// A link of the sink chain placed first, between the poster and the rest
// of the chain: it receives what the poster says in mm and tells `next`
// (the gang change, gang_post.h).
using LatheStage = std::function<std::unique_ptr<post::LatheSink>(post::LatheSink& next)>;

// As postLathe, through `stage` first.
PostedProgram postLathe(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library, const PostOptions& options,
                        const LatheStage& stage);

// The turret station each library tool of the program sits in: 1, 2, … in
// the order of first use (the T number the tape and the control's tool
// table use), as pairs (station, library id).
std::vector<std::pair<int, int>> latheStations(const std::vector<Step>& orderedSteps);

}  // namespace taiwa
