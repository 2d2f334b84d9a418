// Turning steps: facing the bar, centre drilling and drilling a bore (turn_planner.h).
#include "modules/turn/turn_planner.h"
#include "model/translate_noop.h"

namespace taiwa::turning::planner {

void Planner::planFacing()
{
    if (!q_.facing || skipped(kFacing) || q_.bar.face <= zFront_ + kTol) return;
    const Tool* tool = pinned(kFacing);
    std::string reason;
    if (tool) {
        if (!insertGeometry(*tool) || tool->turning.inside) {
            problem(std::string("tools.") + kFacing, fmt::format("{} is not an outside turning insert; facing needs one", toolWords(*tool)));
            return;
        }
        reason = TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned");
    } else {
        tool = roughingInsert(false);
        if (!tool) {
            problem("rows", TAIWA_TRANSLATE_NOOP("taiwa::msg", "the bar has face stock but the tool library has no outside turning insert to face it"));
            return;
        }
        reason = TAIWA_TRANSLATE_NOOP("taiwa::msg", "the outside roughing insert faces the bar (largest nose radius)");
    }
    const auto cutting = cuttingOf(*tool, kFacing, true);
    if (!cutting) return;
    const double rn = tool->cornerRadius;
    TurnStep ts;
    ts.side = ProfileSide::Outer;
    ts.orientation = insertOrientation(false);
    ts.tipFromCentre = tipFromCentre(rn, false);
    ts.depthOfCut = t_.depthOfCut;
    ts.region = fmt::format("front face Z{} from the bar's Z{}", len(zFront_), len(q_.bar.face));
    ts.cutting = *cutting;
    PathWriter w{{}, ts.tipFromCentre};
    const double stock = q_.bar.face - zFront_;
    const int passes = std::max(1, static_cast<int>(std::ceil(stock / t_.depthOfCut - 1e-9)));
    const double rTop = R_ + t_.clearance + rn, rBottom = q_.boreBefore > 0 ? q_.boreBefore / 2.0 - t_.clearance : 0.0;
    w.begin({q_.bar.face + t_.clearance + rn, rTop});
    for (int k = 1; k <= passes; ++k) {
        const double z = q_.bar.face - stock * k / passes + rn;  // nose centre: its front point on the face
        w.rapid({z + 0.0, rTop});
        w.feed({z, rBottom});
        w.feed({z + t_.retract, rBottom + t_.retract});
        w.rapid({z + t_.retract, rTop});
    }
    ts.path = std::move(w.path);
    addStep(StepKind::Facing, MachiningType::Facing, *tool, reason, std::move(ts));
}

const Tool* Planner::roughingInsert(bool inside) const
{
    const Tool* best = nullptr;
    for (const auto& t : lib_)
        if (t.type == ToolType::TurningInsert && t.turning.inside == inside && insertGeometry(t) &&
            (!best || t.cornerRadius > best->cornerRadius + kTol))
            best = &t;
    return best;
}

void Planner::planDrilling()
{
    // The narrowest point of the bore, less the finishing allowance.
    double rMin = 1e300;
    for (std::size_t i = first_; i < last_; ++i) rMin = std::min({rMin, chain_[i].a.r, chain_[i].b.r});
    const Tool* bar = roughingInsert(true);
    const double need = bar ? bar->turning.minBore : 0.0;
    if (q_.boreBefore > 0 && fitsInto(need, q_.boreBefore)) return;  // the bar's bore takes the boring bar
    if (skipped(kDrill)) return;
    const double maxDrill = 2.0 * (rMin - t_.allowanceX) - 1.0;
    const Tool* drill = pinned(kDrill);
    std::string reason = TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned");
    // A plain bore narrower than the boring bar enters: drilled to size.
    bool plain = true;
    for (std::size_t i = first_; i < last_; ++i)
        plain = plain && !chain_[i].arc && std::abs(chain_[i].a.r - rMin) < 1e-6 && std::abs(chain_[i].b.r - rMin) < 1e-6;
    if (!drill && plain && maxDrill < need)
        for (const auto& t : lib_)
            if (t.type == ToolType::Drill && std::abs(t.diameter - 2.0 * rMin) <= kFitTolerance) {
                drill = &t;
                reason = fmt::format("drills the plain bore to size ({}: the boring bar needs {})", dia(rMin), dia(need / 2.0));
                drilledToSize_ = true;
            }
    if (!drill) {
        for (const auto& t : lib_)
            if (t.type == ToolType::Drill && fitsInto(t.diameter, maxDrill) && fitsInto(need, t.diameter) &&
                (!drill || t.diameter > drill->diameter))
                drill = &t;
        if (!drill) {
            problem("rows", maxDrill < need
                                ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the bore is too narrow for the boring bar (it enters {}; the bore less its allowance leaves {}) and no drill of the library makes it to size"), dia(need / 2.0), dia(maxDrill / 2.0))
                                : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the bore needs a drilled hole of {} to {} (the boring bar enters {}), and the tool library has no drill in that range"),
                                              dia(need / 2.0), dia(maxDrill / 2.0), dia(need / 2.0)));
            return;
        }
        reason = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "largest drill within the bore less its allowance ({}), not smaller than the boring bar's bore {}"), dia(maxDrill / 2.0), dia(need / 2.0));
    }
    // Centre drill first.
    if (!skipped(kCentreDrill)) {
        const Tool* cd = pinned(kCentreDrill);
        if (!cd)
            for (const auto& t : lib_)
                if (t.type == ToolType::CentreDrill && (!cd || t.diameter < cd->diameter)) cd = &t;
        if (cd) {
            if (auto c = cuttingOf(*cd, kCentreDrill, false)) {
                TurnStep ts;
                ts.side = ProfileSide::Inner;
                ts.orientation = 7;
                ts.region = "centre of the front face";
                ts.cutting = *c;
                PathWriter w{{}, {}};
                w.begin({zFront_ + t_.clearance, 0.0});
                w.feed({zFront_ - cd->diameter, 0.0}, FeedKind::Plunge);
                w.rapid({zFront_ + t_.clearance, 0.0});
                ts.path = std::move(w.path);
                addStep(StepKind::CentreDrilling, MachiningType::CentreDrilling, *cd, TAIWA_TRANSLATE_NOOP("taiwa::msg", "smallest centre drill"), std::move(ts));
            }
        }
    }
    const auto c = cuttingOf(*drill, kDrill, false);
    if (!c) return;
    // The drill's full diameter reaches the bore's end; through the bar at most.
    const double point = drill->diameter / 2.0 / std::tan(drill->pointAngle / 2.0 * std::numbers::pi / 180.0);
    const double bottom = std::max(zEnd_ - point - 0.5, zBarEnd_ - point - 1.0);
    TurnStep ts;
    ts.side = ProfileSide::Inner;
    ts.orientation = 7;
    ts.region = fmt::format("{} to Z{}", dia(drill->radius()), len(bottom));
    ts.cutting = *c;
    PathWriter w{{}, {}};
    const double zIn = zFront_ + t_.clearance;
    w.begin({zIn, 0.0});
    // Pecks of three diameters, out of the hole between them for the chips.
    const double peck = 3.0 * drill->diameter;
    double at = zFront_;
    while (at > bottom + kTol) {
        const double to = std::max(bottom, at - peck);
        if (at < zFront_) w.rapid({at + 0.5, 0.0});
        w.feed({to, 0.0}, FeedKind::Plunge);
        w.rapid({zIn, 0.0});
        at = to;
    }
    ts.path = std::move(w.path);
    addStep(StepKind::Drilling, MachiningType::Drilling, *drill, reason, std::move(ts));
    drilled_ = drill->diameter;
}

}  // namespace taiwa::turning::planner
