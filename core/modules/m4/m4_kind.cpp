// The door of module M4 (2.5-D pocket): its job-file keys, checks, outline,
// planning and form, as module_kind.h asks. Registered in modules/registry.cpp.
#include "modules/m4/m4_kind.h"
#include "model/translate_noop.h"
#include "modules/m4/m4.h"
#include "modules/pocket_plan.h"
#include "paths/contour.h"

#include "io/job_messages.h"
#include "io/unit_keys.h"
#include "model/codes.h"

#include <algorithm>

namespace taiwa {

namespace {

// "corners": four points [x, y]; each one that is not a point is reported
// at its place ("corners[2]") and read as (0, 0).
io::UnitKey<M4Pocket> cornersKey()
{
    const char* const expected = TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of 4 points [x, y]");
    const auto read = [expected](const io::ObjectFields& f, M4Pocket& m) {
        const nlohmann::json* corners = f.find("corners");
        if (!corners) f.error("corners", msg::io::missing(expected));
        else if (!corners->is_array()) f.error("corners", msg::io::wrongType(expected, *corners));
        else if (corners->size() != 4) f.error("corners", msg::io::cornerCount(corners->size()));
        else
            for (std::size_t i = 0; i < 4; ++i)
                m.corners[i] = f.point((*corners)[i], "corners[" + std::to_string(i) + "]").value_or(Point2{});
    };
    const auto write = [](const M4Pocket& m, nlohmann::ordered_json& u) {
        u["corners"] = nlohmann::ordered_json::array();
        for (const auto& c : m.corners) u["corners"].push_back(io::point(c));
    };
    return io::keys::custom<M4Pocket>({"corners"}, read, write);
}

namespace keys = io::keys;
const io::UnitKeys<M4Pocket> kKeys{
    {cornersKey(), keys::required("cornerRadius", &M4Pocket::cornerRadius), keys::required("depth", &M4Pocket::depth),
     keys::number("taper", &M4Pocket::taper, 0.0), keys::requiredWhole("U", &M4Pocket::toolUse),
     keys::whole("F", &M4Pocket::wallFinish, 1), keys::whole("H", &M4Pocket::pilotHole, 0),
     keys::optional("stepOver", &M4Pocket::stepOver), keys::pins(&M4Pocket::tools)}};

class M4Kind final : public PocketKindOf<M4Pocket> {
public:
    M4Kind() : PocketKindOf(&kKeys, check::checkM4) {}
    std::vector<std::string> stepKeys() const override { return check::millingStepKeys(); }

    // The rounded outline at the top, its walls leaning inward by S: the
    // cross-section at depth d is the outline moved in by d tan S (exact for
    // a convex outline), so a point at distance e inside the outline lies
    // on the wall at depth e / tan S.
    std::optional<Cavity> cavity(const ModuleInput& mm, const TechnologyData& tech) const override
    {
        const M4Pocket& p = mm.as<M4Pocket>();
        Cavity c;
        const Quad top{counterClockwise(p.corners), p.cornerRadius};
        c.min = c.max = top.corners[0];
        for (const Point2& q : top.corners) {
            c.min = {std::min(c.min.x, q.x), std::min(c.min.y, q.y)};
            c.max = {std::max(c.max.x, q.x), std::max(c.max.y, q.y)};
        }
        c.depth = p.depth;
        c.wallAngle = p.taper;
        const double t = tanDeg(p.taper), depth = p.depth;
        c.depthAt = [distance = paths::QuadDistance(top), t, depth](Point2 q, double slack) {
            const double inside = slack - distance(q);
            if (inside < 0.0) return 0.0;
            return t > 0.0 ? std::min(depth, inside / t) : depth;
        };
        // Cored (U7): open to the roughing depth within the roughing outline,
        // as roughing would leave it; wall finishing only (U8): floor
        // finished there too.
        const ToolUse use = toolUseFromCode(p.toolUse).value_or(ToolUse::Standard);
        if (use == ToolUse::Cored || use == ToolUse::WallOnly) {
            const Quad rough = m4RoughOutline(p, tech);
            const double open = use == ToolUse::Cored ? p.depth - tech.beta2 : p.depth;
            c.openAt = [distance = paths::QuadDistance(rough), open](Point2 q) { return distance(q) <= 0.0 ? open : 0.0; };
        }
        return c;
    }

    ModuleInput makeDefault(const Stock& s) const override
    {
        M4Pocket p;
        p.corners = {Point2{s.x + 10, s.y + 10}, Point2{s.x + 60, s.y + 10}, Point2{s.x + 60, s.y + 40},
                     Point2{s.x + 10, s.y + 40}};
        p.cornerRadius = 8;
        p.depth = 10;
        return p;
    }

protected:
    std::optional<Quad> outline(const M4Pocket& mm) const override
    {
        return Quad{counterClockwise(mm.corners), mm.cornerRadius};
    }

    void move(M4Pocket& m, Point2 delta) const override
    {
        for (auto& c : m.corners) c = c + delta;
    }

    std::vector<Step> planInput(const M4Pocket& mm, const UnitPlanContext& ctx, Diagnostics& out) const override
    {
        std::vector<Step> steps = decomposeM4(mm, ctx.tech, ctx.unit);
        setStepOver(steps, mm.stepOver);
        choosePocketTools(steps, mm.tools, ctx, M4Pocket::kName, out);
        return steps;
    }

    // The corners P1.x … P4.y: the job file holds them as one array.
    std::optional<FormField> ownField(const form::FieldText& t) const override
    {
        const std::string& b = t.bind;
        if (b.size() != 4 || b[0] != 'P' || b[1] < '1' || b[1] > '4' || b[2] != '.' || (b[3] != 'x' && b[3] != 'y'))
            return std::nullopt;
        const auto i = static_cast<std::size_t>(b[1] - '1');
        const bool x = b[3] == 'x';
        return form::number<M4Pocket>(
            t.key, t.label, t.checks, [i, x](const M4Pocket& m) { return x ? m.corners[i].x : m.corners[i].y; },
            [i, x](M4Pocket& m, double v) { (x ? m.corners[i].x : m.corners[i].y) = v; });
    }
};

}  // namespace

const ModuleKind& m4Module() { return moduleInstance<M4Kind>(); }

}  // namespace taiwa
