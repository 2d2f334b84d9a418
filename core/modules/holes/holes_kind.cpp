// The door of module HOLES (a pattern of identical holes): its job-file
// keys, checks, figure, cavity, planning and form, as module_kind.h asks.
// Registered in modules/registry.cpp.
#include "modules/holes/holes.h"
#include "modules/module_kind.h"

#include "io/unit_keys.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace taiwa {

namespace {

const std::vector<std::string> kPatternNames{"single", "line", "grid", "bolt circle", "arc"};
const std::vector<std::string> kHoleNames{"drilled", "tapped", "reamed", "bored"};

// Whether a unit's pattern has a key the patterns named use: written for
// them, and for a pattern this program does not know (a file's values are
// kept, not dropped).
auto usedBy(std::initializer_list<const char*> patterns)
{
    return [names = std::vector<std::string>(patterns.begin(), patterns.end())](const HolePattern& h) {
        const bool known = std::find(kPatternNames.begin(), kPatternNames.end(), h.pattern) != kPatternNames.end();
        return !known || std::find(names.begin(), names.end(), h.pattern) != names.end();
    };
}

// "thread": a tapped hole's thread, written for a tapped hole even when
// not yet chosen; absent, none.
io::UnitKey<HolePattern> threadKey()
{
    return io::keys::custom<HolePattern>(
        {"thread"},
        [](const io::ObjectFields& f, HolePattern& h) {
            if (f.find("thread")) h.thread = f.string("thread").value_or("");
        },
        [](const HolePattern& h, nlohmann::ordered_json& u) {
            if (!h.thread.empty() || h.hole == "tapped") u["thread"] = h.thread;
        });
}

namespace keys = io::keys;
using H = HolePattern;
const io::UnitKeys<HolePattern> kKeys{
    {keys::text("pattern", &H::pattern), keys::required("x", &H::x), keys::required("y", &H::y),
     keys::number("radius", &H::radius, 0.0).when(usedBy({"bolt circle", "arc"})),
     keys::number("angle", &H::angle, 0.0).when(usedBy({"line", "grid", "bolt circle", "arc"})),
     keys::number("pitch", &H::pitch, 0.0).when(usedBy({"line", "grid"})),
     keys::number("pitchY", &H::pitchY, 0.0).when(usedBy({"grid"})),
     keys::number("angularPitch", &H::angularPitch, 0.0).when(usedBy({"arc"})),
     keys::whole("count", &H::count, 1).when(usedBy({"line", "grid", "bolt circle", "arc"})),
     keys::whole("rows", &H::rows, 1).when(usedBy({"grid"})), keys::text("hole", &H::hole),
     keys::number("diameter", &H::diameter, 0.0).when([](const H& h) {
         return h.hole != "tapped" || h.diameter != 0.0;
     }),
     threadKey(), keys::required("depth", &H::depth), keys::pins(&H::tools)}};

// The depth of the finished hole at distance r from its centre: the
// finishing tool's flat tip within its radius, the drill's full depth and
// its point (taken as 90°, the longest usual; the pre-drill of a reamed or
// bored hole as wide as the hole) within the drill's.
double profile(const holes::Depths& d, double r)
{
    double depth = 0.0;
    if (r <= d.finishDiameter / 2.0 && d.finish > 0.0) depth = d.finish;
    const double drill = d.drillDiameter > 0.0 ? d.drillDiameter : d.finishDiameter;
    if (r <= drill / 2.0) depth = std::max(depth, d.drillFull + (drill / 2.0 - r));
    return depth;
}

class HolesKind final : public ModuleKindOf<HolePattern> {
public:
    HolesKind() : ModuleKindOf(&kKeys, checkHolePattern, holes::cyclesPath) {}
    std::vector<std::string> stepKeys() const override { return holes::allStepKeys(); }
    // A cycle a hole.
    double estimateMoves(const Step& step, const Tool&, const TechnologyData&, const PathParameters&) const override
    {
        const auto* holes = step.payload.getIf<HoleCentres>();
        return !holes || holes->centres.empty() ? 10 : static_cast<double>(holes->centres.size()) + 2;
    }
    // Every hole the step's cycle runs at, with the diameter it makes and a
    // tap's pitch (mm whatever the job's unit: metric threads).
    void describeStep(const Step& s, LengthUnit u, nlohmann::ordered_json& j) const override
    {
        const auto* holes = s.payload.getIf<HoleCentres>();
        if (!holes || holes->centres.empty()) return;
        j["holeDiameter"] = io::stepLength(millingOf(s).holeDiameter, u);
        if (holes->threadPitch > 0) j["threadPitch"] = holes->threadPitch;
        j["holes"] = nlohmann::ordered_json::array();
        for (const Point2& h : holes->centres) j["holes"].push_back(io::stepPoint(h, u));
    }
    // Centre drilling, then drilling, then tapping, reaming or boring.
    bool stepWaitsFor(const Step& later, const Step& earlier) const override
    {
        const auto rank = [](const Step& s) {
            return s.kind == StepKind::CentreDrilling ? 0 : s.kind == StepKind::Drilling ? 1 : 2;
        };
        return rank(earlier) < rank(later);
    }

    std::vector<Point2> topPolygon(const ModuleInput& mm) const override { return holes::topPolygon(mm.as<HolePattern>()); }

    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData&) const override
    {
        const HolePattern& h = mm.as<HolePattern>();
        const holes::Depths d = holes::depths(h);
        auto at = std::make_shared<std::vector<Point2>>(holes::positions(h));
        if (at->empty() || !(d.finishDiameter > 0.0)) return std::nullopt;
        std::sort(at->begin(), at->end(), [](Point2 a, Point2 b) { return a.x < b.x; });
        const double r = d.finishDiameter / 2.0;
        Cavity c;
        c.min = {at->front().x - r, 1e300};
        c.max = {at->back().x + r, -1e300};
        for (const Point2& p : *at) c.min.y = std::min(c.min.y, p.y - r), c.max.y = std::max(c.max.y, p.y + r);
        c.depth = profile(d, 0.0);
        // Deepest within `slack` (> 0): the profile nearer the centre; shallowest
        // within |slack|: farther out. The holes lie apart, so the nearest decides.
        c.depthAt = [at, d, r](Point2 q, double slack) {
            const double reach = r + std::abs(slack);
            auto it = std::lower_bound(at->begin(), at->end(), q.x - reach, [](Point2 p, double x) { return p.x < x; });
            double deepest = 0.0;
            for (; it != at->end() && it->x <= q.x + reach; ++it)
                deepest = std::max(deepest, profile(d, std::max(distance(q, *it) - slack, 0.0)));
            return deepest;
        };
        return c;
    }

    ModuleInput makeDefault(const Stock& stock) const override
    {
        HolePattern h;
        h.x = stock.x + stock.width / 2;
        h.y = stock.y + stock.length / 2;
        h.diameter = 8;
        h.depth = std::min(10.0, std::floor(stock.height / 2));
        return h;
    }

protected:
    // The box around the figure (its polygon is topPolygon).
    std::optional<Quad> outline(const HolePattern& mm) const override
    {
        const std::vector<Point2> poly = holes::topPolygon(mm);
        if (poly.empty()) return std::nullopt;
        Point2 lo = poly.front(), hi = poly.front();
        for (const Point2& p : poly) lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)}, hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
        return Quad{{lo, Point2{hi.x, lo.y}, hi, Point2{lo.x, hi.y}}, 0.0};
    }

    void move(HolePattern& h, Point2 delta) const override
    {
        h.x += delta.x;
        h.y += delta.y;
    }

    std::vector<Step> planInput(const HolePattern& mm, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        return planHolePattern(mm, ctx.unit, ctx.library, ctx.material, ctx.shownUnit, out);
    }

    // The pattern, the hole and the thread: each a name of a list, offered
    // as codes 0, 1, … (the threads from the thread table, the first none).
    std::optional<FormField> ownField(const form::FieldText& t) const override
    {
        const auto named = [&t](const std::vector<std::string>& names, std::string HolePattern::*m) {
            FormField f = form::number<HolePattern>(
                t.key, t.label, t.checks,
                [names, m](const HolePattern& h) {
                    const auto it = std::find(names.begin(), names.end(), h.*m);
                    return it == names.end() ? -1.0 : static_cast<double>(it - names.begin());
                },
                [names, m](HolePattern& h, double v) {
                    const auto i = static_cast<long>(std::lround(v));
                    if (i >= 0 && i < static_cast<long>(names.size())) h.*m = names[static_cast<std::size_t>(i)];
                });
            f.kind = FormFieldKind::Code;
            for (std::size_t i = 0; i < names.size(); ++i) f.codes.emplace_back(static_cast<int>(i), names[i]);
            return f;
        };
        if (t.bind == "pattern") return named(kPatternNames, &HolePattern::pattern);
        if (t.bind == "hole") return named(kHoleNames, &HolePattern::hole);
        if (t.bind != "thread") return std::nullopt;
        std::vector<std::string> threads{""};
        for (const auto& thread : holes::threadTable()) threads.emplace_back(thread.name);
        return named(threads, &HolePattern::thread);
    }
};

}  // namespace

const ModuleKind& holesModule() { return moduleInstance<HolesKind>(); }

}  // namespace taiwa
