// Module FACE (face milling of the stock top): the decomposition (layers of
// at most γ·D and the tool's cutting length, the finishing pass, the
// allowances), the tool choice, every refusal with its message, the job
// file round trip and the inch conversion, the job-wide order (the top
// first), and a geometric oracle of its own on the rs274 moves of both
// samples' linuxcnc tapes (support/face_oracle.h): the whole face within
// the tool's radius of a pass at the final depth, nothing below Z0 over the
// stock but the passes at their layer's depth, rapids below Z0 only with
// the tool off the stock, each layer at its depth to 1 µm.
#include "modules/face/face.h"
#include "support/face_oracle.h"
#include "support/hand_plan.h"
#include "support/rs274.h"
#include "support/support.h"

#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/registry.h"
#include "paths/cl.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <cmath>

using namespace taiwa;
using namespace taiwa::test;

namespace {

constexpr double kTol = 1e-3;  // 1 µm in mm

std::string messages(const Diagnostics& ds)
{
    std::string s;
    for (const auto& d : ds) s += d.field + ": " + d.message + "\n";
    return s;
}

// A job of one FACE unit (and any others) on a 160 x 100 x 40 block.
Job faceJob(const std::string& units, const std::string& unit = "mm")
{
    const std::string text = R"({"format": "taiwa-job", "version": 5, "lengthUnit": ")" + unit +
                             R"(", "material": "aluminium-6061",
        "stock": {"shape": "block", "x": 0, "y": 0, "width": 160, "length": 100, "height": 40}, "units": [)" +
                             units + "]}";
    auto r = readJob(text);
    if (!r.job) throw std::runtime_error("job not read: " + text);
    return *r.job;
}

std::string messageOn(const Diagnostics& ds, const std::string& field, int unit = 1)
{
    for (const auto& d : ds)
        if (d.field == field && d.unit == unit) return d.message;
    return {};
}

Plan plan(const std::string& units, const std::vector<Tool>& library = defaultToolLibrary())
{
    return planJob(faceJob(units), TechnologyTable::builtIn(), library);
}

// A library of one face mill of the given cutting length, and a drill.
std::vector<Tool> shortInserts(double cuttingLength)
{
    std::vector<Tool> lib;
    for (const Tool& t : defaultToolLibrary())
        if (t.id == 60 || t.id == 8) lib.push_back(t);
    lib[1].fluteLength = cuttingLength;
    return lib;
}

// Where a move is, for a failure message.
QString where(const CanonMove& m)
{
    return QString("step %1 %2 -> X%3 Y%4 Z%5").arg(m.step).arg(m.kind).arg(m.end.x, 0, 'f', 4).arg(m.end.y, 0, 'f', 4).arg(m.end.z, 0, 'f', 4);
}

}  // namespace

class TestFaceMilling : public QObject {
    Q_OBJECT
private slots:
    void sampleIsOneRoughingLayerAndTheFinishingPass()
    {
        const Plan p = samplePlan("face-top.taiwa");
        QVERIFY2(p.ok(), messages(p.diagnostics).c_str());
        // 1.5 mm: β2 = 0.2 for aluminium, so one layer to 1.3 (the face mill
        // cuts 6 mm a layer: min(γ·D = 25, its inserts' 6)), then 0.2.
        QCOMPARE(p.steps.size(), std::size_t{2});
        const Step& rough = p.steps[0];
        const Step& finish = p.steps[1];
        QCOMPARE(rough.kind, StepKind::FaceMilling);
        QCOMPARE(rough.machiningType, MachiningType::FaceMilling);
        QCOMPARE(finish.machiningType, MachiningType::FaceFinishing);
        QCOMPARE(rough.label(), std::string("Face milling I"));
        QCOMPARE(finish.label(), std::string("Face milling II"));
        QCOMPARE(millingOf(rough).startDepth, 0.0);
        QVERIFY(std::abs(millingOf(rough).cutDepth - 1.3) < 1e-12 && std::abs(millingOf(rough).floorAllowance - 0.2) < 1e-12);
        QVERIFY(std::abs(millingOf(finish).startDepth - 1.3) < 1e-12);
        QCOMPARE(millingOf(finish).cutDepth, 1.5);
        QCOMPARE(millingOf(finish).floorAllowance, 0.0);
        for (const Step& s : p.steps) {
            QCOMPARE(s.tool->toolId, 60);  // the library's one face mill
            QVERIFY(s.payload.as<FacePasses>().zigzag);
            QCOMPARE(s.payload.as<FacePasses>().angle, 0.0);
            QCOMPARE(millingOf(s).stepOver.value(), 0.75);
            QVERIFY(millingOf(s).outline);
            const auto& c = millingOf(s).outline->corners;
            QVERIFY(c[0] == (Point2{0, 0}) && c[1] == (Point2{160, 0}) && c[2] == (Point2{160, 100}) && c[3] == (Point2{0, 100}));
            // Its time is estimated; the move budget's guess is not short of the path.
            QVERIFY(s.minutes && *s.minutes > 0.0);
            const Tool& t = *p.tool(60);
            QVERIFY(estimateMoves(s, t, p.technology, {}) >= static_cast<double>(s.path->moves.size()));
        }
    }

    void deepFaceTakesLayersTheInsertsCut()
    {
        // 14 mm with the 6 mm inserts, finish 0.5: 13.5 in three layers of 4.5, then 0.5.
        const Plan p = plan(R"({"module": "FACE", "depth": 14, "finish": 0.5})");
        QVERIFY2(p.ok(), messages(p.diagnostics).c_str());
        QCOMPARE(p.steps.size(), std::size_t{4});
        const double cuts[] = {4.5, 9.0, 13.5, 14.0};
        double from = 0.0;
        for (int k = 0; k < 4; ++k) {
            const Step& s = p.steps[static_cast<std::size_t>(k)];
            QCOMPARE(s.number, k + 1);
            QVERIFY2(std::abs(millingOf(s).cutDepth - cuts[k]) < 1e-12 && std::abs(millingOf(s).startDepth - from) < 1e-12,
                     qPrintable(QString("layer %1: %2 to %3").arg(k + 1).arg(millingOf(s).startDepth).arg(millingOf(s).cutDepth)));
            QVERIFY(std::abs(millingOf(s).floorAllowance - (14.0 - cuts[k])) < 1e-12);
            QCOMPARE(s.machiningType, k == 3 ? MachiningType::FaceFinishing : MachiningType::FaceMilling);
            QVERIFY(!s.payload.as<FacePasses>().zigzag);  // one way unless asked
            from = millingOf(s).cutDepth;
        }
        // A pinned 20 mm end mill cuts γ·D = 10 a layer (its flutes 50): 13.5 in two of 6.75.
        const Plan e = plan(R"({"module": "FACE", "depth": 14, "finish": 0.5, "tools": {"face": 30}})");
        QVERIFY2(e.ok(), messages(e.diagnostics).c_str());
        QCOMPARE(e.steps.size(), std::size_t{3});
        QCOMPARE(millingOf(e.steps[0]).cutDepth, 6.75);
        QCOMPARE(e.steps[0].tool->reason.str(), std::string("pinned by the operator"));
        QCOMPARE(millingOf(e.steps[0]).stepOver.value(), 0.45);  // an end mill: the technology's step-over
        // Roughing only (U9): the layers stop at depth - finish and leave it.
        const Plan r = plan(R"({"module": "FACE", "depth": 3, "U": 9, "finish": 0.4, "stepOver": 0.6})");
        QVERIFY2(r.ok(), messages(r.diagnostics).c_str());
        QCOMPARE(r.steps.size(), std::size_t{1});
        QVERIFY(std::abs(millingOf(r.steps[0]).cutDepth - 2.6) < 1e-12 && std::abs(millingOf(r.steps[0]).floorAllowance - 0.4) < 1e-12);
        QCOMPARE(r.steps[0].machiningType, MachiningType::FaceMilling);
        QCOMPARE(millingOf(r.steps[0]).stepOver.value(), 0.6);
    }

    void largestFaceMillElseLargestEndMill()
    {
        std::vector<Tool> lib = defaultToolLibrary();
        std::erase_if(lib, [](const Tool& t) { return t.type == ToolType::FaceMill; });
        const Plan p = plan(R"({"module": "FACE", "depth": 1})", lib);
        QVERIFY2(p.ok(), messages(p.diagnostics).c_str());
        QCOMPARE(p.steps[0].tool->toolId, 31);  // the 25 mm flat end mill
        // Inserts cutting 0.1 mm cannot take the 0.2 finishing pass, and there is no end mill.
        const Plan s = plan(R"({"module": "FACE", "depth": 1})", shortInserts(0.1));
        QVERIFY(!s.ok());
        QCOMPARE(messageOn(s.diagnostics, "tools.face"),
                 std::string("the tool library has no face mill or flat end mill that cuts the finishing pass 0.2 mm in one "
                             "cut; add one or give a smaller finishing pass"));
    }

    void cavityIsTheDepthEverywhere()
    {
        const Plan p = samplePlan("face-top.taiwa");
        const ModuleInput& m = p.mmJob.units[0].module;
        const auto cav = moduleKind(m).cavity(m, p.technology);
        QVERIFY(cav);
        QCOMPARE(cav->depthAt({0, 0}, 0.0), 1.5);
        QCOMPARE(cav->depthAt({80, 50}, -1.0), 1.5);
        QCOMPARE(cav->depthAt({160, 100}, 0.5), 1.5);
        QVERIFY(cav->min.x <= 0 && cav->min.y <= 0 && cav->max.x >= 160 && cav->max.y >= 100);
        QVERIFY(!moduleKind(m).topOutline(m));  // no figure: it overlaps every unit by design
    }

    void topIsFacedBeforeAnyOtherUnit()
    {
        // A pocket and holes listed before the face: their steps wait for it.
        const Plan p = plan(R"({"module": "M4", "corners": [[20, 20], [80, 20], [80, 65], [20, 65]], "cornerRadius": 6,
                                "depth": 10, "U": 1, "F": 1, "H": 9},
                               {"module": "HOLES", "pattern": "single", "x": 130, "y": 50, "hole": "drilled", "diameter": 8, "depth": 10},
                               {"module": "FACE", "depth": 2, "pattern": 2})");
        QVERIFY2(p.ok(), messages(p.diagnostics).c_str());
        QVERIFY(p.steps.size() > 3);
        QCOMPARE(p.steps[0].unit, 2);
        QCOMPARE(p.steps[1].unit, 2);
        QCOMPARE(p.steps[0].number, 1);
        QCOMPARE(p.steps[1].number, 2);
        for (std::size_t i = 2; i < p.steps.size(); ++i) QVERIFY(p.steps[i].kind != StepKind::FaceMilling);
        // The sample: face first, then its holes.
        const Plan s = samplePlan("face-one-way-angle.taiwa");
        QVERIFY2(s.ok(), messages(s.diagnostics).c_str());
        QCOMPARE(s.steps[0].kind, StepKind::FaceMilling);
        QCOMPARE(s.steps[1].kind, StepKind::FaceMilling);
        QCOMPARE(s.steps[2].kind, StepKind::CentreDrilling);
        // The face does not make the interference check refuse the others.
        QVERIFY(messages(checkJob(faceJob(R"({"module": "FACE", "depth": 2},
            {"module": "HOLES", "pattern": "single", "x": 130, "y": 50, "hole": "drilled", "diameter": 8, "depth": 10})"),
                                  TechnologyTable::builtIn(), defaultToolLibrary()))
                    .empty());
    }

    void jobFileRoundTripAndInches()
    {
        auto read = readJobFile(sourcePath("resources/samples/face-one-way-angle.taiwa").toStdString());
        QVERIFY(read.job);
        QCOMPARE(formatVersionFor(*read.job), 5);
        const std::string text = writeJob(*read.job);
        QVERIFY(text.find("\"margin\": 2") != std::string::npos);
        QVERIFY(text.find("\"finish\": 0.5") != std::string::npos);
        QVERIFY(text.find("\"tools\": {\"face\": 30}") != std::string::npos || text.find("\"face\": 30") != std::string::npos);
        auto again = readJob(text);
        QVERIFY(again.job);
        QCOMPARE(*again.job, *read.job);
        // Absent optional keys stay absent.
        const std::string plain = writeJob(faceJob(R"({"module": "FACE", "depth": 2})"));
        QVERIFY(plain.find("\"finish\"") == std::string::npos && plain.find("\"stepOver\"") == std::string::npos &&
                plain.find("\"margin\"") == std::string::npos);
        // Inch: every length converted, the angle, codes and step-over not.
        const Job inch = faceJob(R"({"module": "FACE", "depth": 0.06, "finish": 0.01, "margin": 0.1, "angle": 30,
                                     "stepOver": 0.6, "pattern": 2, "U": 9})", "inch");
        const Job mm = toMillimetres(inch);
        const FaceUnit& f = mm.units[0].module.as<FaceUnit>();
        QVERIFY(std::abs(f.depth - 1.524) < 1e-9 && std::abs(*f.finish - 0.254) < 1e-9 && std::abs(f.margin - 2.54) < 1e-9);
        QCOMPARE(f.angle, 30.0);
        QCOMPARE(*f.stepOver, 0.6);
        QCOMPARE(f.pattern, 2);
        QCOMPARE(f.toolUse, 9);
        // Messages quote inches in an inch job.
        const Diagnostics ds = checkJob(faceJob(R"({"module": "FACE", "depth": 0.06, "finish": 0.07})", "inch"),
                                        TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY2(messageOn(ds, "finish").find("0.07 in") != std::string::npos, messages(ds).c_str());
    }

    void refusals_data()
    {
        QTest::addColumn<QString>("unit");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("message");
        const auto row = [](const char* name, const char* unit, const char* field, const char* message) {
            QTest::newRow(name) << unit << field << message;
        };
        row("U", R"({"module": "FACE", "depth": 2, "U": 6})", "U",
            "U 6 is not a tool use of face milling; give 1 (roughing layers and a finishing pass) or 9 (roughing only, "
            "the finishing allowance left)");
        row("pattern", R"({"module": "FACE", "depth": 2, "pattern": 3})", "pattern",
            "pattern 3 is not a face-milling pattern; give 1 (one way, climb: every pass in the same direction) or 2 "
            "(zigzag: back and forth)");
        row("depth zero", R"({"module": "FACE", "depth": 0})", "depth",
            "the depth is 0 mm; it must be greater than zero (measured down from the top face)");
        row("depth whole block", R"({"module": "FACE", "depth": 40})", "depth",
            "the depth 40 mm is not less than the stock's height 40 mm: facing takes a layer off the top, it does not "
            "mill the whole block away");
        row("finish zero", R"({"module": "FACE", "depth": 2, "finish": 0})", "finish",
            "the finishing pass is 0 mm; it must be greater than zero (leave the field empty for the technology data's β2)");
        row("finish deep", R"({"module": "FACE", "depth": 2, "finish": 2})", "finish",
            "the finishing pass 2 mm is not less than the depth 2 mm: roughing would have nothing to take; give a "
            "smaller finishing pass");
        row("beta2 deep", R"({"module": "FACE", "depth": 0.2})", "finish",
            "the finishing pass 0.2 mm (the technology data's β2) is not less than the depth 0.2 mm: roughing would "
            "have nothing to take; give a smaller finishing pass");
        row("angle", R"({"module": "FACE", "depth": 2, "angle": 400})", "angle",
            "the angle 400° lies beyond ±360°; give the passes' direction from +X, e.g. 0 or 90");
        row("step-over zero", R"({"module": "FACE", "depth": 2, "stepOver": 0})", "stepOver",
            "the step-over 0 × D must be greater than 0: passes that do not step sideways never cover the face");
        row("step-over small", R"({"module": "FACE", "depth": 2, "stepOver": 0.005})", "stepOver",
            "the step-over 0.005 × D is less than 0.01 × D: the face would take more than a hundred passes a tool diameter");
        row("step-over large", R"({"module": "FACE", "depth": 2, "stepOver": 0.95})", "stepOver",
            "the step-over 0.95 × D is more than 0.9 × D: neighbouring passes would overlap by less than a tenth of the "
            "diameter, and the inserts' corners and the tool's run-out leave ridges between them");
        row("margin", R"({"module": "FACE", "depth": 2, "margin": -1})", "margin",
            "the margin is -1 mm; it must be 0 (the face is the stock's top) or more (the face reaches beyond the "
            "stock's sides): less would leave the top's edges unfaced");
        row("pin key", R"({"module": "FACE", "depth": 2, "tools": {"roughing": 60}})", "tools.roughing",
            "\"roughing\" is not a step of module FACE; its steps are face");
        row("pin unknown", R"({"module": "FACE", "depth": 2, "tools": {"face": 999}})", "tools.face",
            "tool T999 is not in the tool library");
        row("pin drill", R"({"module": "FACE", "depth": 2, "tools": {"face": 8}})", "tools.face",
            "T8 (drill Ø8 mm) is pinned for \"face\" but is not a face mill or a flat end mill: a face is cut flat by the "
            "tool's flat bottom");
        row("cutting key", R"({"module": "FACE", "depth": 2, "cutting": {"roughing": {"S": 1000}}})", "cutting.roughing",
            "");
    }
    void refusals()
    {
        QFETCH(QString, unit);
        QFETCH(QString, field);
        QFETCH(QString, message);
        const Diagnostics ds = checkJob(faceJob(unit.toStdString()), TechnologyTable::builtIn(), defaultToolLibrary());
        const std::string got = messageOn(ds, field.toStdString());
        QVERIFY2(!got.empty(), messages(ds).c_str());
        if (!message.isEmpty()) QCOMPARE(QString::fromStdString(got), message);
        // Nothing is planned from a refused unit.
        QVERIFY(!planJob(faceJob(unit.toStdString()), TechnologyTable::builtIn(), defaultToolLibrary()).ok());
    }

    void pinnedInsertsTooShortForTheFinishingPass()
    {
        const Diagnostics ds = checkJob(faceJob(R"({"module": "FACE", "depth": 3, "finish": 0.5, "tools": {"face": 60}})"),
                                        TechnologyTable::builtIn(), shortInserts(0.3));
        QCOMPARE(messageOn(ds, "tools.face"),
                 std::string("T60 (face mill Ø50 mm) is pinned for \"face\" but cuts 0.3 mm at most, less than the "
                             "finishing pass 0.5 mm; give a smaller finishing pass or another tool"));
    }

    void formHasAHelpLineForEveryField()
    {
        const ModuleKind* k = findModuleKind("FACE");
        QVERIFY(k);
        QStringList keys;
        for (const FormField& f : k->fields()) {
            QVERIFY2(!f.help.empty(), f.key.c_str());
            keys << QString::fromStdString(f.key);
        }
        QCOMPARE(keys, (QStringList{"depth", "U", "finish", "angle", "pattern", "stepOver", "margin"}));
        QCOMPARE(k->stepKeys(), std::vector<std::string>{"face"});
    }

    // The oracle on LinuxCNC's reading of both samples' tapes.
    void tapesCoverTheFaceAndStayOffTheStockBelowZ0_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("units");  // a job of its own when no sample
        QTest::newRow("face-top") << "face-top.taiwa" << "";
        QTest::newRow("face-one-way-angle") << "face-one-way-angle.taiwa" << "";
        // Oblique passes: the bands' ends follow the slanted sides.
        QTest::newRow("zigzag at 30°") << "" << R"({"module": "FACE", "depth": 7, "angle": 30, "pattern": 2, "margin": 3})";
        QTest::newRow("one way at -45°, end mill") << ""
                                                   << R"({"module": "FACE", "depth": 2.5, "angle": -45, "stepOver": 0.6, "tools": {"face": 28}})";
    }
    void tapesCoverTheFaceAndStayOffTheStockBelowZ0()
    {
        QFETCH(QString, sample);
        QFETCH(QString, units);
        const Plan p = sample.isEmpty() ? plan(units.toStdString()) : samplePlan(qPrintable(sample));
        QVERIFY2(p.ok(), messages(p.diagnostics).c_str());
        const std::string nc = postProcess(p.steps, defaultToolLibrary(), postOptions(p, "linuxcnc")).nc;
        const Rs274Result r = runRs274(nc);
        QVERIFY2(r.ok, qPrintable(r.errors));
        const Stock& stock = p.mmJob.stock;
        int faceUnit = -1;
        for (std::size_t u = 0; u < p.mmJob.units.size(); ++u)
            if (p.mmJob.units[u].module.getIf<FaceUnit>()) faceUnit = static_cast<int>(u);
        QVERIFY(faceUnit >= 0);
        const FaceUnit& face = p.mmJob.units[static_cast<std::size_t>(faceUnit)].module.as<FaceUnit>();
        // The face steps, first in the tape; the last is at the full depth.
        int faceSteps = 0;
        while (faceSteps < static_cast<int>(p.steps.size()) && p.steps[static_cast<std::size_t>(faceSteps)].unit == faceUnit)
            ++faceSteps;
        QVERIFY(faceSteps >= 2);
        for (std::size_t i = static_cast<std::size_t>(faceSteps); i < p.steps.size(); ++i) QVERIFY(p.steps[i].unit != faceUnit);
        QCOMPARE(millingOf(p.steps[static_cast<std::size_t>(faceSteps - 1)]).cutDepth, face.depth);
        const Tool& tool = *p.tool(p.steps[0].tool->toolId);
        const double R = tool.radius();

        std::map<int, double> deepest;
        std::vector<std::pair<Point2, Point2>> finalPasses;
        for (const CanonMove& m : r.moves) {
            if (m.step < 1 || m.step > faceSteps) continue;
            const Step& s = p.steps[static_cast<std::size_t>(m.step - 1)];
            const double layer = -millingOf(s).cutDepth;
            const bool atLayer = std::abs(m.start.z - layer) < kTol && std::abs(m.end.z - layer) < kTol;
            QVERIFY2(m.kind != CanonMove::Arc, qPrintable("an arc in a face: " + where(m)));
            deepest[m.step] = std::min(deepest.count(m.step) ? deepest[m.step] : 0.0, std::min(m.start.z, m.end.z));
            QVERIFY2(std::min(m.start.z, m.end.z) >= layer - kTol, qPrintable("below its layer: " + where(m)));
            if (m.kind == CanonMove::Feed && atLayer && m.step == faceSteps)
                finalPasses.push_back({{m.start.x, m.start.y}, {m.end.x, m.end.y}});
            if (std::max(m.start.z, m.end.z) >= -kTol && std::min(m.start.z, m.end.z) >= -kTol) continue;  // above Z0
            // Below Z0: every point of the move with the tool off the stock,
            // but a feed along a pass at its layer's depth.
            if (m.kind == CanonMove::Feed && atLayer) continue;
            const double len = std::hypot(m.end.x - m.start.x, m.end.y - m.start.y);
            const int n = std::max(1, static_cast<int>(std::ceil(len / 0.25)));
            for (int i = 0; i <= n; ++i) {
                const double t = static_cast<double>(i) / n;
                const Point2 c{m.start.x + t * (m.end.x - m.start.x), m.start.y + t * (m.end.y - m.start.y)};
                const double z = m.start.z + t * (m.end.z - m.start.z);
                if (z >= -kTol) continue;
                QVERIFY2(distanceToStock(stock, c) >= R - kTol,
                         qPrintable(QString(m.kind == CanonMove::Traverse ? "rapid" : "feed") +
                                    " below Z0 with the tool over the stock: " + where(m)));
            }
        }
        // Each layer at its depth, the last at -depth, to 1 µm.
        for (int k = 1; k <= faceSteps; ++k) {
            const Step& s = p.steps[static_cast<std::size_t>(k - 1)];
            QVERIFY2(std::abs(deepest[k] + millingOf(s).cutDepth) < kTol, qPrintable(QString("layer %1 reaches %2").arg(k).arg(deepest[k])));
        }
        QVERIFY(std::abs(deepest[faceSteps] + face.depth) < kTol);
        // Every point of the face (1 mm grid, edges and corners) within R of a
        // pass at the final depth.
        QVERIFY(!finalPasses.empty());
        for (const Point2 q : faceGrid(stock, face.margin, 1.0)) {
            double best = 1e300;
            for (const auto& [a, b] : finalPasses) best = std::min(best, distanceToSegment(q, a, b));
            QVERIFY2(best <= R + kTol, qPrintable(QString("X%1 Y%2 is %3 mm from the passes").arg(q.x).arg(q.y).arg(best)));
        }
        // The passes' direction: one way, all along the angle (climb); zigzag back and forth.
        const double a = face.angle * M_PI / 180.0;
        int forward = 0, backward = 0;
        for (const auto& [s, e] : finalPasses) {
            const double along = (e.x - s.x) * std::cos(a) + (e.y - s.y) * std::sin(a);
            const double across = -(e.x - s.x) * std::sin(a) + (e.y - s.y) * std::cos(a);
            if (std::abs(across) > kTol) continue;  // a zigzag's link
            (along > 0 ? forward : backward)++;
        }
        if (face.pattern == face::kOneWay) QCOMPARE(backward, 0);
        else QVERIFY(backward > 0 && std::abs(forward - backward) <= 1);
    }
};

QTEST_APPLESS_MAIN(TestFaceMilling)
#include "test_face_milling.moc"
