// The NC programs of work-centre probing (a WorkSetup, model/setup.h):
// the setting program that hands the centre measured from the operator's
// touches to the control as the job's work offset and moves the spindle to
// it, and the probing cycle that makes the touches on the machine by itself
// (G38.3 with #5061-#5070 on LinuxCNC, G31 with #5061-#5063 on FANUC), does
// the arithmetic on the control and writes the work offset. Both are in mm
// (G21) whatever the job's unit. docs/probing.md describes them.
#pragma once

#include "model/setup.h"
#include "post/dialect.h"
#include "post/post.h"

#include <string>

namespace taiwa {

// Needs setup.measured. Throws Refusal (model/result.h) for an unknown
// dialect, one that writes no probing programs, or a work offset its
// controller does not have.
std::string settingProgram(const WorkSetup& setup, const PostOptions& options);

// Throws as settingProgram does.
std::string probingProgram(const WorkSetup& setup, const PostOptions& options);

// The same in `dialect` (options.dialect not looked up): one not in the
// library, as the tape read-back judges it (verify/tape_readback.h).
std::string settingProgram(const WorkSetup& setup, const PostOptions& options, const post::Dialect& dialect);
std::string probingProgram(const WorkSetup& setup, const PostOptions& options, const post::Dialect& dialect);

}  // namespace taiwa
