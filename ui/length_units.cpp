// Conversion of a whole job between mm and inch.
#include "ui/length_units.h"

#include "figure/figure_units.h"

#include <algorithm>
#include <cmath>

namespace taiwa::ui {

Job convertLengthUnit(const Job& job, LengthUnit to)
{
    if (job.lengthUnit == to) return job;
    // Exact: what the machine cuts must not change with the unit the job is
    // shown in (r1 6 mm rounded to 0.23622 in is 5.99999 mm, and a 12 mm end
    // mill no longer fits). The forms round for display only. The last bits a
    // round trip mm -> inch -> mm adds (6.000000000000001) are taken off, so
    // the values typed come back.
    const LengthUnit from = job.lengthUnit;
    const auto convert = [from, to](double v) {
        const double x = fromMm(toMm(v, from), to);
        const double snapped = std::round(x * 1e9) / 1e9;
        return std::abs(snapped - x) <= 1e-12 * std::max(1.0, std::abs(x)) ? snapped : x;
    };
    Job out = withLengths(job, to, convert);
    // The figure's text is in the job's unit too (its contours are the
    // contour units' geometry).
    out.figure = figure::convertFigureLengths(job.figure, convert);
    return out;
}

}  // namespace taiwa::ui
