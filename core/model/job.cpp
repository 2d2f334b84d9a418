// Job helpers: module names and the conversion of a job to millimetres.
#include "model/job.h"

namespace taiwa {

const char* unitSymbol(LengthUnit u) { return u == LengthUnit::Inch ? "in" : "mm"; }

const char* moduleName(const ModuleInput& m)
{
    struct Name {
        const char* operator()(const M4Pocket&) const { return "M4"; }
        const char* operator()(const M2DPocket&) const { return "M2D"; }
    };
    return std::visit(Name{}, m);
}

namespace {
struct ToMm {
    LengthUnit u;
    double operator()(double v) const { return toMm(v, u); }
    Point2 operator()(Point2 p) const { return {toMm(p.x, u), toMm(p.y, u)}; }
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

Job toMillimetres(const Job& job)
{
    if (job.lengthUnit == LengthUnit::Millimetre) return job;
    const ToMm mm{job.lengthUnit};
    Job out = job;
    out.lengthUnit = LengthUnit::Millimetre;
    out.stock = {mm(job.stock.x), mm(job.stock.y), mm(job.stock.width), mm(job.stock.length), mm(job.stock.height)};
    auto conv = [&](std::optional<double>& v) { if (v) v = mm(*v); };
    conv(out.technology.alpha1);
    conv(out.technology.alpha2);
    conv(out.technology.alpha3);
    conv(out.technology.beta2);
    for (auto& unit : out.units) unit.module = std::visit(mm, unit.module);
    return out;
}

}  // namespace taiwa
