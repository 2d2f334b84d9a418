// The machine's tool table (tool_table.h).
#include "post/tool_table.h"

#include "post/bound_tool.h"
#include "post/gcode_writer.h"
#include "post/lathe_post.h"
#include "post/number_format.h"
#include "turning/turn_tools.h"
#include "model/turn_path.h"

#include <fmt/format.h>

namespace taiwa {

namespace {

bool lathe(const Tool& t)
{
    return t.type == ToolType::TurningInsert || t.type == ToolType::Grooving || t.type == ToolType::Threading;
}

// The imaginary tip a turning tool is set up with (turn_tools): an insert
// 2 outside or 3 in a bore, a blade's front corner 1 (4 inside).
int tipOrientation(const Tool& t)
{
    if (t.type == ToolType::Grooving) return t.turning.inside ? 4 : 1;
    return turning::insertOrientation(t.turning.inside);
}

}  // namespace

std::string linuxcncToolTable(const std::vector<Tool>& tools, LengthUnit units)
{
    const int decimals = units == LengthUnit::Inch ? 4 : 3;
    const auto n = [&](double mm) { return post::formatNumber(fromMm(mm, units), decimals, false); };
    std::string out = fmt::format(";Taiwa tool library, {} tools, {}; lengths (Z) are measured on the machine\n", tools.size(),
                                  units == LengthUnit::Inch ? "inch" : "mm");
    for (const Tool& t : tools) {
        const std::string name = post::commentText(t.name, false);
        if (lathe(t))
            out += fmt::format("T{} P{} X0 Z0 D{} Q{} ;{}\n", t.id, t.id, n(2 * t.cornerRadius), tipOrientation(t), name);
        else
            out += fmt::format("T{} P{} Z0 D{} ;{}\n", t.id, t.id, n(t.diameter), name);
    }
    return out;
}

std::string fanucOffsetProgram(const std::vector<Tool>& tools, LengthUnit units, int programNumber)
{
    const int decimals = units == LengthUnit::Inch ? 4 : 3;
    const auto n = [&](double mm) { return post::formatNumber(fromMm(mm, units), decimals, true); };
    std::string out = fmt::format("%\nO{:04d} (TAIWA TOOL OFFSETS)\n(LENGTHS ARE MEASURED ON THE MACHINE)\n", programNumber);
    out += units == LengthUnit::Inch ? "G20\n" : "G21\n";
    for (const Tool& t : tools) {
        out += "(" + post::commentText(fmt::format("T{} {}", t.id, t.name), true) + ")\n";
        if (lathe(t)) out += fmt::format("G10 P{} R{} Q{}\n", t.id, n(t.cornerRadius), tipOrientation(t));
        else out += fmt::format("G10 L12 P{} R{}\n", t.id, n(t.diameter / 2));
    }
    out += "M30\n%\n";
    return out;
}

std::string linuxcncLatheToolTable(const std::vector<Step>& orderedSteps, const std::vector<Tool>& planTools, const std::string& stem)
{
    std::string out = fmt::format(";Taiwa lathe tool table for {}: turret stations, nose diameter D and tip orientation Q; inch "
                                  "(LinuxCNC's rs274 reads a tool table in inches; a machine set up in mm reads it in mm: "
                                  "D x 25.4); X and Z offsets are measured on the machine\n",
                                  stem.empty() ? std::string("TAIWA") : post::commentText(stem, false));
    for (const auto& [station, id] : latheStations(orderedSteps)) {
        const Tool& t = post::boundTool(planTools, id);
        const bool drill = t.type == ToolType::Drill || t.type == ToolType::CentreDrill;
        const double nose = drill ? 0.0 : t.cornerRadius;
        int orientation = 0;
        for (const auto& s : orderedSteps)
            if (s.tool && s.tool->toolId == id && turnOf(s)) {
                orientation = turnOf(s)->orientation;
                break;
            }
        out += fmt::format("T{} P{} X0 Z0 D{} Q{} ;library T{} {}\n", station, station, post::formatNumber(2.0 * nose / 25.4, 6, false),
                           orientation, id, post::commentText(t.name, false));
    }
    return out;
}

}  // namespace taiwa
