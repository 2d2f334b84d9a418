// Turning steps: the finishing contour where the nose cannot follow the
// profile (turn_planner.h): concave arcs tighter than the nose bridged
// where the nose touches both neighbours, and concave corners next to an
// arc whose elements are too short to hold the nose; every concave corner
// checked as the control's compensation holds it (unheldCorner), and the
// nose measured along the contour (docs/turning.md, "Finishing").
#include "modules/turn/turn_planner.h"

namespace taiwa::turning::planner {

namespace {

// The foot of `p` on the curve `s` lies on.
ZR footOn(const Segment& s, ZR p)
{
    if (s.arc) return s.centre + s.radius * unit(p - s.centre);
    const ZR t = unit(s.b - s.a);
    return s.a + dot(p - s.a, t) * t;
}

// The distance of `p` to the segment `s`.
double distanceTo(const Segment& s, ZR p)
{
    if (s.arc) {
        if (dist(p, s.centre) > 1e-12 && contains(s, s.centre + s.radius * unit(p - s.centre), 1e-7))
            return std::abs(dist(p, s.centre) - s.radius);
        return std::min(dist(p, s.a), dist(p, s.b));
    }
    const ZR d = s.b - s.a;
    const double l2 = dot(d, d);
    const double t = l2 > 0.0 ? std::clamp(dot(p - s.a, d) / l2, 0.0, 1.0) : 0.0;
    return dist(p, s.a + t * d);
}

}  // namespace

std::optional<NoseIntoPart> Planner::noseIntoPart(const std::vector<Segment>& contour, double rn, std::optional<ZR> exitTo,
                                                  bool withEntry) const
{
    const int air = inner_ ? 1 : -1;
    std::vector<std::optional<Segment>> centres;
    for (const Segment& s : contour) centres.push_back(offset(s, rn, air));
    // The exit: from the last offset's end straight to where it is programmed.
    if (exitTo && centres.back()) centres.push_back(lineSegment(centres.back()->b, *exitTo));
    // The edge followed there, or for a line or chord of the contour's own
    // (the entry and the exit too) the edge the nose cuts.
    const auto edgeOf = [&](const Segment& s, std::size_t cut) {
        for (std::size_t i = first_; i < last_; ++i)
            if (dist(chain_[i].a, s.a) < 1e-7 && dist(chain_[i].b, s.b) < 1e-7) return d_.edges[i].id;
        return d_.edges[cut].id;
    };
    std::optional<NoseIntoPart> worst;
    // The part as the verification closes it: the deformed profile, its
    // ends joined to the axis (outer) or out past the bar (inner).
    std::vector<Segment> part = chain_;
    const double rClose = inner_ ? R_ + 5.0 : 0.0;
    const ZR a0 = chain_.front().a, b0 = chain_.back().b;
    if (std::abs(b0.r - rClose) > 1e-9) part.push_back(lineSegment(b0, {b0.z, rClose}));
    if (std::abs(a0.r - rClose) > 1e-9) part.push_back(lineSegment({a0.z, rClose}, a0));
    // The nose centre's run along `centre` from `from` to `to`, against the
    // whole part (its faces too: the entry and the exit pass them).
    // `whole`: against the whole part (the entry, the exit and the step
    // from the entry onto the contour); else against the turned contour's
    // own edges.
    const auto sample = [&](const Segment& centre, double from, double to, const Segment& along, bool whole = false) {
        const int n = std::max(8, static_cast<int>((to - from) / 0.02));
        for (int i = 0; i <= n && to > from; ++i) {
            const ZR c = pointAt(centre, from + (to - from) * i / n);
            for (std::size_t j = whole ? 0 : first_; j < (whole ? part.size() : last_); ++j) {
                const double depth = rn - distanceTo(part[j], c);
                if (depth > 2e-3 && (!worst || depth > worst->depth))
                    worst = NoseIntoPart{depth, c, edgeOf(along, j < chain_.size() ? j : dist(part[j].b, a0) < 1e-9 ? 0 : chain_.size() - 1)};
            }
        }
    };
    // The nose centre's run along each element: from where it meets the
    // previous one's at a concave corner to where it meets the next's.
    const std::size_t n = contour.size();
    std::vector<double> from(n, 0.0), to(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) to[k] = centres[k] ? length(*centres[k]) : 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (!centres[k] || !centres[k + 1]) continue;
        if (s_ * cross(tangentAtEnd(contour[k]), tangentAtStart(contour[k + 1])) >= -1e-9) continue;  // convex: rolls round
        const auto c = nearest(intersections(curveOf(*centres[k]), curveOf(*centres[k + 1])), contour[k].b);
        if (c && contains(*centres[k], *c, 1e-6)) to[k] = parameterOf(*centres[k], *c);
        if (c && contains(*centres[k + 1], *c, 1e-6)) from[k + 1] = parameterOf(*centres[k + 1], *c);
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (!centres[k] || exitTo) continue;  // the exit is measured alone
        sample(*centres[k], from[k], to[k], contour[k], withEntry && k == 0);
        // Where the entry's offset and the first element's do not cross at
        // a concave corner, the nose centre goes straight from the one's
        // end to the other's start.
        if (withEntry && k == 0 && k + 1 < n && centres[k + 1]) {
            const ZR a = pointAt(*centres[k], to[k]), b = pointAt(*centres[k + 1], from[k + 1]);
            if (dist(a, b) > 1e-6 && s_ * cross(tangentAtEnd(contour[k]), tangentAtStart(contour[k + 1])) < -1e-9)
                sample(lineSegment(a, b), 0.0, dist(a, b), lineSegment(contour[k].b, contour[k + 1].a), true);
        }
    }
    if (centres.size() > contour.size())
        sample(*centres.back(), 0.0, length(*centres.back()), lineSegment(contour.back().b, *exitTo), true);
    return worst;
}

std::optional<std::size_t> Planner::unheldCorner(const std::vector<Segment>& contour, double rn) const
{
    const int air = inner_ ? 1 : -1;
    const std::size_t n = contour.size();
    std::vector<std::optional<Segment>> centres;
    for (const Segment& s : contour) centres.push_back(offset(s, rn, air));
    std::vector<double> from(n, 0.0), to(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
        if (!centres[k]) return k;  // a concave arc tighter than the nose
        to[k] = length(*centres[k]);
    }
    for (std::size_t k = 0; k + 1 < n; ++k) {
        if (s_ * cross(tangentAtEnd(contour[k]), tangentAtStart(contour[k + 1])) >= -1e-9) continue;  // convex: rolls round
        const auto c = nearest(intersections(curveOf(*centres[k]), curveOf(*centres[k + 1])), contour[k].b);
        if (!c || !contains(*centres[k], *c, 1e-6)) return k;
        if (!contains(*centres[k + 1], *c, 1e-6)) return k + 1;
        to[k] = parameterOf(*centres[k], *c);
        from[k + 1] = parameterOf(*centres[k + 1], *c);
    }
    for (std::size_t k = 0; k < n; ++k)
        if (from[k] > to[k] + 1e-6) return k;
    return std::nullopt;
}

bool Planner::mergeUnheldElements(std::vector<Segment>& contour, double rn)
{
    bool any = false;
    const auto replaceable = [&](const Segment& s) { return !s.arc || concaveArc(s); };
    for (int guard = 0; guard < 100; ++guard) {
        const auto u = unheldCorner(contour, rn);
        if (!u) break;
        const std::size_t k = *u;
        // The element and the one after it, else the one before it, as one
        // line over both; only a line or concave arc as the neighbour (a
        // convex one bulges over the line).
        const auto merge = [&](std::size_t i) {
            if (i + 1 >= contour.size()) return false;
            const Segment line = lineSegment(contour[i].a, contour[i + 1].b);
            if (length(line) < 1e-6 || overChord({contour[i], contour[i + 1]}, line)) return false;
            contour[i] = line;
            contour.erase(contour.begin() + static_cast<long>(i) + 1);
            return true;
        };
        const bool changed = (k + 1 < contour.size() && (replaceable(contour[k + 1]) || replaceable(contour[k])) && merge(k)) ||
                             (k > 0 && (replaceable(contour[k - 1]) || replaceable(contour[k])) && merge(k - 1));
        if (!changed) break;
        any = true;
        reachableCorners(contour, rn);
    }
    return any;
}

std::string Planner::edgeNear(ZR p) const
{
    std::size_t best = first_;
    for (std::size_t i = first_; i < last_; ++i)
        if (distanceTo(chain_[i], p) < distanceTo(chain_[best], p)) best = i;
    return d_.edges[best].id;
}

bool Planner::overChord(const std::vector<Segment>& skipped, const Segment& chord) const
{
    const ZR d = unit(chord.b - chord.a);
    for (const Segment& e : skipped)
        for (int i = 0; i <= 16; ++i) {
            const ZR x = pointAt(e, length(e) * i / 16.0);
            // The material lies left of the travel outside, right of it in a bore.
            if (s_ * cross(d, x - chord.a) < -1e-6) return true;
        }
    return false;
}

std::optional<ZR> Planner::ontoConvex(const Segment& A, const Segment& B, double rn) const
{
    if (!A.arc || concaveArc(A)) return std::nullopt;
    // From A's end back, 10 µm at a time, the first point q where the line
    // q → B.b turns into the air from A (the rest of A lies under it) by an
    // angle whose corner the nose holds on both (with 10 µm to spare).
    const double total = length(A);
    for (double back = 0.01; back < total - 1e-9; back += 0.01) {
        const ZR q = pointAt(A, total - back);
        const Segment line = lineSegment(q, B.b);
        const double l = length(line);
        if (l < 1e-6) continue;
        const ZR ta = tangentAt(A, q), tl = unit(B.b - q);
        if (s_ * cross(ta, tl) >= 0.0) continue;  // not a concave turn (into the air)
        const double phi = std::acos(std::clamp(dot(ta, tl), -1.0, 1.0));
        const double hold = rn * std::tan(phi / 2.0) + 0.01;
        if (hold > l || hold > total - back) continue;
        if (overChord({piece(A, q, A.b)}, line)) continue;
        return q;
    }
    return std::nullopt;
}

bool Planner::concaveArc(const Segment& s) const { return s.arc && (s.ccw ? 1.0 : -1.0) * s_ < 0; }

void Planner::bridgeTightArcs(std::vector<Segment>& contour, double rn, const Tool& tool)
{
    // The nose placed a little wider than it is (2 µm): the lines it is
    // programmed along then hold it with room to spare, as the control's
    // compensation wants.
    const double rb = rn + 0.002;
    const int air = inner_ ? 1 : -1;  // the air side of the travel (offset's side)
    std::vector<std::string> left;
    double thickest = 0.0;
    for (std::size_t k = 1; k + 1 < contour.size(); ++k) {
        const Segment arc = contour[k];
        if (!concaveArc(arc) || arc.radius > rn + 1e-3) continue;
        const Segment A = contour[k - 1], B = contour[k + 1];
        std::string id = "a concave arc";
        for (std::size_t i = first_; i < last_; ++i)
            if (dist(chain_[i].a, arc.a) < 1e-7 && dist(chain_[i].b, arc.b) < 1e-7) id = d_.edges[i].id;
        // The nose centre against both neighbours, nearest the arc.
        const auto oa = offset(A, rb, air), ob = offset(B, rb, air);
        std::optional<ZR> c;
        if (oa && ob) c = nearest(intersections(curveOf(*oa), curveOf(*ob)), arc.centre);
        bool bridged = false;
        if (c && dist(*c, arc.centre) < 4.0 * rn) {
            const ZR p1 = footOn(A, *c), p2 = footOn(B, *c);
            const ZR t1 = tangentAt(A, p1), t2 = tangentAt(B, p2);
            const auto hit = intersections(lineThrough(p1, t1), lineThrough(p2, t2));
            if (contains(A, p1, 1e-7) && contains(B, p2, 1e-7) && !hit.empty() && dot(hit.front() - p1, t1) > 0 &&
                dot(p2 - hit.front(), t2) > 0) {
                const ZR t = hit.front();
                std::vector<Segment> bridge;
                if (A.arc) {
                    if (dist(A.a, p1) > 1e-9) bridge.push_back(piece(A, A.a, p1));
                    bridge.push_back(lineSegment(p1, t));
                } else {
                    bridge.push_back(lineSegment(A.a, t));
                }
                if (B.arc) {
                    bridge.push_back(lineSegment(t, p2));
                    if (dist(p2, B.b) > 1e-9) bridge.push_back(piece(B, p2, B.b));
                } else {
                    bridge.push_back(lineSegment(t, B.b));
                }
                contour.erase(contour.begin() + static_cast<long>(k) - 1, contour.begin() + static_cast<long>(k) + 2);
                contour.insert(contour.begin() + static_cast<long>(k) - 1, bridge.begin(), bridge.end());
                // The most the nose (rn, where the lines hold it) leaves: on
                // the line from its centre through the arc's centre.
                thickest = std::max(thickest, dist(*c, arc.centre) + arc.radius - rn);
                bridged = true;
            }
        }
        if (!bridged) {
            // No place where the nose touches both (a neighbour too short):
            // across the arc's chord, which lies in the air; the corners at
            // its ends are reachableCorners'.
            contour[k] = lineSegment(arc.a, arc.b);
            thickest = std::max(thickest, arc.radius);
        }
        left.push_back(fmt::format("{} (R{})", id, len(arc.radius)));
    }
    if (!left.empty())
        note(fmt::format("{} is tighter than the nose R{} of {}: the finishing contour bridges it where the nose touches "
                         "both neighbours and leaves up to {} of material in the corner; cut it with a smaller nose or "
                         "a form tool",
                         fmt::join(left, ", "), len(rn), toolWords(tool), len(thickest)));
}

bool Planner::reachableArcCorners(std::vector<Segment>& contour, double rn)
{
    bool any = false;
    const int air = inner_ ? 1 : -1;
    const auto replaceable = [&](const Segment& s) { return !s.arc || concaveArc(s); };
    for (int guard = 0; guard < 1000; ++guard) {
        bool changed = false;
        for (std::size_t k = 0; k + 1 < contour.size() && !changed; ++k) {
            const Segment A = contour[k], B = contour[k + 1];
            if (!A.arc && !B.arc) continue;  // reachableCorners'
            if (cross(tangentAtEnd(A), tangentAtStart(B)) * (inner_ ? -1.0 : 1.0) >= -1e-9) continue;  // convex
            const auto oa = offset(A, rn, air), ob = offset(B, rn, air);
            std::optional<ZR> c;
            if (oa && ob) c = nearest(intersections(curveOf(*oa), curveOf(*ob)), A.b);
            if (!c || dist(*c, A.b) > 4.0 * rn) {
                // Nowhere near the corner does the nose touch both.
                if (!replaceable(A) || !replaceable(B)) continue;
                contour[k] = lineSegment(A.a, B.b);
                contour.erase(contour.begin() + static_cast<long>(k) + 1);
                changed = true;
                continue;
            }
            const bool onA = contains(*oa, *c, 1e-7), onB = contains(*ob, *c, 1e-7);
            if (onA && onB) continue;
            // A line replacing the short one ends on the other only where
            // that is a line or a concave arc (a convex one bulges over it).
            const ZR fb = footOn(B, *c), fa = footOn(A, *c);
            // The short one is replaced by a line to where the nose touches
            // the other; that one may be a convex arc (a relief groove's wall
            // rising out of a convex arc it undercuts) when the piece of it
            // the line leaves out lies under the line, not over it.
            const auto overB = [&](ZR q) { return !replaceable(B) && overChord({piece(B, B.a, q)}, lineSegment(A.a, q)); };
            const auto overA = [&](ZR q) { return !replaceable(A) && overChord({piece(A, q, A.b)}, lineSegment(q, B.b)); };
            const double onward = contains(B, fb, 1e-7) ? std::min(length(B), parameterOf(B, fb) + 0.05) : 0.0;
            const double before = contains(A, fa, 1e-7) ? std::max(0.0, parameterOf(A, fa) - 0.05) : 0.0;
            if (!onA && replaceable(A) && contains(B, fb, 1e-7) && !overB(pointAt(B, onward))) {
                // A too short: from its start to where the nose touches B, a little on.
                const double at = onward;
                const ZR q = pointAt(B, at);
                contour[k] = lineSegment(A.a, q);
                if (at >= length(B) - 1e-9) contour.erase(contour.begin() + static_cast<long>(k) + 1);
                else contour[k + 1] = piece(B, q, B.b);
                changed = true;
            } else if (!onB && replaceable(B) && contains(A, fa, 1e-7) && !overA(pointAt(A, before))) {
                // B too short: from where the nose touches A, a little before, straight to B's end.
                const double at = before;
                const ZR q = pointAt(A, at);
                contour[k + 1] = lineSegment(q, B.b);
                if (at <= 1e-9) contour.erase(contour.begin() + static_cast<long>(k));
                else contour[k] = piece(A, A.a, q);
                changed = true;
            } else if (replaceable(A) && replaceable(B)) {
                // Both too short: one line across both (in the air: lines and concave arcs).
                contour[k] = lineSegment(A.a, B.b);
                contour.erase(contour.begin() + static_cast<long>(k) + 1);
                changed = true;
            } else if (const auto q = ontoConvex(A, B, rn); q && !onB && replaceable(B)) {
                // B too short after a convex arc whose end the nose cannot
                // hold B against (an allowance's side stepping up behind a
                // picked rounding): from the arc, where the line stays over
                // it, straight to B's end.
                contour[k + 1] = lineSegment(*q, B.b);
                contour[k] = piece(A, A.a, *q);
                changed = true;
            }
        }
        if (!changed) break;
        any = true;
    }
    return any;
}

}  // namespace taiwa::turning::planner
