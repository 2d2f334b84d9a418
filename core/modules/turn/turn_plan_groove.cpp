// Turning steps: grooves and parting off (turn_planner.h).
#include "modules/turn/turn_planner.h"
#include "model/translate_noop.h"

#include <cmath>

namespace taiwa::turning::planner {

void Planner::planGrooves()
{
    const auto runs = unreachedRuns();
    if (runs.empty()) return;
    for (const auto& [i, j] : runs) {
        const ZR a = chain_[i].a, b = chain_[j - 1].b;
        const double zHi = std::max(a.z, b.z), zLo = std::min(a.z, b.z);
        const double width = zHi - zLo;
        // The deepest point of the run: the blade must get there.
        double deepest = inner_ ? -1e300 : 1e300;
        for (std::size_t k = i; k < j; ++k)
            for (const ZR p : {chain_[k].a, chain_[k].b}) deepest = inner_ ? std::max(deepest, p.r) : std::min(deepest, p.r);
        const std::string elements = d_.edges[i].id + (j - i > 1 ? "…" + d_.edges[j - 1].id : "");
        // A wall that does not come back up is a shoulder facing the
        // chuck: no blade finishes the surface behind it.
        const bool groove = s_ * (b.r - a.r) >= -1e-6;
        bool own = false;
        for (std::size_t k = i; k < j; ++k) own = own || mustReach(k);
        if (!groove && own) {
            problem("rows", fmt::format("{} cannot be turned: {}; it is a shoulder facing the chuck, which needs a left-hand "
                                        "tool the library does not have (or turn the part round and make it a second job)",
                                        elements, whyNot(*finishingTool(), i)));
            continue;
        }
        const std::vector<const Tool*> blades = groovingBlades(width);
        if (blades.empty()) {
            problem("rows", fmt::format("{} cannot be turned: {}; and the tool library has no {} grooving blade", elements,
                                        whyNot(*finishingTool(), i), inner_ ? "inside" : "outside"));
            continue;
        }
        if (skipped(kGroove)) {
            note(fmt::format("{} is left: grooving is turned off", elements));
            continue;
        }
        const Tool* blade = blades.front();
        const double w = blade->turning.width;
        const double mouth = inner_ ? std::min(a.r, b.r) : std::max(a.r, b.r);
        const double rTop = mouth + s_ * t_.clearance;
        const ForbiddenRegion F = ForbiddenRegion::make(partLoop_, bladeShape(w, 50.0, inner_), 0.0, 0.0, 0.0, 0.0002);
        const std::vector<ZR> bottoms = groovePlunges(F, zLo, zHi, w, rTop);
        double reached = rTop;
        for (const ZR p : bottoms) reached = inner_ ? std::max(reached, p.r) : std::min(reached, p.r);
        if (s_ * (reached - deepest) > 0.01) {
            problem("rows", fmt::format("{} cannot be turned: {}; as a groove it is {} wide and {} deep, and the blade {} ({} wide) "
                                        "gets no deeper than {} into it",
                                        elements, whyNot(*finishingTool(), i), len(width), len(std::abs(mouth - deepest)),
                                        toolWords(*blade), len(w), len(std::abs(mouth - reached))));
            continue;
        }
        // What the blade could not come down to, at either end of the run.
        double zMost = -1e300, zLeast = 1e300;
        for (const ZR p : bottoms) zMost = std::max(zMost, p.z), zLeast = std::min(zLeast, p.z);
        // Rounded up to the micrometre, so that the note never says less is
        // left than is (the free stretch ends a fraction of a micrometre
        // inside the flattened part's grown outline).
        const auto upToMicron = [](double mm) { return std::ceil(mm * 1000.0 - 1e-6) / 1000.0; };
        const double frontLeft = upToMicron(zHi - zMost), backLeft = upToMicron(zLeast - w - zLo);
        if (frontLeft > 0.001)
            note(fmt::format("{} is left {} wide behind Z{}: the part stands over it, and the blade {} comes down only beside it",
                             d_.edges[i].id, len(frontLeft), len(zHi), toolWords(*blade)));
        if (backLeft > 0.001)
            note(fmt::format("{} is left {} wide in front of Z{}: the part stands over it, and the blade {} comes down only beside it",
                             d_.edges[j - 1].id, len(backLeft), len(zLo), toolWords(*blade)));
        const auto cutting = cuttingOf(*blade, kGroove, true);
        if (!cutting) continue;
        TurnStep ts;
        ts.side = side_;
        ts.orientation = inner_ ? 4 : 1;  // the blade's front corner
        ts.withdrawal = t_.withdrawal;
        ts.cutting = *cutting;
        ts.region = fmt::format("{}, Z{} to Z{}", elements, len(zLo), len(zHi));
        ts.path = groovePath(F, bottoms, zHi, w, rTop);
        addStep(StepKind::Grooving, MachiningType::Grooving, *blade,
                blade == pinned(kGroove) ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned")
                : w <= width + kTol
                    ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "widest grooving blade not wider than the groove ({})"), len(width))
                    : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "narrowest grooving blade; it reaches {} from the air beside it"), elements),
                std::move(ts));
    }
}

// The blades to cut a run `width` wide, best first: the widest not wider
// than the groove (fewer plunges); for a narrower groove or a step, the
// narrowest (it may cut a step from the air beside it). A pinned blade alone.
std::vector<const Tool*> Planner::groovingBlades(double width) const
{
    std::vector<const Tool*> blades;
    if (const Tool* pin = pinned(kGroove)) blades.push_back(pin);
    else
        for (const auto& t : lib_)
            if (t.type == ToolType::Grooving && t.turning.inside == inner_ && t.turning.maxDiameter <= 0) blades.push_back(&t);
    std::sort(blades.begin(), blades.end(), [&](const Tool* x, const Tool* y) {
        const bool fx = x->turning.width <= width + kTol, fy = y->turning.width <= width + kTol;
        if (fx != fy) return fx;
        return fx ? x->turning.width > y->turning.width : x->turning.width < y->turning.width;
    });
    return blades;
}

// The bottoms of the plunges of a blade `w` wide into the run from zHi to
// zLo coming down from rTop: from the front wall back, less than a blade
// width apart, each as deep as the blade goes clear of the part (F).
std::vector<ZR> Planner::groovePlunges(const ForbiddenRegion& F, double zLo, double zHi, double w, double rTop) const
{
    const double width = zHi - zLo;
    const double eps = 1e-4, span = std::max(width - w, 0.0);  // off the walls, inside the blade's own narrowing
    const int n = span <= kTol ? 1 : static_cast<int>(std::ceil(span / (0.8 * w) - 1e-9)) + 1;
    // The blade comes down from rTop. Where the part stands over the run
    // (the allowance over a relief groove's undercut, seed 3092 of the
    // generator's plans), the blade cannot come down there at all: the
    // plunge moves to the nearest place where the blade is clear at rTop
    // and still over the run; what no plunge then reaches is left and
    // said, and a run no plunge reaches is refused below.
    const auto clear = [&](double z) { return !F.inside({z, rTop}); };
    const double overLo = zLo + 0.01, overHi = zHi + w - 0.01;  // the blade [z - w, z] still over the run
    const auto clearOverRun = F.freeAlongZ(rTop, overLo, overHi);  // where the blade may come down
    const auto comeDown = [&](double z) -> std::optional<double> {
        if (clear(z)) return z;
        std::optional<double> nearest;
        for (const auto& [z0, z1] : clearOverRun)
            if (const double c = std::clamp(z, z0, z1); !nearest || std::abs(c - z) < std::abs(*nearest - z)) nearest = c;
        return nearest;
    };
    std::vector<ZR> bottoms;
    for (int k = 0; k < n; ++k) {
        const auto z = comeDown(zHi - eps - (n > 1 ? span * k / (n - 1) : 0.0));
        if (!z) continue;  // nowhere clear over the run: this plunge is not made
        double bottom = rTop;
        for (const auto& f : F.freeAlongR(*z, inner_ ? rTop - 1.0 : -1.0, inner_ ? R_ + 100.0 : rTop + 1.0))
            if (f.first <= rTop + 1e-6 && f.second >= rTop - 1e-6) bottom = inner_ ? f.second : f.first;
        bottoms.push_back({*z, bottom});
    }
    return bottoms;
}

// The blade's path: its plunges from rTop, then withdrawn from the last
// bottom and away.
TurnPath Planner::groovePath(const ForbiddenRegion& F, const std::vector<ZR>& bottoms, double zHi, double w, double rTop) const
{
    PathWriter wr{{}, {}};
    // From the run's front at rTop, unless the part stands over it there.
    wr.begin({!F.inside({zHi, rTop}) ? zHi : bottoms.front().z, rTop});
    for (std::size_t k = 0; k < bottoms.size(); ++k) {
        wr.rapid({bottoms[k].z, rTop});
        wr.feed(bottoms[k], FeedKind::Plunge);
        if (k + 1 < bottoms.size()) wr.rapid({bottoms[k].z, rTop});
    }
    // Seed 002: withdrawn along the surface's normal at the end point by da.
    const ZR end = bottoms.back();
    const ZR normal = surfaceNormal(end, first_, chain_.size(), w);
    // Unless the blade's side stands against a wall the normal leans
    // toward (the last plunge against the groove's back wall, its bottom
    // a fillet rising to it): then straight out, along the wall.
    ZR out = t_.withdrawal * normal;
    if (F.inside(end + out) || F.inside(end + 0.5 * out)) out = ZR{0.0, s_ * t_.withdrawal};
    wr.feed(end + out);
    wr.rapid({wr.path.moves.back().end.z, rTop});
    if (inner_) wr.rapid({zFront_ + t_.clearance, rTop});
    return std::move(wr.path);
}

ZR Planner::surfaceNormal(ZR corner, std::size_t i, std::size_t j, double w) const
{
    const ZR mid{corner.z - 0.5 * w, corner.r};
    double best = 1e300;
    ZR n{0.0, s_};
    for (std::size_t k = i; k < j; ++k) {
        const Segment& s = chain_[k];
        ZR p;
        if (s.arc) {
            p = s.centre + s.radius * unit(mid - s.centre);
            if (!contains(s, p)) continue;
        } else {
            const ZR t = s.b - s.a;
            const double u = std::clamp(dot(mid - s.a, t) / std::max(dot(t, t), 1e-18), 0.0, 1.0);
            p = s.a + u * t;
        }
        const double d = dist(p, mid);
        if (d < best) {
            best = d;
            const ZR t = tangentAt(s, p);
            // Air is right of the travel for an outer profile, left for an inner one.
            n = inner_ ? leftNormal(t) : ZR{t.r, -t.z};
        }
    }
    return n;
}

std::pair<double, std::optional<std::string>> Planner::rearmost() const
{
    double z = zEnd_;
    std::optional<std::string> edge;
    for (const DeformedEdge& e : d_.edges) {
        const Segment& g = e.geometry;
        double lowest = std::min(g.a.z, g.b.z);
        // An arc whose sweep passes its circle's rearmost point.
        if (const ZR back{g.centre.z - g.radius, g.centre.r}; g.arc && contains(g, back)) lowest = std::min(lowest, back.z);
        if (lowest < z - 1e-6) {
            z = lowest;
            edge = e.from.empty() ? e.id : e.from;
        }
    }
    return {z, edge};
}

void Planner::planParting()
{
    if (!q_.parting || skipped(kPart)) return;
    const Tool* blade = pinned(kPart);
    if (!blade)
        for (const auto& t : lib_)
            if (t.type == ToolType::Grooving && t.turning.maxDiameter >= q_.bar.diameter - kTol && (!blade || t.turning.width < blade->turning.width))
                blade = &t;
    if (!blade) {
        note(fmt::format("no parting off: no blade of the tool library parts off the bar's {} (saw it off, or add a blade)", dia(R_)));
        return;
    }
    const double width = blade->turning.width;
    // The blade's face must pass behind all of the part: the grinding
    // allowance of a last edge falling to the end (a taper, an arc) reaches
    // past the profile's end along the edge's normal, over the back face,
    // where a plunge at the end would cut it. Parted off behind it, the
    // back face is left long by as much (a note says so).
    const auto [zCut, reaching] = rearmost();
    if (zCut - width < zBarEnd_ - kTol) {
        note(fmt::format("no parting off: the part ends {} from the bar's end, less than the blade's width", len(zCut - zBarEnd_)));
        return;
    }
    if (reaching)
        note(fmt::format("parted off at Z{}, {} behind the part's end: the grinding allowance of {} reaches past the end; the "
                         "back face is left {} long (face it to length)",
                         len(zCut), len(zEnd_ - zCut), *reaching, len(zEnd_ - zCut)));
    const auto cutting = cuttingOf(*blade, kPart, true);
    if (!cutting) return;
    TurnStep ts;
    ts.side = ProfileSide::Outer;
    ts.orientation = 1;
    ts.cutting = *cutting;
    ts.region = fmt::format("at Z{}", len(zCut));
    PathWriter w{{}, {}};
    const double rTop = R_ + t_.clearance;
    const double rBottom = q_.boreBefore > 0 ? q_.boreBefore / 2.0 - 0.5 : -0.5;
    w.begin({zCut, rTop});
    w.rapid({zCut, rTop});
    w.feed({zCut, rBottom}, FeedKind::Plunge);
    w.rapid({zCut, rTop});
    ts.path = std::move(w.path);
    addStep(StepKind::Parting, MachiningType::Parting, *blade,
            blade == pinned(kPart) ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned")
                                   : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "narrowest parting blade for {}"), dia(R_)), std::move(ts));
}

}  // namespace taiwa::turning::planner
