// Conversion of a whole job between mm and inch.
#include "ui/length_units.h"

#include <cmath>

namespace taiwa::ui {
namespace {

struct Scale {
    LengthUnit to;
    double operator()(double mm) const
    {
        const double step = to == LengthUnit::Inch ? 1e-6 : 1e-4;
        return std::round(fromMm(mm, to) / step) * step;
    }
    Point2 operator()(Point2 p) const { return {(*this)(p.x), (*this)(p.y)}; }
    void operator()(std::optional<double>& v) const
    {
        if (v) v = (*this)(*v);
    }
    ModuleInput operator()(M4Pocket m) const
    {
        for (auto& c : m.corners) c = (*this)(c);
        m.cornerRadius = (*this)(m.cornerRadius);
        m.depth = (*this)(m.depth);
        return m;
    }
    ModuleInput operator()(M2DPocket m) const
    {
        m.corner = (*this)(m.corner);
        m.lengthX = (*this)(m.lengthX);
        m.lengthY = (*this)(m.lengthY);
        m.depth = (*this)(m.depth);
        m.cornerRadius = (*this)(m.cornerRadius);
        m.scallop = (*this)(m.scallop);
        return m;
    }
};

}  // namespace

Job convertLengthUnit(const Job& job, LengthUnit to)
{
    if (job.lengthUnit == to) return job;
    Job out = toMillimetres(job);
    const Scale s{to};
    out.lengthUnit = to;
    out.stock = {s(out.stock.x), s(out.stock.y), s(out.stock.width), s(out.stock.length), s(out.stock.height)};
    s(out.technology.alpha1);
    s(out.technology.alpha2);
    s(out.technology.alpha3);
    s(out.technology.beta2);
    for (auto& unit : out.units) unit.module = std::visit(s, unit.module);
    return out;
}

}  // namespace taiwa::ui
