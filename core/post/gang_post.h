// The tape of a job on a gang-tool lathe (docs/two-path-lathe.md
// "Gang-tool tool change"): the lathe post's program with every tool change
// (and the program's end) made the gang change of machine/gang_change.h.
// Positions stay the active tool's tip with a per-tool offset (FANUC
// T0202, LinuxCNC T2 M6 G43, SINUMERIK T2 D1: the tool's mounting offset is
// its geometry offset), so a change is written as: with the old tool's
// offset, G0 Z out until every tool on the slide stands clear of the
// part's front; the T word; G0 X to the start's X with Z where the slide
// already is (in the new tool's offset); then the lathe post's approach,
// which now moves Z alone. The Z clear is deep enough that a control
// applying the new offset at the T word itself (moving the slide by the
// offsets' difference) still keeps every tool clear of the part. The change
// is a link of the lathe post's sink chain (GangChangeAdapter, between the
// poster and the writer), so its blocks are numbered and measured as all
// others; the stations come from the program's (LatheProgramInfo).
#pragma once

#include "machine/gang_change.h"
#include "post/post.h"

namespace taiwa {

// The part's envelope the steps' paths make: out to their largest radius,
// from their largest Z back to their smallest (the bar and every approach
// point inside it, so never smaller than the bar).
PartEnvelope pathsEnvelope(const std::vector<Step>& steps);

// `steps`, `library`, `options` as for postProcess. Throws
// as postProcess does, and Refusal naming the tool
// (`tools.T104: tool 104 has no mounting offset on the gang slide
// (gangSlide.tools)`) for a tool that has no place on the slide.
PostedProgram postGangTool(const std::vector<Step>& steps, const std::vector<Tool>& library, const GangSlide& slide,
                           const PartEnvelope& part, const PostOptions& options);

}  // namespace taiwa
