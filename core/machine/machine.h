// The machines a job can name, as data (resources/machines/*.json, compiled
// in, overridable by the shop's own files in the user's config folder): what
// kind each is (a milling machine or a lathe), its travel, spindle and feed
// limits, rapid rates, tool changer or turret, and for a lathe that X is
// programmed as a diameter and the chuck's envelope. A definition is
// validated when read; every problem names the file, the line and the key.
#pragma once

#include "machine/lathe_kinds.h"
#include "model/local_name.h"
#include "model/result.h"

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace taiwa {

enum class MachineKind { Mill, Lathe };
const char* toKey(MachineKind k);  // "mill", "lathe"

struct AxisTravel {
    double min = 0.0, max = 0.0;  // mm
};

struct Machine {
    std::string id;    // "vmc": what a job's "machine" names
    std::string name;  // "Vertical machining centre"
    LocalNames names;  // the name in other languages ("ja": "立形マシニングセンタ"), for the station
    std::string source;  // where it was read from ("built in: vmc.json")
    MachineKind kind = MachineKind::Mill;
    bool xDiameter = false;                    // lathes: X is programmed as a diameter
    std::map<std::string, AxisTravel> travel;  // "x", "y", "z"
    double maxSpindleSpeed = 0.0;              // rpm
    double maxFeed = 0.0;                      // mm/min
    std::map<std::string, double> rapid;       // mm/min per axis
    int toolPockets = 0;                       // mills: the tool changer's pockets
    int turretStations = 0;                    // lathes
    double chuckDiameter = 0.0;                // lathes [mm]
    double maxBarDiameter = 0.0;               // lathes: the largest bar through the spindle [mm]
    double jawLength = 0.0;                    // lathes: how far the jaws grip along Z [mm]
    LatheLayout layout;                        // lathes: two paths or a gang slide (lathe_kinds.h); none: one turret
    std::string coolantOn = "M8", coolantOff = "M9";
    // Motion (machine/motion_time.h): each axis' acceleration [mm/s²] (none:
    // the machine time is not modelled), how many blocks the control looks
    // ahead to keep its speed through corners (1: it stops at each block's
    // end), and how far it may leave a corner to round it [mm] (G64 P).
    std::map<std::string, double> acceleration;
    int lookAhead = 1;
    double cornerTolerance = 0.01;
    // The slowest axis' rapid rate [mm/min]; 0 when none is given.
    double slowestRapid() const
    {
        double slowest = 0.0;
        for (const auto& [axis, rate] : rapid) slowest = slowest == 0.0 ? rate : std::min(slowest, rate);
        return slowest;
    }
};

// Reads one machine definition; `source` names it in every message.
Result<Machine> readMachine(const std::string& text, const std::string& source);

// The machines this program knows: the shipped definitions, each replaced
// or joined by the user's (*.json in userMachineFolder(), read once).
const std::vector<Machine>& machineLibrary();
// The user's definitions that were left out, one sentence each naming the
// file, the line and the key.
const std::vector<std::string>& machineLibraryProblems();
// $XDG_CONFIG_HOME/taiwa/machines, else ~/.config/taiwa/machines.
std::string userMachineFolder();
const Machine* findMachine(const std::string& id);
std::vector<std::string> machineIds();

}  // namespace taiwa
