// Code tables U, F, H: conversion from the typed number and their meaning.
#include "model/codes.h"

namespace taiwa {

std::optional<ToolUse> toolUseFromCode(int code)
{
    switch (code) {
    case 1: return ToolUse::Standard;
    case 6: return ToolUse::NoWallFinish;
    case 7: return ToolUse::Cored;
    case 8: return ToolUse::WallOnly;
    case 9: return ToolUse::RoughOnly;
    default: return std::nullopt;
    }
}

std::optional<WallFinish> wallFinishFromCode(int code)
{
    if (code >= 1 && code <= 3) return static_cast<WallFinish>(code);
    return std::nullopt;
}

std::optional<PilotHole> pilotHoleFromCode(int code)
{
    if (code == 0) return PilotHole::Drill;
    if (code == 9) return PilotHole::None;
    return std::nullopt;
}

bool hasRoughing(ToolUse u) { return u != ToolUse::Cored && u != ToolUse::WallOnly; }
bool hasFloorFinishing(ToolUse u) { return u != ToolUse::WallOnly && u != ToolUse::RoughOnly; }
bool hasWallFinishing(ToolUse u) { return u != ToolUse::NoWallFinish && u != ToolUse::RoughOnly; }

std::string_view meaning(ToolUse u)
{
    switch (u) {
    case ToolUse::Standard: return "roughing, floor finishing and wall finishing";
    case ToolUse::NoWallFinish: return "roughing and floor finishing, walls left as roughed";
    case ToolUse::Cored: return "floor and wall finishing of a pocket already cored";
    case ToolUse::WallOnly: return "wall finishing only";
    case ToolUse::RoughOnly: return "roughing only";
    }
    return "";
}

std::string_view meaning(WallFinish f)
{
    switch (f) {
    case WallFinish::SingleIncision: return "walls finished to full depth in one incision";
    case WallFinish::MultiIncision: return "walls finished in several Z incisions down to the floor";
    case WallFinish::TwoStage: return "walls semi-finished leaving alpha3, then finished";
    }
    return "";
}

std::string_view meaning(PilotHole h)
{
    switch (h) {
    case PilotHole::Drill: return "drill a pilot hole first";
    case PilotHole::None: return "no pilot hole, the roughing tool ramps in";
    }
    return "";
}

}  // namespace taiwa
