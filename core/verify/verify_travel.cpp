// The paths against the machine's travel (verify_parts.h).
#include "verify/verify_parts.h"

#include "machine/machine.h"

#include <algorithm>

namespace taiwa::verify {

// The tip's extent over every path against the machine's travel.
void addTravelFindings(const Plan& plan, const std::vector<StepData>& steps, FindingMap& all)
{
    const Machine* m = findMachine(plan.mmJob.machine);
    if (!m) return;
    Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (const StepData& d : steps)
        for (const sim::SweptPiece& p : d.pieces)
            for (const Point3& q : {p.from, p.to}) {
                lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
                hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
            }
    if (lo.x > hi.x) return;
    const std::pair<const char*, std::pair<double, double>> axes[] = {
        {"x", {lo.x, hi.x}}, {"y", {lo.y, hi.y}}, {"z", {lo.z, hi.z}}};
    for (const auto& [axis, span] : axes) {
        const auto t = m->travel.find(axis);
        if (t == m->travel.end()) continue;
        const double excess = (span.second - span.first) - (t->second.max - t->second.min);
        if (excess <= 0.0) continue;
        Finding f;
        f.kind = FindingKind::TravelLimit;
        f.part = axis;
        f.size = excess;
        f.position = hi;
        all.try_emplace({static_cast<int>(f.kind), -1, -1, f.part}, f);
    }
}

}  // namespace taiwa::verify
