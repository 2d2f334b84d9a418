// The job's figure elements (Job::figure, the APT-like text in the job's
// length unit) evaluated for the contour units: every contour in mm by name,
// handed to each unit through its door (ModuleKind::resolveContours). The
// text's refusals are job diagnostics on the field "figure", each starting
// with its line and column ("3:12: ...").
#pragma once

#include "model/contour.h"
#include "model/diagnostic.h"
#include "model/job.h"

namespace taiwa {

// The figure's contours in mm. Refusals of the text or of an element go to
// `out` (a contour defined from a refused element is left out).
ContourTable figureContours(const Job& typed, Diagnostics& out);

// Every unit of `mmJob` given the contours it names.
void resolveContours(Job& mmJob, const ContourTable& contours);

// The job in mm with its contour units resolved, the figure's refusals
// dropped (callers that report them use the two functions above).
Job millimetreJob(const Job& typed);

}  // namespace taiwa
