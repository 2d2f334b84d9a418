// Post-processors (pipeline stage 5): CL data to NC data for one controller
// dialect, and the tape image list. A dialect is data plus a small class
// (docs/command-line.md "Dialects"); the writer owns all number formatting.
#pragma once

#include "model/diagnostic.h"
#include "model/job.h"
#include "model/step.h"
#include "model/tool.h"
#include "model/toolpath.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct PostOptions {
    std::string dialect = "linuxcnc";  // a dialect's name (dialectNames())
    LengthUnit units = LengthUnit::Millimetre;
    int programNumber = 1000;          // O-number (fanuc)
    std::string programName;           // job name for the header comment
    std::string fileStem;              // the tape's file name without extension
    std::string material;              // for speeds and feeds
    std::string machine;               // the job's machine, named in the header comment
    std::string workOffset = "G54";    // the job's: G54..G59; G54.1 P1..P48 (fanuc); G59.1..G59.3 (linuxcnc)
    std::vector<std::string> unitNames;  // the operator's name of each unit (by index; empty: none), in the step comments
    bool coolant = true;
    double safeZ = 5.0;                // [mm] above the stock top
    // Milling jobs: the stock block's corners [mm] (HEIDENHAIN's BLK FORM).
    bool hasStock = false;
    Point3 stockMin{}, stockMax{};
    // Lathe jobs: the point the turret retracts to for a tool change (X as
    // a diameter), and whether roughing may be the control's own cycle
    // (G71) where a step has one; false: the explicit passes.
    double latheChangeX = 150.0, latheChangeZ = 50.0;
    bool turningCycles = true;
};

// Where an NC block came from: the step (index into the ordered steps) and
// the move within its path; -1 for blocks of the program frame.
struct BlockSource {
    int step = -1;
    int move = -1;
};

struct PostedProgram {
    std::string nc;                    // the tape
    std::vector<BlockSource> lines;    // one per line of `nc`
    std::string tapeImage;             // printable listing: sequence numbers, block count, tape length
};

std::vector<std::string> dialectNames();
bool isDialect(const std::string& name);

// Why the dialect's controller cannot select `workOffset` (a job's
// "workOffset"), as a diagnostic of that job field; nothing when it can (or
// the dialect is unknown: that is postProcess's to refuse).
std::optional<Diagnostic> workOffsetProblem(const std::string& dialect, const std::string& workOffset);

// Steps in machining order, each with tool and path. Throws Refusal
// (model/result.h) for an unknown dialect, one that cannot write the job, a
// work offset the dialect's controller does not have, or a tool with no
// cutting data for the material; std::logic_error for a step without its
// tool or path, or a tool not in `library` (planJob binds them: a bug).
PostedProgram postProcess(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library,
                          const PostOptions& options);

}  // namespace taiwa
