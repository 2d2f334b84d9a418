// Tool life accounting along the job-wide order: where a tool's remaining
// life runs out, a note for the sheet saying before which step to change it.
#include "tools/step_order.h"

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

namespace taiwa {

std::vector<ToolLifeNote> planToolLife(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library)
{
    std::vector<ToolLifeNote> notes;
    std::map<int, double> left;  // remaining minutes of the tool now in the magazine
    for (std::size_t k = 0; k < orderedSteps.size(); ++k) {
        const Step& s = orderedSteps[k];
        if (!s.tool || !s.minutes) continue;
        const int id = s.tool->toolId;
        const auto it = std::find_if(library.begin(), library.end(), [id](const Tool& t) { return t.id == id; });
        if (it == library.end() || it->lifeMinutes <= 0) continue;
        if (!left.count(id)) left[id] = it->remainingLife();
        if (*s.minutes > left[id]) {
            notes.push_back({static_cast<int>(k), id,
                             fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                              "T{} ({:g} mm {}) reaches its life during step {} (unit {} {}): "
                                                              "{:.1f} min left, the step needs {:.1f} min; change it for a "
                                                              "fresh one before that step"),
                                         id, it->diameter, toString(it->type), k + 1, s.unit + 1, s.label(),
                                         std::max(0.0, left[id]), *s.minutes)});
            left[id] = it->lifeMinutes;  // the change is planned: a fresh tool
        }
        left[id] -= *s.minutes;
    }
    return notes;
}

}  // namespace taiwa
