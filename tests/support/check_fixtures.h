// Fixtures of the input-check tests: a hand-made tool library, an M4 and an
// M2D unit that pass, a job of units, checkJob on it, and EXPECT_ONLY (the
// diagnostics are exactly one, with that unit, field and message). Header
// only.
#pragma once

#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "job/job_check.h"

#include <QByteArray>
#include <QtTest>

#include <string>
#include <vector>

namespace taiwa::test {

inline Tool tool(int id, ToolType type, double diameter, double taper = 0.0)
{
    Tool t;
    t.id = id;
    t.name = "tool " + std::to_string(id);
    t.type = type;
    t.diameter = diameter;
    t.taperAngle = taper;
    return t;
}

inline const std::vector<Tool> kLibrary{
    tool(1, ToolType::Drill, 5),          tool(2, ToolType::FlatEndMill, 2),  tool(3, ToolType::FlatEndMill, 6),
    tool(4, ToolType::FlatEndMill, 10),   tool(5, ToolType::FlatEndMill, 16), tool(6, ToolType::TaperEndMill, 2, 3),
    tool(7, ToolType::BallEndMill, 4),
};

inline M4Pocket m4(double x0 = 20, double y0 = 20, double w = 100, double h = 60)
{
    M4Pocket p;
    p.corners = {{{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}}};
    p.cornerRadius = 8;
    p.depth = 12;
    return p;
}

inline M2DPocket m2d()
{
    M2DPocket p;
    p.corner = {130, 20};
    p.lengthX = 60;
    p.lengthY = 50;
    p.depth = 10;
    p.theta1 = 20;
    p.cornerRadius = 5;
    return p;
}

inline Job job(std::vector<ModuleInput> modules)
{
    Job j;
    j.name = "test";
    j.stock = {0, 0, 200, 150, 40};
    for (auto& m : modules) j.units.push_back({"", std::move(m)});
    return j;
}

inline Diagnostics check(const Job& j, const std::vector<Tool>& library = kLibrary)
{
    return checkJob(j, TechnologyTable::builtIn(), library);
}

inline QByteArray dump(const Diagnostics& ds)
{
    QByteArray out;
    for (const auto& d : ds) out += QByteArray::fromStdString(format("job", d)) + "\n";
    return out;
}

// Exactly one diagnostic, on `unit` (0 = job level) and `field`, whose message contains `text`.
inline bool only(const Diagnostics& ds, int unit, const std::string& field, const std::string& text)
{
    if (ds.size() != 1) return false;
    const Diagnostic& d = ds[0];
    const bool unitOk = unit == 0 ? !d.unit.has_value() && d.module.empty() : d.unit == unit;
    return d.severity == Severity::Error && unitOk && d.field == field && d.message.find(text) != std::string::npos;
}

#define EXPECT_ONLY(ds, unit, field, text)                                                                             \
    do {                                                                                                               \
        const Diagnostics found_ = (ds);                                                                               \
        QVERIFY2(only(found_, unit, field, text), dump(found_).constData());                                           \
    } while (0)


}  // namespace taiwa::test
