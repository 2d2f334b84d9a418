// The probing page's figure (model/sketch.h): the touches as entered with
// their residuals, the fitted circle (and the ball centres' circle) or
// rectangle, the centre from P1 and the work offset to set; a refusal in
// words, with the touch it names flagged.
#include "modules/probe/probe_kind.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace taiwa {

Sketch probeSketch(const ProbeUnit& unit, LengthUnit shown, const std::vector<Tool>& library)
{
    ProbeUnit p = unit;
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
        s.lines.push_back(TAIWA_TRANSLATE_NOOP("taiwa::msg", "No probe in the tool library (type \"probe\"): the ball radius is unknown"));
        return s;
    }
    const std::size_t needed = p.shape == 1 ? 3 : 4;
    if (touches.size() < needed) {
        s.lines.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{} of at least {} touches entered: the probing cycle the export writes makes them on the machine"),
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
        s.lines.push_back(p.where == 2 ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "Bore: diameter {}"), len(2 * c->radius))
                                       : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "Boss: diameter {}"), len(2 * c->radius)));
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
        const std::string turned = r.rotationMeasured ? fmt::format("{:.4f} deg", r.rotation)
                                                      : TAIWA_TRANSLATE_NOOP("taiwa::msg", "(not measured: touch one side twice)");
        s.lines.push_back(p.where == 2 ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "Pocket: {} x {}, turned {}"), len(r.width), len(r.length), turned)
                                       : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "Block: {} x {}, turned {}"), len(r.width), len(r.length), turned));
    }
    s.centre = centre;
    const Point2 machine = p.origin + centre;
    s.lines.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "Centre from P1: X {} Y {}"), len(centre.x), len(centre.y)));
    s.lines.push_back(p.top ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "Work offset to set: X {} Y {} Z {}"), len(machine.x), len(machine.y), len(*p.top))
                            : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "Work offset to set: X {} Y {}"), len(machine.x), len(machine.y)));
    return s;
}

}  // namespace taiwa
