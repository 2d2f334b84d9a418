// Bounded work (issue 39, items 1, 2, 4 and 5): hostile jobs generated here,
// each small as a file, that once ran for minutes. Each test judges the
// result, never the time: a contour pocket of 2,000 edges is sized
// (inscribed and reach radii against their hand values) and passes its
// checks, one of 25,000 edges is refused on its outline naming the count;
// passes drawn at random across an area are refused on their points,
// naming the strips' overlapping pairs, while a zigzag of the same points
// is taken; a FACE whose moves are beyond the job's budget is refused by
// the checks alone (a plan without paths, what `taiwa check` makes),
// naming the field that drives it, and so is a job of 3-D surfaces whose
// moves fit as moves but not as the work they cost; a 20,000-line DXF circle comes back as
// one closed contour of 20,000 segments through the figure text. How long
// they take is bench/bench_work_ladder.cpp's.
#include "support/support.h"

#include "dxf/dxf_import.h"
#include "figure/figure_eval.h"
#include "figure/figure_text.h"
#include "figure/figure_from_contours.h"
#include "job/job_check.h"
#include "job/job_file.h"
#include "modules/area/area.h"
#include "modules/cp/cp.h"
#include "modules/named_region.h"
#include "modules/registry.h"
#include "paths/region.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <random>

using namespace taiwa;
using namespace taiwa::test;

namespace {

std::string messages(const Diagnostics& ds)
{
    std::string s;
    for (const auto& d : ds) s += d.field + ": " + d.message + "\n";
    return s;
}

const Diagnostic* on(const Diagnostics& ds, const std::string& field)
{
    for (const auto& d : ds)
        if (d.field == field && d.severity == Severity::Error) return &d;
    return nullptr;
}

// A job on a `w` x `l` x `h` block with the figure's lines and the units.
Job job(const std::vector<std::string>& figure, const nlohmann::json& units, double w = 1000, double l = 1000,
        double h = 50)
{
    nlohmann::json j{{"format", "taiwa-job"},
                     {"version", 5},
                     {"lengthUnit", "mm"},
                     {"material", "aluminium-6061"},
                     {"stock", {{"shape", "block"}, {"x", 0}, {"y", 0}, {"width", w}, {"length", l}, {"height", h}}},
                     {"units", units}};
    if (!figure.empty()) j["figure"] = figure;
    auto r = readJob(j.dump());
    if (!r.job) throw std::runtime_error("job not read: " + messages(r.diagnostics));
    return *r.job;
}

// A regular n-gon of circumradius r round (500, 500), every corner rounded
// by 5 mm: K1.
std::vector<std::string> roundedPolygon(int n, double r)
{
    std::vector<std::string> f;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        f.push_back(fmt::format("P{} = POINT/{:.9f}, {:.9f}", i + 1, 500 + r * std::cos(a), 500 + r * std::sin(a)));
    }
    std::string k = "K1 = CONTOUR/";
    for (int i = 0; i < n; ++i) {
        f.push_back(fmt::format("L{} = LINE/P{}, P{}", i + 1, i + 1, (i + 1) % n + 1));
        k += fmt::format("{}L{}, ROUND, 5", i ? ", " : "", i + 1);
    }
    f.push_back(k);
    return f;
}

nlohmann::json cpUnit() { return nlohmann::json::array({{{"module", "CP"}, {"name", "gon"}, {"outline", "K1"}, {"depth", 10}}}); }

// A square area 100..900 rounded by 20 mm: K1.
const std::vector<std::string> kSquareArea{"P1 = POINT/100, 100", "P2 = POINT/900, 900", "L1 = LINE/P1, ATANGL, 0",
                                           "L2 = LINE/P2, ATANGL, 90", "L3 = LINE/P2, ATANGL, 180",
                                           "L4 = LINE/P1, ATANGL, 270",
                                           "K1 = CONTOUR/L1, ROUND, 20, L2, ROUND, 20, L3, ROUND, 20, L4, ROUND, 20"};

nlohmann::json areaUnit(const std::vector<Point2>& points)
{
    nlohmann::json pts = nlohmann::json::array();
    for (const Point2 p : points) pts.push_back({p.x, p.y});
    return nlohmann::json::array(
        {{{"module", "AREA"}, {"name", "a"}, {"outline", "K1"}, {"diameter", 10}, {"depth", 5}, {"points", pts}}});
}

const ContourPocket& cpOf(const Job& mm) { return mm.units[0].module.as<ContourPocket>(); }

}  // namespace

class TestBoundedWork : public QObject {
    Q_OBJECT

private slots:
    // Item 1: the sizing of a contour pocket by hand values. A circle of
    // 2,000 edges: the largest circle inside is the apothem (the 5 mm
    // roundings lie at the corners, farther out).
    void manyEdgedPocketIsSizedAndChecked()
    {
        const int n = 2000;
        const double R = 400;
        const Job j = job(roundedPolygon(n, R), cpUnit());
        const CheckedJob c = checkedJob(j, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY2(!hasErrors(c.diagnostics), messages(c.diagnostics).c_str());
        const ContourPocket& p = cpOf(c.mmJob);
        const double apothem = R * std::cos(std::numbers::pi / n);
        QVERIFY2(p.inscribed <= apothem + 1e-6 && p.inscribed >= apothem - 4e-3,
                 fmt::format("inscribed {} against the apothem {}", p.inscribed, apothem).c_str());
        // The 0.18° corners rounded by 5 mm leave less than 4 µm to any
        // cutter up to the radius the reach is looked for to.
        QVERIFY2(std::abs(p.reach - paths::kMaxReach) < 1e-9, fmt::format("reach {}", p.reach).c_str());
        // The whole check and the plan's estimate: no move budget exceeded.
        PlanOptions o;
        o.withToolPaths = false;
        const Plan plan = planJob(j, TechnologyTable::builtIn(), defaultToolLibrary(), o);
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
    }

    // The sizing against regions with known answers: a 100 x 20 slot with
    // 5 mm corners (inscribed 10, reach 5: a cutter up to 10 µm wider
    // leaves less than 4 µm in the 90° corners), a circle (reach =
    // inscribed = radius).
    void sizingByHand_data()
    {
        QTest::addColumn<QString>("figure");
        QTest::addColumn<double>("inscribed");
        QTest::addColumn<double>("reach");
        QTest::newRow("slot") << "P1 = POINT/0, 0\nP2 = POINT/100, 20\nL1 = LINE/P1, ATANGL, 0\nL2 = LINE/P2, ATANGL, 90\n"
                                 "L3 = LINE/P2, ATANGL, 180\nL4 = LINE/P1, ATANGL, 270\n"
                                 "K1 = CONTOUR/L1, ROUND, 5, L2, ROUND, 5, L3, ROUND, 5, L4, ROUND, 5"
                              << 10.0 << 5.0;
        QTest::newRow("circle") << "P1 = POINT/50, 50\nC1 = CIRCLE/CENTER, P1, RADIUS, 30\nK1 = CONTOUR/CCLW, C1" << 30.0
                                << 30.0;
    }
    void sizingByHand()
    {
        QFETCH(QString, figure);
        QFETCH(double, inscribed);
        QFETCH(double, reach);
        const auto parsed = figure::parseFigure(figure.toStdString());
        QVERIFY(parsed.ok());
        const figure::Evaluation e = figure::evaluate(parsed.definitions);
        QVERIFY(e.ok());
        const Region r = normalised(Region{e.findContour("K1")->contour, {}});
        const double in = paths::inscribedRadius(r);
        QVERIFY2(std::abs(in - inscribed) < 2e-3, fmt::format("inscribed {}", in).c_str());
        const double reached = paths::reachRadius(r, in);
        QVERIFY2(reached >= reach - 2e-3 && reached <= reach + 1e-2, fmt::format("reach {}", reached).c_str());
    }

    // Item 1, the refusal: 25,000 edges are more than a region may have;
    // named on the outline with the count, before any sizing.
    void tooManyEdgesAreRefusedOnTheOutline()
    {
        const Job j = job(roundedPolygon(25'000, 400), cpUnit());
        const Diagnostics ds = checkJob(j, TechnologyTable::builtIn(), defaultToolLibrary());
        const Diagnostic* d = on(ds, "outline");
        QVERIFY2(d, messages(ds).c_str());
        QVERIFY2(d->message.find("50000 lines and arcs; at most 20000") != std::string::npos, d->message.c_str());
    }

    // Item 2: passes drawn at random across the area cross each other
    // everywhere (the unswept area's union is quadratic in them): refused
    // on the points, naming the pairs. The same number of points in a
    // zigzag (negative control) is taken, with its unswept warning.
    void crossingPassesAreRefusedZigzagTaken()
    {
        std::mt19937 rng(1);
        std::uniform_real_distribution<double> at(130, 870);
        std::vector<Point2> random, zigzag;
        for (int i = 0; i < 1000; ++i) random.push_back({at(rng), at(rng)});
        for (int row = 0; row < 20; ++row)
            for (int k = 0; k < 50; ++k) zigzag.push_back({row % 2 ? 870.0 - 14.8 * k : 130.0 + 14.8 * k, 130.0 + 38.0 * row});
        const Diagnostics refused = checkJob(job(kSquareArea, areaUnit(random)), TechnologyTable::builtIn(), defaultToolLibrary());
        const Diagnostic* d = on(refused, "points");
        QVERIFY2(d, messages(refused).c_str());
        QVERIFY2(d->message.find("overlap in more than 50000 pairs") != std::string::npos, d->message.c_str());
        const Diagnostics taken = checkJob(job(kSquareArea, areaUnit(zigzag)), TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY2(!hasErrors(taken), messages(taken).c_str());
    }

    // Item 4: the move budget is input processing. A FACE on a 10 x 10 m
    // block 900 deep at step-over 0.01 and one with a margin of 10⁶ mm
    // (at step-over 0.01) are refused by a plan without paths (`taiwa
    // check`), naming the field that drives the moves; the same block at the
    // default step-over is taken.
    void checkRefusesWhatExportWould_data()
    {
        QTest::addColumn<QString>("unit");
        QTest::addColumn<QString>("field");
        QTest::newRow("step-over") << R"({"module": "FACE", "name": "f", "depth": 900, "stepOver": 0.01})" << "stepOver";
        QTest::newRow("margin") << R"({"module": "FACE", "name": "f", "depth": 10, "stepOver": 0.01, "margin": 1000000})"
                                << "margin";
        QTest::newRow("control") << R"({"module": "FACE", "name": "f", "depth": 1})" << "";
    }
    void checkRefusesWhatExportWould()
    {
        QFETCH(QString, unit);
        QFETCH(QString, field);
        const Job j = job({}, nlohmann::json::array({nlohmann::json::parse(unit.toStdString())}), 10'000, 10'000, 1000);
        PlanOptions o;
        o.withToolPaths = false;
        const Plan plan = planJob(j, TechnologyTable::builtIn(), defaultToolLibrary(), o);
        if (field.isEmpty()) {
            QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
            return;
        }
        const Diagnostic* d = on(plan.diagnostics, field.toStdString());
        QVERIFY2(d, messages(plan.diagnostics).c_str());
        QVERIFY2(d->message.find("more than the 1e+07 a job may have") != std::string::npos, d->message.c_str());
    }

    // A 3-D surface's nose points count six pocket moves each in the budget
    // (its door's workPerMove: a drop-cutter each, a ball's disc swept in the
    // verification): 200 copies of the sample's surface, about 2.2 million
    // moves, within the 10⁷ as moves but not as work, are refused by the
    // checks alone on the surface's curve 1 (its roughing has the most
    // moves, and only a smaller surface makes fewer), the message saying
    // how the unit's moves count; 20 copies are taken.
    void surfaceMovesCountAsTheirWork_data()
    {
        QTest::addColumn<int>("copies");
        QTest::addColumn<bool>("refused");
        QTest::newRow("200 copies") << 200 << true;
        QTest::newRow("20 copies") << 20 << false;
    }
    void surfaceMovesCountAsTheirWork()
    {
        QFETCH(int, copies);
        QFETCH(bool, refused);
        nlohmann::json units = nlohmann::json::array();
        for (int k = 0; k < copies; ++k) {
            const double x = 70.0 * (k % 20), y = 50.0 * (k / 20);
            units.push_back({{"module", "SURFACE"},
                             {"name", "s" + std::to_string(k)},
                             {"curve1", {{"points", {{x + 5, y + 5, -7}, {x + 35, y + 5, -9}, {x + 65, y + 5, -7}}}}},
                             {"curve2", {{"points", {{x + 5, y + 45, -3}, {x + 65, y + 45, -3}}}}},
                             {"n", 3},
                             {"m", 12},
                             {"scallop", 0.3},
                             {"allowance", 0.3}});
        }
        PlanOptions o;
        o.withToolPaths = false;
        const Plan plan = planJob(job({}, units, 1400, 500, 25), TechnologyTable::builtIn(), defaultToolLibrary(), o);
        double moves = 0.0, work = 0.0;
        for (const Step& st : plan.steps)
            if (st.tool)
                if (const Tool* t = plan.tool(st.tool->toolId)) {
                    moves += estimateMoves(st, *t, plan.technology, o.path);
                    work += estimateWork(st, *t, plan.technology, o.path);
                }
        QVERIFY2(moves > 0.0 && std::abs(work - 6.0 * moves) < 1e-6 * work, qPrintable(QString("%1 %2").arg(moves).arg(work)));
        QVERIFY(moves < kMaxPlanMoves);
        if (!refused) {
            QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
            return;
        }
        const Diagnostic* d = on(plan.diagnostics, "curve1");
        QVERIFY2(d, messages(plan.diagnostics).c_str());
        QVERIFY2(d->message.find("each of this unit's counts as 6), more than the 1e+07 a job may have") != std::string::npos,
                 d->message.c_str());
    }

    // Item 5: a circle of 20,000 LINEs through the DXF reader and the figure
    // text: one closed contour of 20,000 segments, its figure evaluated with
    // every element looked up through the index.
    void manyLinesFromDxf()
    {
        const int n = 20'000;
        std::string dxf = "0\nSECTION\n2\nENTITIES\n";
        for (int i = 0; i < n; ++i) {
            const double a = 2 * std::numbers::pi * i / n, b = 2 * std::numbers::pi * (i + 1) / n;
            dxf += fmt::format("0\nLINE\n8\n0\n10\n{:.9f}\n20\n{:.9f}\n11\n{:.9f}\n21\n{:.9f}\n", 400 * std::cos(a),
                               400 * std::sin(a), 400 * std::cos(b), 400 * std::sin(b));
        }
        dxf += "0\nENDSEC\n0\nEOF\n";
        const dxf::DxfReadResult r = dxf::readDxfBytes(dxf);
        QVERIFY(r.ok());
        QCOMPARE(r.contours.size(), std::size_t{1});
        QVERIFY(r.contours[0].contour.closed);
        QCOMPARE(r.contours[0].contour.segments.size(), std::size_t(n));
        const FigureFromContours f = figureFromContours({r.contours[0].contour});
        const auto parsed = figure::parseFigure(f.text);
        QVERIFY(parsed.ok());
        const figure::Evaluation e = figure::evaluate(parsed.definitions);
        QVERIFY(e.ok());
        QCOMPARE(e.elementIndex.size(), e.elements.size());
        QCOMPARE(e.contours.size(), std::size_t{1});
        QCOMPARE(e.findContour(f.names[0])->contour.segments.size(), std::size_t(n));
    }
};

QTEST_APPLESS_MAIN(TestBoundedWork)
#include "test_bounded_work.moc"
