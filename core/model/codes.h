// The code tables of the milling modules (spec "Code tables"): tool-use type
// U, finishing type F and pilot-hole code H, as named types with their
// meaning as text for the form, the step list and the instruction sheet.
#pragma once

#include <optional>
#include <string_view>

namespace taiwa {

// Table 1: which steps exist.
enum class ToolUse : int {
    Standard = 1,      // roughing, floor finishing, wall finishing
    NoWallFinish = 6,  // roughing and floor finishing
    Cored = 7,         // floor and wall finishing: the pocket is already cored
    WallOnly = 8,      // wall finishing only
    RoughOnly = 9,     // roughing only
};

// Table 2: how walls are finished (M4 only).
enum class WallFinish : int {
    SingleIncision = 1,  // one step, the wall cut to full depth at once
    MultiIncision = 2,   // one step, several Z incisions down to the floor
    TwoStage = 3,        // semi-finish leaving alpha3, then the final pass
};

// Table 3: pilot (prepared) hole.
enum class PilotHole : int {
    Drill = 0,  // drill a pilot hole first
    None = 9,   // no pilot hole: the roughing tool ramps in
};

// Raw code to named code; nullopt for a value the table does not define.
std::optional<ToolUse> toolUseFromCode(int code);
std::optional<WallFinish> wallFinishFromCode(int code);
std::optional<PilotHole> pilotHoleFromCode(int code);

// Which steps a tool-use code asks for.
bool hasRoughing(ToolUse u);
bool hasFloorFinishing(ToolUse u);
bool hasWallFinishing(ToolUse u);

// One line a machinist reads, e.g. "1 – roughing, floor and wall finishing".
std::string_view meaning(ToolUse u);
std::string_view meaning(WallFinish f);
std::string_view meaning(PilotHole h);

}  // namespace taiwa
