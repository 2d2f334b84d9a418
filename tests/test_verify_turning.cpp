// The verifying simulation of lathe jobs (core/verify, verify_turning.h):
// every lathe sample verifies with nothing fatal, its half-section and
// volumes add up, and each fault class put into a sample's turning paths by
// the test is found on the step and move it was put into: a finishing move
// pushed 0.2 mm into the part (placed on its tape line), a cutting feed
// turned into a rapid, roughing cut short, a move beyond the lathe's travel;
// roughing reaches a profile's end where the bar goes on behind it.
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "post/post.h"
#include "support/hand_plan.h"
#include "support/support.h"
#include "verify/verify.h"
#include "model/turn_path.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <QDir>
#include <QElapsedTimer>
#include <QRegularExpression>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

using namespace taiwa;
using namespace taiwa::verify;

namespace {

std::string kinds(const Report& r, const Plan& plan)
{
    std::string s;
    for (const auto& f : r.findings) s += describe(f, plan) + "\n";
    return s;
}

const Finding* find(const Report& r, FindingKind k, int step, int move = -2)
{
    const auto it = std::find_if(r.findings.begin(), r.findings.end(), [&](const Finding& f) {
        return f.kind == k && f.step == step && (move == -2 || f.move == move);
    });
    return it == r.findings.end() ? nullptr : &*it;
}

int stepOf(const Plan& plan, StepKind k)
{
    for (std::size_t i = 0; i < plan.steps.size(); ++i)
        if (plan.steps[i].kind == k) return static_cast<int>(i);
    return -1;
}

// The volume of closed (z, r) loops turned about the axis [mm³].
double volumeOf(const std::vector<std::vector<turning::ZR>>& loops)
{
    double m = 0.0;
    for (const auto& l : loops)
        for (std::size_t i = 0; i < l.size(); ++i) {
            const turning::ZR a = l[i], b = l[(i + 1) % l.size()];
            m += (a.r + b.r) * (a.z * b.r - b.z * a.r) / 6.0;
        }
    return 2.0 * std::numbers::pi * m;
}

}  // namespace

class TestVerifyTurning : public QObject {
    Q_OBJECT
private slots:
    void samplesVerifyWithNothingFatal_data()
    {
        QTest::addColumn<QString>("sample");
        for (const QString& f : QDir(test::sourcePath("resources/samples")).entryList({"lathe-*.taiwa"}))
            QTest::newRow(qPrintable(f)) << f;
    }
    void samplesVerifyWithNothingFatal()
    {
        QFETCH(QString, sample);
        const Plan plan = test::samplePlan(qPrintable(sample));
        QVERIFY(plan.ok());
        QVERIFY(plan.mmJob.bar);
        QElapsedTimer clock;
        clock.start();
        const Report r = verifyPlan(plan);
        const qint64 ms = clock.elapsed();
        qInfo("%s: %d steps verified in %lld ms, %d findings", qPrintable(sample), static_cast<int>(plan.steps.size()),
              ms, static_cast<int>(r.findings.size()));
        QVERIFY(r.skipped.empty());
        QVERIFY2(!r.fatal(), kinds(r, plan).c_str());
        QVERIFY2(r.findings.empty(), kinds(r, plan).c_str());
        QVERIFY(!r.section.empty());
        QCOMPARE(r.removed.size(), plan.steps.size());
        // What the steps took off is what the bar lost.
        const BarStock& bar = *plan.mmJob.bar;
        const double barVolume =
            std::numbers::pi * (bar.diameter * bar.diameter - bar.bore * bar.bore) / 4.0 * bar.length;
        double removed = 0.0;
        for (std::size_t k = 0; k < r.removed.size(); ++k) {
            QVERIFY2(r.removed[k] >= -1e-6, qPrintable(QString("step %1 removed %2").arg(k + 1).arg(r.removed[k])));
            if (turnOf(plan.steps[k]) && !turnOf(plan.steps[k])->path.moves.empty())
                QVERIFY2(r.removed[k] > 0.0, qPrintable(QString("step %1 cut nothing").arg(k + 1)));
            removed += r.removed[k];
        }
        QVERIFY(std::abs(barVolume - volumeOf(r.section) - removed) < 1e-6 * barVolume);
        QVERIFY2(ms < 5000, qPrintable(QString::number(ms)));  // a few ms on an idle machine
        // Ten times finer (chords within 1 µm, a gouge from 6 µm): still clean.
        Options fine;
        fine.resolution = 0.005;
        const Report f = verifyPlan(plan, fine);
        QVERIFY2(f.findings.empty(), kinds(f, plan).c_str());
    }

    // A cylinder of the finishing contour moved 0.2 mm into the part
    // (outside: toward the axis; in a bore: away from it): a gouge of 0.2 mm
    // on that move, fatal, worded with X as a diameter.
    void finishingGougeFound_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<double>("into");
        QTest::newRow("outside") << "lathe-turned-shaft.taiwa" << -0.2;
        QTest::newRow("bore") << "lathe-bore-grinding.taiwa" << 0.2;
    }
    void finishingGougeFound()
    {
        QFETCH(QString, sample);
        QFETCH(double, into);
        Plan p = test::samplePlan(qPrintable(sample));
        const int finish = stepOf(p, StepKind::TurnFinishing);
        QVERIFY(finish >= 0);
        TurnStep edited = *turnOf(p.steps[static_cast<std::size_t>(finish)]);  // the payload is read-only: edit a copy
        TurnPath& path = edited.path;
        int k = -1;
        double longest = 0.0;
        for (int m = path.compFrom + 1; m < path.compTo; ++m) {
            const TurnMove& a = path.moves[static_cast<std::size_t>(m - 1)];
            const TurnMove& b = path.moves[static_cast<std::size_t>(m)];
            const double l = std::abs(a.end.z - b.end.z);
            if (b.kind == TurnMove::Feed && a.kind == TurnMove::Feed && std::abs(a.end.r - b.end.r) < 1e-9 &&
                l > longest)
                k = m, longest = l;
        }
        QVERIFY(k > 0 && longest > 5.0);
        path.moves[static_cast<std::size_t>(k - 1)].end.r += into;
        path.moves[static_cast<std::size_t>(k)].end.r += into;
        p.steps[static_cast<std::size_t>(finish)].payload = edited;
        const Report r = verifyPlan(p);
        const Finding* g = find(r, FindingKind::Gouge, finish, k);
        QVERIFY2(g, kinds(r, p).c_str());
        QVERIFY2(std::abs(g->size - 0.2) < 0.01, kinds(r, p).c_str());
        QVERIFY(g->area > 0.2 * (longest - 2.0));
        QVERIFY(r.fatal());
        const std::string words = describe(*g, p);
        QVERIFY2(words.find(" Z-") != std::string::npos && words.find(" Y") == std::string::npos, words.c_str());
        // On the FANUC tape: the block that ends the moved cylinder.
        Report placed = r;
        const PostedProgram tape = postProcess(p.steps, p.tools, postOptions(p, "fanuc", std::nullopt, 1000, "job"));
        placeOnTape(placed, tape);
        const Finding* onTape = find(placed, FindingKind::Gouge, finish, k);
        QVERIFY(onTape && onTape->line > 0);
        const QString block = QString::fromStdString(tape.nc).split('\n').value(onTape->line - 1);
        const auto z = QRegularExpression("Z(-?[0-9.]+)").match(block);
        QVERIFY2(z.hasMatch() && std::abs(z.captured(1).toDouble() - path.moves[static_cast<std::size_t>(k)].end.z) < 1e-3,
                 qPrintable(block));
        // The deepest point on the moved cylinder.
        const double dia = 2.0 * (path.moves[static_cast<std::size_t>(k)].end.r);
        QVERIFY2(std::abs(g->position.x - dia) < 0.02, kinds(r, p).c_str());
    }

    // Roughing's longest cutting feed as a rapid: a rapid into stock on it.
    void rapidIntoStockFound()
    {
        Plan p = test::samplePlan("lathe-turned-shaft.taiwa");
        const int rough = stepOf(p, StepKind::TurnRoughing);
        QVERIFY(rough >= 0);
        TurnStep edited = *turnOf(p.steps[static_cast<std::size_t>(rough)]);
        auto& moves = edited.path.moves;
        std::size_t k = 0;
        double longest = 0;
        for (std::size_t i = 1; i < moves.size(); ++i) {
            const double l = std::abs(moves[i].end.z - moves[i - 1].end.z);
            if (moves[i].kind == TurnMove::Feed && moves[i].feed == FeedKind::Cut && l > longest) k = i, longest = l;
        }
        QVERIFY(longest > 10);
        moves[k].kind = TurnMove::Rapid;
        p.steps[static_cast<std::size_t>(rough)].payload = edited;
        const Report r = verifyPlan(p);
        const Finding* f = find(r, FindingKind::RapidIntoStock, rough, static_cast<int>(k));
        QVERIFY2(f, kinds(r, p).c_str());
        QVERIFY2(f->size > 0.5, kinds(r, p).c_str());  // through a whole depth of cut
        QVERIFY(r.fatal());
    }

    // Roughing stopped halfway: material left on its step, not fatal.
    void roughingCutShortLeavesMaterial()
    {
        Plan p = test::samplePlan("lathe-turned-shaft.taiwa");
        const int rough = stepOf(p, StepKind::TurnRoughing);
        QVERIFY(rough >= 0);
        TurnStep edited = *turnOf(p.steps[static_cast<std::size_t>(rough)]);
        edited.path.moves.resize(edited.path.moves.size() / 2);
        p.steps[static_cast<std::size_t>(rough)].payload = edited;
        const Report r = verifyPlan(p);
        const Finding* f = find(r, FindingKind::RestMaterial, rough, -1);
        QVERIFY2(f, kinds(r, p).c_str());
        QVERIFY(!f->fatal());
        QVERIFY2(f->size > 1.0 && f->area > 1.0, kinds(r, p).c_str());
    }

    // Roughing up to where the bar goes on behind the profile's end (the
    // parting's, no step finishes that face): a profile ending at Ø20 Z-50
    // with no shoulder (the two-path cylinder, whose roughing once stopped
    // at Z-49.914 and left a 0.676 mm² sliver), at other diameters and
    // lengths, and with a back face down to the axis. Every pass along -Z
    // above the end's radius reaches the end's Z, and the verification
    // finds nothing left.
    void roughingReachesTheProfilesEnd_data()
    {
        QTest::addColumn<double>("diameter");
        QTest::addColumn<double>("z");
        QTest::addColumn<bool>("backFace");
        for (const double d : {20.0, 27.4, 34.0})
            for (const double z : {-50.0, -23.7}) QTest::newRow(qPrintable(QString("Ø%1 Z%2").arg(d).arg(z))) << d << z << false;
        QTest::newRow("Ø20 Z-50, back face") << 20.0 << -50.0 << true;
    }
    void roughingReachesTheProfilesEnd()
    {
        QFETCH(double, diameter);
        QFETCH(double, z);
        QFETCH(bool, backFace);
        QString text = QString::fromStdString(test::readFile(test::sourcePath("resources/samples/lathe-two-path-cylinder.taiwa")));
        text.replace(QRegularExpression(R"("x": 20,)"), QString(R"("x": %1,)").arg(diameter));
        text.replace(QRegularExpression(R"("z": -50\b)"), QString(R"("z": %1)").arg(z));
        if (backFace)
            text.replace(QRegularExpression(R"(\}\s*\]\s*\}\s*\]\s*\}\s*$)"),
                         QString(R"(}, {"id": 3, "kind": "line", "x": 0, "z": %1} ] } ] })").arg(z));
        const auto read = readJob(text.toStdString());
        QVERIFY2(read.job, qPrintable(text));
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(plan.ok());
        const int rough = stepOf(plan, StepKind::TurnRoughing);
        QVERIFY(rough >= 0);
        const TurnStep& ts = *turnOf(plan.steps[static_cast<std::size_t>(rough)]);
        turning::ZR at = ts.path.start;
        int passes = 0;
        for (const auto& m : ts.path.moves) {
            if (m.kind == TurnMove::Feed && m.end.z < at.z - 1.0 && std::abs(m.end.r - at.r) < 1e-9 &&
                m.end.r > diameter / 2.0 + ts.allowanceX + 1e-6) {
                QVERIFY2(m.end.z <= z + 1e-6, qPrintable(QString("a pass at X%1 ends at Z%2").arg(2.0 * m.end.r).arg(m.end.z)));
                ++passes;
            }
            at = m.end;
        }
        QVERIFY(passes >= 1);
        const Report r = verifyPlan(plan);
        QVERIFY2(r.findings.empty(), kinds(r, plan).c_str());
        Options fine;
        fine.resolution = 0.005;
        const Report f = verifyPlan(plan, fine);
        QVERIFY2(f.findings.empty(), kinds(f, plan).c_str());
    }

    // A rapid out to Ø300 on the lathe whose X travels 260 (a diameter):
    // the paths' span of diameters that much too wide, on that step and move.
    void travelLimitFound()
    {
        Plan p = test::samplePlan("lathe-turned-shaft.taiwa");
        QCOMPARE(QString::fromStdString(p.mmJob.machine), QString("lathe"));
        QVERIFY(verifyPlan(p).count(FindingKind::TravelLimit) == 0);
        double least = 1e300;  // the smallest diameter programmed (the facing runs past the axis)
        for (const Step& s : p.steps) {
            least = std::min(least, 2.0 * turnOf(s)->path.start.r);
            for (const TurnMove& m : turnOf(s)->path.moves) least = std::min(least, 2.0 * m.end.r);
        }
        const int last = static_cast<int>(p.steps.size()) - 1;
        TurnStep edited = *turnOf(p.steps[static_cast<std::size_t>(last)]);
        auto& moves = edited.path.moves;
        const turning::ZR at = moves.back().end;
        moves.push_back({TurnMove::Rapid, {at.z, 150.0}, {}, FeedKind::Cut});
        p.steps[static_cast<std::size_t>(last)].payload = edited;
        const Report r = verifyPlan(p);
        const Finding* f = find(r, FindingKind::TravelLimit, last, static_cast<int>(moves.size()) - 1);
        QVERIFY2(f, kinds(r, p).c_str());
        QCOMPARE(QString::fromStdString(f->part), QString("x"));
        QVERIFY2(std::abs(f->size - (300.0 - least - 260.0)) < 1e-9, kinds(r, p).c_str());
        QVERIFY(std::abs(f->position.x - 300.0) < 1e-9);
        QVERIFY(r.fatal());
    }
};

QTEST_GUILESS_MAIN(TestVerifyTurning)
#include "test_verify_turning.moc"
