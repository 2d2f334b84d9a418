// Job helpers: the conversion of a job between length units.
#include "model/job.h"

#include <string>

namespace taiwa {

const char* unitSymbol(LengthUnit u) { return u == LengthUnit::Inch ? "in" : "mm"; }

Job withLengths(const Job& job, LengthUnit unit, const LengthMap& f)
{
    Job out = job;
    out.lengthUnit = unit;
    out.stock = {f(job.stock.x), f(job.stock.y), f(job.stock.width), f(job.stock.length), f(job.stock.height)};
    if (job.bar) out.bar = BarStock{f(job.bar->diameter), f(job.bar->length), f(job.bar->face), f(job.bar->bore)};
    if (job.clamping) out.clamping->height = f(job.clamping->height);
    for (auto* v : {&out.technology.alpha1, &out.technology.alpha2, &out.technology.alpha3, &out.technology.beta2})
        if (*v) *v = f(**v);
    for (auto& u : out.units) {
        u.module.convertLengths(f);
        for (auto& [key, c] : u.cutting)
            if (c.feed) c.feed = f(*c.feed);  // a length per minute or per revolution
    }
    return out;
}

Job toMillimetres(const Job& job)
{
    if (job.lengthUnit == LengthUnit::Millimetre) return job;
    const LengthUnit from = job.lengthUnit;
    return withLengths(job, LengthUnit::Millimetre, [from](double v) { return toMm(v, from); });
}

}  // namespace taiwa
