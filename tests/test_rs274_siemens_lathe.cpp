// The SINUMERIK lathe tape of every lathe sample, judged through LinuxCNC's
// interpreter: a strict word-for-word translation (below: the few words that
// differ, each with the meaning the Siemens manual gives it; any other word
// refuses the tape) turns it into a program rs274 runs, and its canonical
// moves must equal, move by move, those of the sample's `linuxcnc` tape with
// the same explicit roughing passes (Siemens tapes carry no G71); the lathe
// oracle (support/turning_oracle.h) judges it too. The arcs are where the
// two tapes differ most: Siemens' by their radius (CR=, negative beyond a
// half turn), LinuxCNC's by I K; rs274 reading the radius form (R) must find
// the same centre, so a wrong sign or radius fails here. A threading step's
// passes, written out as G33 (K the lead, the same word in LinuxCNC), must
// be the moves LinuxCNC's G76 makes.
#include "support/rs274.h"
#include "support/support.h"
#include "support/turning_oracle.h"

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QRegularExpression>
#include <QtTest>

#include <cmath>

using namespace taiwa;
using namespace taiwa::test;

namespace {

// The Siemens tape as LinuxCNC reads the same words; an error names the line.
std::string translated(const std::string& mpf, QString* error)
{
    static const QRegularExpression plain(R"(^[GXZFSM]-?[0-9.]+$)");
    QStringList out;
    const QStringList lines = QString::fromStdString(mpf).split('\n', Qt::SkipEmptyParts);
    for (int l = 0; l < lines.size(); ++l) {
        QString line = lines[l];
        if (line.startsWith(';')) {
            out << "(" + line.mid(1).trimmed().remove('(').remove(')') + ")";
            continue;
        }
        QStringList words = line.split(' ', Qt::SkipEmptyParts);
        if (!words.isEmpty() && QRegularExpression(R"(^N[0-9]+$)").match(words.front()).hasMatch()) words.removeFirst();
        QStringList ngc;
        for (int w = 0; w < words.size(); ++w) {
            const QString& word = words[w];
            if (word == "DIAMON") ngc << "G7";                        // X in diameter
            else if (word == "G710") ngc << "G21";                    // mm, feeds too
            else if (word == "G700") ngc << "G20";
            else if (word.startsWith("LIMS=")) ngc << "D" + word.mid(5);  // the spindle limit under G96
            else if (word.startsWith("CR=")) ngc << "R" + word.mid(3);    // arc radius, negative beyond 180°
            else if (word.startsWith('T') && w + 1 < words.size() && words[w + 1] == "D1") {
                ngc << word << "M6" << "G43";                         // turret station and its offset D1
                ++w;
            } else if (word.startsWith('K') && ngc.contains("G33") && plain.match("X" + word.mid(1)).hasMatch()) {
                ngc << word;                                          // G33's lead along Z: the same word in LinuxCNC
            } else if (plain.match(word).hasMatch()) ngc << word;
            else {
                *error = QString("line %1: '%2' is not a word this test translates: %3").arg(l + 1).arg(word, line);
                return {};
            }
        }
        out << ngc.join(' ');
    }
    return (out.join('\n') + "\n").toStdString();
}

QStringList lathe()
{
    QStringList stems;
    for (const auto& f : QDir(sourcePath("resources/samples")).entryInfoList({"lathe-*.taiwa"}, QDir::Files, QDir::Name))
        stems << f.completeBaseName();
    return stems;
}

Plan passesPlan(const QString& stem)
{
    const auto read = readJobFile(sourcePath("resources/samples/" + stem + ".taiwa").toStdString());
    if (!read.job) qFatal("cannot read sample %s", qPrintable(stem));
    Job job = *read.job;
    job.latheRoughingCycles = false;
    return planJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
}

QString describe(const CanonMove& m)
{
    return QString("%1 to Z%2 X%3 centre (%4, %5) rot %6 F%7")
        .arg(m.kind == CanonMove::Arc ? "arc" : m.kind == CanonMove::Feed ? "feed" : "rapid")
        .arg(m.end.z, 0, 'f', 4).arg(m.end.x, 0, 'f', 4).arg(m.centre.x, 0, 'f', 4).arg(m.centre.y, 0, 'f', 4)
        .arg(m.rotation).arg(m.feed);
}

// The first difference between two runs' moves beyond `tol`; empty when none.
// Moves that go nowhere (LinuxCNC's G76 ends with a traverse to where its
// last pass left the tool, which the written-out passes need not say) are
// left out on both sides.
std::vector<CanonMove> moving(const std::vector<CanonMove>& moves)
{
    std::vector<CanonMove> out;
    for (const auto& m : moves)
        if (m.kind == CanonMove::Arc || std::abs(m.end.x - m.start.x) > 1e-9 || std::abs(m.end.z - m.start.z) > 1e-9) out.push_back(m);
    return out;
}

QString firstDifference(const std::vector<CanonMove>& all, const std::vector<CanonMove>& allOther, double tol)
{
    const std::vector<CanonMove> a = moving(all), b = moving(allOther);
    if (a.size() != b.size()) return QString("%1 moves against %2").arg(a.size()).arg(b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        const CanonMove &p = a[i], &q = b[i];
        const bool same = p.kind == q.kind && std::abs(p.end.x - q.end.x) <= tol && std::abs(p.end.z - q.end.z) <= tol &&
                          std::abs(p.feed - q.feed) <= 1e-9 && p.rotation == q.rotation &&
                          (p.kind != CanonMove::Arc ||
                           (std::abs(p.centre.x - q.centre.x) <= tol && std::abs(p.centre.y - q.centre.y) <= tol));
        if (!same) return QString("move %1 (step %2): %3 | %4").arg(i).arg(p.step).arg(describe(p), describe(q));
    }
    return {};
}

}  // namespace

class TestRs274SiemensLathe : public QObject {
    Q_OBJECT
private slots:
    void samples_data()
    {
        QTest::addColumn<QString>("stem");
        const QStringList stems = lathe();
        QVERIFY(stems.size() >= 8);
        for (const auto& s : stems) QTest::newRow(qPrintable(s)) << s;
    }
    void samples()
    {
        QFETCH(QString, stem);
        const Plan plan = passesPlan(stem);
        QVERIFY(plan.ok() && !plan.steps.empty());
        const auto options = [&](const char* dialect) { return postOptions(plan, dialect, LengthUnit::Millimetre, 1000, stem.toStdString()); };
        const std::string siemens = postProcess(plan.steps, plan.tools, options("sinumerik")).nc;
        QVERIFY(!QString::fromStdString(siemens).contains(QRegularExpression(R"(\bG71\b)")));
        QString error;
        const std::string ngc = translated(siemens, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));

        const Rs274Result ours = runRs274(ngc, latheToolTable(plan));
        QVERIFY2(ours.ok, qPrintable("rs274 refuses the translated Siemens tape: " + ours.errors));
        const Rs274Result reference = runRs274(postProcess(plan.steps, plan.tools, options("linuxcnc")).nc, latheToolTable(plan));
        QVERIFY2(reference.ok, qPrintable(reference.errors));
        // The radius form's centre is computed by rs274 from written numbers: 2 µm.
        const QString difference = firstDifference(ours.moves, reference.moves, 0.002);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
        const LatheVerdict v = judgeLatheTape(plan, ours);
        QVERIFY2(v.problems.isEmpty(), qPrintable(v.problems.mid(0, 8).join('\n')));
    }

    // The check can fail: a flipped radius sign (the other arc of that
    // radius), a word it does not know, and a coordinate moved.
    void alteredTapesAreCaught()
    {
        const Plan plan = passesPlan("lathe-turned-shaft");
        const auto o = postOptions(plan, "sinumerik", LengthUnit::Millimetre, 1000, "lathe-turned-shaft");
        const std::string siemens = postProcess(plan.steps, plan.tools, o).nc;
        const Rs274Result reference =
            runRs274(postProcess(plan.steps, plan.tools, postOptions(plan, "linuxcnc", LengthUnit::Millimetre, 1000, "x")).nc,
                     latheToolTable(plan));
        QString s = QString::fromStdString(siemens);
        QVERIFY(s.contains(" CR=1\n"));
        QString error;
        const Rs274Result same = runRs274(translated(siemens, &error), latheToolTable(plan));
        QVERIFY2(same.ok && firstDifference(same.moves, reference.moves, 0.002).isEmpty(), qPrintable(same.errors));
        for (const auto& [from, to] : {std::pair{" CR=1\n", " CR=-1\n"}, std::pair{" Z-35\n", " Z-35.01\n"}}) {
            QString altered = s;
            altered.replace(altered.indexOf(from), QString(from).size(), to);
            const Rs274Result r = runRs274(translated(altered.toStdString(), &error), latheToolTable(plan));
            QVERIFY2(error.isEmpty(), qPrintable(error));
            QVERIFY2(r.ok, qPrintable(r.errors));  // it runs, and moves elsewhere
            QVERIFY2(!firstDifference(r.moves, reference.moves, 0.002).isEmpty(), from);
        }
        QVERIFY(translated(siemens + "N9999 CYCLE95(\"KONTUR\")\n", &error).empty());
        QVERIFY2(error.contains("'CYCLE95(\"KONTUR\")' is not a word this test translates"), qPrintable(error));
    }
};

QTEST_APPLESS_MAIN(TestRs274SiemensLathe)
#include "test_rs274_siemens_lathe.moc"
