// A lathe job from a STEP model (`taiwa import`, the station's File > Import
// STEP): the turned profiles found in it (occt/step_import.h) as TURN units,
// on the lathe, with a bar that holds the part: its diameter the part's
// largest plus 2 mm on the diameter, rounded up to a whole mm; its length
// the part's plus the face stock (1 mm) and the chuck's jaw length.
#pragma once

#include "model/job.h"
#include "model/result.h"

#include <string>

namespace taiwa {

Result<Job> latheJobFromStep(const std::string& stepPath, const std::string& material);

}  // namespace taiwa
