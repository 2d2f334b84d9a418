// The relief grooves of the grinding allowance (allowance_deformer.h): at a
// concave corner of a picked edge whose air side is 90° up to 180°, the
// groove's kind (typed or identified) and its halves (a lateral or a
// longitudinal groove is one, a ring both and the corner between them),
// each laid in the frame of its own edge from the finished corner with
// that edge's own allowance, and checked. The deformer subtracts them from
// the allowance shapes only (Deformer::readBack), so a groove never takes
// finished material off (docs/turning.md, "Relief grooves").
#include "turning/allowance_deformer.h"

namespace taiwa::turning::deform {

namespace {

// One half of a groove, laid along `edge` from the finished corner.
struct Half {
    const Edge* edge = nullptr;
    ZR u;                    // along the edge, away from the corner
    ZR n;                    // out of the part, square to the edge at the corner
    double allowance = 0.0;  // the edge's own allowance
    double width = 0.0, depth = 0.0;
    double room = 0.0;       // how much of the edge there is for it
    double rise = 0.0;       // an arc edge's rise over its tangent along the groove
};

// The half's trapezoid in its edge's frame at the finished corner v: the
// bottom `depth` below the moved edge, from the corner's normal `width`
// along the edge; the 45° wall up to the moved edge (raised by an arc's
// rise); back at `back` (≤ 0: as far back toward the neighbour as the
// allowance reaches) on the corner's side. The part clips what reaches
// into it.
Loop trapezoid(const Half& h, ZR v, double back)
{
    const double bottom = h.allowance - h.depth, top = h.allowance + h.rise;
    const ZR b0 = v + back * h.u + bottom * h.n;
    const ZR p2 = v + h.width * h.u + bottom * h.n;
    const ZR p1 = v + (h.width + h.depth + h.rise) * h.u + top * h.n;
    const ZR t0 = v + back * h.u + top * h.n;
    return {lineSegment(b0, p2), lineSegment(p2, p1), lineSegment(p1, t0), lineSegment(t0, b0)};
}

std::optional<ZR> meet(ZR p, ZR dp, ZR q, ZR dq)
{
    const auto x = intersections(lineThrough(p, dp), lineThrough(q, dq));
    return x.empty() ? std::nullopt : std::optional<ZR>(x.front());
}

// A ring's corner between its halves: the parallelogram between the two
// bottoms and the two moved edges. None when the edges are so near in line
// that it would reach far from the corner (the halves cover it then).
std::optional<Loop> ringCorner(const Half& a, const Half& b, ZR v)
{
    const ZR ab = v + (a.allowance - a.depth) * a.n, at = v + a.allowance * a.n;
    const ZR bb = v + (b.allowance - b.depth) * b.n, bt = v + b.allowance * b.n;
    const auto c = meet(ab, a.u, bb, b.u), p = meet(ab, a.u, bt, b.u), q = meet(at, a.u, bt, b.u),
               r = meet(bb, b.u, at, a.u);
    if (!c || !p || !q || !r) return std::nullopt;
    const double reach = 4.0 * std::max({a.width + a.depth, b.width + b.depth});
    for (ZR x : {*c, *p, *q, *r})
        if (dist(x, v) > reach) return std::nullopt;
    return Loop{lineSegment(*c, *p), lineSegment(*p, *q), lineSegment(*q, *r), lineSegment(*r, *c)};
}

// The kind of a groove not typed: the neighbour ground too → ring; else by
// the picked edge's direction.
void identify(GrooveMade& g, const Edge& pe, const Edge& ne, bool neighbourGround, ZR uP)
{
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

// What a groove's loops reach that they may not: an edge of the profile but
// the two at its corner (its id), or the axis of an outer profile ("").
std::optional<std::string> reachedBeyond(const std::vector<Loop>& loops, const ResolvedProfile& p, int i, int neighbour)
{
    for (const Loop& l : loops)
        for (const Segment& s : l) {
            for (std::size_t j = 0; j < p.edges.size(); ++j) {
                const int ji = static_cast<int>(j);
                if (ji != i && ji != neighbour && !crossings(s, p.edges[j].geometry).empty()) return p.edges[j].id;
            }
            if (p.side == ProfileSide::Outer && std::min(s.a.r, s.b.r) < kPointTol) return std::string();
        }
    return std::nullopt;
}

}  // namespace

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
    const int nRow = edgeRow_[end.neighbour];
    const bool neighbourGround = nRow >= 0;
    GrooveMade g;
    g.width = *row.grooveWidth;
    g.depth = row.grooveDepth.value_or(row.allowance);
    g.corner = *end.grooveCorner;
    // Directions along each edge away from the corner, and out of the part.
    const ZR uP = atStart ? tangentAtStart(pe.geometry) : -1.0 * tangentAtEnd(pe.geometry);
    const ZR uN = atStart ? -1.0 * tangentAtEnd(ne.geometry) : tangentAtStart(ne.geometry);
    const ZR v = atStart ? pe.geometry.a : pe.geometry.b;
    const bool pAxial = std::abs(uP.z) >= std::abs(uN.z);
    g.kind = row.groove;
    if (g.kind == GrooveKind::Auto) identify(g, pe, ne, neighbourGround, uP);
    // Each half takes its own edge's allowance, and its own row's width and
    // depth where that row gives them.
    const double w = g.width;
    Half hp{&pe, uP, outward(pe.geometry, v), row.allowance, w, g.depth, length(movedEdge), 0.0};
    Half hn{&ne, uN, outward(ne.geometry, v), 0.0, w, g.depth,
            dist(*end.grooveCorner, atStart ? ne.geometry.a : ne.geometry.b), 0.0};
    if (neighbourGround) {
        const AllowanceRow& nr = rows_[static_cast<std::size_t>(nRow)];
        hn.allowance = nr.allowance;
        hn.width = nr.grooveWidth.value_or(w);
        hn.depth = nr.grooveDepth.value_or(nr.allowance);
        hn.room = length(ne.geometry);
    }
    std::vector<Half*> halves;
    if (g.kind == GrooveKind::Ring)
        halves = pAxial ? std::vector<Half*>{&hp, &hn} : std::vector<Half*>{&hn, &hp};
    else if (g.identified)
        halves = {&hp};  // the one ground edge at the corner
    else
        halves = {(g.kind == GrooveKind::Lateral) == pAxial ? &hp : &hn};
    for (const Half* h : halves)
        if (h == &hn && !neighbourGround) {
            problem(k, "groove",
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                     "allowance row {}: a {} groove at the corner of {} and {} would "
                                                     "lie in {}, which has no grinding allowance; a relief groove "
                                                     "only takes allowance off"),
                                k + 1, toKey(g.kind), pe.id, ne.id, ne.id));
            return;
        }
    g.depth = halves.front() == &hn && halves.size() == 1 ? hn.depth : hp.depth;
    std::vector<Loop> loops;
    for (Half* h : halves) {
        if (h->width + h->depth > h->room + kPointTol) {
            problem(k, "grooveWidth",
                    fmt::format(TAIWA_TRANSLATE_NOOP(
                                    "taiwa::msg", "allowance row {}: a {} groove {} wide and {} deep takes {} of "
                                                  "{}, which is {} long"),
                                k + 1, toKey(g.kind), len(h->width), len(h->depth), len(h->width + h->depth),
                                h->edge->id, len(h->room)));
            return;
        }
        // An arc curving away from the part (its centre on the air side)
        // rises above its tangent: the groove's top rises with it (at most
        // reach² / R over the groove), so no sliver of allowance is left
        // above the groove.
        const Segment& along = h->edge->geometry;
        if (along.arc && dot(along.centre - v, h->n) > 0.0) {
            const double reach = h->width + h->depth + h->allowance;
            h->rise = reach * reach / std::max(along.radius - h->allowance, kPointTol);
        }
        // Back toward the neighbour as far as the allowance reaches there.
        const double back = std::min(0.0, dot(*end.grooveCorner - v, h->u));
        loops.push_back(trapezoid(*h, v, back));
        g.inEdge += (g.inEdge.empty() ? "" : ", ") + h->edge->id;
    }
    if (g.kind == GrooveKind::Ring)
        if (auto c = ringCorner(*halves[0], *halves[1], v)) loops.push_back(std::move(*c));
    // The groove must stay inside the part: no edge of the profile but the
    // two at its corner may be reached, nor the axis.
    if (const auto reached = reachedBeyond(loops, p_, i, end.neighbour)) {
        problem(k, "grooveDepth",
                reached->empty()
                    ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "allowance row {}: a groove {} deep at {} reaches "
                                                                     "the axis; it is deeper than the part allows"),
                                  k + 1, len(g.depth), pe.id)
                    : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "allowance row {}: a groove {} deep at {} reaches "
                                                                     "{}; it is deeper than the part allows"),
                                  k + 1, len(g.depth), pe.id, *reached));
        return;
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
