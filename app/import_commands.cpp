// `taiwa import STEP` and `taiwa figure-from-dxf DXF` (import_commands.h):
// a lathe job from a STEP model or a milling job from a STEP face set
// (job/step_job.h), a DXF drawing's contours
// as figure text (figure/figure_from_contours.h).
#include "app/import_commands.h"

#include "app/exit_codes.h"
#include "dxf/dxf_import.h"
#include "io/job_io.h"
#include "figure/figure_from_contours.h"
#include "job/job_file.h"
#include "job/step_job.h"
#include "model/technology.h"

#include <fmt/format.h>

#include <malloc.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace taiwa::app {

int importStep(const Options& o)
{
    std::error_code ec;
    if (std::filesystem::exists(o.out, ec)) {
        std::cerr << "taiwa: import: " << o.out << " exists; give a new file name (nothing was written)\n";
        return kInputErrors;
    }
    if (!TechnologyTable::builtIn().find(o.material)) {
        std::cerr << "taiwa: import: material '" << o.material << "' is not in the technology table\n";
        return kInputErrors;
    }
    if (o.surfaceSpacing) {
        // A face set as a SURFACE unit on the mill.
        const auto imported = surfaceJobFromStep(o.job, o.material, *o.surfaceSpacing);
        if (!imported) {
            std::cerr << "taiwa: import: " << imported.error() << '\n';
            return kInputErrors;
        }
        if (auto saved = writeFileAtomically(o.out, writeJob(imported->job)); !saved) {
            std::cerr << "taiwa: import: " << saved.error() << '\n';
            return kInternal;
        }
        const Stock& s = imported->job.stock;
        std::cout << fmt::format("taiwa: wrote {}: a SURFACE unit on a block {:g} x {:g} x {:g} mm at X {:g} Y {:g}; the "
                                 "faces moved {} {:g} mm (Z) to put their top at Z 0; the paths stay within {:.2f} um of "
                                 "the faces\n",
                                 o.out, s.width, s.length, s.height, s.x, s.y, imported->lowered >= 0 ? "down" : "up",
                                 std::abs(imported->lowered), imported->deviation * 1000);
        return kOk;
    }
    const auto job = latheJobFromStep(o.job, o.material);
    if (!job) {
        std::cerr << "taiwa: import: " << job.error() << '\n';
        return kInputErrors;
    }
    if (auto saved = writeFileAtomically(o.out, writeJob(*job)); !saved) {
        std::cerr << "taiwa: import: " << saved.error() << '\n';
        return kInternal;
    }
    std::cout << "taiwa: wrote " << o.out << ": " << job->units.size() << " turned profile"
              << (job->units.size() == 1 ? "" : "s") << " on a bar D" << job->bar->diameter << " x " << job->bar->length
              << " mm\n";
    return kOk;
}

// A DXF drawing's contours as figure text on stdout (figure/figure_from_contours.h), and
// on stderr what was read and what is wrong with it.
int figureFromDxf(const Options& o)
{
    // A command that ends when it is done: the large lists it makes and
    // frees (the drawing's entities and pieces, each attempt's definitions
    // and evaluation, the text read back) are kept by malloc for the next
    // one instead of being mapped afresh and faulted in page by page. For a
    // circle of 200,000 LINEs that was a fifth of the time (docs/dxf-import.md).
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    const std::string name = std::filesystem::path(o.job).filename().string();
    dxf::DxfOptions d;
    d.layers = o.layers;
    if (o.gap) d.gapTolerance = *o.gap;
    if (o.units) d.units = *o.units == LengthUnit::Inch ? dxf::Units::Inches : dxf::Units::Millimetres;
    dxf::DxfReadResult r = dxf::readDxf(o.job, d);
    for (const auto& w : r.warnings) std::cerr << name << ": " << w << '\n';
    if (!r.ok()) {
        std::cerr << name << ": " << *r.error << '\n';
        return kInputErrors;
    }
    std::vector<Contour> contours;
    // Moved, not copied (a drawing of 200,000 segments): the counts below read only whether each is closed.
    for (auto& c : r.contours) contours.push_back(std::move(c.contour));
    const FigureFromContours f = figureFromContours(contours);
    std::cout << f.text;
    std::string layers;
    for (const auto& l : r.layers)
        if (l.selected) layers += (layers.empty() ? "" : ", ") + l.name;
    std::cerr << name << ": " << r.contours.size() << " contours (" << r.closedCount() << " closed, " << r.openCount()
              << " open) on " << (layers.empty() ? "no layer" : "layers " + layers) << ", drawn in " << r.units
              << ", written in mm; " << r.gaps.size() << " gaps, " << r.branches.size() << " branches\n";
    for (const auto& g : r.gaps) std::cerr << name << ": " << g.message << '\n';
    for (const auto& b : r.branches) std::cerr << name << ": " << b.message << '\n';
    for (const auto& n : f.notes) std::cerr << name << ": " << n << '\n';
    for (const auto& x : f.refusals) std::cerr << name << ": " << x << '\n';
    return r.gaps.empty() && f.refusals.empty() ? kOk : kInputErrors;
}

}  // namespace taiwa::app
