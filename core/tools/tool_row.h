// One row of the tools table, as both tool libraries read it: the station's
// SQLite file (tool_library.cpp) and the shop server (pg_tool_rows.cpp)
// select "id, " followed by kToolColumns, write their rows in the same
// order, and turn each row into a Tool with toolFromRow.
#pragma once

#include "model/result.h"
#include "model/tool.h"
#include "model/translate_noop.h"
#include "tools/turning_text.h"

#include <fmt/format.h>

#include <string>

namespace taiwa {

// The tools table's columns after its id: column k of a row read as
// "id, kToolColumns" is the (k+1)-th here.
inline constexpr const char* kToolColumns = "name, type, diameter, corner_radius, taper_angle, point_angle, flute_length, stickout, "
                                            "holder, flutes, life_minutes, used_minutes, centre_cutting, turning, holder_diameter, "
                                            "holder_length";

// The tool of one row. `Row` gives integer(c), real(c), text(c) and flag(c)
// (a boolean, as its database stores one) of its columns; `library` names
// the library in the refusals.
template <class Row>
Result<Tool> toolFromRow(const Row& r, const std::string& library)
{
    Tool t;
    t.id = static_cast<int>(r.integer(0));
    t.name = r.text(1);
    const auto type = toolTypeFromKey(r.text(2));
    if (!type) return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool {} has an unknown type '{}'"), library, t.id, r.text(2))};
    t.type = *type;
    t.diameter = r.real(3);
    t.cornerRadius = r.real(4);
    t.taperAngle = r.real(5);
    t.pointAngle = r.real(6);
    t.fluteLength = r.real(7);
    t.stickout = r.real(8);
    t.holder = r.text(9);
    t.flutes = static_cast<int>(r.integer(10));
    t.lifeMinutes = r.real(11);
    t.usedMinutes = r.real(12);
    t.centreCutting = r.flag(13);
    const auto turning = turningFrom(r.text(14));
    if (!turning)
        return Failure{fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: tool {} has unreadable lathe data '{}'"), library, t.id, r.text(14))};
    t.turning = *turning;
    t.holderDiameter = r.real(15);
    t.holderLength = r.real(16);
    return t;
}

}  // namespace taiwa
