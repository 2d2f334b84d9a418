// Plan lookups: a tool by id, the notes for the sheet.
#include "model/plan.h"

#include <algorithm>

namespace taiwa {

const Tool* Plan::tool(int id) const
{
    const auto it = std::find_if(tools.begin(), tools.end(), [id](const Tool& t) { return t.id == id; });
    return it == tools.end() ? nullptr : &*it;
}

std::vector<std::string> Plan::notes() const
{
    std::vector<std::string> out;
    for (const auto& d : diagnostics)
        if (d.severity == Severity::Warning) out.push_back(d.message);
    return out;
}

}  // namespace taiwa
