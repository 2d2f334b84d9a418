// The messages of SIDE, side milling along a contour: its contour, codes,
// width, pins and room: the sentences of input processing (check/messages.h
// quotes lengths and tools for them) that only this module says, kept in its
// folder.
#pragma once

#include "check/messages.h"

#include <string>
#include <vector>

namespace taiwa::msg {

std::string sideContourNotNamed();
std::string sideCodeUnknown(const std::string& code, int value, const std::string& allowed);
std::string sideWidthNotAboveAllowance(Len width, Len alpha2);
std::string sideNoTool(const std::string& step, const std::string& why);
std::string sideChannelTooNarrow(const std::string& name, const std::string& tool, Len x, Len y);

}  // namespace taiwa::msg
