// The instruction sheet's pictures, drawn by the core on the processor
// (picture/canvas.h) with the preview's lighting: no OpenGL, no display.
// A milling step: the simulated stock after it (sim::StockSimulation, a
// grid of about one cell per two pixels) in the iso view, what the step cut
// in its own colour, its feed moves over it. A lathe step: the turned
// bar's section after it (sim/turned_stock.h) seen from the front, shaded
// as the solid of revolution, what the step took off in its colour. The
// setup: the block in the vice's jaws or the bar in the chuck, the work
// offset's origin with its axes and name (as viz's setup picture showed).
#pragma once

#include "model/plan.h"
#include "model/result.h"
#include "picture/image.h"
#include "sim/height_field.h"

#include <vector>

namespace taiwa::picture {

// The sheet's picture size.
inline constexpr int kSheetWidth = 320, kSheetHeight = 240;

// The pictures of the first `limit` steps, in step order; the failure
// names what could not be drawn (a picture below 16 pixels).
// A broken simulation is a bug: its logic_error goes to the top.
Result<std::vector<Picture>> stepPictures(const Plan& plan, int width, int height, int limit);

// The setup: iso view (milling) or from the front (lathe).
Picture setupPicture(const Plan& plan, int width, int height);

// One milling picture: the stock `after` a step (the cells lower than
// `before` in the step's colour), the step's feed moves of `path` over it.
Picture heightFieldPicture(const sim::HeightField& after, const sim::HeightField* before, const ToolPath* path, int width,
                           int height);

// One lathe picture: the bar's section loops after a step and before it
// (sim::turnedStockAfter), from the front: the bar out of the chuck.
Picture turnedPicture(const Plan& plan, int step, int width, int height);

// A lathe job's setup: the bar in the chuck's jaws at its stick-out, from
// the front.
Picture latheSetupPicture(const Plan& plan, int width, int height);

}  // namespace taiwa::picture
