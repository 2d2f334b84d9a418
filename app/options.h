// Parsing of the command line into an Options value (no side effects).
#pragma once

#include "model/job.h"
#include "model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::app {

enum class Command {
    Station, Check, Export, Verify, Render, Import, FigureFromDxf, ImportTools, Store, ListMachines, ListDialects, Help, Version
};

struct Options {
    Command command = Command::Station;
    std::string job;                  // JOB argument (import: the STEP file; figure-from-dxf: the DXF file;
                                      // import-tools: the SQLite library; store history, unlock: the job's name)
    std::string storeAction;          // store: list, history, locks or unlock
    std::string out;                  // --out
    std::string dialect;              // --dialect; empty: the job's, else linuxcnc
    std::optional<LengthUnit> units;  // --units (figure-from-dxf: the drawing's)
    std::string tools;                // --tools
    std::optional<int> step;          // --step K (1-based); empty = all
    bool stock = false;               // --stock
    int width = 800, height = 600;    // --size WxH
    std::string view = "iso";         // --view
    std::string material = "steel-s45c";  // --material (import)
    std::optional<double> surfaceSpacing;   // --surface MM (import): the face set as a SURFACE unit, sampled every MM
    std::optional<double> resolution;  // --resolution (verify, export) [mm]; none: verify::defaultResolution
    bool json = false;                // --json (verify)
    bool force = false;               // --force (export): write a tape the verification finds fault with;
                                      // (store unlock): release a lock whose station is connected
    bool cache = true;                // verify, export: the verification cache (--no-cache: verify afresh, store nothing read)
    bool pictures = true;             // export: the sheet's pictures of the steps (--no-pictures: none)
    std::vector<std::string> layers;  // --layers A,B (figure-from-dxf); empty: all
    std::optional<double> gap;        // --gap MM (figure-from-dxf): the gap tolerance
    std::string fromStore;            // --from-store NAME (export): the job from the shop server's store
};

// Fills `o`; fails with a message naming the bad argument.
Result<void> parseOptions(int argc, char** argv, Options& o);

}  // namespace taiwa::app
