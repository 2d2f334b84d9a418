// The grinding allowance (allowance.h): applyAllowances and the deformer's
// run (allowance_deformer.h): rows mapped to edges, shapes united, the
// deformed chain read back. Each row's shape: allowance_shapes.cpp; its
// relief grooves: allowance_grooves.cpp.
#include "turning/allowance_deformer.h"

#include "check/messages.h"
#include "tools/turning_tools.h"

namespace taiwa::turning::deform {

Deformation Deformer::run()
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

Loop Deformer::edgesLoop() const
{
    Loop l;
    for (const auto& e : p_.edges) l.push_back(e.geometry);
    return l;
}

void Deformer::mapRows()
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

// The deformed chain from the boundary of the union, each piece named by
// the curve it lies on.
void Deformer::readBack()
{
    // The grooves come off the allowance shapes only, never off the part
    // (seed 001: the groove shape is subtracted from the allowance shape).
    std::vector<Loop> add{part_};
    for (const Loop& s : shapes_) add.push_back(s);
    auto boundary = cuts_.empty() ? regionBoundary(add, {}) : regionBoundary(shapes_, cuts_, {part_});
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

void Deformer::keepProfileUnchanged()
{
    out_.profile.edges.clear();
    for (const auto& e : p_.edges) out_.profile.edges.push_back({e.id, e.geometry, e.attributes, Origin::Original, e.id, -1});
}

}  // namespace taiwa::turning::deform

namespace taiwa::turning {

using deform::Deformer;

Deformation applyAllowances(const ResolvedProfile& profile, const std::vector<AllowanceRow>& rows,
                            const AllowanceOptions& options)
{
    return Deformer(profile, rows, options).run();
}

AllowanceOptions allowanceOptions(const TurnedProfile& profile, const std::vector<Tool>& library, LengthUnit shown)
{
    AllowanceOptions o;
    o.shown = shown;
    if (const Tool* t = finishingTurningTool(library, profile.side == ProfileSide::Inner)) {
        o.noseRadius = t->cornerRadius;
        o.toolName = msg::toolName(*t);
    }
    return o;
}

Deformation deformProfile(const TurnedProfile& profile, const ResolvedProfile& resolved, const std::vector<Tool>& library,
                          LengthUnit shown)
{
    return applyAllowances(resolved, profile.allowances, allowanceOptions(profile, library, shown));
}

}  // namespace taiwa::turning
