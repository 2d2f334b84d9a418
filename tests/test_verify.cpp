// The verifying simulation (core/verify): small exact cases (a slot's volume,
// a ball's scallop, a gouge at its block, a rapid through stock, a short
// holder and too short flutes in a deep pocket, the travel), every milling
// sample clean, and each fault class caught when a test puts it into a
// sample's paths; the colour map of gouges and material left.
#include "modules/m4/m4.h"
#include "post/post.h"
#include "tools/holder_shape.h"
#include "support/hand_plan.h"
#include "support/support.h"
#include "verify/deviation.h"
#include "verify/verify.h"

#include <QtTest>

#include <QDir>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

using namespace taiwa;
using namespace taiwa::verify;

namespace {

Tool endMill(int id, ToolType type, double d, double flute, double stickout)
{
    Tool t;
    t.id = id;
    t.type = type;
    t.diameter = d;
    t.cornerRadius = type == ToolType::BallEndMill ? d / 2 : 0.0;
    t.fluteLength = flute;
    t.stickout = stickout;
    t.holder = "HSK63 shrink-fit";
    t.cutting = {{"aluminium-6061", 300, 0.01, 0.5}};
    return t;
}

// A plan by hand: one M4 unit (a rectangle [x0,x1] x [y0,y1] with radius r
// and depth T) in a block of stock, one step of `kind` with `tool` and `path`.
Plan planOf(double x0, double y0, double x1, double y1, double r, double T, const Tool& tool, ToolPath path,
            StepKind kind = StepKind::Roughing, double stockHeight = 30)
{
    Plan plan;
    plan.mmJob.stock = {0, 0, 100, 80, stockHeight};
    M4Pocket p;
    p.corners = {Point2{x0, y0}, Point2{x1, y0}, Point2{x1, y1}, Point2{x0, y1}};
    p.cornerRadius = r;
    p.depth = T;
    p.toolUse = 1;
    plan.mmJob.units.push_back({"pocket", p, {}});
    plan.job = plan.mmJob;
    plan.tools = {tool};
    Step s;
    s.module = "M4";
    s.kind = kind;
    editMilling(s).cutDepth = T;
    s.tool = ToolChoice{tool.id, "test"};
    s.path = std::move(path);
    plan.steps = {s};
    return plan;
}

ToolPath line(Point3 from, Point3 to)
{
    ToolPath p{{from.x, from.y, 5}, {}};
    p.moves.push_back({MoveKind::Rapid, {from.x, from.y, 1}});
    p.moves.push_back({MoveKind::Feed, from, {}, FeedKind::Plunge});
    p.moves.push_back({MoveKind::Feed, to});
    p.moves.push_back({MoveKind::Rapid, {to.x, to.y, 5}});
    return p;
}

// The slot from (30,40) to (70,40) 5 deep in its own pocket, dipping to
// Z-5.5 at (60,40): a gouge of 0.5 mm on move 3 (down) and 4 (back up).
Plan gougedSlot(const Tool& mill)
{
    ToolPath p = line({30, 40, -5}, {50, 40, -5});
    p.moves.insert(p.moves.begin() + 3, Move{MoveKind::Feed, {60, 40, -5.5}});
    p.moves.insert(p.moves.begin() + 4, Move{MoveKind::Feed, {70, 40, -5}});
    return planOf(25, 35, 75, 45, 5, 5, mill, p);
}

const Finding* first(const Report& r, FindingKind k)
{
    const auto it = std::find_if(r.findings.begin(), r.findings.end(), [k](const Finding& f) { return f.kind == k; });
    return it == r.findings.end() ? nullptr : &*it;
}

DeviationBand bandAt(const DeviationMap& m, double x, double y)
{
    const int i = static_cast<int>(std::floor((x - m.stock.stock().x) / m.stock.cellSize()));
    const int j = static_cast<int>(std::floor((y - m.stock.stock().y) / m.stock.cellSize()));
    return m.band[m.stock.indexOf(i, j)];
}

long count(const DeviationMap& m, DeviationBand b) { return static_cast<long>(std::count(m.band.begin(), m.band.end(), b)); }

std::string kinds(const Report& r, const Plan& plan)
{
    std::string s;
    for (const auto& f : r.findings) s += describe(f, plan) + "\n";
    return s;
}

}  // namespace

class TestVerify : public QObject {
    Q_OBJECT
private slots:
    // A D10 flat end mill 5 deep from (30,40) to (70,40): a stadium of
    // 40 x 10 and two half discs, the pocket's own outline, so nothing is
    // left and nothing gouged; the volume to the resolution.
    void slotRemovesItsVolume()
    {
        const Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
        const Plan plan = planOf(25, 35, 75, 45, 5, 5, mill, line({30, 40, -5}, {70, 40, -5}));
        const Report r = verifyPlan(plan);
        QVERIFY2(r.findings.empty(), kinds(r, plan).c_str());
        const double exact = (40 * 10 + std::numbers::pi * 25) * 5;
        const double perimeter = 2 * 40 + 2 * std::numbers::pi * 5;
        QCOMPARE(r.removed.size(), std::size_t{1});
        QVERIFY2(std::abs(r.removed[0] - exact) <= perimeter * r.resolution * 5,
                 qPrintable(QString("removed %1 mm³, exact %2").arg(r.removed[0]).arg(exact)));
        // Coarser cells, the same volume to their resolution.
        Options coarse;
        coarse.resolution = 0.25;
        const Report c = verifyPlan(plan, coarse);
        QVERIFY(std::abs(c.removed[0] - exact) <= perimeter * 0.25 * 5);
        QVERIFY(std::abs(c.removed[0] - exact) > std::abs(r.removed[0] - exact) - 1e-9);
    }

    // A move cut as 2,000 chords of 0.02 mm removes what the one move
    // removes, with a flat end mill and with a corner radius (a chord's
    // start is not visited again within the flat bottom the chord before
    // cut; skipping out to the corner radius would leave its ring uncut).
    void shortChordsCutAsOneMove()
    {
        for (const double corner : {0.0, 2.0}) {
            Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
            mill.cornerRadius = corner;  // a bull nose
            const Plan one = planOf(25, 35, 75, 45, 5, 5, mill, line({30, 40, -5}, {70, 40, -5}));
            ToolPath chords = line({30, 40, -5}, {70, 40, -5});
            chords.moves.erase(chords.moves.begin() + 2);  // the move itself, put back in pieces
            for (int k = 1999; k >= 1; --k)
                chords.moves.insert(chords.moves.begin() + 2, Move{MoveKind::Feed, {30 + k * 0.02, 40, -5}});
            chords.moves.insert(chords.moves.begin() + 2 + 1999, Move{MoveKind::Feed, {70, 40, -5}});
            QCOMPARE(chords.moves.size(), std::size_t{2003});
            const Plan many = planOf(25, 35, 75, 45, 5, 5, mill, chords);
            const Report a = verifyPlan(one), b = verifyPlan(many);
            QVERIFY2(a.findings.empty() && b.findings.empty(), (kinds(a, one) + kinds(b, many)).c_str());
            QVERIFY2(std::abs(a.removed[0] - b.removed[0]) <= 1e-6 * a.removed[0],
                     qPrintable(QString("corner %1: one move %2 mm³, chords %3 mm³").arg(corner).arg(a.removed[0]).arg(b.removed[0])));
        }
    }

    // Two passes of a ball R3 two millimetres apart leave the analytic
    // scallop R - sqrt(R² - (s/2)²) between them.
    void ballLeavesTheScallop()
    {
        const Tool ball = endMill(1, ToolType::BallEndMill, 6, 12, 40);
        ToolPath p = line({30, 39, -2}, {70, 39, -2});
        p.moves.push_back({MoveKind::Rapid, {30, 41, 5}});
        p.moves.push_back({MoveKind::Feed, {30, 41, -2}, {}, FeedKind::Plunge});
        p.moves.push_back({MoveKind::Feed, {70, 41, -2}});
        p.moves.push_back({MoveKind::Rapid, {70, 41, 5}});
        const Plan plan = planOf(20, 30, 80, 50, 5, 2, ball, p, StepKind::InclinedFaceFinishing);
        const Report r = verifyPlan(plan);
        QCOMPARE(r.count(FindingKind::Gouge), 0);
        const double scallop = 3 - std::sqrt(9 - 1);
        // Along the line midway between the passes, away from their ends.
        const sim::HeightField& f = r.stock;
        const int j = static_cast<int>(std::floor(40 / f.cellSize()));
        double highest = -1e9, lowestBeside = 1e9;
        for (int i = static_cast<int>(40 / f.cellSize()); i < static_cast<int>(60 / f.cellSize()); ++i) {
            for (int dj = -1; dj <= 0; ++dj) highest = std::max(highest, f.at(i, j + dj));
            lowestBeside = std::min(lowestBeside, f.at(i, static_cast<int>(39 / f.cellSize())));
        }
        // The cells nearest the cusp lie within half a cell of it, where the
        // ball's flank falls by at most slope x half a cell.
        const double slope = 1.0 / std::sqrt(9 - 1), nearCusp = slope * f.cellSize();
        QVERIFY2(highest <= -2 + scallop + 1e-6 && highest >= -2 + scallop - nearCusp,
                 qPrintable(QString("highest %1, analytic %2").arg(highest).arg(-2 + scallop)));
        QVERIFY(std::abs(lowestBeside + 2) < 1e-3);  // under a pass: the ball's bottom
    }

    // A hand-written tape that dips 0.5 mm below the floor on one move:
    // found at that move, and on the tape at the line that writes it.
    void gougeFoundAtItsBlock()
    {
        const Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
        const Plan plan = gougedSlot(mill);
        Report r = verifyPlan(plan);
        QCOMPARE(r.count(FindingKind::Gouge), 2);  // down to (60,40,-5.5) and back up from it
        const Finding* g = first(r, FindingKind::Gouge);
        QCOMPARE(g->move, 3);
        QVERIFY2(std::abs(g->size - 0.5) < 0.01, qPrintable(QString::number(g->size)));
        QVERIFY(std::abs(g->position.x - 60) <= 5 + r.resolution);
        QVERIFY(g->fatal());
        QVERIFY(r.fatal());
        PostOptions o;
        o.material = "aluminium-6061";
        const PostedProgram tape = postProcess(plan.steps, plan.tools, o);
        placeOnTape(r, tape);
        QVERIFY(first(r, FindingKind::Gouge)->line > 0);
        const QStringList lines = QString::fromStdString(tape.nc).split('\n');
        QVERIFY2(lines[first(r, FindingKind::Gouge)->line - 1].contains("Z-5.5"),
                 qPrintable(lines[first(r, FindingKind::Gouge)->line - 1]));
        QVERIFY2(QString::fromStdString(describe(*first(r, FindingKind::Gouge), plan)).contains("gouge 0.50"),
                 kinds(r, plan).c_str());
        // And a path that runs 0.3 mm past the wall.
        const Plan wide = planOf(25, 35, 75, 45, 5, 5, mill, line({30, 40, -5}, {70.3, 40, -5}));
        const Report w = verifyPlan(wide);
        QCOMPARE(w.count(FindingKind::Gouge), 1);
        const Point3 at = first(w, FindingKind::Gouge)->position;
        QVERIFY(std::hypot(at.x - 70, at.y - 40) > 5);  // outside the pocket's end
    }

    // A G0 through uncut stock is a rapid into stock, at that move.
    void rapidThroughStockFound()
    {
        const Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
        ToolPath p{{30, 40, 5}, {}};
        p.moves.push_back({MoveKind::Rapid, {30, 40, 1}});
        p.moves.push_back({MoveKind::Feed, {30, 40, -3}, {}, FeedKind::Plunge});
        p.moves.push_back({MoveKind::Rapid, {70, 40, -3}});
        p.moves.push_back({MoveKind::Rapid, {70, 40, 5}});
        const Plan plan = planOf(25, 35, 75, 45, 5, 5, mill, p);
        const Report r = verifyPlan(plan);
        const Finding* f = first(r, FindingKind::RapidIntoStock);
        QVERIFY(f);
        QCOMPARE(f->move, 2);
        QVERIFY(std::abs(f->size - 3) < 1e-3);
        QCOMPARE(r.count(FindingKind::Gouge), 0);
        // The same move at feed is no finding of that kind.
        p.moves[2].kind = MoveKind::Feed;
        QCOMPARE(verifyPlan(planOf(25, 35, 75, 45, 5, 5, mill, p)).count(FindingKind::RapidIntoStock), 0);
    }

    // A pocket 50 deep cut along its wall: a holder 45 out runs its
    // shrink-fit nose (Ø24) into the wall, one 70 out does not; flutes of
    // 20 cutting 30 deep into solid stock take the shank into it.
    void holderAndShankCollide()
    {
        ToolPath p{{30, 40, 5}, {}};
        for (double z = -5; z >= -50; z -= 5) {
            p.moves.push_back({MoveKind::Feed, {30, 40, z}, {}, FeedKind::Plunge});
            for (Point2 q : {Point2{70, 40}, Point2{70, 45}, Point2{30, 45}, Point2{30, 40}})
                p.moves.push_back({MoveKind::Feed, {q.x, q.y, z}});
        }
        p.moves.push_back({MoveKind::Rapid, {30, 40, 5}});
        const auto withTool = [&](double flute, double stickout) {
            return verifyPlan(
                planOf(25, 35, 75, 50, 5, 50, endMill(1, ToolType::FlatEndMill, 10, flute, stickout), p, StepKind::Roughing, 60));
        };
        const Report shortHolder = withTool(44, 45);
        const Finding* c = first(shortHolder, FindingKind::Collision);
        QVERIFY(c);
        QCOMPARE(QString::fromStdString(c->part), QString("holder"));
        QVERIFY(c->position.z > -5 - 1e-3);  // the stock above the holder's face at the last level
        QVERIFY(shortHolder.fatal());
        const Report longHolder = withTool(55, 70);  // (flutes past the depth: no shank in stock)
        QVERIFY2(longHolder.findings.empty(), kinds(longHolder, Plan{}).c_str());

        // The library's own holder measure before the name's rule: a Ø10
        // nose on the same short stick-out keeps clear of the walls.
        Tool slim = endMill(1, ToolType::FlatEndMill, 10, 44, 45);
        slim.holderDiameter = 10;
        QCOMPARE(tools::holderShape(slim).noseDiameter, 10.0);
        QCOMPARE(tools::holderShape(endMill(1, ToolType::FlatEndMill, 10, 44, 45)).noseDiameter, 24.0);  // shrink-fit, Ø10 shank
        QCOMPARE(verifyPlan(planOf(25, 35, 75, 50, 5, 50, slim, p, StepKind::Roughing, 60)).count(FindingKind::Collision), 0);

        ToolPath plunge = line({50, 42, -30}, {50, 42, -30});
        const Report shortFlutes = verifyPlan(
            planOf(25, 35, 75, 50, 5, 50, endMill(1, ToolType::FlatEndMill, 10, 20, 70), plunge, StepKind::Roughing, 60));
        const Finding* s = first(shortFlutes, FindingKind::Collision);
        QVERIFY(s);
        QCOMPARE(QString::fromStdString(s->part), QString("shank"));
        QVERIFY(std::abs(s->size - 10) < 1e-3);  // 30 deep with 20 of flutes
    }

    // Material a roughing layer should have cleared is found on its step.
    void restMaterialFound()
    {
        const Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
        const Plan plan = planOf(25, 35, 75, 45, 5, 5, mill, line({30, 40, -5}, {60, 40, -5}));
        const Report r = verifyPlan(plan);
        const Finding* f = first(r, FindingKind::RestMaterial);
        QVERIFY(f);
        QCOMPARE(f->step, 0);
        QVERIFY(std::abs(f->size - 5) < 1e-3);
        QVERIFY2(f->position.x > 60, kinds(r, plan).c_str());  // past the tool's reach from X60
        // The uncut end, less a band of one cell along its edge.
        const double area = 10 * 10;  // between the half discs at X60 and X70
        QVERIFY2(std::abs(f->area - area) < 20 * r.resolution * 2, qPrintable(QString::number(f->area)));
        QVERIFY(!r.fatal());
    }

    void travelLimitFound()
    {
        Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
        Plan plan = planOf(25, 35, 75, 45, 5, 5, mill, line({30, 40, -5}, {70, 40, -5}));
        plan.mmJob.machine = "vmc";  // X travels 800
        plan.steps[0].path->moves.push_back({MoveKind::Rapid, {900, 40, 5}});
        const Report r = verifyPlan(plan);
        const Finding* f = first(r, FindingKind::TravelLimit);
        QVERIFY(f);
        QCOMPARE(QString::fromStdString(f->part), QString("x"));
        QVERIFY(std::abs(f->size - (900 - 30 - 800)) < 1e-9);
    }

    void resolutionRefused()
    {
        const Plan plan = test::samplePlan("m4-standard.taiwa");
        Options o;
        o.resolution = 0.001;
        QVERIFY_THROWS_EXCEPTION(Refusal, verifyPlan(plan, o));
        o.resolution = std::nan("");
        QVERIFY_THROWS_EXCEPTION(Refusal, verifyPlan(plan, o));
    }

    void samplesVerifyClean_data()
    {
        QTest::addColumn<QString>("sample");
        for (const QString& f : QDir(test::sourcePath("resources/samples")).entryList({"*.taiwa"}))
            if (!f.startsWith("lathe-")) QTest::newRow(qPrintable(f)) << f;
    }
    void samplesVerifyClean()
    {
        QFETCH(QString, sample);
        const Plan plan = test::samplePlan(qPrintable(sample));
        QVERIFY(plan.ok());
        const Report r = verifyPlan(plan);
        QVERIFY(r.skipped.empty());
        QVERIFY2(r.findings.empty(), kinds(r, plan).c_str());
        double removed = 0;
        for (double v : r.removed) removed += v;
        if (!plan.steps.empty() && sample != "probe-bore.taiwa" && sample != "probe-vise-block.taiwa") QVERIFY(removed > 0);
        // Its colour map agrees: no gouge anywhere.
        QCOMPARE(count(deviationMap(plan, r), DeviationBand::Gouge), 0L);
    }

    // A lathe job is simulated on its half-section (tests/test_verify_turning.cpp).
    void latheJobVerified()
    {
        const Report r = verifyPlan(test::samplePlan("lathe-turned-shaft.taiwa"));
        QVERIFY(r.skipped.empty());
        QVERIFY(!r.section.empty());
        QCOMPARE(r.columns, 0);
    }

    // Each fault class put into the paths of m4-standard.taiwa is found on
    // the step and move it was put into.
    void faultsInASampleFound()
    {
        const Plan clean = test::samplePlan("m4-standard.taiwa");
        const auto stepOf = [&](StepKind k) {
            for (std::size_t i = 0; i < clean.steps.size(); ++i)
                if (clean.steps[i].kind == k) return static_cast<int>(i);
            return -1;
        };
        const int floor = stepOf(StepKind::FloorFinishing), rough = stepOf(StepKind::Roughing),
                  wall = stepOf(StepKind::WallFinishing);
        QVERIFY(floor >= 0 && rough >= 0 && wall >= 0);

        {  // the floor pass 0.2 mm too deep on one feed move
            Plan p = clean;
            auto& moves = p.steps[floor].path->moves;
            const auto it = std::find_if(moves.begin() + 2, moves.end(), [](const Move& m) { return m.kind == MoveKind::Feed; });
            const int k = static_cast<int>(it - moves.begin());
            it->end.z -= 0.2;
            const Report r = verifyPlan(p);
            const Finding* g = first(r, FindingKind::Gouge);
            QVERIFY2(g, kinds(r, p).c_str());
            QCOMPARE(g->step, floor);
            QCOMPARE(g->move, k);
            QVERIFY(std::abs(g->size - 0.2) < 0.01);
        }
        {  // roughing's longest cutting move as a rapid
            Plan p = clean;
            auto& moves = p.steps[rough].path->moves;
            std::size_t k = 0;
            double longest = 0;
            for (std::size_t i = 1; i < moves.size(); ++i) {
                const double l = std::hypot(moves[i].end.x - moves[i - 1].end.x, moves[i].end.y - moves[i - 1].end.y);
                if (moves[i].kind == MoveKind::Feed && moves[i].feed == FeedKind::Cut && l > longest) k = i, longest = l;
            }
            QVERIFY(longest > 10);
            const auto it = moves.begin() + static_cast<std::ptrdiff_t>(k);
            it->kind = MoveKind::Rapid;
            const Report r = verifyPlan(p);
            const Finding* f = first(r, FindingKind::RapidIntoStock);
            QVERIFY2(f, kinds(r, p).c_str());
            QCOMPARE(f->step, rough);
            QCOMPARE(f->move, static_cast<int>(it - moves.begin()));
        }
        {  // roughing stopped halfway: its layer not cleared
            Plan p = clean;
            auto& moves = p.steps[rough].path->moves;
            moves.resize(moves.size() / 2);
            const Report r = verifyPlan(p);
            const Finding* f = first(r, FindingKind::RestMaterial);
            QVERIFY2(f, kinds(r, p).c_str());
            QCOMPARE(f->step, rough);
        }
        {  // the wall finisher's holder too short for the pocket
            Plan p = clean;
            for (Tool& t : p.tools)
                if (t.id == p.steps[wall].tool->toolId) t.stickout = 5, t.fluteLength = 5;
            const Report r = verifyPlan(p);
            const Finding* f = first(r, FindingKind::Collision);
            QVERIFY2(f, kinds(r, p).c_str());
        }
        {  // the wall pass moved out by 0.1 mm: a gouge in the wall
            Plan p = clean;
            const Point2 c = millingOf(p.steps[wall]).position;
            for (Move& m : p.steps[wall].path->moves) {
                if (m.end.z >= 0) continue;
                const Point2 d{m.end.x - c.x, m.end.y - c.y};
                const double l = std::hypot(d.x, d.y);
                if (l > 0) m.end = {m.end.x + 0.1 * d.x / l, m.end.y + 0.1 * d.y / l, m.end.z};
                if (m.kind == MoveKind::ArcCW || m.kind == MoveKind::ArcCCW) m.kind = MoveKind::Feed;
            }
            const Report r = verifyPlan(p);
            QVERIFY2(r.count(FindingKind::Gouge) > 0, kinds(r, p).c_str());
            QCOMPARE(first(r, FindingKind::Gouge)->step, wall);
        }
    }

    // The colour map (verify/deviation.h) of a D10 slot in a pocket that is
    // its own outline: at size in the slot and along its edge, the stock
    // around it untouched, nothing else; 3.2 M verification cells drawn on
    // a grid of at most a million.
    void colourMapOfACleanSlot()
    {
        const Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
        const Plan plan = planOf(25, 35, 75, 45, 5, 5, mill, line({30, 40, -5}, {70, 40, -5}));
        const Report r = verifyPlan(plan);
        const DeviationMap m = deviationMap(plan, r);
        QCOMPARE(m.factor, 2);
        QCOMPARE(m.stock.columns(), 1000);
        QCOMPARE(m.band.size(), m.amount.size());
        QCOMPARE(bandAt(m, 50, 40), DeviationBand::AtSize);
        QCOMPARE(bandAt(m, 26, 40), DeviationBand::AtSize);
        QCOMPARE(bandAt(m, 10, 10), DeviationBand::Untouched);
        QCOMPARE(bandAt(m, 50, 46), DeviationBand::Untouched);
        for (const DeviationBand b : {DeviationBand::Gouge, DeviationBand::RestThin, DeviationBand::RestMedium, DeviationBand::RestThick})
            QCOMPARE(count(m, b), 0);
        QCOMPARE(m.stock.atPoint(50, 40), -5.0);
        // A lathe job's report has no stock: no map.
        Report none;
        none.skipped = "lathe";
        QVERIFY(deviationMap(plan, none).empty());
    }

    // A floor 0.5 mm too deep is a gouge of 0.5 mm where the verification
    // found it, on the fine map and on one 30 times coarser (the worst cell
    // of each block shown); material left by a floor too high is banded by
    // its thickness, and the uncut end of a short path is thick.
    void colourMapShowsGougesAndMaterialLeft()
    {
        const Tool mill = endMill(1, ToolType::FlatEndMill, 10, 25, 45);
        const Plan gouged = gougedSlot(mill);
        const Report r = verifyPlan(gouged);
        for (const std::size_t cells : {std::size_t{4'000'000}, std::size_t{4'000}}) {
            const DeviationMap m = deviationMap(gouged, r, cells);
            QCOMPARE(bandAt(m, 60, 40), DeviationBand::Gouge);
            QVERIFY2(std::abs(*std::min_element(m.amount.begin(), m.amount.end()) + 0.5) < 0.01,
                     qPrintable(QString::number(*std::min_element(m.amount.begin(), m.amount.end()))));
            QCOMPARE(bandAt(m, 10, 10), DeviationBand::Untouched);
        }
        QCOMPARE(deviationMap(gouged, r, 4'000).factor, 29);  // ceil(sqrt(3.2 M / 4,000))
        const auto floorAt = [&](double z) {
            const Plan plan = planOf(25, 35, 75, 45, 5, 5, mill, line({30, 40, z}, {60, 40, z}));
            return deviationMap(plan, verifyPlan(plan));
        };
        const DeviationMap thin = floorAt(-4.95), medium = floorAt(-4.7);
        QCOMPARE(bandAt(thin, 45, 40), DeviationBand::RestThin);
        QVERIFY(std::abs(thin.amount[thin.stock.indexOf(450, 400)] - 0.05) < 1e-4);
        QCOMPARE(bandAt(medium, 45, 40), DeviationBand::RestMedium);
        QCOMPARE(bandAt(medium, 68, 40), DeviationBand::RestThick);  // past the path's reach: 5 mm left
        QVERIFY(std::abs(medium.amount[medium.stock.indexOf(680, 400)] - 5.0) < 1e-4);
    }
};

QTEST_GUILESS_MAIN(TestVerify)
#include "test_verify.moc"
