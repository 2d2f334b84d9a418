// The turning steps of one turned-profile unit (turn_plan.h): which steps,
// which tools, and every path, computed with the nose centre and written as
// the programmed point (the imaginary tip of the tool's orientation). This
// file holds what the steps share (the part's loop, pinned tools, cutting
// data, the inserts' reach, the spindle limit) and the door; each kind of
// step is planned in a file of its own (turn_planner.h lists them).
#include "modules/turn/turn_planner.h"

namespace taiwa::turning {

namespace planner {

std::vector<Segment> Planner::makePartLoop() const
{
    std::vector<Segment> loop = chain_;
    std::vector<ZR> pts;
    const ZR start = chain_.front().a, end = chain_.back().b;
    const double zLo = std::min(zBarEnd_, zEnd_) - 1.0;
    if (!inner_) {
        pts = {end, {zEnd_, R_}, {zLo, R_}, {zLo, 0.0}, {start.z, 0.0}, start};
    } else {
        const double rOut = R_ + 1.0;
        pts = {end, {zLo, rEnd_}, {zLo, rOut}, {start.z, rOut}, start};
    }
    for (std::size_t i = 0; i + 1 < pts.size(); ++i)
        if (dist(pts[i], pts[i + 1]) > kTol) loop.push_back(lineSegment(pts[i], pts[i + 1]));
    return loop;
}

const Tool* Planner::pinned(const char* key) const
{
    const auto it = q_.pins.find(key);
    return it == q_.pins.end() ? nullptr : findTool(lib_, it->second);
}

std::optional<TurnCutting> Planner::cuttingOf(const Tool& tool, const char* key, bool css)
{
    const CuttingData* cd = tool.cuttingFor(q_.material);
    if (!cd) {
        problem(std::string("tools.") + key, fmt::format("{} has no cutting data for {}; add it in the tool library", toolWords(tool), q_.material));
        return std::nullopt;
    }
    TurnCutting c;
    c.constantSurfaceSpeed = css;
    c.surfaceSpeed = cd->surfaceSpeed;
    c.maxRpm = q_.maxRpm;
    c.feedPerRev = cd->feedPerTooth;
    c.plungeFeedPerRev = cd->feedPerTooth * std::clamp(cd->plungeFactor, 0.1, 1.0);
    if (!css) {  // drills: one feed, at the rpm of their diameter
        c.rpm = std::min(q_.maxRpm, std::round(1000.0 * cd->surfaceSpeed / (std::numbers::pi * std::max(tool.diameter, 0.1))));
        c.plungeFeedPerRev = cd->feedPerTooth;
    }
    // The operator's S and F for this kind of step (the plunge feed in
    // proportion): the spindle limit's check and the time see them too.
    if (const auto it = q_.cutting.find(key); it != q_.cutting.end()) {
        if (it->second.speed) (css ? c.surfaceSpeed : c.rpm) = *it->second.speed;
        if (it->second.feed) {
            c.plungeFeedPerRev *= *it->second.feed / c.feedPerRev;
            c.feedPerRev = *it->second.feed;
        }
    }
    return c;
}

Step& Planner::addStep(StepKind kind, MachiningType type, const Tool& tool, std::string reason, TurnStep turn)
{
    Step s;
    s.unit = q_.unit;
    s.module = "TURN";
    s.kind = kind;
    s.machiningType = type;
    s.number = 1 + static_cast<int>(std::count_if(out_.steps.begin(), out_.steps.end(), [&](const Step& o) { return o.kind == kind; }));
    s.tool = ToolChoice{tool.id, std::move(reason)};
    s.minutes = turnMinutes(turn.path, turn.cutting, q_.rapid);
    s.payload = std::move(turn);
    out_.steps.push_back(std::move(s));
    return out_.steps.back();
}

double Planner::safeR() const
{
    return inner_ ? std::max(std::max(q_.boreBefore, drilled_) / 2.0 - t_.clearance, 0.0) : R_ + t_.clearance;
}

std::vector<const Tool*> Planner::inserts() const
{
    std::vector<const Tool*> v;
    for (const auto& t : lib_)
        if (t.type == ToolType::TurningInsert && t.turning.inside == inner_ && insertGeometry(t)) v.push_back(&t);
    return v;
}

int Planner::firstUnreached(const Tool& t, std::size_t from, std::size_t to, bool tightArcs) const
{
    const auto g = *insertGeometry(t);
    for (std::size_t i = from; i < to; ++i) {
        const Segment& s = chain_[i];
        if (!reaches(g, s, side_)) return static_cast<int>(i);
        // A concave arc (material outside the arc's circle) must be wider than the nose.
        if (s.arc && tightArcs) {
            const bool materialOutside = (s.ccw ? 1.0 : -1.0) * s_ < 0;  // a turn away from the material
            if (materialOutside && s.radius <= g.noseRadius + kTol) return static_cast<int>(i);
        }
    }
    return -1;
}

bool Planner::mustReach(std::size_t i) const
{
    const Origin o = d_.edges[i].origin;
    return o == Origin::Original || o == Origin::Moved;
}

std::vector<bool> Planner::reachedBy(const Tool& t) const
{
    std::vector<bool> ok(chain_.size(), true);
    for (std::size_t i = first_; i < last_; ++i) ok[i] = !mustReach(i) || firstUnreached(t, i, i + 1, false) < 0;
    return ok;
}

std::string Planner::whyNot(const Tool& t, std::size_t i) const
{
    const auto g = *insertGeometry(t);
    const Segment& s = chain_[i];
    if (s.arc && !reaches(g, s, side_)) return fmt::format("its arc turns beyond what {} can follow", toolWords(t));
    if (s.arc) return fmt::format("its concave radius {} is not larger than the nose radius {} of {}", len(s.radius), len(g.noseRadius), toolWords(t));
    const double th = riseDegrees(tangentAtStart(s), side_);
    if (th > g.maxRise())
        return fmt::format("it rises {:.1f}° against the feed, more than the {:.1f}° the holder of {} allows (it would cut backward)", th, g.maxRise(), toolWords(t));
    return fmt::format("it falls {:.1f}° behind the insert, more than the {:.1f}° clearance of {}", -th, -g.minRise(), toolWords(t));
}

void Planner::checkSpindleLimit(const Tool& tool, const TurnCutting& c, const char* key)
{
    double rMin = 1e300;
    for (std::size_t i = first_; i < last_; ++i) rMin = std::min({rMin, chain_[i].a.r, chain_[i].b.r});
    if (rMin <= 0.01) return;
    const double vcAt = std::numbers::pi * 2.0 * rMin * q_.maxRpm / 1000.0;
    if (vcAt < kMinSpeedShare * c.surfaceSpeed)
        problem(std::string("tools.") + key,
                fmt::format("the spindle limit of {:.0f} rpm turns {} at only {:.0f} m/min, less than half the {:.0f} m/min {} needs there; "
                            "choose a machine with a higher speed limit or a tool for lower speeds",
                            q_.maxRpm, dia(rMin), vcAt, c.surfaceSpeed, toolWords(tool)));
}

}  // namespace planner

using namespace planner;

const std::vector<std::string>& turnStepKeys()
{
    static const std::vector<std::string> keys{kFacing, kCentreDrill, kDrill, kRough, kFinish, kGroove, kThread, kPart};
    return keys;
}

TurnPlanResult planTurnedUnit(const TurnPlanRequest& request)
{
    if (!request.deformed || request.deformed->edges.empty() || !request.library) return {};
    return Planner(request).run();
}

const Tool* finishingInsert(const TurnPlanRequest& request)
{
    if (!request.deformed || request.deformed->edges.empty() || !request.library) return nullptr;
    return Planner(request).finishingInsert();
}

}  // namespace taiwa::turning
