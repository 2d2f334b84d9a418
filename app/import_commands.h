// The commands that make Taiwa's text of another program's file
// (app/import_commands.cpp): `taiwa import STEP --out JOB` (a lathe job
// from a turned part's solid model, docs/turning.md) and `taiwa
// figure-from-dxf DXF` (a drawing's contours as figure text,
// docs/dxf-import.md).
#pragma once

#include "app/options.h"

namespace taiwa::app {

// `taiwa import`: the job written to o.out, which must not exist. Exit 0,
// 2 when the model, the material or the out file is refused, 1 when the
// write fails.
int importStep(const Options& o);

// `taiwa figure-from-dxf`: the figure text on stdout, what was read and
// what is wrong with it on stderr. Exit 0, or 2 with gaps or refusals.
int figureFromDxf(const Options& o);

}  // namespace taiwa::app
