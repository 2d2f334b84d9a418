// The module's door owns its steps (issue 32): the stages outside a module
// name none of its step kinds, a step's own data travels in its payload,
// its path, move estimate and order come from its module, and each step is
// bound once to its tool and its speeds and feeds, so that a library edited
// after planning cannot change what is posted from the plan; and the door
// checks every module's tool pins against the module's own step keys.
#include "io/json_fields.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "model/turn_path.h"
#include "modules/face/face.h"
#include "modules/inclined_face.h"
#include "modules/side/side.h"
#include "modules/registry.h"
#include "post/post.h"
#include "support/hand_plan.h"
#include "support/support.h"
#include "tools/tool_library.h"
#include "tools/cutting.h"
#include "tools/step_order.h"

#include <QDirIterator>
#include <QRegularExpression>
#include <QtTest>

#include <algorithm>
#include <functional>
#include <set>

using namespace taiwa;

namespace {

// The places in `text` that name a step kind, as "line: text".
QStringList stepKindNames(const QString& text)
{
    QStringList found;
    const QStringList lines = text.split('\n');
    for (int i = 0; i < lines.size(); ++i)
        if (lines[i].contains("StepKind::")) found << QString("%1: %2").arg(i + 1).arg(lines[i].trimmed());
    return found;
}

struct Tagged {
    static constexpr const char* kName = "tagged";
    int tag = 0;
    friend bool operator==(const Tagged&, const Tagged&) = default;
};
struct Other {
    static constexpr const char* kName = "other";
    friend bool operator==(const Other&, const Other&) = default;
};

Step stepOf(int unit, const char* module, StepKind kind, int number, int tool)
{
    Step s;
    s.unit = unit;
    s.module = module;
    s.kind = kind;
    s.number = number;
    s.tool = ToolChoice{tool, ""};
    return s;
}

// The places in `text` that look a tool up in a library by its id, as
// "line: text": findTool, or a search of its own by id (as the milling post
// once had).
QStringList toolLookUps(const QString& text)
{
    QStringList found;
    const QStringList lines = text.split('\n');
    for (int i = 0; i < lines.size(); ++i)
        if ((lines[i].contains("findTool(") || (lines[i].contains("find_if(") && lines[i].contains(".id =="))) &&
            !lines[i].trimmed().startsWith("//"))
            found << QString("%1: %2").arg(i + 1).arg(lines[i].trimmed());
    return found;
}

// A door that gives its adapter neither a job-file table nor a check, and
// overrides neither reader, writer nor check, and has no description file:
// using them is a bug of the program, not an operator's error.
struct BareUnit {
    static constexpr const char* kName = "BARE";
    static constexpr int kSinceFormatVersion = 1;
    void convertLengths(const LengthMap&) {}
    friend bool operator==(const BareUnit&, const BareUnit&) = default;
};

class BareKind final : public ModuleKindOf<BareUnit> {
public:
    ModuleInput makeDefault(const Stock&) const override { return BareUnit{}; }

protected:
    std::optional<Quad> outline(const BareUnit&) const override { return std::nullopt; }
    void move(BareUnit&, Point2) const override {}
    std::vector<Step> planInput(const BareUnit&, const UnitPlanContext&, Diagnostics&) const override { return {}; }
};

}  // namespace

class TestModuleDoor : public QObject {
    Q_OBJECT

private slots:
    // No stage outside core/modules/ and core/model/ dispatches on a step
    // kind: a new module's steps reach them through its door.
    void stagesNameNoStepKind()
    {
        // The rule sees a kind where one is named (negative control).
        QCOMPARE(stepKindNames("int a;\n  if (s.kind == StepKind::Roughing) return;\n").size(), 1);
        QStringList found;
        int files = 0;
        QDirIterator it(test::sourcePath("core"), {"*.cpp", "*.h"}, QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString path = it.next();
            const QString rel = QDir(test::sourcePath("")).relativeFilePath(path);
            if (rel.startsWith("core/modules/") || rel.startsWith("core/model/")) continue;
            ++files;
            for (const QString& f : stepKindNames(QString::fromStdString(test::readFile(path)))) found << rel + ":" + f;
        }
        QVERIFY(files > 100);
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }

    void payloadCopiesComparesAndRefusesAnotherKind()
    {
        Step a;
        QVERIFY(a.payload.empty());
        a.payload = Tagged{7};
        Step b = a;  // a copy (sharing the payload until one of them is changed)
        QCOMPARE(b.payload.as<Tagged>().tag, 7);
        QVERIFY(a == b);
        b.payload = Tagged{8};
        QVERIFY(!(a == b));
        QCOMPARE(a.payload.as<Tagged>().tag, 7);
        QVERIFY(a.payload.getIf<Other>() == nullptr);
        QVERIFY_THROWS_EXCEPTION(std::logic_error, a.payload.as<Other>());
        b.payload = StepPayload{};
        QVERIFY(!(a == b) && !(b == a));
    }

    // A turning step's data and an inclined face are payloads, as every
    // module's own data is: the step names neither (model/step.h), turnOf
    // finds the one and nothing in a step that holds another, and copies
    // share them. The step's size is printed for issue 35 (its memory).
    void turningAndInclinedFaceAreThePayload()
    {
        QString code = QString::fromStdString(test::readFile(test::sourcePath("core/model/step.h")));
        code.remove(QRegularExpression("//[^\n]*"));  // its comments may say where the payloads are
        QVERIFY(code.contains(QRegularExpression("StepPayload payload(\\{\\})?;")));
        for (const char* name : {"TurnStep", "InclinedFace", "scallop", "turn_path"})  // InclinedFaceFinishing is a kind
            QVERIFY2(!code.contains(QRegularExpression(QString("\\b%1\\b").arg(name))),
                     qPrintable(QString("core/model/step.h names %1, a module's own data").arg(name)));

        Step milled;
        QVERIFY(turnOf(milled) == nullptr);
        milled.payload = InclinedFace{{{{0, 0}, {0, 40}}}, {{{3, 0}, {3, 40}}}, 20, 0.01};
        QVERIFY(turnOf(milled) == nullptr);
        QCOMPARE(milled.payload.as<InclinedFace>().scallop, 0.01);

        Step turned;
        TurnStep t;
        t.region = "E1";
        t.path.moves.push_back({TurnMove::Feed, {-10, 5}, {}, FeedKind::Cut});
        turned.payload = t;
        QVERIFY(turnOf(turned) && turnOf(turned)->region == "E1");
        Step copy = turned;
        QVERIFY(turnOf(copy) == turnOf(turned));  // copies share the payload until one is changed
        QVERIFY(copy == turned);
        t.region = "E2";
        copy.payload = t;
        QVERIFY(!(copy == turned));
        QCOMPARE(QString::fromStdString(turnOf(turned)->region), QString("E1"));
        qInfo("sizeof(Step) %zu bytes (its payload %zu, a TurnStep on the heap %zu, an InclinedFace %zu)", sizeof(Step),
              sizeof(StepPayload), sizeof(TurnStep), sizeof(InclinedFace));
    }

    // A step holds what every stage reads of every step; a milling step's
    // geometry (outline or region, depths, allowances, ...) is its payload:
    // alone (a pocket's) or as the member `milling` of its module's own data
    // (SIDE's passes). A turning step has none: millingOf gives it an empty
    // one, and filling one in is a bug. A changed copy leaves the original.
    void millingGeometryIsThePayload()
    {
        QString code = QString::fromStdString(test::readFile(test::sourcePath("core/model/step.h")));
        code.remove(QRegularExpression("//[^\n]*"));
        const qsizetype from = code.indexOf("struct Step {"), to = code.indexOf("\n};", from);
        QVERIFY(from >= 0 && to > from);
        const QString members = code.mid(from, to - from);
        for (const char* name : {"outline", "region", "reach", "inscribed", "position", "holeDiameter", "startDepth",
                                 "cutDepth", "wallTaper", "wallAllowance", "floorAllowance", "multiIncision", "stepOver"})
            QVERIFY2(!members.contains(QRegularExpression(QString("\\b%1\\b").arg(name))),
                     qPrintable(QString("Step names %1, a milling step's geometry").arg(name)));

        int milled = 0, turned = 0;
        for (const char* sample : {"plate.taiwa", "m2d-standard.taiwa", "cp-islands.taiwa", "side-boss.taiwa", "face-top.taiwa",
                                   "holes-grid.taiwa", "area-drawn-passes.taiwa", "surface-cover.taiwa", "lathe-turned-shaft.taiwa"}) {
            const Plan plan = test::samplePlan(sample);
            QVERIFY2(plan.ok(), sample);
            for (const Step& s : plan.steps) {
                const QByteArray where = QByteArray(sample) + ": " + QByteArray::fromStdString(s.label());
                if (turnOf(s)) {
                    ++turned;
                    QVERIFY2(!s.payload.milling() && millingOf(s) == MillingGeometry{}, where);
                    continue;
                }
                ++milled;
                QVERIFY2(s.payload.milling() == &millingOf(s), where);
                QVERIFY2(millingOf(s).cutDepth > millingOf(s).startDepth, where);
            }
        }
        QVERIFY(milled >= 20 && turned >= 3);

        const Plan side = test::samplePlan("side-boss.taiwa");
        QVERIFY(side.ok());
        const Step& s = side.steps.front();
        const auto* passes = s.payload.getIf<SidePasses>();
        QVERIFY(passes && &passes->milling == &millingOf(s));
        Step copy = s;
        editMilling(copy).cutDepth += 1.0;
        QCOMPARE(millingOf(copy).cutDepth, millingOf(s).cutDepth + 1.0);
        QVERIFY(copy.payload.getIf<SidePasses>() && copy.payload.getIf<SidePasses>()->offsets == passes->offsets);
        QVERIFY(!(copy == s));

        Step fresh;
        editMilling(fresh).cutDepth = 2.0;
        QVERIFY(fresh.payload.getIf<MillingGeometry>() && millingOf(fresh).cutDepth == 2.0);
        Step lathe = test::samplePlan("lathe-turned-shaft.taiwa").steps.front();
        QVERIFY(turnOf(lathe));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, editMilling(lathe));
    }

    // Each module makes its own steps' paths; one that has none to make
    // (a turned profile's come with its steps) refuses as a bug.
    void pathsComeThroughTheStepsModule()
    {
        const Plan plate = test::samplePlan("plate.taiwa");
        QVERIFY(plate.ok());
        for (const Step& s : plate.steps) {
            const Tool& t = *plate.tool(s.tool->toolId);
            QCOMPARE(moduleKind(s).toolPath(s, t, plate.technology, {}), *s.path);
            QVERIFY(estimateMoves(s, t, plate.technology, {}) >= 1);
        }
        Step turned = plate.steps.front();
        turned.module = "TURN";
        QVERIFY_THROWS_EXCEPTION(std::logic_error, makeToolPath(turned, *plate.tool(turned.tool->toolId), plate.technology, {}));
        turned.module = "NOPE";
        QVERIFY_THROWS_EXCEPTION(std::logic_error, moduleKind(turned));
    }

    // The job-wide order keeps what each module says of its own steps and
    // otherwise saves tool changes.
    void orderKeepsWhatTheDoorsSay()
    {
        // Unit 0 a pocket, unit 1 a face: the face first (FACE cuts before
        // other units); then the pocket's pilot hole before its roughing,
        // the roughing layers in their numbers, the floor last (M4's order).
        std::vector<Step> steps{stepOf(0, "M4", StepKind::Roughing, 2, 5), stepOf(0, "M4", StepKind::Roughing, 1, 5),
                                stepOf(0, "M4", StepKind::PilotHole, 1, 9), stepOf(0, "M4", StepKind::FloorFinishing, 1, 5),
                                stepOf(1, "FACE", StepKind::FaceMilling, 1, 7), stepOf(1, "FACE", StepKind::FaceMilling, 2, 7)};
        const std::vector<int> order = orderSteps(steps);
        QCOMPARE(order, (std::vector<int>{4, 5, 2, 1, 0, 3}));
        // The same steps with no rule at all: only the tools group them.
        const StepOrderRules none{[](const Step&, const Step&) { return false; }, [](const Step&) { return false; }};
        QCOMPARE(orderStepsBy(steps, none), (std::vector<int>{0, 1, 3, 2, 4, 5}));
    }

    // planJob binds every milling step to its speeds and feeds once; the
    // post reads them, so cutting data edited in the library after planning
    // changes nothing on the tape posted from the plan.
    // Every module with steps, through its door alone: a pin of a step the
    // module does not have is refused naming its steps, a pin of a tool not
    // in the library naming the tool, each once, on the pin's field; a pin
    // of a step it has, of a tool the library has, is not refused as a pin.
    // A door with no job-file table and no check of its own is a bug: its
    // unit's reading, writing and check throw logic_error, saying so, and
    // never pass for an operator's refusal.
    void aDoorWithoutTableOrCheckIsABug()
    {
        const BareKind bare;
        const nlohmann::json object = nlohmann::json::object();
        DiagnosticSink sink;
        const io::ObjectFields fields(object, io::Place{1, "BARE", ""}, sink);
        QVERIFY_THROWS_EXCEPTION(std::logic_error, bare.read(fields));
        nlohmann::ordered_json unit;
        QVERIFY_THROWS_EXCEPTION(std::logic_error, bare.write(bare.makeDefault({}), unit));
        try {
            bare.check(bare.makeDefault({}), 1, check::Context{});
            QFAIL("a check without a check function passed");
        } catch (const std::logic_error& e) {
            QCOMPARE(std::string(e.what()), std::string("module BARE has no input check"));
        }
        QVERIFY(sink.empty());
        // Its palette words and form are its description file's, which it lacks.
        for (const auto& use : std::vector<std::function<void()>>{[&] { (void)bare.paletteText(); },
                                                                  [&] { (void)bare.fields(); }}) {
            try {
                use();
                QFAIL("a door without a description file has words");
            } catch (const std::logic_error& e) {
                QCOMPARE(std::string(e.what()), std::string("no module description core/modules/bare/bare.module.json"));
            }
        }
        QCOMPARE(std::string(bare.drawing()), std::string(":/modules/bare.svg"));
    }

    void theDoorChecksEveryModulesPins()
    {
        const std::vector<Tool> library = defaultToolLibrary();
        const Stock stock;
        const BarStock bar;
        check::Context ctx;
        ctx.stock = &stock;
        ctx.bar = &bar;
        ctx.library = &library;
        int modules = 0;
        for (const ModuleKind* kind : moduleKinds()) {
            const std::vector<std::string> keys = kind->stepKeys();
            if (keys.empty()) continue;
            ++modules;
            nlohmann::ordered_json unit;
            kind->write(kind->makeDefault(stock), unit);
            unit["tools"] = {{"nonsense", library.front().id}, {keys.front(), 99999}};
            DiagnosticSink sink;
            const nlohmann::json plain = nlohmann::json::parse(unit.dump());
            const ModuleInput m = kind->read(io::ObjectFields(plain, io::Place{1, kind->name(), ""}, sink));
            QVERIFY2(std::move(sink).finish().empty(), kind->name());
            const Diagnostics found = kind->check(m, 1, ctx).diagnostics;
            const auto on = [&](const std::string& field) {
                std::vector<std::string> messages;
                for (const Diagnostic& d : found)
                    if (d.field == field) messages.push_back(d.message);
                return messages;
            };
            std::string list, all = kind->name();
            for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
            for (const Diagnostic& d : found) all += "\n" + d.field + ": " + d.message;
            const auto nonsense = on("tools.nonsense");
            QVERIFY2(nonsense.size() == 1, all.c_str());
            QCOMPARE(nonsense.front(), "\"nonsense\" is not a step of module " + std::string(kind->name()) + "; its steps are " + list);
            const auto missing = on("tools." + keys.front());
            QVERIFY2(missing.size() == 1, all.c_str());
            QCOMPARE(missing.front(), std::string("tool T99999 is not in the tool library"));

            // The control: the same unit with a known key and a library tool.
            unit["tools"] = {{keys.front(), library.front().id}};
            const nlohmann::json good = nlohmann::json::parse(unit.dump());
            DiagnosticSink again;
            const ModuleInput g = kind->read(io::ObjectFields(good, io::Place{1, kind->name(), ""}, again));
            for (const Diagnostic& d : kind->check(g, 1, ctx).diagnostics)
                QVERIFY2(d.message.find("is not a step of module") == std::string::npos &&
                             d.message.find("is not in the tool library") == std::string::npos,
                         (std::string(kind->name()) + ": " + d.message).c_str());
        }
        QVERIFY(modules >= 9);  // M4, M2D, CP, AREA, HOLES, FACE, SIDE, SURFACE, TURN
    }

    // A tool is looked up in a library only where it is chosen or bound
    // (the modules, the input checks, planJob's binding); the stages after
    // the plan (posts, tool tables, sheet, verification, pictures, the
    // station) read the tool each step was bound to (post/bound_tool.h).
    void onlyChoosingAndBindingLookToolsUp()
    {
        // The rule sees both kinds, and not a comment.
        QCOMPARE(toolLookUps("int a;\n  const Tool* t = findTool(library, id);\n  // findTool(x)\n").size(), 1);
        QCOMPARE(toolLookUps("auto it = std::find_if(l.begin(), l.end(), [&](const Tool& t) { return t.id == id; });").size(), 1);
        QStringList found;
        int files = 0;
        for (const char* folder : {"core/post", "core/export", "core/sheet", "core/verify", "core/picture", "core/sim", "viz", "ui", "app"}) {
            QDirIterator it(test::sourcePath(folder), {"*.cpp", "*.h"}, QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext()) {
                const QString path = it.next();
                const QString rel = QDir(test::sourcePath("")).relativeFilePath(path);
                if (rel == "core/post/bound_tool.h") continue;
                ++files;
                for (const QString& f : toolLookUps(QString::fromStdString(test::readFile(path)))) found << rel + ":" + f;
            }
        }
        QVERIFY(files > 150);
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }

    void aLibraryEditAfterPlanningChangesNoTape()
    {
        const auto read = readJobFile(test::sourcePath("resources/samples/plate.taiwa").toStdString());
        QVERIFY(read.job);
        std::vector<Tool> library = defaultToolLibrary();
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), library);
        QVERIFY(plan.ok());
        for (const Step& s : plan.steps) {
            QVERIFY(s.speeds);
            QCOMPARE(*s.speeds, *stepSpeedsFeeds(s, *plan.tool(s.tool->toolId), plan.mmJob.material));
        }
        const PostOptions o = postOptions(plan, "linuxcnc");
        const std::string before = postProcess(plan.steps, library, o).nc;
        for (Tool& t : library)
            for (CuttingData& c : t.cutting) {
                c.surfaceSpeed *= 2;
                c.feedPerTooth *= 3;
            }
        QCOMPARE(postProcess(plan.steps, library, o).nc, before);
        QCOMPARE(postProcess(plan.steps, plan.tools, o).nc, before);
    }

    // A turning unit's profile is deformed once: by its check, which hands
    // the part on (CheckedJob::turned), and the plan cuts that one. The
    // checked part is the door's own (turned() makes the same); a mark put
    // on it reaches the plan, which a second deformation would lose.
    void thePlanCutsTheDeformationTheCheckMade()
    {
        const auto read = readJobFile(test::sourcePath("resources/samples/lathe-tangent-nose.taiwa").toStdString());
        QVERIFY(read.job);
        const std::vector<Tool> library = defaultToolLibrary();
        CheckedJob c = checkedJob(*read.job, TechnologyTable::builtIn(), library);
        QVERIFY(c.ok());
        QCOMPARE(c.turned.size(), c.mmJob.units.size());
        std::vector<std::size_t> turning;
        for (std::size_t u = 0; u < c.mmJob.units.size(); ++u) {
            const ModuleInput& m = c.mmJob.units[u].module;
            const UnitPlanContext ctx{*c.technology, library, c.mmJob.material, static_cast<int>(u), &c.mmJob};
            const std::optional<TurnedPart> own = moduleKind(m).turned(m, ctx);
            QCOMPARE(c.turned[u].has_value(), own.has_value());
            if (!own) continue;
            turning.push_back(u);
            QVERIFY(c.turned[u]->complete);
            QCOMPARE(c.turned[u]->noseRadiusTool, own->noseRadiusTool);
            QVERIFY(!own->noseRadiusTool.empty());  // the sample's tangent joint takes the finishing insert's radius
            QVERIFY(c.turned[u]->deformed.edges == own->deformed.edges);
            c.turned[u]->noseRadiusTool = "marked by the test";
        }
        QVERIFY(!turning.empty());
        const Plan plan = planJob(std::move(c), library);
        QVERIFY(plan.ok());
        QCOMPARE(plan.turned.size(), turning.size());
        for (const TurnedPart& part : plan.turned) QCOMPARE(part.noseRadiusTool, std::string("marked by the test"));
    }
};

QTEST_APPLESS_MAIN(TestModuleDoor)
#include "test_module_door.moc"
