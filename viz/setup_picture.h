// The instruction sheet's picture of the setup, drawn offscreen like the
// steps' pictures (viz/render.h): a milling job's stock block in the vice's
// jaws (translucent, on the faces the job's clamping grips; none when the
// job does not say), a lathe job's bar in the chuck at its stick-out, and
// the work offset's origin marked with its axes and name.
#pragma once

#include "model/plan.h"
#include "model/result.h"

#include <string>

namespace taiwa::viz {

// PNG bytes of the setup in the iso view (milling) or from the front
// (lathe), width x height pixels; the error when there is no display.
Result<std::string> setupPicture(const Plan& plan, int width, int height);

}  // namespace taiwa::viz
