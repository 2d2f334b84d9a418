// The door of module PROBE (work-centre probing): its job-file keys, checks
// (the fits' refusals name the touch point), form and setup (the measured
// centre and the probing cycle's data), as module_kind.h asks. It has no
// figure in the XY plane and no machining steps. Registered in
// modules/registry.cpp.
#include "modules/probe/probe_kind.h"
#include "model/translate_noop.h"

#include "io/job_messages.h"
#include "io/unit_keys.h"

#include <algorithm>
#include <variant>

namespace taiwa {

namespace {

// "touches" and "sides": the points touched, [x, y] each, and each one's
// side code. A touch not (wholly) entered is null, or has null for the
// coordinate not yet typed: saved as the operator left it. Absent: one
// touch at (0, 0).
void readTouches(const io::ObjectFields& f, ProbeUnit& p)
{
    using nlohmann::json;
    if (const json* touches = f.find("touches")) {
        if (!touches->is_array() || touches->empty() || touches->size() > ProbeUnit::kMaxTouches) {
            f.error("touches",
                    msg::io::wrongType(
                        TAIWA_TRANSLATE_NOOP("taiwa::msg", "an array of 1 to 8 points [x, y], the first [0, 0]"),
                        *touches));
        } else {
            for (std::size_t i = 0; i < touches->size(); ++i) {
                const json& t = (*touches)[i];
                const std::string field = "touches[" + std::to_string(i) + "]";
                if (t.is_null()) continue;
                if (!t.is_array() || t.size() != 2) {
                    f.error(field,
                            msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "a point [x, y] or null"), t));
                    continue;
                }
                if (!t[0].is_null()) p.x[i] = f.numberValue(t[0], field);
                if (!t[1].is_null()) p.y[i] = f.numberValue(t[1], field);
            }
        }
    } else {
        p.x[0] = p.y[0] = 0.0;
    }
    if (const json* sides = f.find("sides")) {
        if (!sides->is_array() || sides->size() > ProbeUnit::kMaxTouches) {
            f.error("sides",
                    msg::io::wrongType(TAIWA_TRANSLATE_NOOP(
                                           "taiwa::msg", "an array of up to 8 side codes (1 -X, 2 +X, 3 -Y, 4 +Y)"),
                                       *sides));
        } else {
            for (std::size_t i = 0; i < sides->size(); ++i)
                p.side[i] = f.wholeValue((*sides)[i], "sides[" + std::to_string(i) + "]").value_or(0);
        }
    }
}

void writeTouches(const ProbeUnit& p, nlohmann::ordered_json& u)
{
    u["touches"] = nlohmann::ordered_json::array();
    u["sides"] = nlohmann::ordered_json::array();
    std::size_t last = 0;  // up to the last touch entered; one not (wholly) entered is null (or has a null)
    for (std::size_t i = 0; i < ProbeUnit::kMaxTouches; ++i)
        if (p.x[i] || p.y[i] || p.side[i]) last = i;
    const auto coordinate = [](const std::optional<double>& v) {
        return v ? nlohmann::ordered_json(io::number(*v)) : nlohmann::ordered_json(nullptr);
    };
    for (std::size_t i = 0; i <= last; ++i) {
        if (p.x[i] || p.y[i]) u["touches"].push_back(nlohmann::ordered_json::array({coordinate(p.x[i]), coordinate(p.y[i])}));
        else u["touches"].push_back(nullptr);
        u["sides"].push_back(p.side[i]);
    }
    // Side codes are kept whatever the shape: an operator who turns a
    // rectangle round and back loses nothing.
    if (std::all_of(p.side.begin(), p.side.end(), [](int v) { return v == 0; })) u.erase("sides");
}

namespace keys = io::keys;
const io::UnitKeys<ProbeUnit> kKeys{
    {keys::requiredWhole("shape", &ProbeUnit::shape), keys::whole("where", &ProbeUnit::where, 1),
     keys::custom<ProbeUnit>({"touches", "sides"}, readTouches, writeTouches),
     keys::point("origin", &ProbeUnit::origin), keys::optional("top", &ProbeUnit::top),
     keys::whole("T", &ProbeUnit::tool, 0).when([](const ProbeUnit& p) { return p.tool != 0; }),
     keys::number("tolerance", &ProbeUnit::tolerance, 0.01), keys::required("sizeX", &ProbeUnit::sizeX),
     // Kept whatever the shape: an operator who turns a rectangle round
     // and back loses nothing.
     keys::number("sizeY", &ProbeUnit::sizeY, 0.0).when([](const ProbeUnit& p) {
         return p.shape != 1 || p.sizeY != 0;
     }),
     keys::number("touchDepth", &ProbeUnit::touchDepth, 5.0), keys::number("clearance", &ProbeUnit::clearance, 5.0),
     keys::number("search", &ProbeUnit::search, 10.0), keys::number("feed", &ProbeUnit::feed, 100.0)},
    io::UnitKeys<ProbeUnit>::Cutting::None};

class ProbeKind final : public ModuleKindOf<ProbeUnit> {
public:
    ProbeKind() : ModuleKindOf(&kKeys, check::checkProbe) {}

    ModuleInput makeDefault(const Stock& s) const override
    {
        ProbeUnit p;
        p.x[0] = p.y[0] = 0.0;
        p.sizeX = std::min(s.width, s.length);
        return p;
    }

    bool setsWorkOffset() const override { return true; }
    std::optional<WorkSetup> setup(const ModuleInput& mm, const UnitPlanContext& ctx) const override
    {
        const ProbeUnit& p = mm.as<ProbeUnit>();
        const Tool* tool = probeTool(p, ctx.library);
        WorkSetup w;
        w.unit = ctx.unit;
        w.round = p.shape == 1;
        w.inside = p.where == 2;
        w.tool = tool ? tool->id : 0;
        w.ballRadius = tool ? tool->radius() : 0.0;
        w.sizeX = p.sizeX;
        w.sizeY = w.round ? p.sizeX : p.sizeY;
        w.touchDepth = p.touchDepth;
        w.clearance = p.clearance;
        w.search = p.search;
        w.feed = p.feed;
        const auto touches = touchesOf(p);
        if (touches.size() <= 1) return w;  // no touches yet: the cycle only
        if (!tool) return w;
        const UnitFit fit = fitOf(p, touches, *tool);
        WorkSetup::Measured m;
        if (const auto* c = std::get_if<probe::CircleFit>(&fit)) {
            m.centre = p.origin + c->centre;
            m.radius = c->radius;
            m.residuals = c->residuals;
        } else if (const auto* r = std::get_if<probe::RectangleFit>(&fit)) {
            m.centre = p.origin + r->centre;
            m.width = r->width;
            m.length = r->length;
            m.rotation = r->rotation;
            m.rotationMeasured = r->rotationMeasured;
            m.residuals = r->residuals;
        } else {
            return w;  // refused by the checks already
        }
        m.top = p.top;
        w.measured = m;
        return w;
    }

    std::optional<Sketch> sketch(const ModuleInput& unit, LengthUnit shown, const std::vector<Tool>& library) const override
    {
        return probeSketch(unit.as<ProbeUnit>(), shown, library);
    }

protected:
    std::optional<Quad> outline(const ProbeUnit&) const override { return std::nullopt; }
    void move(ProbeUnit&, Point2) const override {}
    std::vector<Step> planInput(const ProbeUnit&, const UnitPlanContext&, Diagnostics&) const override { return {}; }

    // The touches after the first, P2.x … P8.side: the job file holds them as
    // two arrays ("touches", "sides").
    std::optional<FormField> ownField(const form::FieldText& t) const override
    {
        const std::string& b = t.bind;
        if (b.size() < 4 || b[0] != 'P' || b[2] != '.' || b[1] < '2' || b[1] >= '1' + static_cast<char>(ProbeUnit::kMaxTouches))
            return std::nullopt;
        const auto i = static_cast<std::size_t>(b[1] - '1');
        const std::string what = b.substr(3);
        if (what == "side") {
            FormField side = form::number<ProbeUnit>(
                t.key, t.label, t.checks, [i](const ProbeUnit& p) { return double(p.side[i]); },
                [i](ProbeUnit& p, double v) { p.side[i] = static_cast<int>(std::lround(v)); });
            side.kind = FormFieldKind::Code;
            return side;
        }
        if (what != "x" && what != "y") return std::nullopt;
        const bool isX = what == "x";
        FormField f;
        f.kind = FormFieldKind::OptionalNumber;
        f.get = [i, isX](const ModuleInput& m) -> std::optional<double> {
            const ProbeUnit* p = m.getIf<ProbeUnit>();
            return p ? (isX ? p->x[i] : p->y[i]) : std::nullopt;
        };
        f.set = [i, isX](ModuleInput& m, std::optional<double> v) {
            if (ProbeUnit* p = m.getIf<ProbeUnit>()) (isX ? p->x[i] : p->y[i]) = v;
        };
        return f;
    }
};

}  // namespace

const ModuleKind& probeModule() { return moduleInstance<ProbeKind>(); }

}  // namespace taiwa
