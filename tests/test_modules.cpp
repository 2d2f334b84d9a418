// The contract of a module's door (core/modules/module_kind.h), checked on
// every registered module kind, so a new module is held to it without a test
// of its own: its default unit checks clean and plans; it survives the job
// file; every form field reads back what it sets; lengths convert both ways;
// its name finds it in the registry.
#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/registry.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "model/turn_path.h"

#include <QtTest>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

using namespace taiwa;

namespace {

Job jobWith(const ModuleKind& kind)
{
    Job j;
    j.name = std::string("default ") + kind.name();
    j.stock = {0, 0, 200, 150, 40};
    if (kind.machineKind() == MachineKind::Lathe) {  // a turning module: a lathe and a bar
        j.machine = "lathe";
        j.bar = BarStock{50, 100, 1, 0};
        j.stock = {};  // a lathe job's file holds its bar, not a block
    }
    j.units.push_back({"u", kind.makeDefault(j.stock)});
    j.figure = kind.defaultFigure(j.stock);  // contour units: the contours their default unit names
    return j;
}

}  // namespace

class TestModules : public QObject {
    Q_OBJECT
private slots:
    void registryFindsEveryKindByName()
    {
        QVERIFY(moduleKinds().size() >= 2);
        for (const ModuleKind* k : moduleKinds()) {
            QCOMPARE(findModuleKind(k->name()), k);
            QCOMPARE(std::string(k->makeDefault({}).name()), std::string(k->name()));
            QVERIFY(std::string(k->drawing()).starts_with(":/modules/"));
            QVERIFY(!std::string(k->paletteText()).empty());
        }
        QVERIFY(!findModuleKind("M99"));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, moduleKind(ModuleInput{}));
    }

    void defaultUnitChecksCleanAndPlans()
    {
        for (const ModuleKind* k : moduleKinds()) {
            const Job j = jobWith(*k);
            const Diagnostics ds = checkJob(j, TechnologyTable::builtIn(), defaultToolLibrary());
            QVERIFY2(!hasErrors(ds), qPrintable(QString::fromStdString(ds.empty() ? "" : format("job", ds.front()))));
            const Plan plan = planJob(j, TechnologyTable::builtIn(), defaultToolLibrary());
            QVERIFY2(plan.ok(), k->name());
            // A machining unit plans steps; a setup unit (probing) hands on its
            // setup instead; a turning unit its steps and the profile they cut.
            if (k->machineKind() == MachineKind::Lathe) QVERIFY2(!plan.steps.empty() && !plan.turned.empty(), k->name());
            else QVERIFY2(int(!plan.steps.empty()) + int(!plan.setups.empty()) + int(!plan.turned.empty()) == 1, k->name());
            for (const Step& s : plan.steps) {
                QCOMPARE(s.module, std::string(k->name()));
                QVERIFY(s.tool && (s.path || turnOf(s)) && s.minutes);
            }
        }
    }

    void unitSurvivesTheJobFile()
    {
        for (const ModuleKind* k : moduleKinds()) {
            const Job j = jobWith(*k);
            const JobReadResult back = readJob(writeJob(j));
            QVERIFY2(back.job, k->name());
            QVERIFY(*back.job == j);
            QCOMPARE(writeJob(*back.job), writeJob(j));
        }
    }

    // Each value the operator can type survives the job file: a field set
    // away from its default is written under its key (the first of its
    // check fields, "corners" of "corners[2]", "start" of "start.z") and read
    // back the same, with nothing refused. A module's job-file table
    // (io/unit_keys.h) names each key once for its reader and its writer;
    // this holds the table to the form. A key the unit's variant does not use
    // (a hole pattern's pitch on a single hole) may be left out, but some
    // variant (another code of another field: a grid) must write it.
    void everyFieldSurvivesTheJobFile()
    {
        for (const ModuleKind* k : moduleKinds()) {
            for (const FormField& f : k->fields()) {
                const QString what = QString("%1 %2").arg(k->name(), f.key.c_str());
                const std::string key = f.diagFields.front().substr(0, f.diagFields.front().find_first_of("[."));
                // The variants: the default unit, then each code of each other code field.
                std::vector<std::pair<const FormField*, double>> variants{{nullptr, 0.0}};
                for (const FormField& g : k->fields())
                    if (&g != &f && g.kind == FormFieldKind::Code)
                        for (const auto& [code, label] : g.codes) variants.push_back({&g, double(code)});
                bool written = false;
                for (const auto& [g, code] : variants) {
                    Job j = jobWith(*k);
                    ModuleInput& m = j.units[0].module;
                    if (g) g->set(m, code);
                    if (f.isText())  // AREA's drawn points, SURFACE's curves and boundary (3-D points), or a name
                        f.setText(m, key == "points" ? "1, 2; 30, 4" : key.starts_with("curve") || key == "boundary" ? "1, 2, -3; 40, 5, -6" : "K9");
                    else f.set(m, f.kind == FormFieldKind::Code ? f.codes.back().first : f.whole ? 3.0 : 3.25);
                    const std::string text = writeJob(j);
                    const JobReadResult back = readJob(text);
                    QVERIFY2(back.job && back.diagnostics.empty(), qPrintable(what));
                    if (!nlohmann::json::parse(text)["units"][0].contains(key)) continue;
                    written = true;
                    const ModuleInput& r = back.job->units[0].module;
                    if (f.isText()) QVERIFY2(f.getText(r) == f.getText(m), qPrintable(what + ": " + f.getText(r).c_str()));
                    else QVERIFY2(f.get(r) == f.get(m), qPrintable(what));
                    break;
                }
                QVERIFY2(written, qPrintable(what + " is written by no variant of the unit"));
            }
        }
    }

    // A pocket's own step-over: through its form field it reaches its
    // roughing steps and makes their rings closer (more moves) than the
    // technology data's, survives the job file, and out of range it is
    // refused on its field in the technology's words.
    void unitStepOverOverridesTheTechnology()
    {
        int pockets = 0;
        for (const ModuleKind* k : moduleKinds()) {
            const auto field = std::find_if(k->fields().begin(), k->fields().end(), [](const FormField& f) { return f.key == "stepOver"; });
            if (field == k->fields().end()) continue;  // not a pocket
            ++pockets;
            const Job plain = jobWith(*k);
            Job fine = plain;
            field->set(fine.units[0].module, 0.1);
            QCOMPARE(field->get(fine.units[0].module), std::optional<double>(0.1));
            // Roughing: a pocket's, face milling's layers, or side milling's roughing passes.
            const auto roughing = [](const Step& s) {
                return s.kind == StepKind::Roughing || s.kind == StepKind::FaceMilling ||
                       s.machiningType == MachiningType::SideMilling;
            };
            const auto roughingMoves = [&](const Plan& p) {
                std::size_t n = 0;
                for (const Step& s : p.steps)
                    if (roughing(s)) n += s.path->moves.size();
                return n;
            };
            const Plan a = planJob(plain, TechnologyTable::builtIn(), defaultToolLibrary());
            const Plan b = planJob(fine, TechnologyTable::builtIn(), defaultToolLibrary());
            QVERIFY2(a.ok() && b.ok(), k->name());
            for (const Step& s : b.steps)
                if (roughing(s)) QCOMPARE(millingOf(s).stepOver, std::optional<double>(0.1));
            QVERIFY2(roughingMoves(b) > roughingMoves(a), k->name());
            const JobReadResult back = readJob(writeJob(fine));
            QVERIFY(back.job && *back.job == fine);
            field->set(fine.units[0].module, 0.95);
            const Diagnostics ds = checkJob(fine, TechnologyTable::builtIn(), defaultToolLibrary());
            QVERIFY(!ds.empty());
            QCOMPARE(ds[0].field, std::string("stepOver"));
            QVERIFY2(ds[0].message.find("the step-over") != std::string::npos && ds[0].message.find("0.9") != std::string::npos,
                     ds[0].message.c_str());
        }
        QCOMPARE(pockets, 5);  // M4, M2D, CP, FACE (its passes, not rings) and SIDE
    }

    void everyFormFieldReadsBackWhatItSets()
    {
        for (const ModuleKind* k : moduleKinds()) {
            QVERIFY(!k->fields().empty());
            ModuleInput m = k->makeDefault({});
            for (const FormField& f : k->fields()) {
                if (f.isText()) {  // contour names: text, not numbers
                    f.setText(m, "K9");
                    QCOMPARE(f.getText(m), std::string("K9"));
                    QVERIFY(!f.label.empty() && !f.diagFields.empty());
                    continue;
                }
                const double v = f.kind == FormFieldKind::Code ? f.codes.back().first : f.whole ? 3.0 : 3.25;
                f.set(m, v);
                QVERIFY2(f.get(m) && *f.get(m) == v, f.key.c_str());
                QVERIFY(!f.label.empty() && !f.diagFields.empty());
                if (f.kind == FormFieldKind::OptionalNumber) {
                    f.set(m, std::nullopt);
                    QVERIFY(!f.get(m));
                }
            }
        }
    }

    void lengthsConvertBothWays()
    {
        for (const ModuleKind* k : moduleKinds()) {
            const ModuleInput mm = k->makeDefault({});
            ModuleInput m = mm;
            m.convertLengths([](double v) { return v / 25.4; });
            QVERIFY(!(m == mm));
            m.convertLengths([](double v) { return v * 25.4; });
            // Every field within rounding of the original.
            for (const FormField& f : k->fields()) {
                const auto a = f.get(mm), b = f.get(m);
                QCOMPARE(a.has_value(), b.has_value());
                if (a) QVERIFY2(std::abs(*a - *b) <= 1e-12 * std::max(1.0, std::abs(*a)), f.key.c_str());
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestModules)
#include "test_modules.moc"
