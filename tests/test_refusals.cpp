// The one refusal type (model/result.h): what the operator must fix outside
// the job — a data file, a figure text, a STEP file, a dialect, an option —
// comes back from every reader's door as a Failure (or figure error) carrying
// its Place, and only a bug is a std::logic_error. The last test reads the
// product's sources: no second refusal type, no std::invalid_argument or
// std::runtime_error for the operator's trouble, with a planted control.
#include "figure/figure_eval.h"
#include "figure/figure_text.h"
#include "machine/lathe_kinds.h"
#include "machine/machine.h"
#include "model/result.h"
#include "model/technology.h"
#include "occt/step_import.h"
#include "post/dialect.h"
#include "support/hand_plan.h"
#include "support/support.h"
#include "verify/verify.h"

#include <nlohmann/json.hpp>

#include <QDirIterator>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace taiwa;

namespace {

// "file:line: what" for every line of a product source that refuses the
// operator's trouble another way than Refusal: a type of its own named
// Refus…, or std::invalid_argument / std::runtime_error thrown or caught.
QStringList otherRefusals(const QString& file, const QString& text)
{
    static const QRegularExpression own(R"(^\s*(struct|class)\s+\w*Refus\w*\b)"),
        std(R"(\b(throw|catch\s*\(\s*const)\s+std::(invalid_argument|runtime_error)\b)");
    QStringList out;
    const QStringList lines = text.split('\n');
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString& l = lines[i];
        if (l.trimmed().startsWith("//")) continue;
        if (own.match(l).hasMatch() && !l.contains("class Refusal : public std::exception"))
            out << QString("%1:%2: %3").arg(file).arg(i + 1).arg(l.trimmed());
        else if (std.match(l).hasMatch())
            out << QString("%1:%2: %3").arg(file).arg(i + 1).arg(l.trimmed());
    }
    return out;
}

}  // namespace

class TestRefusals : public QObject {
    Q_OBJECT

private slots:
    void aPlaceSaysWhereInWords()
    {
        QCOMPARE(Place::inFile("haas.json", 12, "lineLength").text(), std::string("haas.json:12: lineLength"));
        QCOMPARE(Place::inFile("shaft.step").text(), std::string("shaft.step"));
        QCOMPARE(Place::inText(3, 7).text(), std::string("line 3, column 7"));
        QCOMPARE(Place::atKey("paths[1].turret").text(), std::string("paths[1].turret"));
        Place unit = Place::atKey("depth");
        unit.unit = 2;
        QCOMPARE(unit.text(), std::string("unit 2: depth"));
        QVERIFY(Place{}.empty());
        QCOMPARE(Place{}.text(), std::string());

        const Refusal r("must be a positive number", Place::inFile("m.json", 4, "turret.slots"));
        QCOMPARE(std::string(r.what()), std::string("m.json:4: turret.slots: must be a positive number"));
        QCOMPARE(r.message(), std::string("must be a positive number"));
        const Failure f = r.failure();
        QCOMPARE(f.message, std::string(r.what()));
        QCOMPARE(f.place, r.place());
        QCOMPARE(std::string(Refusal("no place").what()), std::string("no place"));
    }

    // Each reader's door names the place twice: in the Failure's words, for
    // the operator, and as its Place, for a program to go to (the station's
    // form, an editor's line).
    void aDialectFileIsRefusedAtItsLineAndKey()
    {
        std::string text = test::readFile(test::sourcePath("resources/dialects/fanuc.json"));
        const std::string key = "\"maxLineLength\": ";
        const auto at = text.find(key);
        QVERIFY(at != std::string::npos);
        text.replace(at + key.size(), text.find_first_of(",\n", at) - at - key.size(), "7");  // below its range
        const auto d = post::readDialect(text, "shop.json");
        QVERIFY(!d.ok());
        QCOMPARE(d.error().rfind("shop.json:", 0), std::size_t{0});
        const int line = static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) + 1;
        QVERIFY2(d.error().find("shop.json:" + std::to_string(line) + ": maxLineLength: ") == 0, d.error().c_str());
        QCOMPARE(d.place().file, std::string("shop.json"));
        QCOMPARE(d.place().line, line);
        QCOMPARE(d.place().key, std::string("maxLineLength"));
        QCOMPARE(d.failure().message, d.error());

        const auto broken = readMachine("{\n  \"name\": \"x\",\n  oops\n}", "mill.json");
        QVERIFY(!broken.ok());
        QVERIFY2(broken.error().starts_with("mill.json:3: not valid JSON"), broken.error().c_str());
        QCOMPARE(broken.place().file, std::string("mill.json"));
        QCOMPARE(broken.place().line, 3);
    }

    void aLatheLayoutIsRefusedAtItsKey()
    {
        const auto l = readLatheLayout(nlohmann::json::parse(R"({"waitCodes": [100, 199]})"));
        QVERIFY(!l.ok());
        QCOMPARE(l.error(), std::string("waitCodes: only a lathe with \"paths\" waits"));
        QCOMPARE(l.place().key, std::string("waitCodes"));
    }

    void aFigureTextIsRefusedAtItsLineAndColumn()
    {
        const figure::ParseResult p = figure::parseFigure("P1 = POINT/0, 0\nL1 = LINE/P1, ?\n");
        QVERIFY(!p.ok());
        QCOMPARE(p.error->line, 2);
        QCOMPARE(p.error->column, 15);
        const figure::ParseResult parallel = figure::parseFigure("P1 = POINT/0, 0\nP2 = POINT/10, 0\nP3 = POINT/0, 5\nP4 = POINT/10, 5\n"
                                                                 "L1 = LINE/P1, P2\nL2 = LINE/P3, P4\nP5 = POINT/INTOF, L1, L2\n");
        QVERIFY(parallel.ok());
        const figure::Evaluation ev = figure::evaluate(parallel.definitions);
        QCOMPARE(ev.errors.size(), std::size_t{1});
        QCOMPARE(ev.errors.front().line, 7);
        QVERIFY2(ev.errors.front().message.starts_with("P5: L1 and L2 are parallel"), ev.errors.front().message.c_str());
    }

    void aStepFileIsRefusedNamingTheFile()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("not-a-solid.step").toStdString();
        std::ofstream(path) << "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n";
        const auto r = turning::importStepProfiles(path);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().starts_with(path + ": "), r.error().c_str());
        QCOMPARE(r.place().file, path);
    }

    void theTechnologyTableIsRefusedAtTheMaterial()
    {
        try {
            TechnologyTable::fromJson(R"({"format": "taiwa-technology", "materials": [{"id": "x", "alpha1": 1, "alpha2": -1}]})");
            QFAIL("a negative alpha2 was taken");
        } catch (const Refusal& r) {
            QCOMPARE(r.place().file, std::string("technology table"));
            QCOMPARE(r.place().key, std::string("material x: alpha2"));
            QCOMPARE(r.place().line, 1);
            QVERIFY2(std::string(r.what()).starts_with("technology table:1: material x: alpha2: must be a number above 0"), r.what());
        }
        QVERIFY_THROWS_EXCEPTION(Refusal, TechnologyTable::fromJson("not json"));
    }

    // The technology table goes through the one validating reader of data
    // files (io/data_reader.h): each row is the shipped form of two
    // materials with one thing wrong, refused at its line and key.
    void theTechnologyTableIsReadLikeEveryDataFile_data()
    {
        QTest::addColumn<QString>("second");  // the second material's values, from line 6
        QTest::addColumn<QString>("key");
        QTest::addColumn<int>("line");
        QTest::addColumn<QString>("reason");
        const QString ok = R"(      "alpha1": 1.0, "alpha2": 0.4, "alpha3": 0.15, "beta2": 0.25, "gamma": 0.3,)";
        QTest::newRow("control") << ok << "" << 0 << "";
        QTest::newRow("key given twice") << ok + R"( "gamma": 0.3,)" << "materials[1].gamma" << 6 << "given twice";
        QTest::newRow("a typo") << R"(      "alpha1": 1.0, "alpha2": 0.4, "alpha3": 0.15, "beta2": 0.25, "gama": 0.3,)"
                                << "material b: gama" << 6 << "not a key of a material";
        QTest::newRow("far out of range") << R"(      "alpha1": 1e300, "alpha2": 0.4, "alpha3": 0.15, "beta2": 0.25, "gamma": 0.3,)"
                                          << "material b: alpha1" << 6 << "must be a number above 0 up to 50, not 1e+300";
        QTest::newRow("gamma zero") << R"(      "alpha1": 1.0, "alpha2": 0.4, "alpha3": 0.15, "beta2": 0.25, "gamma": 0,)"
                                    << "material b: gamma" << 6 << "must be a number above 0.01 up to 2, not 0";
        QTest::newRow("turning typo") << ok + "\n" + R"(      "turning": {"depthOfCut": 2.0, "retrakt": 0.5},)"
                                      << "material b: turning.retrakt" << 7 << "not a key of a material's turning";
        QTest::newRow("turning out of range") << ok + "\n" + R"(      "turning": {"depthOfCut": 2.0, "withdrawal": 1e9},)"
                                              << "material b: turning.withdrawal" << 7 << "up to 20, not 1e+09";
        QTest::newRow("escape in the description") << ok + "\n" + "      \"description\": \"Steel \\u001b[31m\","  // JSON's escape of ESC, not in a raw string: moc cannot parse it there
                                                   << "material b: description" << 7 << "";
    }

    void theTechnologyTableIsReadLikeEveryDataFile()
    {
        QFETCH(QString, second);
        QFETCH(QString, key);
        QFETCH(int, line);
        QFETCH(QString, reason);
        const QString text = QString("{\n"
                                     "  \"format\": \"taiwa-technology\",\n"
                                     "  \"materials\": [\n"
                                     "    {\"id\": \"a\", \"alpha1\": 1.0, \"alpha2\": 0.3, \"alpha3\": 0.1, "
                                     "\"beta2\": 0.2, \"gamma\": 0.5},\n"
                                     "    {\"id\": \"b\",\n"
                                     "%1\n"
                                     "      \"names\": {\"ja\": \"steel\"}\n"
                                     "    }\n"
                                     "  ]\n"
                                     "}\n")
                                 .arg(second);
        try {
            const TechnologyTable table = TechnologyTable::fromJson(text.toStdString());
            QVERIFY2(key.isEmpty(), qPrintable("taken: " + key));
            QCOMPARE(table.materials().size(), std::size_t(2));
            QCOMPARE(table.materials()[1].data.beta2, 0.25);
        } catch (const Refusal& r) {
            QVERIFY2(!key.isEmpty(), r.what());
            QCOMPARE(QString::fromStdString(r.place().file), QString("technology table"));
            QCOMPARE(QString::fromStdString(r.place().key), key);
            QCOMPARE(r.place().line, line);
            QVERIFY2(QString::fromStdString(r.message()).contains(reason), r.what());
        }
    }

    // Two materials of one id: which one a job means is not to be guessed.
    void aMaterialGivenTwiceIsRefused()
    {
        try {
            TechnologyTable::fromJson(std::string(R"({"format": "taiwa-technology", "materials": [)") + "\n" +
                                      R"(  {"id": "x", "alpha1": 1, "alpha2": 0.3, "alpha3": 0.1, "beta2": 0.2, "gamma": 0.5},)" +
                                      "\n" +
                                      R"(  {"id": "x", "alpha1": 2, "alpha2": 0.3, "alpha3": 0.1, "beta2": 0.2, "gamma": 0.5}]})");
            QFAIL("a material given twice was taken");
        } catch (const Refusal& r) {
            QCOMPARE(r.place().key, std::string("material x"));
            QCOMPARE(r.place().line, 3);
            QCOMPARE(r.message(), std::string("given twice"));
        }
    }

    void whetherADialectCanPostIsAResult()
    {
        const post::Dialect* heidenhain = post::findDialect("heidenhain");
        const post::Dialect* fanuc = post::findDialect("fanuc");
        QVERIFY(heidenhain && fanuc);
        QVERIFY(post::canPost(*heidenhain, post::Task::MillingTape).ok());
        const auto lathe = post::canPost(*heidenhain, post::taskOf(true, false));
        QVERIFY(!lathe.ok());
        QVERIFY2(lathe.error().find("writes no lathe tapes") != std::string::npos, lathe.error().c_str());
        QVERIFY(post::canPost(*fanuc, post::Task::LatheTape).ok());
        QVERIFY(post::canPost(*fanuc, post::Task::ProbingPrograms).ok());
        QVERIFY_THROWS_EXCEPTION(Refusal, post::dialectNamed("mazatrol"));
    }

    // The operator's resolution is refused as such, never as a bug.
    void aResolutionIsTheOperatorsNotABug()
    {
        const Plan plan = test::samplePlan("m4-standard.taiwa");
        verify::Options o;
        o.resolution = 0.001;
        try {
            (void)verify::verifyPlan(plan, o);
            QFAIL("0.001 mm was taken");
        } catch (const std::logic_error&) {
            QFAIL("the operator's resolution was refused as a bug");
        } catch (const Refusal& r) {
            QVERIFY2(std::string(r.what()).find("resolution must be at least") != std::string::npos, r.what());
        }
    }

    void noOtherRefusalTypeInTheProduct()
    {
        // The rule catches what it is for.
        QCOMPARE(otherRefusals("planted.cpp", "struct Refused {\n    std::string message;\n};").size(), 1);
        QCOMPARE(otherRefusals("planted.cpp", "    struct DataRefusal {").size(), 1);
        QCOMPARE(otherRefusals("planted.cpp", "    if (!ok) throw std::invalid_argument(\"bad\");").size(), 1);
        QCOMPARE(otherRefusals("planted.cpp", "    } catch (const std::runtime_error& e) {").size(), 1);
        QCOMPARE(otherRefusals("planted.cpp", "// throw std::invalid_argument in a comment\nthrow Refusal(\"x\");\nthrow std::logic_error(\"bug\");").size(), 0);

        QStringList found;
        int files = 0;
        for (const char* folder : {"core", "app", "ui", "viz"}) {
            QDirIterator it(test::sourcePath(folder), {"*.cpp", "*.h"}, QDir::Files, QDirIterator::Subdirectories);
            while (it.hasNext()) {
                const QString path = it.next();
                QFile f(path);
                QVERIFY(f.open(QIODevice::ReadOnly));
                found << otherRefusals(QDir(test::sourcePath("")).relativeFilePath(path), QString::fromUtf8(f.readAll()));
                ++files;
            }
        }
        QVERIFY(files > 300);
        QVERIFY2(found.isEmpty(), qPrintable(found.join('\n')));
    }
};

QTEST_GUILESS_MAIN(TestRefusals)
#include "test_refusals.moc"
