// Every lathe sample's `linuxcnc` tape, posted in-process from its plan
// (readJobFile, the default tool library, planJob, postOptions,
// postProcess) with the roughing as the control's G71 cycle and as the
// explicit passes (Job::latheRoughingCycles), must pass LinuxCNC's own
// interpreter (rs274, with a lathe tool table: nose radius and orientation
// per turret station), and the canonical moves it prints are judged by an
// oracle of the test's own (support/turning_oracle.h) against the finished
// deformed profile of each unit, step by step:
// - no cut enters its unit's material by more than 1 µm,
// - finishing keeps the nose centre a nose radius off the profile and
//   touches every element of the part it must (origin original or moved,
//   longer than two nose radii; the front face is the facing's),
// - roughing leaves at least its finishing allowance,
// - no rapid runs through stock not yet cut (a stock simulation of the bar),
// - a groove's blade leaves along the profile's outward normal by the
//   step's withdrawal,
// - a threading insert (LinuxCNC's G76) goes no deeper than the thread's
//   root: the profile less the thread's depth over the threaded row (a
//   K made deeper is seen).
// Where a turning insert's edges (not its nose) reach into the part, the
// run says so (QINFO "insert body"), without failing.
// The inch tape of two samples describes the same moves as the mm tape
// within 2.5 µm (steps run as a G71 cycle excepted: rs274 expands those in
// the program's units, differently; the oracle judges them), and the oracle
// is shown to see a finishing move 0.01 mm into the part (outside and in a
// bore), a plunge 0.01 mm too deep, a rapid 5 mm into the bar and one
// 0.05 mm into the stock, a G71 leaving less than the allowance, a wrong
// withdrawal and a finishing contour 0.01 mm proud, in tapes altered for it.
// TAIWA_TURNING_DUMP=<folder> writes each sample's tape, tool table,
// rs274 output and verdict there.
#include "support/rs274.h"
#include "support/support.h"
#include "support/turning_oracle.h"
#include "model/turn_path.h"

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "post/lathe_post.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>

using namespace taiwa;
using namespace taiwa::test;

namespace {

// The plan of a lathe sample, roughing as cycles or as passes (the job's
// own setting, as `latheRoughing: passes` in the file would say), planned once.
const Plan& planned(const QString& stem, bool cycles)
{
    static std::map<std::pair<QString, bool>, Plan> cache;
    const auto key = std::make_pair(stem, cycles);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
    const auto read = readJobFile(sourcePath("resources/samples/" + stem + ".taiwa").toStdString());
    if (!read.job) qFatal("cannot read sample %s", qPrintable(stem));
    Job job = *read.job;
    job.latheRoughingCycles = cycles;
    return cache.emplace(key, planJob(job, TechnologyTable::builtIn(), defaultToolLibrary())).first->second;
}

std::string tape(const Plan& plan, const QString& stem, LengthUnit units = LengthUnit::Millimetre)
{
    return postProcess(plan.steps, plan.tools, postOptions(plan, "linuxcnc", units, 1000, stem.toStdString())).nc;
}

QStringList lathe()
{
    QStringList stems;
    for (const auto& f : QDir(sourcePath("resources/samples")).entryInfoList({"lathe-*.taiwa"}, QDir::Files, QDir::Name))
        stems << f.completeBaseName();
    return stems;
}

QString firstProblems(const LatheVerdict& v)
{
    return QStringList(v.problems.mid(0, 12)).join("\n");
}

// ---- altering a tape for the oracle's own test ---------------------------

QStringList tapeLines(const std::string& nc) { return QString::fromStdString(nc).split('\n'); }
std::string joined(const QStringList& lines) { return lines.join('\n').toStdString(); }

// The index of the line "(STEP k: ..." of the first step of that kind (of
// that unit, 0-based, when not -1); -1: none.
int stepLine(const QStringList& lines, const Plan& plan, StepKind kind, int unit = -1)
{
    for (std::size_t i = 0; i < plan.steps.size(); ++i)
        if (plan.steps[i].kind == kind && (unit < 0 || plan.steps[i].unit == unit)) {
            const QString marker = QString("(STEP %1:").arg(i + 1);
            for (int l = 0; l < lines.size(); ++l)
                if (lines[l].startsWith(marker)) return l;
        }
    return -1;
}

double word(const QString& line, QChar letter, double otherwise)
{
    const auto m = QRegularExpression(QString("(?:^|\\s)%1(-?[0-9.]+)").arg(letter)).match(line);
    return m.hasMatch() ? m.captured(1).toDouble() : otherwise;
}

QString number(double v) { return QString::number(v, 'f', 3); }

// The oracle's verdict on an altered tape, which rs274 must still run.
LatheVerdict judgeAltered(const Plan& plan, const QStringList& lines)
{
    const Rs274Result r = runRs274(joined(lines), latheToolTable(plan));
    if (!r.ok) {
        LatheVerdict v;
        v.problems << "rs274 refuses the altered tape: " + r.errors;
        return v;
    }
    return judgeLatheTape(plan, r);
}

}  // namespace

class TestRs274Turning : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY2(QFileInfo::exists(TAIWA_RS274), "LinuxCNC's rs274 is not installed (" TAIWA_RS274 ")");
        QVERIFY2(lathe().size() >= 8, qPrintable("lathe samples: " + lathe().join(", ")));
    }

    // The oracle's own geometry: orientation vectors and the tool table.
    void toolTableFollowsTheTapeHeader()
    {
        QCOMPARE(orientationOffset(2, 0.4).x, -0.4);  // Z -r
        QCOMPARE(orientationOffset(2, 0.4).y, -0.4);  // X -r
        QCOMPARE(orientationOffset(3, 0.4).y, 0.4);   // X +r
        const Plan& plan = planned("lathe-bushing", true);
        QVERIFY(plan.ok());
        const QString table = QString::fromStdString(latheToolTable(plan));
        const QStringList header = tapeLines(tape(plan, "lathe-bushing")).filter(QRegularExpression(R"(^\(T\d\d = library T\d+)"));
        QCOMPARE(header.size(), static_cast<qsizetype>(latheStations(plan.steps).size()));
        for (const auto& [station, id] : latheStations(plan.steps)) {
            const QString h = header.at(station - 1);
            const auto m = QRegularExpression(R"(^\(T(\d\d) = library T(\d+) .* orientation (\d+)\)$)").match(h);
            QVERIFY2(m.hasMatch(), qPrintable(h));
            QCOMPARE(m.captured(1).toInt(), station);
            QCOMPARE(m.captured(2).toInt(), id);
            QVERIFY2(table.contains(QRegularExpression(QString(R"((^|\n)T%1 P%1 X0 Z0 D[0-9.]+ Q%2 )").arg(station).arg(m.captured(3)))),
                     qPrintable(table));
        }
        // The OD roughing insert R0.8: D = 1.6 mm in inches.
        QVERIFY2(table.contains("T1 P1 X0 Z0 D0.062992 Q2 "), qPrintable(table));
    }

    void samples_data()
    {
        QTest::addColumn<QString>("stem");
        QTest::addColumn<bool>("cycles");
        for (const auto& stem : lathe()) {
            QTest::newRow(qPrintable(stem + " G71")) << stem << true;
            QTest::newRow(qPrintable(stem + " passes")) << stem << false;
        }
    }
    void samples()
    {
        QFETCH(QString, stem);
        QFETCH(bool, cycles);
        const Plan& plan = planned(stem, cycles);
        QVERIFY2(plan.ok(), qPrintable(stem + " does not plan"));
        QVERIFY(!plan.steps.empty());
        QVERIFY(!plan.turned.empty());
        const std::string nc = tape(plan, stem);
        const bool anyCycle = std::any_of(plan.steps.begin(), plan.steps.end(), [](const Step& s) { return turnOf(s) && turnOf(s)->path.cycle; });
        QCOMPARE(QString::fromStdString(nc).contains(QRegularExpression(R"(\nG71 Q\d+)")), cycles && anyCycle);

        const Rs274Result r = runRs274(nc, latheToolTable(plan));
        // TAIWA_TURNING_DUMP=<folder>: the tape, tool table and rs274's output to look at.
        if (const QString dump = qEnvironmentVariable("TAIWA_TURNING_DUMP"); !dump.isEmpty()) {
            const QString base = QDir(dump).filePath(stem + (cycles ? "-g71" : "-passes"));
            writeFile(base + ".ngc", nc);
            writeFile(base + ".tbl", latheToolTable(plan));
            writeFile(base + ".canon", r.out.toStdString());
        }
        QVERIFY2(r.ok, qPrintable("rs274 refuses the tape: " + r.errors));
        QVERIFY(!r.moves.empty());
        QVERIFY(!r.inches);

        const LatheVerdict v = judgeLatheTape(plan, r);
        if (const QString dump = qEnvironmentVariable("TAIWA_TURNING_DUMP"); !dump.isEmpty())
            writeFile(QDir(dump).filePath(stem + (cycles ? "-g71" : "-passes") + ".verdict"),
                      (v.touched.join('\n') + "\nworst rapid " + v.worstRapidMove + "\n" + v.problems.join('\n') + "\n").toStdString());
        qInfo("%s: %d cuts, %d rapids; deepest cut into the part %.4f mm, worst rapid overlap %.4f mm, roughing clearance beyond the allowance %.4f mm",
              qPrintable(stem + (cycles ? " G71" : " passes")), v.feeds, v.rapids, v.worstGouge, v.worstRapid, v.closestRoughing);
        for (const auto& b : v.insertBody) qInfo("insert body: %s", qPrintable(b));
        QVERIFY2(v.problems.isEmpty(), qPrintable(QString("%1 problem(s):\n").arg(v.problems.size()) + firstProblems(v)));
        QVERIFY(v.feeds > 0 && v.rapids > 0);
        QVERIFY2(!v.touched.isEmpty(), "no element was checked for the finishing contact");
    }

    void inchTapeIsTheMmTapeScaled_data()
    {
        QTest::addColumn<QString>("stem");
        QTest::addColumn<bool>("cycles");
        for (const QString stem : {"lathe-bushing", "lathe-turned-shaft"}) {
            QTest::newRow(qPrintable(stem + " G71")) << stem << true;
            QTest::newRow(qPrintable(stem + " passes")) << stem << false;
        }
    }
    void inchTapeIsTheMmTapeScaled()
    {
        QFETCH(QString, stem);
        QFETCH(bool, cycles);
        const Plan& plan = planned(stem, cycles);
        QVERIFY(plan.ok());
        const std::string table = latheToolTable(plan);
        const Rs274Result mm = runRs274(tape(plan, stem), table);
        const Rs274Result in = runRs274(tape(plan, stem, LengthUnit::Inch), table);
        QVERIFY2(mm.ok, qPrintable(mm.errors));
        QVERIFY2(in.ok, qPrintable(in.errors));
        QVERIFY(in.inches);
        QVERIFY(!in.canon.filter("USE_LENGTH_UNITS(CANON_UNITS_INCHES)").isEmpty());
        // Step by step; a step the control runs as its G71 cycle is left to
        // the oracle below: rs274 expands the cycle from the contour in the
        // program's units and does not make the same moves in G20 (its
        // offset corners come out sharp where the mm run rounds them with
        // arcs of radius D, and I, D and the start are rounded to 0.0001 in).
        const auto byStep = [](const Rs274Result& r) {
            std::map<int, std::vector<CanonMove>> steps;
            for (const auto& m : r.moves) steps[m.step].push_back(m);
            return steps;
        };
        const auto a = byStep(mm), b = byStep(in);
        QCOMPARE(b.size(), a.size());
        int compared = 0;
        for (const auto& [step, moves] : a) {
            const bool cycle = step > 0 && turnOf(plan.steps[static_cast<std::size_t>(step - 1)]) &&
                               turnOf(plan.steps[static_cast<std::size_t>(step - 1)])->path.cycle && cycles;
            QVERIFY2(b.count(step), qPrintable(QString("step %1 is missing from the inch run").arg(step)));
            if (cycle) continue;
            const auto& other = b.at(step);
            QVERIFY2(other.size() == moves.size(),
                     qPrintable(QString("step %1: %2 moves in mm, %3 in inch").arg(step).arg(moves.size()).arg(other.size())));
            for (std::size_t i = 0; i < moves.size(); ++i, ++compared) {
                const CanonMove& x = moves[i];
                const CanonMove& y = other[i];
                const QString m = QString("step %1 move %2: mm X%3 Z%4, inch X%5 Z%6")
                                      .arg(step).arg(i).arg(x.end.x, 0, 'f', 4).arg(x.end.z, 0, 'f', 4)
                                      .arg(y.end.x * 25.4, 0, 'f', 4).arg(y.end.z * 25.4, 0, 'f', 4);
                QVERIFY2(x.kind == y.kind && x.tool == y.tool && x.rotation == y.rotation, qPrintable(m));
                // 4 inch decimals: 2.54 µm.
                QVERIFY2(std::abs(x.end.x - y.end.x * 25.4) <= 2.5e-3 && std::abs(x.end.y - y.end.y * 25.4) <= 2.5e-3 &&
                             std::abs(x.end.z - y.end.z * 25.4) <= 2.5e-3,
                         qPrintable(m));
                if (x.kind == CanonMove::Arc)
                    QVERIFY2(std::abs(x.centre.x - y.centre.x * 25.4) <= 2.5e-3 && std::abs(x.centre.y - y.centre.y * 25.4) <= 2.5e-3,
                             qPrintable(m + " (arc centre)"));
            }
        }
        QVERIFY(compared > 20);
        // And the oracle judges the inch run as it does the mm run, to the
        // inch tape's resolution (0.0001 in = 2.54 µm: the programmed
        // points are rounded by up to 1.27 µm in X and Z).
        LatheOracleOptions inch;
        inch.tolerance = 2.5e-3;
        const LatheVerdict v = judgeLatheTape(plan, in, inch);
        QVERIFY2(v.problems.isEmpty(), qPrintable(firstProblems(v)));
    }

    // ---- the oracle sees what it must -----------------------------------

    void oracleSeesAGouge()
    {
        // A finishing move 0.01 mm into the part: the first straight Z move
        // after G41/G42 of the unit's finishing step ends 0.02 further into
        // it in diameter (outside: smaller, in the bore: larger).
        const Plan& plan = planned("lathe-bushing", true);
        for (const int unit : {0, 1}) {
            const bool inner = plan.turned.at(static_cast<std::size_t>(unit)).deformed.side == turning::ProfileSide::Inner;
            QStringList lines = tapeLines(tape(plan, "lathe-bushing"));
            const int from = stepLine(lines, plan, StepKind::TurnFinishing, unit);
            QVERIFY(from >= 0);
            double x = 0;
            bool comp = false;
            int changed = -1;
            for (int l = from + 1; l < lines.size() && !lines[l].startsWith("(STEP"); ++l) {
                comp = comp || lines[l].contains("G42") || lines[l].contains("G41");
                if (comp && QRegularExpression(R"(^Z-?[0-9.]+$)").match(lines[l]).hasMatch()) {
                    lines[l] = QString("X%1 %2").arg(number(x + (inner ? 0.02 : -0.02)), lines[l]);
                    changed = l;
                    break;
                }
                x = word(lines[l], 'X', x);
            }
            QVERIFY2(changed > 0, "no straight Z move in the finishing step");
            const LatheVerdict v = judgeAltered(plan, lines);
            QVERIFY2(!v.problems.filter(QString("gouge of")).filter(QString("unit %1's part").arg(unit + 1)).isEmpty(),
                     qPrintable("no gouge seen after " + lines[changed] + "\n" + firstProblems(v)));
            QVERIFY2(v.worstGouge > 0.009 && v.worstGouge < 0.011, qPrintable(QString("the gouge is %1 mm, not 0.01").arg(v.worstGouge)));
        }

        // A groove's plunge 0.01 mm deeper than its bottom.
        const Plan& grooved = planned("lathe-grooved-shaft", true);
        QStringList lines = tapeLines(tape(grooved, "lathe-grooved-shaft"));
        const int from = stepLine(lines, grooved, StepKind::Grooving);
        QVERIFY(from >= 0);
        int changed = -1;
        for (int l = from + 1; l < lines.size() && !lines[l].startsWith("(STEP"); ++l)
            if (lines[l].startsWith("G1 X")) {
                lines[l].replace(QRegularExpression(R"(X(-?[0-9.]+))"), QString("X%1").arg(number(word(lines[l], 'X', 0) - 0.02)));
                changed = l;
                break;
            }
        QVERIFY(changed > 0);
        const LatheVerdict v = judgeAltered(grooved, lines);
        QVERIFY2(!v.problems.filter("gouge of").filter("Grooving").isEmpty(), qPrintable("no gouge seen after " + lines[changed] + "\n" + firstProblems(v)));
    }

    void oracleSeesAFinishingPassThatStaysOff()
    {
        // The bushing's outside finished 0.01 mm proud: every X of the
        // compensated contour 0.02 larger.
        const Plan& plan = planned("lathe-bushing", true);
        QStringList lines = tapeLines(tape(plan, "lathe-bushing"));
        const int from = stepLine(lines, plan, StepKind::TurnFinishing);
        QVERIFY(from >= 0);
        bool comp = false;
        int changed = 0;
        for (int l = from + 1; l < lines.size() && !lines[l].startsWith("(STEP"); ++l) {
            if (lines[l].contains("G40")) break;
            comp = comp || lines[l].contains("G42") || lines[l].contains("G41");
            if (!comp || !lines[l].contains(QRegularExpression(R"((^|\s)X)"))) continue;
            lines[l].replace(QRegularExpression(R"(X(-?[0-9.]+))"), QString("X%1").arg(number(word(lines[l], 'X', 0) + 0.02)));
            ++changed;
        }
        QVERIFY(changed >= 2);
        const Rs274Result r = runRs274(joined(lines), latheToolTable(plan));
        QVERIFY2(r.ok, qPrintable(r.errors));
        const LatheVerdict v = judgeLatheTape(plan, r);
        QVERIFY2(!v.problems.filter(QRegularExpression("E2 .* is not finished at the nose radius")).isEmpty(), qPrintable(firstProblems(v)));
        QVERIFY2(v.problems.filter("gouge of").isEmpty(), qPrintable(firstProblems(v)));
    }

    void oracleSeesARapidJustIntoTheStock()
    {
        // The grooved shaft's first roughing pass (explicit passes) lifts
        // 0.05 mm into the stock instead of out of it before its rapid back.
        const Plan& plan = planned("lathe-grooved-shaft", false);
        QStringList lines = tapeLines(tape(plan, "lathe-grooved-shaft"));
        const int from = stepLine(lines, plan, StepKind::TurnRoughing);
        QVERIFY(from >= 0);
        double x = 0;
        int changed = -1;
        for (int l = from + 1; l + 1 < lines.size() && !lines[l].startsWith("(STEP"); ++l) {
            if (lines[l].startsWith("G1 Z") && QRegularExpression(R"(^X-?[0-9.]+$)").match(lines[l + 1]).hasMatch()) {
                lines[l + 1] = QString("X%1").arg(number(x - 0.1));
                changed = l + 1;
                break;
            }
            x = word(lines[l], 'X', x);
        }
        QVERIFY2(changed > 0, "no pass with a retract in X");
        const Rs274Result r = runRs274(joined(lines), latheToolTable(plan));
        QVERIFY2(r.ok, qPrintable(r.errors));
        const LatheVerdict v = judgeLatheTape(plan, r);
        QVERIFY2(!v.problems.filter("rapid into stock").isEmpty(), qPrintable("no rapid into the stock seen after " + lines[changed]));
        QVERIFY2(std::abs(v.worstRapid - 0.05) < 2e-3, qPrintable(QString("overlap %1 mm, not 0.05").arg(v.worstRapid)));
    }

    void oracleSeesARapidIntoTheBar()
    {
        // The parting blade's approach rapid ends 5 mm inside the bar.
        const Plan& plan = planned("lathe-bushing", true);
        QStringList lines = tapeLines(tape(plan, "lathe-bushing"));
        const int from = stepLine(lines, plan, StepKind::Parting);
        QVERIFY(from >= 0);
        int changed = -1;
        for (int l = from + 1; l < lines.size(); ++l)
            if (lines[l].startsWith("G0 X") && lines[l].contains(" Z")) {
                const double x = word(lines[l], 'X', 0);
                lines[l] = QString("G0 X%1 Z%2").arg(number(x - 2 * (x / 2 - plan.mmJob.bar->diameter / 2 + 5))).arg(word(lines[l], 'Z', 0));
                changed = l;
                break;
            }
        QVERIFY(changed > 0);
        const Rs274Result r = runRs274(joined(lines), latheToolTable(plan));
        QVERIFY2(r.ok, qPrintable(r.errors));
        const LatheVerdict v = judgeLatheTape(plan, r);
        QVERIFY2(!v.problems.filter("rapid into stock").isEmpty(), qPrintable("no rapid into the bar seen after " + lines[changed]));
        QVERIFY2(v.worstRapid > 4.9, qPrintable(QString("overlap %1 mm").arg(v.worstRapid)));
    }

    void oracleSeesRoughingIntoTheAllowance()
    {
        // The G71 cycle told to leave 0.05 mm instead of the allowance.
        const Plan& plan = planned("lathe-bushing", true);
        QString nc = QString::fromStdString(tape(plan, "lathe-bushing"));
        const QRegularExpression d(R"((\nG71 Q\d+ X[-0-9.]+ Z[-0-9.]+) D[0-9.]+)");
        QVERIFY(nc.contains(d));
        nc.replace(d, "\\1 D0.05");
        const Rs274Result r = runRs274(nc.toStdString(), latheToolTable(plan));
        QVERIFY2(r.ok, qPrintable(r.errors));
        const LatheVerdict v = judgeLatheTape(plan, r);
        QVERIFY2(!v.problems.filter("roughing leaves less than its allowance").isEmpty(), qPrintable(firstProblems(v)));
        QVERIFY2(v.problems.filter("gouge of").isEmpty(), qPrintable(firstProblems(v)));
    }

    void oracleSeesAWrongWithdrawal()
    {
        // The groove's withdrawal 0.05 mm longer (X 0.1 in diameter).
        const Plan& plan = planned("lathe-grooved-shaft", true);
        QStringList lines = tapeLines(tape(plan, "lathe-grooved-shaft"));
        const int from = stepLine(lines, plan, StepKind::Grooving);
        QVERIFY(from >= 0);
        // The last feed line before a rapid, of the whole step.
        int last = -1, feed = -1;
        bool feeding = false;
        for (int l = from + 1; l < lines.size() && !lines[l].startsWith("(STEP"); ++l) {
            if (lines[l].startsWith("G0")) {
                if (feeding) last = feed;
                feeding = false;
            } else if (lines[l].startsWith("G1") || (feeding && lines[l].startsWith("X"))) {
                feeding = true;
                feed = l;
            }
        }
        QVERIFY(last > 0);
        lines[last].replace(QRegularExpression(R"(X(-?[0-9.]+))"), QString("X%1").arg(number(word(lines[last], 'X', 0) + 0.1)));
        const Rs274Result r = runRs274(joined(lines), latheToolTable(plan));
        QVERIFY2(r.ok, qPrintable(r.errors));
        const LatheVerdict v = judgeLatheTape(plan, r);
        QVERIFY2(!v.problems.filter("the withdrawal").isEmpty(), qPrintable("nothing seen after " + lines[last] + "\n" + firstProblems(v)));
    }

    void oracleSeesAThreadCutTooDeep()
    {
        // The threading insert may go below the finished row by the
        // thread's depth, and no further: K 0.07 mm deeper on the radius.
        const Plan& plan = planned("lathe-threaded-shaft", true);
        QStringList lines = tapeLines(tape(plan, "lathe-threaded-shaft"));
        const int at = static_cast<int>(lines.indexOf(QRegularExpression("G76 .*")));
        QVERIFY(at > 0);
        QVERIFY2(judgeAltered(plan, lines).problems.isEmpty(), "the tape as written is judged wrong");
        lines[at].replace(QRegularExpression(R"(K[0-9.]+)"), QString("K%1").arg(number(word(lines[at], 'K', 0) + 0.14)));
        const LatheVerdict v = judgeAltered(plan, lines);
        QVERIFY2(!v.problems.filter(QRegularExpression("gouge of 0.0[67]\\d+ mm .*Threading I")).isEmpty(), qPrintable("nothing seen after " + lines[at] + "\n" + firstProblems(v)));
    }

};

QTEST_APPLESS_MAIN(TestRs274Turning)
#include "test_rs274_turning.moc"
