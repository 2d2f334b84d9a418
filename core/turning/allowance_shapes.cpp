// The grinding allowance's shapes per row (allowance_deformer.h): where a
// picked edge's allowance starts and ends at each of its ends, the shape
// laid on it, and the relief groove cut at a concave corner.
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

void Deformer::groove(std::size_t k, int i, bool atStart, const End& end, EndOutcome& oc, const Segment& movedEdge)
{
    if (!end.grooveCorner) return;
    const AllowanceRow& row = rows_[k];
    if (row.groove == GrooveKind::None) {
        oc.grooveNote = "none asked for";
        return;
    }
    if (!row.grooveWidth) {
        oc.grooveNote = "none: no groove width given";
        return;
    }
    const Edge& pe = p_.edges[i];
    const Edge& ne = p_.edges[end.neighbour];
    const bool neighbourGround = edgeRow_[end.neighbour] >= 0;
    GrooveMade g;
    g.width = *row.grooveWidth;
    g.depth = row.grooveDepth.value_or(row.allowance);
    g.corner = *end.grooveCorner;
    // Directions along each edge away from the corner, and into the part.
    const ZR uP = atStart ? tangentAtStart(pe.geometry) : -1.0 * tangentAtEnd(pe.geometry);
    const ZR uN = atStart ? -1.0 * tangentAtEnd(ne.geometry) : tangentAtStart(ne.geometry);
    const ZR v = atStart ? pe.geometry.a : pe.geometry.b;
    const ZR mP = -1.0 * outward(pe.geometry, v), mN = -1.0 * outward(ne.geometry, v);
    const bool pAxial = std::abs(uP.z) >= std::abs(uN.z);
    g.kind = row.groove;
    if (g.kind == GrooveKind::Auto) {
        g.identified = true;
        if (neighbourGround) {
            g.kind = GrooveKind::Ring;
            g.rule = "the neighbour " + ne.id + " is ground too";
        } else if (std::abs(uP.r) < 1e-9) {
            g.kind = GrooveKind::Lateral;
            g.rule = pe.id + " runs along the spindle axis";
        } else if (std::abs(uP.z) < 1e-9) {
            g.kind = GrooveKind::Longitudinal;
            g.rule = pe.id + " is square to the spindle axis";
        } else {
            g.kind = std::abs(uP.z) >= std::abs(uP.r) ? GrooveKind::Lateral : GrooveKind::Longitudinal;
            g.rule = pe.id + (g.kind == GrooveKind::Lateral ? " is nearer to the axis direction"
                                                            : " is nearer to square to the axis");
        }
    }
    struct Frame {
        const Edge* edge;
        ZR u, m;
        double room;
    };
    const Frame fp{&pe, uP, mP, length(movedEdge)};
    const Frame fn{&ne, uN, mN, neighbourGround ? length(ne.geometry) : dist(*end.grooveCorner, atStart ? ne.geometry.a : ne.geometry.b)};
    const Frame& axial = pAxial ? fp : fn;
    const Frame& radial = pAxial ? fn : fp;
    std::vector<const Frame*> frames;
    if (g.kind == GrooveKind::Lateral || g.kind == GrooveKind::Ring) frames.push_back(&axial);
    if (g.kind == GrooveKind::Longitudinal || g.kind == GrooveKind::Ring) frames.push_back(&radial);
    const ZR q = g.corner;
    const double w = g.width, d = g.depth;
    std::vector<Loop> loops;
    for (const Frame* f : frames) {
        if (w + d > f->room + kPointTol) {
            problem(k, "grooveWidth",
                    fmt::format(TAIWA_TRANSLATE_NOOP(
                                    "taiwa::msg", "allowance row {}: a {} groove {} wide and {} deep takes {} of "
                                                  "{}, which is {} long"),
                                k + 1, toKey(g.kind), len(w), len(d), len(w + d), f->edge->id, len(f->room)));
            return;
        }
        const ZR p1 = q + (w + d) * f->u, p2 = q + w * f->u + d * f->m, p3 = q + d * f->m;
        loops.push_back({lineSegment(q, p1), lineSegment(p1, p2), lineSegment(p2, p3), lineSegment(p3, q)});
        g.inEdge += (g.inEdge.empty() ? "" : ", ") + f->edge->id;
    }
    if (g.kind == GrooveKind::Ring) {
        const ZR c1 = q + d * axial.m, c2 = q + d * axial.m + d * radial.m, c3 = q + d * radial.m;
        loops.push_back({lineSegment(q, c1), lineSegment(c1, c2), lineSegment(c2, c3), lineSegment(c3, q)});
    }
    // The groove must stay inside the part: no edge of the profile but the
    // two at its corner may be reached, nor the axis.
    for (const Loop& l : loops)
        for (const Segment& s : l) {
            for (std::size_t j = 0; j < p_.edges.size(); ++j) {
                const int ji = static_cast<int>(j);
                if (ji == i || ji == end.neighbour) continue;
                if (!crossings(s, p_.edges[j].geometry).empty()) {
                    problem(k, "grooveDepth",
                            fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                             "allowance row {}: a groove {} deep at {} reaches {}; "
                                                             "it is deeper than the part allows"),
                                        k + 1, len(d), pe.id, p_.edges[j].id));
                    return;
                }
            }
            if (p_.side == ProfileSide::Outer && std::min(s.a.r, s.b.r) < kPointTol) {
                problem(k, "grooveDepth",
                        fmt::format(TAIWA_TRANSLATE_NOOP(
                                        "taiwa::msg", "allowance row {}: a groove {} deep at {} reaches the axis; "
                                                      "it is deeper than the part allows"),
                                    k + 1, len(d), pe.id));
                return;
            }
        }
    const int n = static_cast<int>(std::count_if(sources_.begin(), sources_.end(),
                                                 [&](const Source& s) { return s.origin == Origin::Groove && s.from == pe.id; }));
    int made = 0;
    for (const Loop& l : loops) {
        cuts_.push_back(l);
        for (const Segment& s : l)
            grooveSources_.push_back({s, Origin::Groove, pe.id, fmt::format("{}.groove{}", pe.id, n + ++made),
                                      static_cast<int>(k), {}});
    }
    oc.groove = g;
}

}  // namespace taiwa::turning::deform
