// The field descriptions of the M4 and M2D forms.
#include "ui/field_spec.h"

#include "model/codes.h"

#include <cmath>

namespace taiwa::ui {
namespace {

template <class M, class Get, class Set>
FieldSpec number(QString key, QString label, QStringList diag, Get get, Set set)
{
    FieldSpec f;
    f.key = std::move(key);
    f.label = std::move(label);
    f.diagFields = std::move(diag);
    f.get = [get](const MachiningUnit& u) -> std::optional<double> {
        if (const auto* m = std::get_if<M>(&u.module)) return get(*m);
        return std::nullopt;
    };
    f.set = [set](MachiningUnit& u, std::optional<double> v) {
        if (auto* m = std::get_if<M>(&u.module); m && v) set(*m, *v);
    };
    return f;
}

template <class Code>
std::vector<std::pair<int, QString>> codeItems(std::initializer_list<Code> codes)
{
    std::vector<std::pair<int, QString>> items;
    for (Code c : codes) {
        const auto text = meaning(c);
        // "1 – roughing, floor finishing and wall finishing": the code first, as on the drawing.
        const QString meaningText = QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
        items.emplace_back(static_cast<int>(c), QStringLiteral("%1 – %2").arg(static_cast<int>(c)).arg(meaningText));
    }
    return items;
}

template <class M>
FieldSpec code(QString key, QString label, std::vector<std::pair<int, QString>> items, int M::*member)
{
    FieldSpec f = number<M>(key, std::move(label), QStringList{key},
                            [member](const M& m) { return static_cast<double>(m.*member); },
                            [member](M& m, double v) { m.*member = static_cast<int>(std::lround(v)); });
    f.kind = FieldKind::Code;
    f.codes = std::move(items);
    return f;
}

std::vector<FieldSpec> makeM4()
{
    std::vector<FieldSpec> fs;
    for (int i = 0; i < 4; ++i) {
        const QString p = QStringLiteral("P%1").arg(i + 1);
        const QStringList diag{QStringLiteral("corners[%1]").arg(i), QStringLiteral("corners")};
        const auto idx = static_cast<std::size_t>(i);
        fs.push_back(number<M4Pocket>(p + ".x", p + " X", diag, [idx](const M4Pocket& m) { return m.corners[idx].x; },
                                      [idx](M4Pocket& m, double v) { m.corners[idx].x = v; }));
        fs.push_back(number<M4Pocket>(p + ".y", p + " Y", diag, [idx](const M4Pocket& m) { return m.corners[idx].y; },
                                      [idx](M4Pocket& m, double v) { m.corners[idx].y = v; }));
    }
    fs.push_back(number<M4Pocket>("r1", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "r1 (corner radius)"), {"cornerRadius"},
                                  [](const M4Pocket& m) { return m.cornerRadius; },
                                  [](M4Pocket& m, double v) { m.cornerRadius = v; }));
    fs.push_back(number<M4Pocket>("depth", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "T (depth)"), {"depth"}, [](const M4Pocket& m) { return m.depth; },
                                  [](M4Pocket& m, double v) { m.depth = v; }));
    fs.push_back(number<M4Pocket>("taper", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "S (taper, °/side)"), {"taper"}, [](const M4Pocket& m) { return m.taper; },
                                  [](M4Pocket& m, double v) { m.taper = v; }));
    fs.push_back(code<M4Pocket>("U", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "U (tool use)"),
                                codeItems({ToolUse::Standard, ToolUse::NoWallFinish, ToolUse::Cored, ToolUse::WallOnly,
                                           ToolUse::RoughOnly}),
                                &M4Pocket::toolUse));
    fs.push_back(code<M4Pocket>("F", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "F (wall finish)"),
                                codeItems({WallFinish::SingleIncision, WallFinish::MultiIncision, WallFinish::TwoStage}),
                                &M4Pocket::wallFinish));
    fs.push_back(code<M4Pocket>("H", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "H (pilot hole)"), codeItems({PilotHole::Drill, PilotHole::None}),
                                &M4Pocket::pilotHole));
    return fs;
}

std::vector<FieldSpec> makeM2D()
{
    std::vector<FieldSpec> fs;
    fs.push_back(number<M2DPocket>("X1", "X1", {"corner"}, [](const M2DPocket& m) { return m.corner.x; },
                                   [](M2DPocket& m, double v) { m.corner.x = v; }));
    fs.push_back(number<M2DPocket>("Y1", "Y1", {"corner"}, [](const M2DPocket& m) { return m.corner.y; },
                                   [](M2DPocket& m, double v) { m.corner.y = v; }));
    fs.push_back(number<M2DPocket>("L1", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "L1 (length X)"), {"L1"}, [](const M2DPocket& m) { return m.lengthX; },
                                   [](M2DPocket& m, double v) { m.lengthX = v; }));
    fs.push_back(number<M2DPocket>("L2", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "L2 (length Y)"), {"L2"}, [](const M2DPocket& m) { return m.lengthY; },
                                   [](M2DPocket& m, double v) { m.lengthY = v; }));
    fs.push_back(number<M2DPocket>("depth", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "T (depth)"), {"depth"}, [](const M2DPocket& m) { return m.depth; },
                                   [](M2DPocket& m, double v) { m.depth = v; }));
    fs.push_back(number<M2DPocket>("theta1", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "θ1 (left wall, °)"), {"theta1"},
                                   [](const M2DPocket& m) { return m.theta1; },
                                   [](M2DPocket& m, double v) { m.theta1 = v; }));
    FieldSpec t2;
    t2.key = "theta2";
    t2.label = QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "θ2 (right wall, °)");
    t2.diagFields = {"theta2"};
    t2.kind = FieldKind::OptionalNumber;
    t2.placeholder = QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "empty = same as θ1");
    t2.get = [](const MachiningUnit& u) -> std::optional<double> {
        if (const auto* m = std::get_if<M2DPocket>(&u.module)) return m->theta2;
        return std::nullopt;
    };
    t2.set = [](MachiningUnit& u, std::optional<double> v) {
        if (auto* m = std::get_if<M2DPocket>(&u.module)) m->theta2 = v;
    };
    fs.push_back(std::move(t2));
    fs.push_back(number<M2DPocket>("r1", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "r1 (corner radius)"), {"cornerRadius"},
                                   [](const M2DPocket& m) { return m.cornerRadius; },
                                   [](M2DPocket& m, double v) { m.cornerRadius = v; }));
    fs.push_back(code<M2DPocket>("U", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "U (tool use)"), codeItems({ToolUse::Standard, ToolUse::RoughOnly}),
                                 &M2DPocket::toolUse));
    fs.push_back(code<M2DPocket>("H", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "H (pilot hole)"), codeItems({PilotHole::Drill, PilotHole::None}),
                                 &M2DPocket::pilotHole));
    fs.push_back(number<M2DPocket>("scallop", QT_TRANSLATE_NOOP("taiwa::ui::FieldSpec", "Scallop height"), {"scallop"},
                                   [](const M2DPocket& m) { return m.scallop; },
                                   [](M2DPocket& m, double v) { m.scallop = v; }));
    return fs;
}

}  // namespace

const std::vector<FieldSpec>& m4Fields()
{
    static const std::vector<FieldSpec> fs = makeM4();
    return fs;
}

const std::vector<FieldSpec>& m2dFields()
{
    static const std::vector<FieldSpec> fs = makeM2D();
    return fs;
}

const std::vector<FieldSpec>& fieldsFor(const ModuleInput& m)
{
    return std::holds_alternative<M4Pocket>(m) ? m4Fields() : m2dFields();
}

QString modulePrefix(const ModuleInput& m) { return std::holds_alternative<M4Pocket>(m) ? "m4" : "m2d"; }

}  // namespace taiwa::ui
