// Code tables U, F, H: conversion from the typed number and their meaning,
// each table's codes and texts in one list.
#include "model/codes.h"

#include <array>

namespace taiwa {

namespace {

// One code of a table and what it means.
template <class Code>
struct CodeRow {
    Code code;
    std::string_view meaning;
};

constexpr std::array<CodeRow<ToolUse>, 5> kToolUses{{
    {ToolUse::Standard, "roughing, floor finishing and wall finishing"},
    {ToolUse::NoWallFinish, "roughing and floor finishing, walls left as roughed"},
    {ToolUse::Cored, "floor and wall finishing of a pocket already cored"},
    {ToolUse::WallOnly, "wall finishing only"},
    {ToolUse::RoughOnly, "roughing only"},
}};

constexpr std::array<CodeRow<WallFinish>, 3> kWallFinishes{{
    {WallFinish::SingleIncision, "walls finished to full depth in one incision"},
    {WallFinish::MultiIncision, "walls finished in several Z incisions down to the floor"},
    {WallFinish::TwoStage, "walls semi-finished leaving alpha3, then finished"},
}};

constexpr std::array<CodeRow<PilotHole>, 2> kPilotHoles{{
    {PilotHole::Drill, "drill a pilot hole first"},
    {PilotHole::None, "no pilot hole, the roughing tool ramps in"},
}};

// The table's row of the typed number, or of the named code; null when it has none.
template <class Code, std::size_t N>
const CodeRow<Code>* rowOf(const std::array<CodeRow<Code>, N>& table, int code)
{
    for (const auto& row : table)
        if (static_cast<int>(row.code) == code) return &row;
    return nullptr;
}

template <class Code, std::size_t N>
std::optional<Code> fromCode(const std::array<CodeRow<Code>, N>& table, int code)
{
    const auto* row = rowOf(table, code);
    return row ? std::optional<Code>(row->code) : std::nullopt;
}

template <class Code, std::size_t N>
std::string_view meaningOf(const std::array<CodeRow<Code>, N>& table, Code code)
{
    const auto* row = rowOf(table, static_cast<int>(code));
    return row ? row->meaning : "";
}

}  // namespace

std::optional<ToolUse> toolUseFromCode(int code) { return fromCode(kToolUses, code); }
std::optional<WallFinish> wallFinishFromCode(int code) { return fromCode(kWallFinishes, code); }
std::optional<PilotHole> pilotHoleFromCode(int code) { return fromCode(kPilotHoles, code); }

bool hasRoughing(ToolUse u) { return u != ToolUse::Cored && u != ToolUse::WallOnly; }
bool hasFloorFinishing(ToolUse u) { return u != ToolUse::WallOnly && u != ToolUse::RoughOnly; }
bool hasWallFinishing(ToolUse u) { return u != ToolUse::NoWallFinish && u != ToolUse::RoughOnly; }

std::string_view meaning(ToolUse u) { return meaningOf(kToolUses, u); }
std::string_view meaning(WallFinish f) { return meaningOf(kWallFinishes, f); }
std::string_view meaning(PilotHole h) { return meaningOf(kPilotHoles, h); }

}  // namespace taiwa
