// The frame of every module's check function: the report of one unit and
// the reporter that adds to it, made together (the reporter writes into the
// report's diagnostics), the module's checks run against them and the
// report returned.
#pragma once

#include "check/unit_checks.h"

namespace taiwa::check {

// Runs `checks(reporter, report)` for unit `unitNo` (1-based) of `module`
// and returns what they found. The checks stop early by returning.
template <class Checks>
UnitReport checkUnit(int unitNo, const char* module, const Context& ctx, Checks&& checks)
{
    UnitReport report;
    Reporter r{unitNo, module, ctx, report.diagnostics};
    checks(r, report);
    return report;
}

}  // namespace taiwa::check
