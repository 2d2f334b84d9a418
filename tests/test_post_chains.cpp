// The lathe and probing posts go through the same chain as milling's: the
// unit adapter (an inch lathe tape is the mm tape with every length, feed
// and surface speed converted, nothing else changed) and the block tape
// (block numbers where the dialect numbers blocks, the line limit, labels a
// probing program jumps to kept clear of the numbered blocks).
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "post/block_tape.h"
#include "post/dialect.h"
#include "post/lathe_writer.h"
#include "post/probe_program.h"
#include "support/support.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QRegularExpression>
#include <QtTest>

#include <cmath>
#include <stdexcept>

using namespace taiwa;

namespace {

Plan planSample(const QString& sample)
{
    const auto read = readJobFile(test::sourcePath("resources/samples/" + sample).toStdString());
    if (!read.job) return {};
    return planJob(toMillimetres(*read.job), TechnologyTable::builtIn(), defaultToolLibrary());
}

QStringList tapeLines(const std::string& nc) { return QString::fromStdString(nc).split('\n'); }

// A line without its numbers: what must be the same in both units.
QString shape(QString line)
{
    static const QRegularExpression number(QStringLiteral("-?\\d+(\\.\\d*)?"));
    return line.replace(number, QStringLiteral("#"));
}

// The length words of a lathe block (X, Z, I, K, U, W, F and CR=), as
// letter and value, in order; nothing of comments.
QList<QPair<QString, double>> lengthWords(const QString& line)
{
    QList<QPair<QString, double>> out;
    if (line.startsWith('(') || line.startsWith(';') || line.startsWith('O') || line.startsWith('o')) return out;
    static const QRegularExpression word(QStringLiteral("(?:^|\\s)(CR=|[XZIKUWF])(-?\\d+(?:\\.\\d*)?)"));
    for (auto it = word.globalMatch(line); it.hasNext();) {
        const auto m = it.next();
        out.append({m.captured(1), m.captured(2).toDouble()});
    }
    return out;
}

}  // namespace

class TestPostChains : public QObject {
    Q_OBJECT

private slots:
    void inchLatheTapeIsTheMmTapeConverted_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<QString>("dialect");
        const QStringList samples = QDir(test::sourcePath("resources/samples")).entryList({"lathe-*.taiwa"}, QDir::Files, QDir::Name);
        QVERIFY(samples.size() >= 5);
        for (const QString& s : samples)
            for (const char* d : {"fanuc", "haas", "linuxcnc", "sinumerik"})
                QTest::newRow(qPrintable(s + "/" + d)) << s << QString(d);
    }

    void inchLatheTapeIsTheMmTapeConverted()
    {
        QFETCH(QString, sample);
        QFETCH(QString, dialect);
        const Plan plan = planSample(sample);
        QVERIFY2(plan.ok() && !plan.steps.empty(), qPrintable(sample));
        const auto library = defaultToolLibrary();
        const QStringList mm = tapeLines(postProcess(plan.steps, library, postOptions(plan, dialect.toStdString(), LengthUnit::Millimetre)).nc);
        const QStringList inch = tapeLines(postProcess(plan.steps, library, postOptions(plan, dialect.toStdString(), LengthUnit::Inch)).nc);
        QCOMPARE(inch.size(), mm.size());
        QVERIFY(inch.filter(QRegularExpression("\\bG20\\b|\\bG700\\b")).size() == 1);
        QVERIFY(inch.filter("UNITS INCH", Qt::CaseInsensitive).size() == 1);
        int lengths = 0, surfaceSpeeds = 0;
        for (qsizetype i = 0; i < mm.size(); ++i) {
            const QString& a = mm[i];
            const QString& b = inch[i];
            if (a.contains("UNITS MM", Qt::CaseInsensitive) || a.contains(QRegularExpression("\\bG2[01]\\b|\\bG7[01]\\b"))) continue;
            QVERIFY2(shape(a) == shape(b), qPrintable(QString("line %1:\n  mm:   %2\n  inch: %3").arg(i + 1).arg(a, b)));
            const auto wa = lengthWords(a), wb = lengthWords(b);
            QCOMPARE(wb.size(), wa.size());
            for (qsizetype k = 0; k < wa.size(); ++k) {
                QCOMPARE(wb[k].first, wa[k].first);
                // Each rounded to its last decimal: 0.001 mm, 0.0001 inch.
                const double slack = 0.0005 + 0.00005 * 25.4 + 1e-9;
                QVERIFY2(std::abs(wb[k].second * 25.4 - wa[k].second) <= slack,
                         qPrintable(QString("line %1, %2: %3 inch against %4 mm").arg(i + 1).arg(wa[k].first).arg(wb[k].second).arg(wa[k].second)));
                ++lengths;
            }
            // G96 S: metres per minute, feet per minute under G20.
            static const QRegularExpression css(QStringLiteral("G96 (?:D\\d+ )?S(\\d+)"));
            const auto ma = css.match(a), mb = css.match(b);
            QCOMPARE(mb.hasMatch(), ma.hasMatch());
            if (ma.hasMatch()) {
                QVERIFY(std::abs(mb.captured(1).toDouble() - ma.captured(1).toDouble() * 1000.0 / 304.8) <= 0.5 + 3.3 * 0.5);
                ++surfaceSpeeds;
            }
        }
        QVERIFY(lengths > 20);
        QVERIFY(surfaceSpeeds > 0);
    }

    // The lathe writer's blocks are measured by the block tape: a dialect
    // whose lines are short refuses the roughing cycle's long block.
    void latheBlocksKeepToTheDialectsLineLimit()
    {
        post::Dialect d = *post::findDialect("fanuc");
        TurnCycle c;
        c.contour.push_back({false, {0, 10}, {-40, 10}, {}, 0, false});
        c.start = {2, 12};
        c.depthOfCut = 1.5;
        c.allowanceX = 0.2;
        c.allowanceZ = 0.1;
        c.retract = 0.5;
        {
            post::LatheWriter w(d, LengthUnit::Millimetre);
            w.roughingCycle(101, c, 0.25);
            const QStringList l = tapeLines(w.takeText());
            QCOMPARE(l[0], QString("N10 G71 U1.5 R0.5"));
            QCOMPARE(l[1], QString("N20 G71 P30 Q50 U0.4 W0.1 F0.25"));  // P and Q name the contour's first and last blocks
            QCOMPARE(l[2], QString("N30 G0 X20."));
            QCOMPARE(l[4], QString("N50 G1 Z-40."));
        }
        d.maxLineLength = 24;
        post::LatheWriter shortLines(d, LengthUnit::Millimetre);
        QVERIFY_THROWS_EXCEPTION(std::length_error, shortLines.roughingCycle(101, c, 0.25));
    }

    // FANUC numbers the probing cycle's blocks; its alarms and end are
    // labels the GOTOs name, none of them a number a block carries.
    void probingProgramsNumberTheirBlocks_data()
    {
        QTest::addColumn<QString>("dialect");
        QTest::newRow("fanuc") << "fanuc";
        QTest::newRow("haas") << "haas";
        QTest::newRow("linuxcnc") << "linuxcnc";
    }

    void probingProgramsNumberTheirBlocks()
    {
        QFETCH(QString, dialect);
        const Plan plan = planSample("probe-vise-block.taiwa");
        QVERIFY(plan.ok() && !plan.setups.empty());
        const PostOptions o = postOptions(plan, dialect.toStdString());
        const bool numbered = post::findDialect(o.dialect)->sequenceNumbers;
        for (const std::string& program : {probingProgram(plan.setups.front(), o), settingProgram(plan.setups.front(), o)}) {
            QSet<int> labels, numbers;
            int last = 0, blocks = 0;
            static const QRegularExpression n(QStringLiteral("^N(\\d+) "));
            for (const QString& line : tapeLines(program)) {
                if (line.isEmpty() || line == "%" || line.startsWith('(') || line.startsWith('O')) continue;
                ++blocks;
                const auto m = n.match(line);
                if (!numbered) {
                    QVERIFY2(!m.hasMatch(), qPrintable(line));
                    continue;
                }
                QVERIFY2(m.hasMatch(), qPrintable(line));
                const int k = m.captured(1).toInt();
                if (k >= 9001) {
                    labels.insert(k);
                    continue;
                }
                QVERIFY2(k > last, qPrintable(line));  // numbered in order, once each
                last = k;
                numbers.insert(k);
            }
            QVERIFY(blocks >= 4);
            static const QRegularExpression gotoWord(QStringLiteral("GOTO (\\d+)"));
            for (auto it = gotoWord.globalMatch(QString::fromStdString(program)); it.hasNext();) {
                const int target = it.next().captured(1).toInt();
                QVERIFY2(labels.contains(target), qPrintable(QString("GOTO %1 names no label").arg(target)));
                QVERIFY(!numbers.contains(target));
            }
        }
    }

    // The block tape itself: numbers wrap past the dialect's largest, a
    // block that says nothing takes back its number.
    void blockTapeNumbersAndTakesBack()
    {
        post::Dialect d = *post::findDialect("fanuc");
        d.sequenceStart = 5;
        d.sequenceIncrement = 5;
        d.sequenceMax = 15;
        post::BlockTape t(d);
        t.block("G0 X1.");
        t.line("%");
        t.block("G0 X2.");
        const auto mark = t.mark();
        t.beginBlock();
        t.rollback(mark);
        t.block("G0 X3.");
        t.block("G0 X4.");
        t.comment("a (nested) comment");
        QCOMPARE(QString::fromStdString(t.text()), QString("N5 G0 X1.\n%\nN10 G0 X2.\nN15 G0 X3.\nN5 G0 X4.\n(A  NESTED  COMMENT)\n"));
        QCOMPARE(t.sources().size(), std::size_t{6});
    }
};

QTEST_GUILESS_MAIN(TestPostChains)
#include "test_post_chains.moc"
