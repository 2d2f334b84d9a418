// mm to inch at the output edge (see unit_adapter.h).
#include "post/unit_adapter.h"

#include "model/job.h"

namespace taiwa::post {

double InchAdapter::inch(double mm) { return mm / kMillimetresPerInch; }

void InchAdapter::programStart(const ProgramInfo& info)
{
    ProgramInfo converted = info;
    for (auto& t : converted.tools) t.diameter = inch(t.diameter);
    converted.stockMin = inch(info.stockMin);
    converted.stockMax = inch(info.stockMax);
    next_.programStart(converted);
}

void InchAdapter::arc(const Point3& to, Point2 centre, bool clockwise, double feedRate)
{
    next_.arc(inch(to), {inch(centre.x), inch(centre.y)}, clockwise, inch(feedRate));
}

void InchAdapter::drillCycle(const DrillCycle& cycle)
{
    next_.drillCycle({inch(cycle.bottom), inch(cycle.retractZ), inch(cycle.peck), inch(cycle.feed), cycle.cycle, inch(cycle.pitch)});
}

}  // namespace taiwa::post
