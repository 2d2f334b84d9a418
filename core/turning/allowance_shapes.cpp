// The grinding allowance's shapes per row (allowance_deformer.h): where a
// picked edge's allowance starts and ends at each of its ends and the shape
// laid on it. The relief grooves at its concave corners: allowance_grooves.cpp.
#include "turning/allowance_deformer.h"

namespace taiwa::turning::deform {

End Deformer::endOf(std::size_t k, int i, bool atStart, const Segment& pm)
{
    const Segment& P = p_.edges[i].geometry;
    const double a = rows_[k].allowance;
    const int ni = atStart ? i - 1 : i + 1;
    const ZR v = atStart ? P.a : P.b;
    End e;
    e.foot = v;
    e.onMoved = v + a * outward(P, v);
    e.side = lineSegment(e.foot, e.onMoved);
    if (ni < 0 || ni >= static_cast<int>(p_.edges.size())) return e;  // free end
    e.neighbour = ni;
    const Segment& N = p_.edges[ni].geometry;
    const ZR in = atStart ? tangentAtEnd(N) : tangentAtEnd(P);
    const ZR out = atStart ? tangentAtStart(P) : tangentAtStart(N);
    const double theta = partAngle(in, out);
    EndOutcome& oc = e.outcome;
    oc.angle = theta;
    oc.neighbour = p_.edges[ni].id;
    const int nRow = edgeRow_[ni];
    const bool tangent = std::abs(theta - 180.0) <= kAngleTolDeg;
    const Curve movedCurve = curveOf(pm);
    if (nRow >= 0 && theta < 180.0 - kAngleTolDeg) {
        oc.joint = Joint::BothSet;
        const auto nm = moved(ni, rows_[nRow].allowance);
        const auto x = nm ? nearest(intersections(movedCurve, curveOf(*nm)), e.onMoved) : std::nullopt;
        if (!x) {
            problem(k, "allowance",
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                     "allowance row {}: the moved {} and the moved {} do not meet"),
                                k + 1, p_.edges[i].id, oc.neighbour));
            return e;
        }
        e.onMoved = *x;
        e.side = lineSegment(v, *x);
    } else if (tangent) {
        oc.joint = Joint::Tangent;
        if (nRow >= 0) {
            oc.adjustmentFrom = "none: the neighbour is ground too";
        } else {
            double adj = 0.0;
            if (rows_[k].adjustment) {
                adj = *rows_[k].adjustment;
                oc.adjustmentFrom = "typed";
            } else if (o_.noseRadius) {
                adj = *o_.noseRadius;
                oc.adjustmentFrom = "nose radius of " + o_.toolName;
            } else {
                problem(k, "adjustment",
                        fmt::format(
                            TAIWA_TRANSLATE_NOOP(
                                "taiwa::msg",
                                "allowance row {}: {} meets {} at a tangent joint, where the tool's nose radius "
                                "leaves a ridge; give the adjustment, or add a finishing turning tool to the "
                                "library so that its nose radius is taken"),
                            k + 1, p_.edges[i].id, oc.neighbour));
                return e;
            }
            if (adj >= length(P) - kPointTol) {
                problem(
                    k, "adjustment",
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                     "allowance row {}: an adjustment of {} is not shorter than {} "
                                                     "({} long)"),
                                k + 1, len(adj), p_.edges[i].id, len(length(P))));
                return e;
            }
            oc.adjustment = adj;
            e.foot = pointAt(P, atStart ? adj : length(P) - adj);
            e.onMoved = e.foot + a * outward(P, e.foot);
            e.side = lineSegment(e.foot, e.onMoved);
        }
    } else if (theta <= 90.0 + kAngleTolDeg) {
        oc.joint = Joint::UpTo90;
    } else if (theta < 180.0) {
        oc.joint = Joint::Obtuse;
        // The neighbour's tangent carried on past the vertex.
        const ZR dir = atStart ? in : -1.0 * out;
        std::vector<ZR> ahead;
        for (ZR x : intersections(lineThrough(v, dir), movedCurve))
            if (dot(x - v, dir) > 0.0) ahead.push_back(x);
        const auto x = nearest(ahead, v);
        if (!x) {
            problem(
                k, "allowance",
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                 "allowance row {}: the tangent of {} does not reach the moved {}"),
                            k + 1, oc.neighbour, p_.edges[i].id));
            return e;
        }
        e.onMoved = *x;
        e.side = lineSegment(v, *x);
    } else {
        oc.joint = Joint::Concave;
        std::vector<ZR> onN;
        for (ZR x : intersections(curveOf(N), movedCurve))
            if (contains(N, x) && dist(x, v) > kPointTol) onN.push_back(x);
        const auto x = nearest(onN, v);
        if (!x) {
            problem(k, "allowance",
                    fmt::format(TAIWA_TRANSLATE_NOOP(
                                    "taiwa::msg",
                                    "allowance row {}: an allowance of {} on {} reaches past the end of its "
                                    "neighbour {} ({} long); the edges would cross"),
                                k + 1, len(a), p_.edges[i].id, oc.neighbour, len(length(N))));
            return e;
        }
        e.onMoved = *x;
        e.side = atStart ? reversed(piece(N, *x, v)) : piece(N, v, *x);
        if (theta <= 270.0 + kAngleTolDeg) {
            e.grooveCorner = *x;
            if (nRow >= 0) {
                const auto nm = moved(ni, rows_[nRow].allowance);
                if (const auto q = nm ? nearest(intersections(movedCurve, curveOf(*nm)), *x) : std::nullopt)
                    e.grooveCorner = *q;
            }
        }
    }
    return e;
}

// The allowance shape of row k, its sources and its grooves.
void Deformer::shapeOf(std::size_t k)
{
    const int i = rowEdge_[k];
    const Edge& edge = p_.edges[i];
    const Segment& P = edge.geometry;
    const double a = rows_[k].allowance;
    AllowanceOutcome oc{edge.id, a, {}, {}};
    const auto pmFull = moved(i, a);
    if (!pmFull) {
        problem(k, "allowance",
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                 "allowance row {}: {} is an arc of radius {}; an allowance of {} "
                                                 "leaves it no radius"),
                            k + 1, edge.id, len(P.radius), len(a)));
        return;
    }
    const std::size_t before = out_.problems.size();
    End s = endOf(k, i, true, *pmFull);
    End e = endOf(k, i, false, *pmFull);
    oc.start = s.outcome;
    oc.end = e.outcome;
    if (out_.problems.size() != before) return;
    if (signedParameter(*pmFull, s.onMoved) >= signedParameter(*pmFull, e.onMoved) - kPointTol) {
        problem(k, "allowance",
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                 "allowance row {}: with an allowance of {} the moved {} vanishes "
                                                 "between its neighbours; the edges would cross"),
                            k + 1, len(a), edge.id));
        return;
    }
    // A straight side that crosses the moved edge once more before it meets
    // it makes the shape's loop cross itself, which the booleans cannot
    // take: a concave arc's moved circle runs nearly along the side where
    // they meet (seed 5444 of the generated lathe parts: moved E2, R3.21,
    // crosses its side to moved E1 0.1 mm short of their meeting point). The
    // shape then closes at that crossing. The lobe cut off lies beyond the
    // side: in the neighbour's own shape when both are ground (their side is
    // one line, which names the piece between), else past the neighbour's
    // surface carried on, where no allowance belongs.
    const auto closeAtCrossing = [&](End& end, bool atStart) {
        if (end.side.arc) return;
        const Segment whole = piece(*pmFull, s.onMoved, e.onMoved);
        std::optional<double> at;
        for (const ZR c : crossings(end.side, whole)) {
            if (dist(c, end.onMoved) <= kPointTol || dist(c, end.foot) <= kPointTol) continue;
            const double t = parameterOf(whole, c);
            if (!at || (atStart ? t > *at : t < *at)) at = t;
        }
        if (!at) return;
        end.onMoved = pointAt(whole, *at);
        end.side = lineSegment(end.foot, end.onMoved);
    };
    closeAtCrossing(s, true);
    closeAtCrossing(e, false);
    const Segment movedEdge = piece(*pmFull, s.onMoved, e.onMoved);
    for (std::size_t j = 0; j < p_.edges.size(); ++j) {
        const int ji = static_cast<int>(j);
        if (ji == i || ji == s.neighbour || ji == e.neighbour) continue;
        if (!crossings(movedEdge, p_.edges[j].geometry).empty()) {
            problem(
                k, "allowance",
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                 "allowance row {}: an allowance of {} moves {} into {}; the edges "
                                                 "would cross"),
                            k + 1, len(a), edge.id, p_.edges[j].id));
            return;
        }
    }
    const double lowest = std::min({movedEdge.a.r, movedEdge.b.r,
                                    movedEdge.arc && contains(movedEdge, {movedEdge.centre.z, movedEdge.centre.r - movedEdge.radius})
                                        ? movedEdge.centre.r - movedEdge.radius
                                        : movedEdge.a.r});
    if (lowest < -kPointTol) {
        problem(k, "allowance",
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                 "allowance row {}: an allowance of {} moves {} past the axis"),
                            k + 1, len(a), edge.id));
        return;
    }
    shapes_.push_back({piece(P, s.foot, e.foot), e.side, reversed(movedEdge), reversed(s.side)});
    sources_.push_back({movedEdge, Origin::Moved, edge.id, edge.id + ".moved", static_cast<int>(k), edge.attributes});
    // A side along a concave neighbour lies on the neighbour itself, which names it.
    if (s.outcome.joint != Joint::Concave)
        sources_.push_back({s.side, Origin::Side, edge.id, edge.id + ".start", static_cast<int>(k), {}});
    if (e.outcome.joint != Joint::Concave)
        sources_.push_back({e.side, Origin::Side, edge.id, edge.id + ".end", static_cast<int>(k), {}});
    groove(k, i, true, s, oc.start, movedEdge);
    groove(k, i, false, e, oc.end, movedEdge);
    out_.profile.rows.push_back(oc);
}

}  // namespace taiwa::turning::deform
