// Placing a unit in free stock: candidates on a grid over the stock, nearest
// first, each tried against the other units with the interference check.
#include "job/placement.h"

#include "check/unit_checks.h"
#include "job/figure_contours.h"
#include "modules/registry.h"

#include <algorithm>
#include <cmath>

namespace taiwa {

namespace {

struct Box {
    double minX, minY, maxX, maxY;
};

Box boxOf(const Quad& q)
{
    Box b{q.corners[0].x, q.corners[0].y, q.corners[0].x, q.corners[0].y};
    for (const auto& c : q.corners) {
        b.minX = std::min(b.minX, c.x), b.maxX = std::max(b.maxX, c.x);
        b.minY = std::min(b.minY, c.y), b.maxY = std::max(b.maxY, c.y);
    }
    return b;
}

}  // namespace

std::optional<ModuleInput> placeInFreeStock(const Job& typed, ModuleInput typedUnit)
{
    // Work in mm (the interference check's tolerances are in mm); move the
    // unit as typed by the same distance in its own unit.
    const Job job = millimetreJob(typed);
    ModuleInput unit = typedUnit;
    const LengthUnit lu = typed.lengthUnit;
    unit.convertLengths([lu](double v) { return toMm(v, lu); });
    const ModuleKind& kind = moduleKind(unit);
    const auto outline = kind.topOutline(unit);
    if (!outline) return typedUnit;
    std::vector<check::UnitFigure> others;
    for (std::size_t u = 0; u < job.units.size(); ++u) {
        const ModuleInput& m = job.units[u].module;
        if (const ModuleKind* k = findModuleKind(m.name()))
            if (const auto o = k->topOutline(m))
                others.push_back({static_cast<int>(u), k->name(), k->outlineField(), *o, k->topPolygon(m)});
    }
    const Box box = boxOf(*outline);
    const Stock& s = job.stock;
    // Candidate offsets that keep the figure's box inside the stock, on a grid
    // of a twentieth of the stock (at least 1 length unit), nearest first.
    const double step = std::max({s.width / 20.0, s.length / 20.0, 1.0});
    std::vector<Point2> deltas;
    for (double y = s.y - box.minY; y <= s.y + s.length - box.maxY + 1e-9; y += step)
        for (double x = s.x - box.minX; x <= s.x + s.width - box.maxX + 1e-9; x += step) deltas.push_back({x, y});
    // Where it is, first, when it is inside the stock.
    if (box.minX >= s.x && box.minY >= s.y && box.maxX <= s.x + s.width && box.maxY <= s.y + s.length)
        deltas.insert(deltas.begin(), Point2{0, 0});
    std::stable_sort(deltas.begin(), deltas.end(), [](Point2 a, Point2 b) { return length(a) < length(b); });
    const int self = static_cast<int>(job.units.size());
    for (const Point2 d : deltas) {
        ModuleInput moved = unit;
        kind.moveBy(moved, d);
        auto figures = others;
        figures.push_back({self, kind.name(), kind.outlineField(), *kind.topOutline(moved), kind.topPolygon(moved)});
        if (!check::interferences(std::move(figures), LengthUnit::Millimetre).empty()) continue;
        kind.moveBy(typedUnit, {fromMm(d.x, lu), fromMm(d.y, lu)});
        return typedUnit;
    }
    return std::nullopt;
}

}  // namespace taiwa
