// The messages of units on contours of the figure (CP, AREA, SIDE, and the
// pockets' outline in the stock): naming, closing and crossing contours,
// islands, sharp corners. Sentences of input processing that only these
// modules say (check/messages.h quotes lengths and tools for them).
#pragma once

#include "check/messages.h"

#include <string>
#include <vector>

namespace taiwa::msg {

std::string outsideStock(const std::string& figure);
std::string contourNotNamed(const std::string& role);                 // role: "outline"
std::string contourUnknown(const std::string& name, const std::vector<std::string>& known);
std::string contourOpen(const std::string& name, const std::string& what, const std::string& role);  // what: "pocket"
std::string contourCrossesItself(const std::string& name);
std::string islandOutside(const std::string& island, const std::string& what, const std::string& outline);
std::string islandsOverlap(const std::string& a, const std::string& b);
std::string sharpInsideCorner(const std::string& name, Len x, Len y);

}  // namespace taiwa::msg
