// Conversion of a whole job between mm and inch.
#include "ui/length_units.h"

#include <cmath>

namespace taiwa::ui {

Job convertLengthUnit(const Job& job, LengthUnit to)
{
    if (job.lengthUnit == to) return job;
    // Rounded to what the form shows, so that mm -> inch -> mm gives back the
    // typed values. Divided by the power of ten (not multiplied by its
    // inverse): the result is the double nearest the decimal, 0.393701 and
    // not 0.39370099999999997.
    const double scale = to == LengthUnit::Inch ? 1e6 : 1e4;
    return withLengths(toMillimetres(job), to,
                       [to, scale](double mm) { return std::round(fromMm(mm, to) * scale) / scale; });
}

}  // namespace taiwa::ui
