// The machining instruction sheet (pipeline stage 4): job header, material
// and stock, work offset and setup, the step table (tool, T/H numbers, speed,
// feed, depths, estimated time), the tool list with stick-out and life, total
// time, and the tool-life notes. HTML for the screen, PDF through Qt's
// QPdfWriter.
#pragma once

#include "model/plan.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

namespace sheet {
struct Table {
    std::vector<std::string> headers;
    std::vector<bool> numeric;                   // right-aligned columns
    std::vector<double> widths;                  // relative column widths
    std::vector<std::vector<std::string>> rows;
};
// A table of its own under a heading, with a line after it.
struct Section {
    std::string heading;
    Table table;
    std::string note;
};
}  // namespace sheet

struct SheetOptions {
    LengthUnit units = LengthUnit::Millimetre;  // lengths shown in this unit
    std::string dialect = "linuxcnc";
    std::string jobFile;                        // file name shown in the header
    int programNumber = 0;                      // O-number of the tape; 0 = not shown
    std::string date;                           // printed date; empty = none (tests)
    // What the verification found wrong with a tape written anyway (taiwa
    // export --force): shown first, in red.
    std::vector<std::string> faults;
    // Pictures of the stock after each step (PNG bytes, in step order; the
    // steps past the last have none), and when there are none or too few,
    // why (no display to draw on, a job too large).
    std::vector<std::string> stepPictures;
    std::string picturesNote;
    // The setup in a picture (viz::setupPicture: the stock, the vice's jaws
    // or the chuck's, the work offset's origin), PNG bytes; empty: none.
    std::string setupPicture;
    // A two-path lathe's sections, made where the timeline is run
    // (export/two_path_sheet.h): each step's path and the balanced
    // roughing's blocks per path in time, the waits marked; none: one path.
    std::vector<sheet::Section> paths;
    // Where the tools came from when not the station's own file
    // (ToolStore::origin: the shop server's library and its time, or the
    // copy read while the server is away), one sentence; empty: none.
    std::string toolsOrigin;
};

// How far a lathe job's bar must stand out of the chuck's jaws: the part
// (from its face stock to the deepest Z of its profiles), the parting
// blade's width and 2 mm [mm].
double barStickOut(const Plan& plan);

// A self-contained HTML document (inline CSS, no external resources).
std::string sheetHtml(const Plan& plan, const SheetOptions& options);

}  // namespace taiwa
