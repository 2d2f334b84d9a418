// Export of a planned job: the files of docs/command-line.md ("export writes into
// DIR"), each written atomically. Shared by `taiwa export` and the window's
// export dialog. Its own library (taiwa_export): the PDF sheet is painted
// with Qt, which the rest of the core does without.
#pragma once

#include "model/plan.h"
#include "model/result.h"
#include "post/post.h"
#include "post/posted_job.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct ExportOptions {
    std::string dialect = "linuxcnc";
    std::optional<LengthUnit> units;  // default: the job's own unit
    std::string jobFile;              // shown on the sheet
    int programNumber = 1000;
    // What the verification found wrong with a tape written anyway (taiwa
    // export --force), one sentence each: the sheet shows them in red.
    std::vector<std::string> verificationFaults;
    // The sheet's pictures of the steps, PNG bytes (addSheetPictures of
    // export/sheet_pictures.h draws them; none unless asked) and why some
    // are missing.
    std::vector<std::string> stepPictures;
    std::string picturesNote;
    // The sheet's picture of the setup (addSheetPictures), PNG bytes; empty: none.
    std::string setupPicture;
    // Where the tools came from, for the sheet (ToolStore::origin); empty: the station's own file.
    std::string toolsOrigin;
    // The programs already posted with these options (postJob with
    // postOptions of the plan, the dialect, units, program number and stem;
    // taiwa export and the station post them first to read them back and to
    // place the verification's findings on the tape): the tape, a two-path
    // lathe's programs and the probing units' programs written as they are,
    // not posted again. Null: the export posts them.
    const PostedJob* posted = nullptr;
};

// STEM.nc, STEM.tape.txt, STEM.sheet.html, STEM.sheet.pdf, STEM.steps.json
// (and a probing unit's programs, a surface unit's STEM.uN.surface.step) in
// outDir (created if missing), replaced as one set (io::FileSet): all are
// written completely before any is renamed, so a failure leaves the old set
// whole and the message says nothing was changed; exports of one stem into
// one folder run one after the other. Refuses a plan with input errors. The
// PDF needs a QGuiApplication. The paths written, in order.
Result<std::vector<std::string>> exportPlan(const Plan& plan, const std::string& outDir, const std::string& stem,
                                            const ExportOptions& options);

// The machine-readable step list (STEM.steps.json).
std::string stepsJson(const Plan& plan);

}  // namespace taiwa
