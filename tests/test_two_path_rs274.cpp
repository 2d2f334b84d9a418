// The programs of a balanced cut (post/two_path_post.h) for LinuxCNC, run by
// LinuxCNC's interpreter: both paths' programs of each two-path sample
// (resources/samples/lathe-two-path-*.taiwa) in lathe mode (G18 G7) with the tool table the
// export writes (linuxcncLatheToolTable), accepted, their feeds the path's
// blocks' feeds in the path's coordinates (path 2: X mirrored), one dwell
// per follower block, and the handshake (M64/M65 P0, M66 P0 L3/L4) once per
// wait, the same number of times on both paths. Holds the rs274 lock (its
// name says rs274: tests/CMakeLists.txt).
#include "support/rs274.h"
#include "support/support.h"

#include "job/job_file.h"
#include "machine/machine.h"
#include "turning/balanced_roughing.h"
#include "pipeline/pipeline.h"
#include "post/tool_table.h"
#include "post/two_path_post.h"
#include "tools/tool_library.h"

#include <QRegularExpression>
#include <QtTest>

#include <cmath>

using namespace taiwa;
using namespace taiwa::test;

class TestTwoPathRs274 : public QObject {
    Q_OBJECT
private slots:
    void bothProgramsRunInLinuxcnc_data()
    {
        QTest::addColumn<QString>("stem");
        QTest::addColumn<bool>("everywhere");
        QTest::addColumn<bool>("whole");
        QTest::newRow("cylinder") << "lathe-two-path-cylinder" << false << false;
        QTest::newRow("cylinder, waits everywhere") << "lathe-two-path-cylinder" << true << false;
        QTest::newRow("taper") << "lathe-two-path-taper" << false << false;
        QTest::newRow("cylinder, the whole job") << "lathe-two-path-cylinder" << false << true;
        QTest::newRow("taper, the whole job") << "lathe-two-path-taper" << false << true;
    }
    void bothProgramsRunInLinuxcnc()
    {
        QFETCH(QString, stem);
        QFETCH(bool, everywhere);
        QFETCH(bool, whole);
        auto read = readJobFile(sourcePath("resources/samples/" + stem + ".taiwa").toStdString());
        QVERIFY(read.job);
        const Plan plan = planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(plan.ok());
        const Step* rough = nullptr;
        std::size_t index = 0;
        for (std::size_t k = 0; k < plan.steps.size(); ++k)
            if (plan.steps[k].kind == StepKind::TurnRoughing) {
                rough = &plan.steps[k];
                index = k;
            }
        QVERIFY(rough);
        const Machine& m = *findMachine("lathe-two-path");
        turning::BalanceSettings set;
        set.waitsEverywhere = everywhere;
        set.meetAtEnds = whole;
        const auto cut = turning::balanceRoughing(turnOf(*rough)->path, turnOf(*rough)->cutting, m, set);
        QVERIFY(cut);
        const PostOptions o = postOptions(plan, "linuxcnc", std::nullopt, 1000, stem.toStdString());
        const std::vector<Step> alone{*rough};
        const auto programs = whole ? postBalancedCut(*cut, plan.steps, index, *m.layout.multiPath, defaultToolLibrary(), o)
                                    : postBalancedCut(*cut, alone, 0, *m.layout.multiPath, defaultToolLibrary(), o);
        QCOMPARE(programs.size(), std::size_t{2});
        int handshakes[2] = {0, 0};
        for (std::size_t p = 0; p < 2; ++p) {
            const std::string& nc = programs[p].nc;
            const QString text = QString::fromStdString(nc);
            QCOMPARE(programs[p].lines.size(), static_cast<std::size_t>(text.count('\n')));
            const std::string table = linuxcncLatheToolTable(whole && p == 0 ? plan.steps : alone, defaultToolLibrary(),
                                                             stem.toStdString() + ".p" + std::to_string(p + 1));
            const Rs274Result run = runRs274(nc, table);
            QVERIFY2(run.ok, qPrintable(QString("path %1: %2\n%3").arg(p + 1).arg(run.errors, text.left(3000))));
            // The feeds rs274 made are the path's blocks' feeds, in the path's coordinates (X a radius).
            std::vector<turning::ZR> want;
            int followers = 0, waits = 0;
            for (const auto& b : cut->paths[p].blocks) {
                for (const auto& mv : b.moves)
                    if (mv.kind != TurnMove::Rapid) want.push_back(mv.end);
                followers += b.dwellSeconds > 0 ? 1 : 0;
                waits += b.wait ? 1 : 0;
            }
            waits += cut->paths[p].tailWait ? 1 : 0;
            waits += cut->paths[p].endWait ? 1 : 0;
            // The roughing's feeds (path 1's whole program: those of its roughing step).
            std::vector<turning::ZR> got;
            for (const auto& mv : run.moves)
                if (mv.kind == CanonMove::Feed && (!whole || p > 0 || mv.step == static_cast<int>(index) + 1)) got.push_back({mv.end.z, mv.end.x});
            QCOMPARE(got.size(), want.size());
            for (std::size_t i = 0; i < got.size(); ++i)
                QVERIFY2(std::abs(got[i].z - want[i].z) < 1e-3 && std::abs(got[i].r - want[i].r) < 1e-3,
                         qPrintable(QString("path %1 feed %2: Z%3 X%4, wanted Z%5 X%6").arg(p + 1).arg(i).arg(got[i].z).arg(got[i].r).arg(want[i].z).arg(want[i].r)));
            if (p == 1) for (const auto& w : want) QVERIFY(w.r < 0);  // the other side of the axis
            if (!whole || p > 0) QCOMPARE(run.dwells, followers);
            QCOMPARE(followers, p == 0 ? 0 : static_cast<int>(cut->paths[1].blocks.size()));
            handshakes[p] = static_cast<int>(text.count(QRegularExpression(R"(^M66 P0 L[34] Q60$)", QRegularExpression::MultilineOption)));
            QCOMPARE(handshakes[p], waits);
            QCOMPARE(static_cast<int>(text.count(QRegularExpression(R"(^M6[45] P0$)", QRegularExpression::MultilineOption))), waits);
            // A whole program of its own, naming its path and its table.
            QVERIFY2(text.startsWith(QString("(Program Path %1 ").arg(p + 1)), qPrintable(text.left(200)));
            QVERIFY(text.contains(QString("(Tool table %1.p%2.tbl: ").arg(stem).arg(p + 1)));
            QVERIFY(text.trimmed().endsWith("M30"));
        }
        QCOMPARE(handshakes[0], handshakes[1]);
        if (everywhere || whole) QVERIFY(handshakes[0] > 0);
        else if (stem.contains("cylinder")) QCOMPARE(handshakes[0], 0);
        else QVERIFY(handshakes[0] > 0);
    }
};

QTEST_APPLESS_MAIN(TestTwoPathRs274)
#include "test_two_path_rs274.moc"
