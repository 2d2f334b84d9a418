// Issue 39, items 6 to 13: shop data files that could poison a tape
// (tests/data/hostile/), refused by the one validating reader naming file,
// line and key; special files in the shop's folders refused by kind; two
// shop files of one name refused; refusals by design exit 2; automatic S and
// F within the machine's limits; an export set never mixed; messages that
// print numbers in a sane form.
#include "support/support.h"

#include "machine/machine.h"
#include "post/dialect.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

#include <sys/stat.h>

using namespace taiwa;
using namespace taiwa::test;
using nlohmann::json;

namespace {

QString hostile(const QString& relative) { return dataPath("hostile/" + relative); }

// "FILE:LINE: key: ..." with LINE the line `key` stands on in the file.
QString expectNamed(const std::string& error, const QString& file, const QString& key)
{
    const QString e = QString::fromStdString(error);
    const QRegularExpression form("^" + QRegularExpression::escape(file) + ":([0-9]+): " + QRegularExpression::escape(key) + ": ");
    const auto m = form.match(e);
    if (!m.hasMatch()) return "not FILE:LINE: " + key + ": … — " + e;
    const QStringList lines = QString::fromStdString(readFile(file)).split('\n');
    const int line = m.captured(1).toInt();
    const QString bare = key.section('.', -1).section('[', 0, 0);
    if (line < 1 || line > lines.size() || !lines[line - 1].contains("\"" + bare + "\""))
        return QString("line %1 does not hold \"%2\": %3").arg(line).arg(bare, e);
    return {};
}

}  // namespace

class TestCliHostile : public QObject {
    Q_OBJECT
    QTemporaryDir noShopFiles_;
private slots:
    // The libraries this process reads are the shipped ones only.
    void initTestCase() { qputenv("XDG_CONFIG_HOME", QFile::encodeName(noShopFiles_.path())); }

    // Items 6 to 8: every hostile dialect refused, naming file, line and key,
    // with the reason; the shipped ones and a benign shop file still read.
    void hostileDialectsRefused_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("why");
        QTest::newRow("width") << "format_width" << "programNumberLine" << "a width or precision over 16";
        QTest::newRow("nested width") << "nested_width" << "toolChange" << "a field inside a field";
        QTest::newRow("newline rapid") << "coolant_newline_rapid" << "coolantOn" << "control character";
        QTest::newRow("inline rapid") << "coolant_rapid" << "coolantOn" << "must be M words only";
        QTest::newRow("tool change rapid") << "tool_change_rapid" << "toolChange" << "moves an axis";
        QTest::newRow("unclosed comment") << "spindle_stop_unclosed" << "spindleStop" << "never closes";
        QTest::newRow("percent after newline") << "program_end_percent" << "programEnd" << "control character";
        QTest::newRow("percent") << "program_end_percent_inline" << "programEnd" << "holds '%'";
        QTest::newRow("semicolon") << "semicolon_in_word" << "coolantOff" << "holds ';'";
        QTest::newRow("empty tool change") << "empty_tool_change" << "toolChange" << "must use {tool}";
        QTest::newRow("tool change without tool") << "tool_change_without_tool" << "toolChange" << "must use {tool}";
        QTest::newRow("empty spindle") << "empty_spindle_clockwise" << "spindleClockwise" << "must not be empty";
        QTest::newRow("empty end") << "empty_program_end" << "programEnd" << "must not be empty";
        QTest::newRow("preamble name") << "preamble_name" << "preamble" << "it uses {name}, which this word cannot be given; its fields: {units}, {workOffset}";
        QTest::newRow("tool change number") << "tool_change_number" << "toolChange" << "it uses {number}, which this word cannot be given; its fields: {tool}";
        QTest::newRow("decimals wrap") << "decimals_wrap" << "lengthDecimals.mm" << "must be a whole number from 0 to 6";
        QTest::newRow("too long") << "template_too_long" << "preamble" << "the dialect's maxLineLength is 40";
        QTest::newRow("escape") << "escape_in_description" << "description" << "control character";
        QTest::newRow("duplicate key") << "duplicate_key" << "coolantOn" << "given twice";
    }
    void hostileDialectsRefused()
    {
        QFETCH(QString, file);
        QFETCH(QString, key);
        QFETCH(QString, why);
        const QString path = hostile("dialects/" + file + ".json");
        const auto d = post::readDialect(readFile(path), path.toStdString());
        QVERIFY2(!d.ok(), qPrintable(file + " was read"));
        const QString named = expectNamed(d.error(), path, key);
        QVERIFY2(named.isEmpty(), qPrintable(named));
        QVERIFY2(QString::fromStdString(d.error()).contains(why), d.error().c_str());
    }
    // The negative control: a shop file with two M words for coolant and a
    // commented tool change reads; so does every shipped dialect.
    void benignDialectsRead()
    {
        const QString path = hostile("dialects/good.json");
        const auto d = post::readDialect(readFile(path), path.toStdString());
        QVERIFY2(d.ok(), d.ok() ? "" : d.error().c_str());
        QCOMPARE(d->coolantOn, std::string("M8 M50"));
        QCOMPARE(static_cast<int>(post::dialectLibrary().size()), shippedDialects().size());
        // The line of a repeated key is the second one's.
        const QString twice = hostile("dialects/duplicate_key.json");
        const auto t = post::readDialect(readFile(twice), twice.toStdString());
        QVERIFY(!t.ok());
        const QStringList lines = QString::fromStdString(readFile(twice)).split('\n');
        const int first = static_cast<int>(lines.indexOf(QRegularExpression(".*\"coolantOn\".*"))) + 1;
        QVERIFY2(QString::fromStdString(t.error()).startsWith(twice + ":" + QString::number(first + 1) + ": coolantOn: given twice"),
                 t.error().c_str());
    }

    // Item 10: hostile machines refused naming file, line and key.
    void hostileMachinesRefused_data()
    {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("why");
        QTest::newRow("id path") << "id_path" << "id" << "lower-case letters";
        QTest::newRow("id escape") << "id_escape" << "id" << "lower-case letters";
        QTest::newRow("name escape") << "name_escape" << "name" << "control character";
        QTest::newRow("rapid") << "rapid_tiny" << "rapid.x" << "must be from 1 to 1e+06 mm/min, not 1e-300";
        QTest::newRow("acceleration") << "acceleration_tiny" << "acceleration.y" << "must be from 1 to 1e+06 mm/s², not 1e-300";
        QTest::newRow("maxFeed") << "max_feed_tiny" << "maxFeed" << "must be from 1 to 1e+06 mm/min, not 1e-300";
        QTest::newRow("travel") << "travel_huge" << "travel.x[0]" << "must be a number from -100000 up to 100000, not -1e+308";
        QTest::newRow("pockets") << "pockets_huge" << "toolChanger.pockets" << "must be a whole number from 1 to 10000";
        QTest::newRow("lookAhead") << "look_ahead_wrap" << "lookAhead" << "must be a whole number from 1 to 10000";
        QTest::newRow("coolant") << "coolant_rapid" << "coolant.flood" << "must be M words only";
        QTest::newRow("duplicate key") << "duplicate_key" << "maxFeed" << "given twice";
    }
    void hostileMachinesRefused()
    {
        QFETCH(QString, file);
        QFETCH(QString, key);
        QFETCH(QString, why);
        const QString path = hostile("machines/" + file + ".json");
        const auto m = readMachine(readFile(path), path.toStdString());
        QVERIFY2(!m.ok(), qPrintable(file + " was read"));
        const QString named = expectNamed(m.error(), path, key);
        QVERIFY2(named.isEmpty(), qPrintable(named));
        QVERIFY2(QString::fromStdString(m.error()).contains(why), m.error().c_str());
    }
    void benignMachineReads()
    {
        const QString path = hostile("machines/good.json");
        const auto m = readMachine(readFile(path), path.toStdString());
        QVERIFY2(m.ok(), m.ok() ? "" : m.error().c_str());
        QCOMPARE(m->maxSpindleSpeed, 3000.0);
        QCOMPARE(static_cast<int>(machineLibrary().size()), shippedMachines().size());
    }

    // Item 10: in the shop's folders a directory, a FIFO and a link to
    // /dev/zero named *.json are refused by their kind (never opened); of
    // two files of one name the first is used and the second refused naming
    // the first; a hostile file is left out, the good one listed.
    void shopFoldersRefuseSpecialFilesAndTwins_data()
    {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("option");
        QTest::addColumn<QString>("key");
        QTest::newRow("dialects") << "dialects" << "--list-dialects" << "name";
        QTest::newRow("machines") << "machines" << "--list-machines" << "id";
    }
    void shopFoldersRefuseSpecialFilesAndTwins()
    {
        QFETCH(QString, kind);
        QFETCH(QString, option);
        QFETCH(QString, key);
        QTemporaryDir config;
        const QString folder = config.filePath("taiwa/" + kind);
        QVERIFY(QDir().mkpath(folder + "/folder.json"));
        QVERIFY(::mkfifo(QFile::encodeName(folder + "/pipe.json").constData(), 0600) == 0);
        QVERIFY(QFile::link("/dev/zero", folder + "/zero.json"));
        QVERIFY(QFile::copy(hostile(kind + "/good.json"), folder + "/a-good.json"));
        QVERIFY(QFile::copy(hostile(kind + "/good.json"), folder + "/b-twin.json"));
        QVERIFY(QFile::copy(hostile(kind + "/duplicate_key.json"), folder + "/c-twice.json"));
        const auto r = runTaiwa({option}, {"XDG_CONFIG_HOME=" + config.path()});
        QCOMPARE(r.exitCode, 0);
        const std::string name = json::parse(readFile(hostile(kind + "/good.json"))).at(key.toStdString()).get<std::string>();
        QCOMPARE(r.out.count(QString::fromStdString(name) + "\t"), 1);
        QVERIFY2(r.out.contains(folder + "/a-good.json\n"), qPrintable(r.out));
        QVERIFY2(r.err.contains("taiwa: " + folder + "/folder.json: a directory, not a definition\n"), qPrintable(r.err));
        QVERIFY2(r.err.contains("taiwa: " + folder + "/pipe.json: a named pipe (FIFO), not a definition\n"), qPrintable(r.err));
        QVERIFY2(r.err.contains("taiwa: " + folder + "/zero.json: a character device, not a definition\n"), qPrintable(r.err));
        QVERIFY2(r.err.contains("taiwa: " + folder + "/b-twin.json: '" + QString::fromStdString(name) + "' is already defined by " +
                                folder + "/a-good.json"),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QRegularExpression(QRegularExpression::escape(folder + "/c-twice.json:") + "[0-9]+: [a-zA-Z]+: given twice")),
                 qPrintable(r.err));
        QVERIFY(!r.out.contains("shop-duplicate-key"));
        QCOMPARE(r.err.count('\n'), 5);
    }

    // Item 6: a hostile dialect in the shop's folder costs nothing: the
    // listing and a check run as without it (the width is refused before
    // anything is expanded; bench-free: the run simply completes).
    void hostileDialectFolderStillExports()
    {
        QTemporaryDir config;
        const QString folder = config.filePath("taiwa/dialects");
        QVERIFY(QDir().mkpath(folder));
        for (const auto& f : QDir(hostile("dialects")).entryInfoList({"*.json"}, QDir::Files))
            QVERIFY(QFile::copy(f.absoluteFilePath(), folder + "/" + f.fileName()));
        QTemporaryDir out;
        const auto r = runTaiwa({"export", sourcePath("resources/samples/m4-standard.taiwa"), "--out", out.filePath("x"),
                                 "--dialect", "shop-good", "--no-pictures"},
                                {"XDG_CONFIG_HOME=" + config.path()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const std::string nc = readFile(out.filePath("x/m4-standard.nc"));
        QVERIFY(nc.find("M8 M50") != std::string::npos);
        QVERIFY(QString::fromStdString(nc).contains(QRegularExpression(R"(\n(N[0-9]+ )?T([0-9]+) M6 \(TOOL 0*\2\)\n)")));
        // Every hostile file left out with its line, none of them offered.
        const auto listed = runTaiwa({"--list-dialects"}, {"XDG_CONFIG_HOME=" + config.path()});
        QCOMPARE(static_cast<int>(listed.err.count("(left out; the shipped dialects stay)")),
                 static_cast<int>(QDir(hostile("dialects")).entryList({"*.json"}).size()) - 1);
        const auto bad = runTaiwa({"export", sourcePath("resources/samples/m4-standard.taiwa"), "--out", out.filePath("y"),
                                   "--dialect", "shop-coolant-rapid"},
                                  {"XDG_CONFIG_HOME=" + config.path()});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("unknown dialect 'shop-coolant-rapid'"), qPrintable(bad.err));
        QVERIFY(!QFileInfo::exists(out.filePath("y")));
    }
};

QTEST_APPLESS_MAIN(TestCliHostile)
#include "test_cli_hostile.moc"
