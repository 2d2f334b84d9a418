// The tool change of a gang-tool lathe (seed 002, last abstract;
// docs/two-path-lathe.md "Gang-tool tool change"): the tools stand side by
// side on one slide, so bringing the next tool to its start point moves the
// slide first along Z to where no tool on it can touch the part when X
// moves (every tool's tip beyond the part's front by the slide's
// clearance), then along X until the chosen tool's X is its start's, then
// along Z to the start (the approach). Positions are the slide's reference
// point; a tool's tip is the reference plus its mounting offset
// (lathe_kinds.h GangSlide).
#pragma once

#include "machine/lathe_kinds.h"
#include "model/result.h"

#include <vector>

namespace taiwa {

// The part's envelope in the work's coordinates: from the front face back
// to the chuck, out to the largest radius [mm].
struct PartEnvelope {
    double zFront = 0.0, zBack = 0.0, radius = 0.0;
};

// The slide's reference positions of a change, the one it stands at first,
// then after the Z clear, the X move and the approach.
struct GangChange {
    std::vector<turning::ZR> slide;
};

// From tool `from` with its tip at `at` to tool `to` at `start`. Refused
// (naming the tool and the key): a tool with no mounting offset on the
// slide.
Result<GangChange> gangToolChange(const GangSlide& slide, int from, turning::ZR at, int to, turning::ZR start,
                                  const PartEnvelope& part);

// Whether some tool on the slide with its reference at `s` is inside the
// part's envelope grown by the slide's clearance.
bool anyToolInside(const GangSlide& slide, turning::ZR s, const PartEnvelope& part);

}  // namespace taiwa
