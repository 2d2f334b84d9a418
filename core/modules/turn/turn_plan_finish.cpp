// Turning steps: the finishing insert and the finishing contour (turn_planner.h).
#include "modules/turn/turn_planner.h"
#include "model/translate_noop.h"

namespace taiwa::turning::planner {

const Tool* Planner::chooseFinishing()
{
    if (skipped(kFinish)) return nullptr;
    if (const Tool* t = pinned(kFinish)) {
        if (!insertGeometry(*t) || t->turning.inside != inner_) {
            problem(std::string("tools.") + kFinish, fmt::format("{} is not an {} turning insert", toolWords(*t), inner_ ? "inside" : "outside"));
            return nullptr;
        }
        finishReason_ = TAIWA_TRANSLATE_NOOP("taiwa::msg", "pinned");
        finishReach_ = reachedBy(*t);
        finishTool_ = t;
        return t;
    }
    // The insert that reaches every element; of those the smallest nose
    // radius (the finest finish), then the lowest number. Failing that,
    // the one reaching most, the rest left for a grooving blade.
    // Of equal reach over the part, the one that also follows more of
    // the allowance's relief grooves (fewer left).
    const Tool* best = nullptr;
    int bestMissing = 1 << 30, bestGrooves = 1 << 30;
    for (const Tool* t : inserts()) {
        const auto ok = reachedBy(*t);
        const int missing = static_cast<int>(std::count(ok.begin() + static_cast<long>(first_), ok.end(), false));
        int grooves = 0;
        for (std::size_t i = first_; i < last_; ++i) grooves += !mustReach(i) && firstUnreached(*t, i, i + 1) >= 0;
        if (!best || missing < bestMissing || (missing == bestMissing && grooves < bestGrooves) ||
            (missing == bestMissing && grooves == bestGrooves && t->cornerRadius < best->cornerRadius - kTol)) {
            best = t;
            bestMissing = missing;
            bestGrooves = grooves;
        }
    }
    if (!best) {
        problem("rows", inner_ ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool library has no inside (boring) turning insert")
                                : TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool library has no outside turning insert"));
        return nullptr;
    }
    finishReach_ = reachedBy(*best);
    finishTool_ = best;
    finishReason_ = bestMissing == 0
                        ? TAIWA_TRANSLATE_NOOP("taiwa::msg", "reaches every element; smallest nose radius of those that do")
                        : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "reaches all but {} element(s); smallest nose radius of those that reach most"),
                                      bestMissing);
    return best;
}

std::vector<std::pair<std::size_t, std::size_t>> Planner::unreachedRuns() const
{
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t i = first_; i < last_;) {
        if (finishReach_.empty() || finishReach_[i]) {
            ++i;
            continue;
        }
        std::size_t j = i;
        while (j < last_ && !finishReach_[j]) ++j;
        // A wall the insert cannot go down opens a groove: the run goes
        // on to where the profile comes back up to its mouth (within
        // kGrooveReach), the bottom in the insert's shadow too.
        const double mouth = chain_[i].a.r;
        if (s_ * (chain_[j - 1].b.r - mouth) < -1e-6) {
            std::size_t k = j;
            while (k < last_ && s_ * (chain_[k].b.r - mouth) < -1e-6 && chain_[i].a.z - chain_[k].b.z <= kGrooveReach) ++k;
            if (k < last_ && chain_[i].a.z - chain_[k].b.z <= kGrooveReach) j = k + 1;
        }
        runs.emplace_back(i, j);  // [i, j)
        i = j;
    }
    return runs;
}

void Planner::planFinishing(const Tool& tool)
{
    const auto cutting = cuttingOf(tool, kFinish, true);
    if (!cutting) return;
    checkSpindleLimit(tool, *cutting, kFinish);
    const auto g = *insertGeometry(tool);
    const double rn = g.noseRadius;
    TurnStep ts;
    ts.side = side_;
    ts.orientation = insertOrientation(inner_);
    ts.tipFromCentre = tipFromCentre(rn, inner_);
    ts.cutting = *cutting;
    ts.region = fmt::format("the deformed profile from Z{} to Z{}", len(zFront_), len(zEnd_));
    std::vector<Segment> contour = finishingContour(tool, rn);
    const auto entryLine = [&](const std::vector<Segment>& c) {
        const ZR e = finishingEntry(c, rn) - ts.tipFromCentre;
        return lineSegment({e.z, c.front().a.r}, c.front().a);
    };
    // The nose measured along the entry, the contour and the exit before
    // the plan is returned (the verification refuses a plan that cuts the
    // part anywhere: issue 33, item 3). The contour first: where it cuts,
    // the plan is refused naming the edge. Then the ways in (the entry
    // along -Z onto each of finishingWays in turn) and out (up and forward
    // or straight out).
    std::optional<NoseIntoPart> into = out_.problems.empty() ? noseIntoPart(contour, rn) : std::nullopt;
    bool upAndForward = dot(unit(finishingUpAndOut(rn)), airNormal(tangentAtEnd(contour.back()))) > 0.25;
    std::optional<Segment> unheld;  // the first element of a way the control cannot hold the nose against
    if (!into && out_.problems.empty()) {
        const std::vector<std::vector<Segment>> ways = finishingWays(contour, rn);
        std::optional<NoseIntoPart> firstInto;
        bool found = false;
        for (const auto& c : ways) {
            std::vector<Segment> measured{entryLine(c)};
            measured.insert(measured.end(), c.begin(), c.end());
            // A way whose corners the control's compensation cannot hold
            // (the entry onto an element too short to sit against, or onto
            // a rounding the nose meets beyond its end) is not taken.
            if (const auto k = unheldCorner(measured, rn)) {
                if (!unheld) unheld = measured[*k];
                continue;
            }
            std::optional<NoseIntoPart> bad = noseIntoPart(measured, rn, std::nullopt, true);
            if (!bad) {
                // The exit: the way chosen by the last element, else the other.
                bad = noseIntoPart({c.back()}, rn, finishingExit(c, upAndForward, rn, ts.tipFromCentre) - ts.tipFromCentre);
                if (bad && !noseIntoPart({c.back()}, rn, finishingExit(c, !upAndForward, rn, ts.tipFromCentre) - ts.tipFromCentre)) {
                    upAndForward = !upAndForward;
                    bad.reset();
                }
            }
            if (!bad) {
                contour = c;
                found = true;
                break;
            }
            if (!firstInto) firstInto = bad;
        }
        if (!found) into = firstInto;
        if (!found && !into && unheld) {
            problem("rows", fmt::format("{} cannot be finished as drawn: the nose R{} of {} cannot sit in the concave corner at X{} Z{} "
                                        "(an element there is shorter than the nose needs, and no other way in is clear); change "
                                        "the allowance or the corner there",
                                        edgeNear(midpoint(*unheld)), len(rn), toolWords(tool), len(2.0 * unheld->b.r), len(unheld->b.z)));
            return;
        }
    }
    // A contour along which (or into or out of which) the nose would cut
    // the part is refused, not planned. Only asked of a plan not refused
    // already (its reason comes first).
    if (into) {
        problem("rows", fmt::format("{} cannot be finished as drawn: along it the nose R{} of {} would cut {} into the part with "
                                    "its centre at X{} Z{} (a corner too tight for the nose next to it); change the allowance or the "
                                    "corner there",
                                    into->edge, len(rn), toolWords(tool), len(into->depth), len(2.0 * into->centre.r),
                                    len(into->centre.z)));
        return;
    }
    ts.path = finishingPath(contour, upAndForward, rn, ts.tipFromCentre);
    addStep(StepKind::TurnFinishing, MachiningType::TurnFinishing, tool, finishReason_, std::move(ts));
}

// The contour as cut: the profile, each groove the insert cannot enter
// bridged by a line across its mouth (the blade cuts it after), the
// allowance's stock crossed, the corners and arcs the nose cannot follow
// bridged.
std::vector<Segment> Planner::finishingContour(const Tool& tool, double rn)
{
    std::vector<Segment> contour;
    const auto runs = unreachedRuns();
    for (std::size_t i = first_; i < last_;) {
        const auto run = std::find_if(runs.begin(), runs.end(), [&](const auto& r) { return r.first == i; });
        if (run == runs.end()) {
            contour.push_back(chain_[i]);
            ++i;
            continue;
        }
        const ZR a = chain_[run->first].a, b = chain_[run->second - 1].b;
        if (dist(a, b) > kTol) contour.push_back(lineSegment(a, b));
        i = run->second;
    }
    crossGrindingStockRuns(contour, tool);
    // A step back toward the front at the end (an allowance's side coming
    // back to the part's last point): the nose on it would sit behind
    // and below that point, in the part; the contour ends before it.
    while (contour.size() > 1 && !contour.back().arc && contour.back().b.z > contour.back().a.z + 1e-6) contour.pop_back();
    // Likewise a step up shorter than the nose at the start (an allowance's
    // side at the front corner): entering along -Z onto its foot, the nose
    // would sit over what follows it, in the part; the contour starts after it.
    while (contour.size() > 1 && !contour.front().arc && length(contour.front()) < rn &&
           s_ * (contour.front().b.r - contour.front().a.r) > std::abs(contour.front().b.z - contour.front().a.z))
        contour.erase(contour.begin());
    bridgeTightArcs(contour, rn, tool);
    reachableCorners(contour, rn);
    // The lines that makes at arcs, at line corners in their turn.
    if (reachableArcCorners(contour, rn)) reachableCorners(contour, rn);
    mergeUnheldElements(contour, rn);
    return contour;
}

void Planner::crossGrindingStockRuns(std::vector<Segment>& contour, const Tool& tool)
{
    const auto g = *insertGeometry(tool);
    const double rn = g.noseRadius;
    std::vector<std::string> left;
    for (std::size_t i = first_; i < last_;) {
        if (mustReach(i) || firstUnreached(tool, i, i + 1) < 0) {
            ++i;
            continue;
        }
        // The whole run of the allowance's edges around it (a relief
        // groove is several), from one edge of the part to the next.
        std::size_t j = i;
        while (j < last_ && !mustReach(j)) ++j;
        while (i > first_ && !mustReach(i - 1)) --i;
        const ZR a = chain_[i].a, b = chain_[j - 1].b;
        // The run in the contour: the element starting at a, the one ending at b.
        std::size_t ka = contour.size(), kb = contour.size();
        for (std::size_t k = 0; k < contour.size(); ++k) {
            if (ka == contour.size() && dist(contour[k].a, a) < 1e-9) ka = k;
            if (dist(contour[k].b, b) < 1e-9) kb = k;
        }
        if (ka >= contour.size() || kb >= contour.size() || kb < ka || ka == 0 || kb + 1 >= contour.size()) {
            i = j;
            continue;
        }
        for (double reach = 2.0 * rn; reach <= 16.0 * rn; reach *= 2.0) {
            const Segment& before = contour[ka - 1];
            const Segment& after = contour[kb + 1];
            if (length(before) < reach || length(after) < reach) break;
            const ZR p = pointAt(before, length(before) - reach), q = pointAt(after, reach);
            const Segment chord = lineSegment(p, q);
            if (!reaches(g, chord, side_)) continue;
            bool clear = true;
            for (const auto& e : chain_)
                for (const ZR x : crossings(e, chord))
                    clear = clear && (dist(x, p) < 1e-7 || dist(x, q) < 1e-7);
            // Nor under what it skips (a convex arc it ends on bulges over it).
            std::vector<Segment> skipped(contour.begin() + static_cast<long>(ka), contour.begin() + static_cast<long>(kb) + 1);
            if (dist(p, before.b) > 1e-9) skipped.push_back(piece(before, p, before.b));
            if (dist(after.a, q) > 1e-9) skipped.push_back(piece(after, after.a, q));
            clear = clear && !overChord(skipped, chord);
            if (!clear) continue;
            const Segment head = piece(before, before.a, p), tail = piece(after, q, after.b);
            contour.erase(contour.begin() + static_cast<long>(ka) - 1, contour.begin() + static_cast<long>(kb) + 2);
            contour.insert(contour.begin() + static_cast<long>(ka) - 1, {head, chord, tail});
            left.push_back(d_.edges[i].id + (j - i > 1 ? "…" + d_.edges[j - 1].id : ""));
            break;
        }
        i = j;
    }
    if (!left.empty())
        note(fmt::format("{} of the grinding allowance cannot be followed by {} and is left (the finishing contour "
                         "crosses it); cut it with a form tool or grind it out",
                         fmt::join(left, ", "), toolWords(tool)));
}

void Planner::reachableCorners(std::vector<Segment>& contour, double rn)
{
    // A line shorter than two nose radii into a concave corner: the
    // contour runs from its start straight to the point two nose radii
    // on (through whatever lines and arcs follow), or to the first
    // outside corner before it.
    for (std::size_t k = 0; k + 1 < contour.size(); ++k) {
        const Segment& A = contour[k];
        if (A.arc || length(A) >= 2.0 * rn) continue;
        const ZR ta = tangentAtEnd(A), tb = tangentAtStart(contour[k + 1]);
        if (cross(ta, tb) * (inner_ ? -1.0 : 1.0) >= -1e-9) continue;  // a left turn (outer) goes round the material: convex
        // Two nose radii on, or the first outside corner before that: a
        // chord past an outside corner would cut through the material
        // the corner holds.
        const auto convexAfter = [&](std::size_t e) {
            return e + 1 < contour.size() &&
                   cross(tangentAtEnd(contour[e]), tangentAtStart(contour[e + 1])) * (inner_ ? -1.0 : 1.0) > 1e-9;
        };
        double left = 2.0 * rn;
        std::size_t m = k + 1;
        while (m < contour.size() && length(contour[m]) <= left && !convexAfter(m)) left -= length(contour[m++]);
        if (m >= contour.size()) break;
        const bool corner = length(contour[m]) <= left && convexAfter(m);
        const ZR q = corner ? contour[m].b : pointAt(contour[m], left);
        const Segment chord = lineSegment(A.a, q);
        std::vector<Segment> skipped(contour.begin() + static_cast<long>(k), contour.begin() + static_cast<long>(m));
        if (corner) skipped.push_back(contour[m]);
        else if (dist(contour[m].a, q) > 1e-9) skipped.push_back(piece(contour[m], contour[m].a, q));
        if (overChord(skipped, chord)) continue;  // it would cut what it skips
        if (corner) {
            contour.erase(contour.begin() + static_cast<long>(k), contour.begin() + static_cast<long>(m) + 1);
            contour.insert(contour.begin() + static_cast<long>(k), chord);
        } else {
            const Segment rest = piece(contour[m], q, contour[m].b);
            contour.erase(contour.begin() + static_cast<long>(k), contour.begin() + static_cast<long>(m) + 1);
            contour.insert(contour.begin() + static_cast<long>(k), {chord, rest});
        }
    }
    for (int guard = 0; guard < 1000; ++guard) {
        bool changed = false;
        for (std::size_t k = 0; k + 1 < contour.size() && !changed; ++k) {
            Segment& A = contour[k];
            Segment& B = contour[k + 1];
            if (A.arc || B.arc) continue;
            const ZR ta = unit(A.b - A.a), tb = unit(B.b - B.a);
            const double turn = cross(ta, tb) * (inner_ ? -1.0 : 1.0);
            if (turn >= -1e-9) continue;  // straight on or convex: concave turns toward the air
            // Where the nose centre sits against both lines.
            const Curve ca = lineThrough(A.a + rn * airNormal(ta), ta), cb = lineThrough(B.a + rn * airNormal(tb), tb);
            const auto hit = intersections(ca, cb);
            if (hit.empty()) continue;
            const double onA = dot(hit.front() - (A.a + rn * airNormal(ta)), ta);
            const double onB = dot(hit.front() - (B.a + rn * airNormal(tb)), tb);
            const double lenA = dist(A.a, A.b), lenB = dist(B.a, B.b);
            if (onA >= -1e-9 && onB <= lenB + 1e-9) continue;
            if (onA < -1e-9) {
                // A is too short: from A's start to where the nose touches B, a little further on.
                const double along = std::min(lenB, std::max(onB, 0.0) + 0.05);
                const ZR q = B.a + along * tb;
                A = lineSegment(A.a, q);
                if (along >= lenB - 1e-9) contour.erase(contour.begin() + static_cast<long>(k) + 1);
                else B = lineSegment(q, B.b);
            } else {
                // B is too short: from where the nose touches A straight to B's end.
                const double along = std::max(0.0, std::min(lenA, onA) - 0.05);
                const ZR q = A.a + along * ta;
                B = lineSegment(q, B.b);
                if (along <= 1e-9) contour.erase(contour.begin() + static_cast<long>(k));
                else A = lineSegment(A.a, q);
            }
            changed = true;
            }
        if (!changed) break;
    }
}

}  // namespace taiwa::turning::planner
