// The content of the machining instruction sheet as plain values (header
// fields, the step table, the tool table, notes), computed once from a plan
// and laid out by both the HTML and the PDF writer.
#pragma once

#include "sheet/sheet.h"
#include "sheet/tool_drawing.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace taiwa::sheet {

struct Content {
    std::string title;
    std::vector<std::pair<std::string, std::string>> fields;  // "Job" -> "Cover plate"
    std::string setup;                                        // work offset and origin, one sentence
    std::string clamping;  // milling jobs: how the block is held, or that the job does not say
    std::string toolsOrigin;  // SheetOptions::toolsOrigin: the shop server's tools, or its copy's
    Table steps;
    std::vector<Section> paths;  // a two-path lathe's (SheetOptions::paths), after the steps
    Table workCentre;  // probing units: the measured centre, size, rotation and residuals; empty rows when none
    Table allowances;  // turning units: every grinding-allowance row with its edge, attributes and groove
    Table turned;      // turning units: the deformed profile the lathe cuts, edge by edge
    Table tools;
    struct Drawing {
        std::string caption;  // "T12 Ø10 end mill"
        ToolDrawing drawing;
    };
    std::vector<Drawing> toolDrawings;  // the tools' with a drawing (not lathe tools), in the tool table's order
    Table latheTools;  // lathe jobs: each tool's turret station, insert or blade, nose radius and tip orientation
    std::vector<std::string> notes;
    std::vector<std::string> faults;  // the verification's, for a tape written anyway (red, before the steps)
    struct Picture {
        std::string caption;  // "3. Roughing I, unit 1 Locator pocket"
        std::string png;      // PNG bytes
    };
    std::optional<Picture> setupPicture;
    std::vector<Picture> pictures;  // the steps', in order
    std::string picturesNote;       // why there are none or too few
    std::string total;
};

Content content(const Plan& plan, const SheetOptions& options);

}  // namespace taiwa::sheet
