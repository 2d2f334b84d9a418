// The job's figure text evaluated into contours in mm for its contour units
// (job/figure_contours.h).
#include "job/figure_contours.h"

#include "figure/figure_eval.h"
#include "modules/registry.h"

namespace taiwa {

ContourTable figureContours(const Job& typed, Diagnostics& out)
{
    ContourTable table;
    if (typed.figure.empty()) return table;
    const auto refuse = [&](const figure::FigureError& e) {
        out.push_back({Severity::Error, std::nullopt, "", "figure", e.text()});
    };
    const figure::ParseResult parsed = figure::parseFigure(typed.figure);
    if (!parsed.ok()) {
        refuse(*parsed.error);
        return table;
    }
    const figure::Evaluation evaluated = figure::evaluate(parsed.definitions);
    for (const auto& e : evaluated.errors) refuse(e);
    // Geometry is the same at any scale: the text's numbers are in the
    // job's unit, the contours are scaled to mm as a whole.
    const double k = toMm(1.0, typed.lengthUnit);
    const auto mm = [k](Point2 p) { return Point2{k * p.x, k * p.y}; };
    for (const auto& c : evaluated.contours) {
        Contour contour = c.contour;
        if (k != 1.0)
            for (auto& s : contour.segments) s.start = mm(s.start), s.end = mm(s.end), s.centre = mm(s.centre);
        table.emplace(c.name, std::move(contour));
    }
    return table;
}

void resolveContours(Job& mmJob, const ContourTable& contours)
{
    for (auto& u : mmJob.units)
        if (const ModuleKind* kind = findModuleKind(u.module.name())) kind->resolveContours(u.module, contours);
}

Job millimetreJob(const Job& typed)
{
    Job mm = toMillimetres(typed);
    Diagnostics ignored;
    resolveContours(mm, figureContours(typed, ignored));
    return mm;
}

}  // namespace taiwa
