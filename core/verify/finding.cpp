// The verification's findings: their keys, their place on the tape and
// their words (templates the station translates, model/translate_noop.h).
#include "verify/verify.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace taiwa::verify {

const char* toKey(FindingKind k)
{
    switch (k) {
    case FindingKind::Gouge: return "gouge";
    case FindingKind::Collision: return "collision";
    case FindingKind::RapidIntoStock: return "rapid-into-stock";
    case FindingKind::TravelLimit: return "travel-limit";
    case FindingKind::RestMaterial: return "rest-material";
    case FindingKind::UnplannedMove: return "unplanned-move";
    case FindingKind::UnreadTape: return "unread-tape";
    case FindingKind::UnpairedWait: return "unpaired-wait";
    }
    return "?";
}

bool Report::fatal() const
{
    return std::any_of(findings.begin(), findings.end(), [](const Finding& f) { return f.fatal(); });
}

int Report::count(FindingKind k) const
{
    return static_cast<int>(std::count_if(findings.begin(), findings.end(), [k](const Finding& f) { return f.kind == k; }));
}

void placeOnTape(Report& report, const PostedProgram& program)
{
    // The first line of each move, and of each step.
    std::map<std::pair<int, int>, int> first;
    for (std::size_t i = 0; i < program.lines.size(); ++i) {
        const BlockSource& s = program.lines[i];
        if (s.step < 0) continue;
        first.try_emplace({s.step, s.move}, static_cast<int>(i) + 1);
        first.try_emplace({s.step, -1}, static_cast<int>(i) + 1);
    }
    for (Finding& f : report.findings) {
        const auto it = first.find({f.step, f.move});
        f.line = it != first.end() ? it->second : 0;
    }
}

std::string describe(const Finding& f, const Plan& plan)
{
    const LengthUnit u = plan.job.lengthUnit;
    const int digits = u == LengthUnit::Inch ? 4 : 3;
    const auto len = [&](double mm) { return fmt::format("{:.{}f} {}", fromMm(mm, u), digits, unitSymbol(u)); };
    // A lathe's position is X (a diameter) and Z, as its tape writes them.
    const bool lathe = plan.mmJob.bar.has_value();
    const auto at = [&](Point3 p) {
        if (lathe) return fmt::format("X{:.{}f} Z{:.{}f}", fromMm(p.x, u), digits, fromMm(p.z, u), digits);
        return fmt::format("X{:.{}f} Y{:.{}f} Z{:.{}f}", fromMm(p.x, u), digits, fromMm(p.y, u), digits, fromMm(p.z, u),
                           digits);
    };
    std::string where = TAIWA_TRANSLATE_NOOP("taiwa::msg", "the job");
    if (f.step >= 0 && f.step < static_cast<int>(plan.steps.size())) {
        const Step& s = plan.steps[static_cast<std::size_t>(f.step)];
        const std::string& name = s.unit < static_cast<int>(plan.job.units.size()) ? plan.job.units[s.unit].name : "";
        where = name.empty() ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "step {} ({}, unit {})"), f.step + 1,
                                           s.label(), s.unit + 1)
                             : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "step {} ({}, unit {} '{}')"), f.step + 1,
                                           s.label(), s.unit + 1, name);
    }
    // A finding of a size at a place over an area (a gouge, material left):
    // the lathe's template (an area of the half-section) and the mill's.
    using AreaText = fmt::format_string<std::string, std::string, const double&>;
    struct AreaTexts {
        AreaText lathe, mill;
    };
    static constexpr AreaTexts gouge{TAIWA_TRANSLATE_NOOP("taiwa::msg", "gouge {} deep into the finished part at {}, over "
                                                                        "{:.3f} mm² of the half-section"),
                                     TAIWA_TRANSLATE_NOOP("taiwa::msg", "gouge {} deep into the finished part at {}, over "
                                                                        "{:.3f} mm²")};
    static constexpr AreaTexts rest{TAIWA_TRANSLATE_NOOP("taiwa::msg", "material left up to {} thicker than it should leave, thickest "
                                                                       "at {}, over {:.3f} mm² of the half-section"),
                                    TAIWA_TRANSLATE_NOOP("taiwa::msg", "material left up to {} above what it should leave, highest "
                                                                       "at {}, over {:.3f} mm²")};
    std::string what;
    switch (f.kind) {
    case FindingKind::Gouge:
    case FindingKind::RestMaterial: {
        const AreaTexts& t = f.kind == FindingKind::Gouge ? gouge : rest;
        what = fmt::format(lathe ? t.lathe : t.mill, len(f.size), at(f.position), f.area);
        break;
    }
    case FindingKind::Collision:
        what = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tool's {} runs {} into stock at {}"), f.part, len(f.size), at(f.position));
        break;
    case FindingKind::RapidIntoStock:
        what = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "rapid (G0) {} into stock at {}"), len(f.size), at(f.position));
        break;
    case FindingKind::TravelLimit:
        what = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the paths span {} more along {} than the machine '{}' travels"), len(f.size), f.part,
                           plan.job.machine);
        break;
    case FindingKind::UnplannedMove: {
        // The tape's own: X or Y may be unknown before the first move after the first tool change (a lathe's: X and Z).
        const auto coordinate = [&](double mm) {
            return std::isnan(mm) ? std::string("?") : fmt::format("{:.{}f}", fromMm(mm, u), digits);
        };
        const Point3& p = f.position;
        const std::string to = "X" + coordinate(p.x) + (lathe ? "" : " Y" + coordinate(p.y)) + " Z" + coordinate(p.z);
        what = f.size > 0.0 ? fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tape has a {} the plan does not, to {}, "
                                                                              "{} into stock"),
                                          f.part, to, len(f.size))
                            : fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tape has a {} the plan does not, to {}"),
                                          f.part, to);
        break;
    }
    case FindingKind::UnreadTape:
        what = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the tape cannot be read back, so it is not verified "
                                                              "from here on: {}"),
                           f.part);
        break;
    case FindingKind::UnpairedWait:
        what = fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "the wait {} is not met by the other path's program at its turn: "
                                                              "both paths would stop there (a deadlock)"),
                           f.part);
        break;
    }
    // Where on the tape, when known: one template for each case, so that the
    // station translates the whole. A program other than the tape (a
    // two-path lathe's, a probing unit's) by its file's name.
    if (!f.program.empty() && f.line > 0)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}, in {} at line {}"), where, what, f.program, f.line);
    if (f.move >= 0 && f.line > 0)
        return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}, move {}, tape line {}"), where, what, f.move + 1,
                           f.line);
    if (f.move >= 0) return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}, move {}"), where, what, f.move + 1);
    if (f.line > 0) return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}, tape line {}"), where, what, f.line);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "{}: {}"), where, what);
}

}  // namespace taiwa::verify
