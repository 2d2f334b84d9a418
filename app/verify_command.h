// What the command line does with the verification (docs/verification.md):
// `taiwa verify`'s report in words or JSON, the verification `taiwa export`
// runs before it writes, and the sheet's pictures of the steps and of the
// setup it draws.
#pragma once

#include "app/options.h"
#include "export/export.h"
#include "model/plan.h"
#include "post/post.h"
#include "verify/verify.h"

#include <optional>
#include <string>

namespace taiwa::app {

// The plan verified at the options' resolution, its findings placed on
// the tape posted with `post`; that tape kept in `tape` (posted only when
// there are findings to place, and when the dialect can post the job).
// Through the verification cache (export/verification_cache.h) unless
// --no-cache: `reused` says whether the report was the stored one.
verify::Report verified(const Plan& plan, const Options& o, const PostOptions& post, std::optional<PostedProgram>& tape,
                        bool* reused = nullptr);

// Prints the report of the plan of job file `name` on stdout, in words or
// (--json) as one document; whether it found anything fatal.
bool printVerification(const Plan& plan, const Options& o, const std::string& name, const std::string& dialect);

// The sheet's pictures of the steps into `e`, drawn offscreen by the 3-D
// view's renderer; without a display (or a build without the view) the
// note says why there are none.
void stepPicturesFor(const Plan& plan, ExportOptions& e);

// The setup picture into `e` (the stock in its vice or chuck and the work
// offset's origin, viz::setupPicture, 320 x 240 like the steps'); none
// without a display or in a build without the 3-D view (the steps'
// pictures' note says why).
void setupPictureFor(const Plan& plan, ExportOptions& e);

}  // namespace taiwa::app
