// The grinding allowance (allowance.h): allowance shapes per row, relief
// grooves, the union and the reading back of the deformed chain.
#include "turning/allowance.h"
#include "model/translate_noop.h"

#include "check/messages.h"
#include "occt/profile_boolean.h"
#include "model/turned_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace taiwa::turning {

namespace {

// A curve of the deformed profile may lie on, in the order of preference when
// a piece lies on more than one.
struct Source {
    Segment s;
    Origin origin = Origin::Original;
    std::string from;
    std::string id;
    int row = -1;
    EdgeAttributes attributes;
    bool closure = false;
};

// Arc length from the start of `s` to p, negative for points before its start.
double signedParameter(const Segment& s, ZR p)
{
    const double t = parameterOf(s, p);
    if (!s.arc) return t;
    const double full = 2.0 * std::numbers::pi * s.radius, len = length(s);
    return t > len + 0.5 * (full - len) ? t - full : t;
}

bool sameCurve(const Segment& x, const Segment& y)
{
    if (x.arc != y.arc) return false;
    if (x.arc) return x.ccw == y.ccw && dist(x.centre, y.centre) < 1e-6 && std::abs(x.radius - y.radius) < 1e-6;
    const ZR d = unit(x.b - x.a);
    return std::abs(cross(d, unit(y.b - y.a))) < 1e-9 && dot(d, y.b - y.a) > 0.0 && std::abs(cross(d, y.a - x.a)) < 1e-7;
}

// One end of a picked edge, worked out.
struct End {
    EndOutcome outcome;
    ZR foot;        // where the allowance shape starts on the picked edge
    ZR onMoved;     // where it meets the moved edge
    Segment side;   // from foot to onMoved
    std::optional<ZR> grooveCorner;  // a concave corner of 90°-180° (air side)
    int neighbour = -1;
};

class Deformer {
public:
    Deformer(const ResolvedProfile& p, const std::vector<AllowanceRow>& rows, const AllowanceOptions& o)
        : p_(p), rows_(rows), o_(o)
    {
    }

    Deformation run()
    {
        out_.profile.side = p_.side;
        if (p_.edges.empty()) return std::move(out_);
        mapRows();
        double rMax = 0.0, deepest = 0.0;
        for (const auto& e : p_.edges) rMax = std::max({rMax, e.geometry.a.r, e.geometry.b.r, e.geometry.arc ? e.geometry.centre.r + e.geometry.radius : 0.0});
        for (const auto& r : rows_) deepest = std::max({deepest, r.allowance, r.grooveDepth.value_or(0.0)});
        closureRadius_ = rMax + deepest + 1.0;
        part_ = edgesLoop();
        for (const Segment& c : closure(p_, closureRadius_)) part_.push_back(c);
        side_ = signedArea(part_) > 0.0 ? 1 : -1;

        if (out_.problems.empty())
            for (std::size_t k = 0; k < rows_.size(); ++k) shapeOf(k);
        if (!out_.problems.empty() || rows_.empty()) {
            keepProfileUnchanged();
            return std::move(out_);
        }
        readBack();
        if (!out_.problems.empty()) keepProfileUnchanged();
        return std::move(out_);
    }

private:
    std::string len(double mm) const { return msg::quote({mm, o_.shown}); }
    void problem(std::size_t row, const char* key, std::string message)
    {
        out_.problems.push_back({allowanceField(row, key), std::move(message)});
    }

    Loop edgesLoop() const
    {
        Loop l;
        for (const auto& e : p_.edges) l.push_back(e.geometry);
        return l;
    }

    void mapRows()
    {
        edgeRow_.assign(p_.edges.size(), -1);
        rowEdge_.assign(rows_.size(), -1);
        for (std::size_t k = 0; k < rows_.size(); ++k) {
            const AllowanceRow& r = rows_[k];
            int found = -1;
            for (std::size_t i = 0; i < p_.edges.size(); ++i)
                if (p_.edges[i].id == r.edge) found = static_cast<int>(i);
            if (found < 0) {
                problem(k, "edge",
                        fmt::format(
                            TAIWA_TRANSLATE_NOOP("taiwa::msg", "allowance row {}: there is no edge {} in the profile"),
                            k + 1, r.edge.empty() ? "(none given)" : r.edge));
                continue;
            }
            if (edgeRow_[found] >= 0) {
                problem(k, "edge",
                        fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                         "allowance row {}: {} already has an allowance in row {}"),
                                    k + 1, r.edge, edgeRow_[found] + 1));
                continue;
            }
            if (!(r.allowance > 0.0) || !std::isfinite(r.allowance))
                problem(k, "allowance",
                        fmt::format(
                            TAIWA_TRANSLATE_NOOP("taiwa::msg", "allowance row {}: the allowance must be above zero"),
                            k + 1));
            if (r.adjustment && !(*r.adjustment >= 0.0))
                problem(k, "adjustment",
                        fmt::format(
                            TAIWA_TRANSLATE_NOOP("taiwa::msg", "allowance row {}: the adjustment cannot be below zero"),
                            k + 1));
            if (r.grooveWidth && !(*r.grooveWidth > 0.0))
                problem(k, "grooveWidth",
                        fmt::format(
                            TAIWA_TRANSLATE_NOOP("taiwa::msg", "allowance row {}: a groove width must be above zero"),
                            k + 1));
            if (r.grooveDepth && !(*r.grooveDepth > 0.0))
                problem(k, "grooveDepth",
                        fmt::format(
                            TAIWA_TRANSLATE_NOOP("taiwa::msg", "allowance row {}: a groove depth must be above zero"),
                            k + 1));
            edgeRow_[found] = static_cast<int>(k);
            rowEdge_[k] = found;
        }
    }

    // Outward (into the stock) normal of an edge at p.
    ZR outward(const Segment& s, ZR p) const { return static_cast<double>(-side_) * leftNormal(tangentAt(s, p)); }
    // The part's angle at a vertex, from the direction arriving to the one leaving.
    double partAngle(ZR in, ZR out) const { return 180.0 - static_cast<double>(side_) * turnDegrees(in, out); }
    std::optional<Segment> moved(int edge, double a) const { return offset(p_.edges[edge].geometry, a, -side_); }

    End endOf(std::size_t k, int i, bool atStart, const Segment& pm)
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
    void shapeOf(std::size_t k)
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

    void groove(std::size_t k, int i, bool atStart, const End& end, EndOutcome& oc, const Segment& movedEdge)
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

    // The deformed chain from the boundary of the union, each piece named by
    // the curve it lies on.
    void readBack()
    {
        std::vector<Loop> add{part_};
        for (const Loop& s : shapes_) add.push_back(s);
        auto boundary = regionBoundary(add, cuts_);
        // Problems of the union as a whole are the table's, not one row's.
        if (!boundary) {
            out_.problems.push_back({"allowances", boundary.error()});
            return;
        }
        if (boundary->size() != 1) {
            out_.problems.push_back(
                {"allowances",
                 fmt::format(
                     TAIWA_TRANSLATE_NOOP("taiwa::msg", "the allowances and grooves split the part into {} pieces"),
                     boundary->size())});
            return;
        }
        // Preference: moved, side, untouched edges, grooves, picked edges, closure.
        std::vector<Source> order = sources_;
        for (std::size_t j = 0; j < p_.edges.size(); ++j)
            if (edgeRow_[j] < 0) order.push_back({p_.edges[j].geometry, Origin::Original, p_.edges[j].id, p_.edges[j].id, -1, p_.edges[j].attributes});
        for (const Source& g : grooveSources_) order.push_back(g);
        for (std::size_t j = 0; j < p_.edges.size(); ++j)
            if (edgeRow_[j] >= 0) order.push_back({p_.edges[j].geometry, Origin::Original, p_.edges[j].id, p_.edges[j].id, edgeRow_[j], p_.edges[j].attributes});
        for (const Segment& c : closure(p_, closureRadius_)) order.push_back({c, Origin::Original, "", "", -1, {}, true});

        Loop loop = boundary->front();
        if ((signedArea(loop) > 0.0 ? 1 : -1) != side_) {
            Loop r;
            for (auto it = loop.rbegin(); it != loop.rend(); ++it) r.push_back(reversed(*it));
            loop = std::move(r);
        }
        std::vector<int> tag(loop.size(), -1);
        const int axisTag = static_cast<int>(order.size());
        order.push_back({lineSegment({0.0, 0.0}, {1.0, 0.0}), Origin::Original, "", "", -1, {}, true});
        for (std::size_t j = 0; j < loop.size(); ++j) {
            const Segment& piece = loop[j];
            const ZR mid = midpoint(piece);
            // On the axis an outer profile has no edge: a piece there closes it.
            if (p_.side == ProfileSide::Outer && !piece.arc && std::abs(piece.a.r) < kPointTol &&
                std::abs(piece.b.r) < kPointTol) {
                tag[j] = axisTag;
                continue;
            }
            for (std::size_t s = 0; s < order.size() && tag[j] < 0; ++s)
                if (order[s].s.arc == piece.arc && contains(order[s].s, mid, 1e-6) && contains(order[s].s, piece.a, 1e-6) &&
                    contains(order[s].s, piece.b, 1e-6))
                    tag[j] = static_cast<int>(s);
            if (tag[j] < 0) {
                out_.problems.push_back(
                    {"allowances", fmt::format(TAIWA_TRANSLATE_NOOP(
                                                   "taiwa::msg", "internal: a piece of the deformed profile at Z{} X{} "
                                                                 "lies on no edge; please report this job"),
                                               len(mid.z), len(2.0 * mid.r))});
                return;
            }
        }
        // Start right after the closure.
        std::size_t first = 0;
        for (std::size_t j = 0; j < loop.size(); ++j)
            if (order[tag[j]].closure && !order[tag[(j + 1) % loop.size()]].closure) first = (j + 1) % loop.size();
        std::map<std::string, int> seen, grooves;
        auto& edges = out_.profile.edges;
        for (std::size_t n = 0; n < loop.size(); ++n) {
            const std::size_t j = (first + n) % loop.size();
            const Source& src = order[tag[j]];
            if (src.closure) break;
            // Pieces of one origin on one curve make one edge.
            if (!edges.empty() && edges.back().origin == src.origin && edges.back().from == src.from &&
                edges.back().allowanceRow == src.row && sameCurve(edges.back().geometry, loop[j])) {
                edges.back().geometry.b = loop[j].b;
                continue;
            }
            std::string id = src.origin == Origin::Groove ? fmt::format("{}.groove{}", src.from, ++grooves[src.from]) : src.id;
            const int count = ++seen[id];
            if (count > 1) id = fmt::format("{}#{}", id, count);
            edges.push_back({id, loop[j], src.attributes, src.origin, src.from, src.row});
        }
    }

    void keepProfileUnchanged()
    {
        out_.profile.edges.clear();
        for (const auto& e : p_.edges) out_.profile.edges.push_back({e.id, e.geometry, e.attributes, Origin::Original, e.id, -1});
    }

    const ResolvedProfile& p_;
    const std::vector<AllowanceRow>& rows_;
    const AllowanceOptions& o_;
    Deformation out_;
    std::vector<int> edgeRow_, rowEdge_;
    int side_ = 1;  // +1: the part lies left of the direction of travel
    double closureRadius_ = 0.0;
    Loop part_;
    std::vector<Loop> shapes_, cuts_;
    std::vector<Source> sources_, grooveSources_;
};

}  // namespace

Deformation applyAllowances(const ResolvedProfile& profile, const std::vector<AllowanceRow>& rows,
                            const AllowanceOptions& options)
{
    return Deformer(profile, rows, options).run();
}

}  // namespace taiwa::turning
