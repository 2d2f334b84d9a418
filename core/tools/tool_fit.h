// What a step asks of a tool (type, corner radius to fit, diameter bounds,
// depth of cut, taper angle) and the search of the library for it.
#pragma once

#include "model/tool.h"

#include <string>
#include <vector>

namespace taiwa::tools {

struct Fit {
    ToolType type = ToolType::FlatEndMill;
    double cornerRadius = 0.0;  // the tool radius must not exceed it (0 = no corner to fit)
    double minDiameter = 0.0;
    double maxDiameter = 1e9;
    double depth = 0.0;         // depth the flutes must reach
    double reach = 0.0;         // depth the stick-out must reach (flutes may be shorter)
    double taperAngle = 0.0;    // taper end mills: exactly this angle
    bool centreCutting = false; // it ramps into solid material (no pilot hole)
};

bool fits(const Tool& t, const Fit& f, const std::string& material);
std::string whyNot(const Tool& t, const Fit& f, const std::string& material);
const Tool* largestFitting(const std::vector<Tool>& library, const Fit& f, const std::string& material);
const Tool* smallestFitting(const std::vector<Tool>& library, const Fit& f, const std::string& material);
// "no flat end mill in the library fits: ... (the smallest has radius 1 mm)".
std::string noFitMessage(const std::vector<Tool>& library, const Fit& f, const std::string& material,
                         const std::string& what);

}  // namespace taiwa::tools
