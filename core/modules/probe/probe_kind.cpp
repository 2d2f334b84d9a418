// The door of module PROBE (work-centre probing): its job-file keys, checks
// (the fits' refusals name the touch point), form and setup (the measured
// centre and the probing cycle's data), as module_kind.h asks. It has no
// figure in the XY plane and no machining steps. Registered in
// modules/registry.cpp.
#include "modules/probe/probe.h"
#include "modules/probe/probe_fit.h"
#include "modules/module_kind.h"

#include "check/messages.h"
#include "io/job_messages.h"
#include "io/json_write.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <variant>

namespace taiwa {

namespace {

const std::vector<std::string> kKeys{"module", "name", "shape", "where", "touches", "sides", "origin", "top",
                                     "T", "tolerance", "sizeX", "sizeY", "touchDepth", "clearance", "search", "feed"};

// The touches entered, in order (the first at 0, 0).
std::vector<probe::Touch> touchesOf(const ProbeUnit& p)
{
    std::vector<probe::Touch> t;
    for (std::size_t i = 0; i < ProbeUnit::kMaxTouches; ++i)
        if (p.x[i] && p.y[i]) t.push_back({{*p.x[i], *p.y[i]}, static_cast<probe::Side>(p.side[i])});
    return t;
}

const Tool* probeTool(const ProbeUnit& p, const std::vector<Tool>& library)
{
    const Tool* found = nullptr;
    for (const Tool& t : library)
        if (t.type == ToolType::Probe && (p.tool == 0 || t.id == p.tool)) {
            if (found && p.tool == 0) return nullptr;  // several probes: which one must be said
            found = &t;
        }
    return found;
}

// The fit of the unit's touches (in mm) with its probe's ball: the
// workpiece's circle or rectangle, or why not.
using UnitFit = std::variant<probe::CircleFit, probe::RectangleFit, probe::FitProblem>;
UnitFit fitOf(const ProbeUnit& p, const std::vector<probe::Touch>& touches, const Tool& probe)
{
    const probe::FitSettings fs{probe.radius(), p.where == 2, p.tolerance};
    const auto widen = [](auto&& fit) { return std::visit([](auto&& v) -> UnitFit { return v; }, fit); };
    return p.shape == 1 ? widen(probe::fitCircle(touches, fs)) : widen(probe::fitRectangle(touches, fs));
}

class ProbeKind final : public ModuleKindOf<ProbeUnit> {
public:
    const char* paletteText() const override
    {
        return TAIWA_TRANSLATE_NOOP("taiwa::ui::ModulePalette", "Add work-centre probing");
    }
    const char* drawing() const override { return ":/modules/probe.svg"; }
    const char* outlineField() const override { return "touches"; }

    ModuleInput makeDefault(const Stock& s) const override
    {
        ProbeUnit p;
        p.x[0] = p.y[0] = 0.0;
        p.sizeX = std::min(s.width, s.length);
        return p;
    }

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
        ProbeUnit p = unit.as<ProbeUnit>();
        p.convertLengths([shown](double v) { return toMm(v, shown); });
        const auto len = [shown](double mm) {
            const int decimals = shown == LengthUnit::Inch ? 4 : 3;
            const double v = fromMm(mm, shown);
            return fmt::format("{:.{}f} {}", std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v, decimals, unitSymbol(shown));
        };
        Sketch s;
        const auto touches = touchesOf(p);
        std::vector<std::size_t> index;  // of each touch among P1..P8
        for (std::size_t i = 0; i < ProbeUnit::kMaxTouches; ++i)
            if (p.x[i] && p.y[i]) index.push_back(i);
        for (std::size_t k = 0; k < touches.size(); ++k) {
            std::string label = "P" + std::to_string(index[k] + 1);
            if (p.shape == 2 && touches[k].side != probe::Side::None) label += std::string(" ") + probe::toString(touches[k].side);
            s.marks.push_back({touches[k].at, label, false});
        }
        const Tool* tool = probeTool(p, library);
        if (!tool) {
            s.problem = true;
            s.lines.push_back("No probe in the tool library (type \"probe\"): the ball radius is unknown");
            return s;
        }
        const std::size_t needed = p.shape == 1 ? 3 : 4;
        if (touches.size() < needed) {
            s.lines.push_back(fmt::format("{} of at least {} touches entered: the probing cycle the export writes "
                                          "makes them on the machine",
                                          touches.size(), needed));
            return s;
        }
        const auto flag = [&](int point, const std::string& message) {
            s.problem = true;
            s.lines.push_back(message);
            for (std::size_t k = 0; k < s.marks.size(); ++k)
                if (static_cast<int>(index[k]) + 1 == point) s.marks[k].flagged = true;
        };
        const auto residualLabels = [&](const std::vector<double>& residuals) {
            for (std::size_t k = 0; k < s.marks.size() && k < residuals.size(); ++k)
                // Residuals below half the last digit shown as +0.0000, not -0.0000.
                s.marks[k].label += fmt::format(" {:+.4f}", std::abs(residuals[k]) < 5e-5 ? 0.0 : fromMm(residuals[k], shown));
        };
        const UnitFit fit = fitOf(p, touches, *tool);
        Point2 centre;
        if (const auto* e = std::get_if<probe::FitProblem>(&fit)) {
            flag(e->point, e->message);
            return s;
        } else if (const auto* c = std::get_if<probe::CircleFit>(&fit)) {
            centre = c->centre;
            residualLabels(c->residuals);
            // The workpiece's outline, and the ball centres' circle it was fitted to.
            const double ballPath = p.where == 2 ? c->radius - tool->radius() : c->radius + tool->radius();
            for (const double r : {c->radius, ballPath}) {
                std::vector<Point2> ring;
                for (int k = 0; k < 120; ++k)
                    ring.push_back(c->centre + r * Point2{std::cos(k * std::numbers::pi / 60), std::sin(k * std::numbers::pi / 60)});
                s.outlines.push_back(std::move(ring));
            }
            s.lines.push_back(fmt::format("{}: diameter {}", p.where == 2 ? "Bore" : "Boss", len(2 * c->radius)));
        } else {
            const auto& r = std::get<probe::RectangleFit>(fit);
            centre = r.centre;
            residualLabels(r.residuals);
            const double a = r.rotation * std::numbers::pi / 180;
            const Point2 ex{std::cos(a), std::sin(a)}, ey{-std::sin(a), std::cos(a)};
            std::vector<Point2> box;
            for (const auto& [u, v] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
                box.push_back(r.centre + (u * r.width / 2) * ex + (v * r.length / 2) * ey);
            s.outlines.push_back(std::move(box));
            s.lines.push_back(fmt::format("{}: {} x {}, turned {}", p.where == 2 ? "Pocket" : "Block", len(r.width), len(r.length),
                                          r.rotationMeasured ? fmt::format("{:.4f} deg", r.rotation) : "(not measured: touch one side twice)"));
        }
        s.centre = centre;
        const Point2 machine = p.origin + centre;
        s.lines.push_back(fmt::format("Centre from P1: X {} Y {}", len(centre.x), len(centre.y)));
        s.lines.push_back(fmt::format("Work offset to set: X {} Y {}{}", len(machine.x), len(machine.y),
                                      p.top ? " Z " + len(*p.top) : std::string()));
        return s;
    }

protected:
    ProbeUnit readInput(const io::ObjectFields& f) const override
    {
        using nlohmann::json;
        ProbeUnit p;
        f.rejectUnknown("module PROBE", kKeys);
        p.shape = f.whole("shape").value_or(0);
        p.where = f.whole("where", 1);
        if (const json* touches = f.find("touches")) {
            if (!touches->is_array() || touches->empty() || touches->size() > ProbeUnit::kMaxTouches) {
                f.error("touches", msg::io::wrongType("an array of 1 to 8 points [x, y], the first [0, 0]", *touches));
            } else {
                // A touch not (wholly) entered is null, or has null for the
                // coordinate not yet typed: saved as the operator left it.
                for (std::size_t i = 0; i < touches->size(); ++i) {
                    const json& t = (*touches)[i];
                    const std::string field = "touches[" + std::to_string(i) + "]";
                    if (t.is_null()) continue;
                    if (!t.is_array() || t.size() != 2) {
                        f.error(field, msg::io::wrongType("a point [x, y] or null", t));
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
                f.error("sides", msg::io::wrongType("an array of up to 8 side codes (1 -X, 2 +X, 3 -Y, 4 +Y)", *sides));
            } else {
                for (std::size_t i = 0; i < sides->size(); ++i)
                    p.side[i] = f.wholeValue((*sides)[i], "sides[" + std::to_string(i) + "]").value_or(0);
            }
        }
        p.origin = f.point("origin").value_or(Point2{});
        p.top = f.optionalNumber("top");
        p.tool = f.whole("T", 0);
        p.tolerance = f.number("tolerance", 0.01);
        p.sizeX = f.number("sizeX").value_or(0.0);
        p.sizeY = f.number("sizeY", 0.0);
        p.touchDepth = f.number("touchDepth", 5.0);
        p.clearance = f.number("clearance", 5.0);
        p.search = f.number("search", 10.0);
        p.feed = f.number("feed", 100.0);
        return p;
    }

    void writeInput(const ProbeUnit& p, nlohmann::ordered_json& u) const override
    {
        u["shape"] = p.shape;
        u["where"] = p.where;
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
        if (p.shape == 1) u.erase("sides");
        u["origin"] = io::point(p.origin);
        if (p.top) u["top"] = io::number(*p.top);
        if (p.tool) u["T"] = p.tool;
        u["tolerance"] = io::number(p.tolerance);
        u["sizeX"] = io::number(p.sizeX);
        if (p.shape != 1) u["sizeY"] = io::number(p.sizeY);
        u["touchDepth"] = io::number(p.touchDepth);
        u["clearance"] = io::number(p.clearance);
        u["search"] = io::number(p.search);
        u["feed"] = io::number(p.feed);
    }

    check::UnitReport checkInput(const ProbeUnit& p, int unitNo, const check::Context& ctx) const override
    {
        check::UnitReport report;
        check::Reporter r{unitNo, ProbeUnit::kName, ctx, report.diagnostics};
        if (p.shape != 1 && p.shape != 2)
            r.unit("shape", fmt::format("shape {} is not defined: 1 round (boss or bore), 2 rectangular (block or pocket)", p.shape));
        if (p.where != 1 && p.where != 2)
            r.unit("where", fmt::format("where {} is not defined: 1 touched from outside (boss, block), 2 from inside "
                                        "(bore, pocket)",
                                        p.where));
        bool finite = true;
        for (std::size_t i = 0; i < ProbeUnit::kMaxTouches; ++i) {
            const std::string field = "touches[" + std::to_string(i) + "]", point = "P" + std::to_string(i + 1);
            if (p.x[i]) finite &= check::checkLength(*p.x[i], field, "the X of " + point, r);
            if (p.y[i]) finite &= check::checkLength(*p.y[i], field, "the Y of " + point, r);
            if (static_cast<bool>(p.x[i]) != static_cast<bool>(p.y[i])) {
                r.unit(field, fmt::format("point {}: its {} is missing", i + 1, p.x[i] ? "Y" : "X"));
                finite = false;
            }
            if (p.shape == 2 && p.x[i] && p.y[i] && (p.side[i] < 1 || p.side[i] > 4)) {
                r.unit("sides[" + std::to_string(i) + "]",
                       fmt::format("point {}: say which side it touches: 1 -X, 2 +X, 3 -Y, 4 +Y", i + 1));
                finite = false;
            }
        }
        if (!p.x[0] || !p.y[0] || *p.x[0] != 0.0 || *p.y[0] != 0.0) {
            r.unit("touches[0]", "point 1 is the measuring origin: it is at 0, 0 and the others are measured from it");
            finite = false;
        }
        finite &= check::checkLength(p.origin.x, "origin", "the machine X of point 1", r) &&
                  check::checkLength(p.origin.y, "origin", "the machine Y of point 1", r);
        if (p.top) finite &= check::checkLength(*p.top, "top", "the machine Z of the top face", r);
        const auto positive = [&](double v, const char* field, const char* what, double most) {
            if (!std::isfinite(v) || v <= 0 || v > most) {
                r.unit(field, fmt::format("{} must be above 0 and at most {:g} mm, not {:g}", what, most, v));
                return false;
            }
            return true;
        };
        positive(p.sizeX, "sizeX", p.shape == 2 ? "the nominal width along X" : "the nominal diameter", check::kMaxLength);
        if (p.shape == 2) positive(p.sizeY, "sizeY", "the nominal length along Y", check::kMaxLength);
        positive(p.touchDepth, "touchDepth", "the depth of the side touches", 1000);
        positive(p.clearance, "clearance", "the clearance", 1000);
        positive(p.search, "search", "the search distance", 1000);
        if (!std::isfinite(p.feed) || p.feed <= 0 || p.feed > 5000)
            r.unit("feed", fmt::format("the probing feed must be above 0 and at most 5000 mm/min, not {:g}", p.feed));
        if (!std::isfinite(p.tolerance) || p.tolerance < 0.001 || p.tolerance > 1)
            r.unit("tolerance", fmt::format("the tolerance must lie between 0.001 and 1 mm, not {:g}", p.tolerance));

        const Tool* tool = ctx.library ? probeTool(p, *ctx.library) : nullptr;
        if (ctx.library && !tool) {
            if (p.tool != 0) r.unit("T", fmt::format("T{} is not a probe in the tool library", p.tool));
            else r.unit("T", "the tool library has no probe, or several: add one of type \"probe\" or say which (T)");
        }
        if (!finite || !tool || hasErrors(report.diagnostics)) return report;

        // The fit of the touches entered (none but the origin: the cycle only).
        const auto touches = touchesOf(p);
        if (touches.size() <= 1) return report;
        const UnitFit fit = fitOf(p, touches, *tool);
        if (const auto* e = std::get_if<probe::FitProblem>(&fit))
            r.unit(e->point > 0 ? "touches[" + std::to_string(e->point - 1) + "]" : "touches", e->message);
        return report;
    }

    std::optional<Quad> outline(const ProbeUnit&) const override { return std::nullopt; }
    void move(ProbeUnit&, Point2) const override {}
    std::vector<Step> planInput(const ProbeUnit&, const UnitPlanContext&, Diagnostics&) const override { return {}; }

    std::vector<FormField> formFields() const override
    {
        using form::member;
        using form::number;
        std::vector<FormField> fs;
        const auto codeField = [](std::string key, std::string label, std::vector<std::pair<int, std::string>> codes,
                                  int ProbeUnit::*m) {
            FormField f = number<ProbeUnit>(key, std::move(label), {key}, [m](const ProbeUnit& p) { return double(p.*m); },
                                            [m](ProbeUnit& p, double v) { p.*m = static_cast<int>(std::lround(v)); });
            f.kind = FormFieldKind::Code;
            f.codes = std::move(codes);
            return f;
        };
        fs.push_back(codeField("shape", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Shape"),
                               {{1, "round (boss or bore)"}, {2, "rectangular (block or pocket)"}}, &ProbeUnit::shape));
        fs.push_back(codeField("where", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Touched from"),
                               {{1, "outside (boss, block)"}, {2, "inside (bore, pocket)"}}, &ProbeUnit::where));
        fs.push_back(number<ProbeUnit>("origin.x", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "P1 machine X"), {"origin"},
                                       [](const ProbeUnit& p) { return p.origin.x; }, [](ProbeUnit& p, double v) { p.origin.x = v; }));
        fs.push_back(number<ProbeUnit>("origin.y", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "P1 machine Y"), {"origin"},
                                       [](const ProbeUnit& p) { return p.origin.y; }, [](ProbeUnit& p, double v) { p.origin.y = v; }));
        for (std::size_t i = 1; i < ProbeUnit::kMaxTouches; ++i) {
            const std::string key = "P" + std::to_string(i + 1);
            const std::vector<std::string> diag{"touches[" + std::to_string(i) + "]"};
            for (const bool isX : {true, false}) {
                FormField f;
                f.key = key + (isX ? ".x" : ".y");
                f.label = key + (isX ? " X" : " Y");
                f.placeholder = "not touched";
                f.diagFields = diag;
                f.kind = FormFieldKind::OptionalNumber;
                f.get = [i, isX](const ModuleInput& m) -> std::optional<double> {
                    const ProbeUnit* p = m.getIf<ProbeUnit>();
                    return p ? (isX ? p->x[i] : p->y[i]) : std::nullopt;
                };
                f.set = [i, isX](ModuleInput& m, std::optional<double> v) {
                    if (ProbeUnit* p = m.getIf<ProbeUnit>()) (isX ? p->x[i] : p->y[i]) = v;
                };
                fs.push_back(std::move(f));
            }
            FormField side = number<ProbeUnit>(
                key + ".side", key + " side", {"sides[" + std::to_string(i) + "]"},
                [i](const ProbeUnit& p) { return double(p.side[i]); },
                [i](ProbeUnit& p, double v) { p.side[i] = static_cast<int>(std::lround(v)); });
            side.kind = FormFieldKind::Code;
            side.codes = {{0, "(round: none)"}, {1, "-X"}, {2, "+X"}, {3, "-Y"}, {4, "+Y"}};
            fs.push_back(std::move(side));
        }
        fs.push_back(form::optionalMember<ProbeUnit>("top", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Top face machine Z"),
                                                     "not touched", {"top"}, &ProbeUnit::top));
        fs.push_back(member<ProbeUnit>("tolerance", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Tolerance"), {"tolerance"},
                                       &ProbeUnit::tolerance));
        fs.push_back(member<ProbeUnit>("sizeX", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Nominal diameter / width X"),
                                       {"sizeX"}, &ProbeUnit::sizeX));
        fs.push_back(member<ProbeUnit>("sizeY", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Nominal length Y"), {"sizeY"},
                                       &ProbeUnit::sizeY));
        fs.push_back(member<ProbeUnit>("touchDepth", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Touch depth"),
                                       {"touchDepth"}, &ProbeUnit::touchDepth));
        fs.push_back(member<ProbeUnit>("clearance", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Clearance"), {"clearance"},
                                       &ProbeUnit::clearance));
        fs.push_back(member<ProbeUnit>("search", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Search distance"), {"search"},
                                       &ProbeUnit::search));
        fs.push_back(member<ProbeUnit>("feed", TAIWA_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Probing feed (mm/min)"),
                                       {"feed"}, &ProbeUnit::feed));
        return fs;
    }
};

}  // namespace

const ModuleKind& probeModule() { return moduleInstance<ProbeKind>(); }

}  // namespace taiwa
