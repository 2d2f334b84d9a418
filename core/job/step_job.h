// Jobs from STEP files. A lathe job from a STEP model (`taiwa import`, the
// station's File > Import STEP): the turned profiles found in it (occt/step_import.h) as TURN units,
// on the lathe, with a bar that holds the part: its diameter the part's
// largest plus 2 mm on the diameter, rounded up to a whole mm; its length
// the part's plus the face stock (1 mm) and the chuck's jaw length.
#pragma once

#include "model/job.h"
#include "model/result.h"

#include <string>

namespace taiwa {

Result<Job> latheJobFromStep(const std::string& stepPath, const std::string& material);

// A milling job from a STEP face set (`taiwa import --surface MM`): one
// SURFACE unit whose surface is the faces sampled every `spacing` mm
// (occt/surface_step.h sampleStepFaces), on the mill, the block exactly the
// faces' X-Y rectangle and its top at their highest point (the faces
// moved down by `lowered`, Z only), 5 mm deeper than their lowest.
struct SurfaceImport {
    Job job;
    double lowered = 0.0;    // mm the faces were moved down (Z)
    double deviation = 0.0;  // mm the paths stray from the faces at most (sampleStepFaces)
};
Result<SurfaceImport> surfaceJobFromStep(const std::string& stepPath, const std::string& material, double spacing);

}  // namespace taiwa
