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
// Applies one length conversion to every length of a module.
struct ConvertLengths {
    const std::function<double(double)>& f;
    Point2 operator()(Point2 p) const { return {f(p.x), f(p.y)}; }
    ModuleInput operator()(M4Pocket m) const
    {
        for (auto& c : m.corners) c = (*this)(c);
        m.cornerRadius = f(m.cornerRadius);
        m.depth = f(m.depth);
        return m;
    }
    ModuleInput operator()(M2DPocket m) const
    {
        m.corner = (*this)(m.corner);
        m.lengthX = f(m.lengthX);
        m.lengthY = f(m.lengthY);
        m.depth = f(m.depth);
        m.cornerRadius = f(m.cornerRadius);
        m.scallop = f(m.scallop);
        return m;
    }
};
}  // namespace

Job withLengths(const Job& job, LengthUnit unit, const std::function<double(double)>& f)
{
    Job out = job;
    out.lengthUnit = unit;
    out.stock = {f(job.stock.x), f(job.stock.y), f(job.stock.width), f(job.stock.length), f(job.stock.height)};
    for (auto* v : {&out.technology.alpha1, &out.technology.alpha2, &out.technology.alpha3, &out.technology.beta2})
        if (*v) *v = f(**v);
    const ConvertLengths convert{f};
    for (auto& u : out.units) u.module = std::visit(convert, u.module);
    return out;
}

Job toMillimetres(const Job& job)
{
    if (job.lengthUnit == LengthUnit::Millimetre) return job;
    const LengthUnit from = job.lengthUnit;
    return withLengths(job, LengthUnit::Millimetre, [from](double v) { return toMm(v, from); });
}

}  // namespace taiwa
