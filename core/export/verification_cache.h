// One verification per export (docs/verification.md, "The verification
// cache"): a milling job's verification at 0.05 mm takes seconds, and
// `taiwa verify` followed by `taiwa export` of the same job, or the
// station's Verify followed by its Export, would run it twice. The report
// (its findings and figures, not its height field) is kept in the user's
// cache folder under a key that is the SHA-256 of everything the
// verification depends on: this program's build, the cell size, the job as
// typed, the library tools its steps use and the machine it runs on. Any
// change to one of them is another key; a file that cannot be read back is
// a miss, never an error. In the export library: it hashes with Qt Core.
#pragma once

#include "model/plan.h"
#include "model/result.h"
#include "verify/verify.h"

#include <optional>
#include <string>

namespace taiwa {

// $TAIWA_CACHE_DIR, else $XDG_CACHE_HOME/taiwa/verification, else
// ~/.cache/taiwa/verification.
std::string verificationCacheFolder();

// 64 hex digits. The plan must be the one the job, its library tools and its
// machine give with this build (planJob's result); of the options, the cell
// size and the bound of the work count (not the threads).
std::string verificationKey(const Plan& plan, const verify::Options& options);

// The report stored under `key`, without its height field and section
// (Report::stock and ::section stay empty) and with its findings' tape
// lines cleared (placeOnTape places them again); nothing when there is
// none or it cannot be read.
std::optional<verify::Report> loadVerification(const std::string& key);

// Keeps the report under `key`, written atomically; the oldest files past
// kCachedVerifications are removed. A failure is returned, never thrown:
// the caller carries on without the cache.
constexpr int kCachedVerifications = 64;
Result<void> storeVerification(const std::string& key, const verify::Report& report);

// verifyPlan through the cache: the stored report when there is one for
// this plan and options, else a fresh one, stored. `reused` says which.
verify::Report verifyPlanCached(const Plan& plan, const verify::Options& options, bool* reused = nullptr);

}  // namespace taiwa
