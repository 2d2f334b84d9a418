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

double LatheInchAdapter::inch(double mm) { return mm / kMillimetresPerInch; }

TurnCycle LatheInchAdapter::inch(const TurnCycle& mm)
{
    TurnCycle c = mm;
    for (auto& s : c.contour) {
        s.a = inch(s.a);
        s.b = inch(s.b);
        s.centre = inch(s.centre);
        s.radius = inch(s.radius);
    }
    c.start = inch(mm.start);
    c.depthOfCut = inch(mm.depthOfCut);
    c.allowanceX = inch(mm.allowanceX);
    c.allowanceZ = inch(mm.allowanceZ);
    c.retract = inch(mm.retract);
    return c;
}

void LatheInchAdapter::programStart(const LatheProgramInfo& info)
{
    LatheProgramInfo converted = info;
    for (auto& s : converted.stations) s.noseRadius = inch(s.noseRadius);
    next_.programStart(converted);
}

void LatheInchAdapter::spindle(const LatheSpindle& speeds)
{
    LatheSpindle converted = speeds;
    converted.surfaceSpeed = speeds.surfaceSpeed * 1000.0 / 304.8;  // m/min to ft/min: G96 S under G20
    next_.spindle(converted);
}

void LatheInchAdapter::threadingCycle(const TurnThread& thread)
{
    TurnThread t = thread;
    for (double* v : {&t.pitch, &t.depth, &t.firstDepth, &t.crestR, &t.clearance, &t.zStart, &t.zEnd}) *v = inch(*v);
    for (auto& d : t.passDepths) d = inch(d);
    next_.threadingCycle(t);
}

}  // namespace taiwa::post
