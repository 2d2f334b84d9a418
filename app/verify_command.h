// What the command line does with the verification (docs/verification.md):
// `taiwa verify`'s report in words or JSON, the verification `taiwa export`
// runs before it writes, and the sheet's pictures of the steps and of the
// setup it draws.
#pragma once

#include "app/options.h"
#include "export/export.h"
#include "model/plan.h"
#include "post/post.h"
#include "post/posted_job.h"
#include "verify/verify.h"

#include <optional>
#include <string>

namespace taiwa::app {

// The plan verified at the options' resolution, its findings placed on
// the tape posted with `post` and every program of the export read back
// (verify/tape_readback.h); the programs kept in `posted` (post/posted_job.h:
// each posted once, the export writes them as they are; none when the
// dialect cannot post the job).
// Through the verification cache (export/verification_cache.h) unless
// --no-cache: `reused` says whether the report was the stored one.
verify::Report verified(const Plan& plan, const Options& o, const PostOptions& post, std::optional<PostedJob>& posted,
                        bool* reused = nullptr);

// Prints the report of the plan of job file `name` on stdout, in words or
// (--json) as one document; whether it found anything fatal.
bool printVerification(const Plan& plan, const Options& o, const std::string& name, const std::string& dialect);

// The sheet's setup picture and step pictures into `e`, drawn by the core
// on the processor (no display needed); where one cannot be made, the
// sheet's note and stderr say why.
void picturesFor(const Plan& plan, ExportOptions& e);

}  // namespace taiwa::app
