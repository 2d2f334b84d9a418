// Issue 39, items 6 to 13: shop data files that could poison a tape
// (tests/data/hostile/), refused by the one validating reader naming file,
// line and key; special files in the shop's folders refused by kind; two
// shop files of one name refused; refusals by design exit 2; automatic S and
// F within the machine's limits; an export set never mixed; messages that
// print numbers in a sane form.
#include "support/support.h"

#include "io/job_io.h"
#include "machine/machine.h"
#include "post/dialect.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include <regex>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

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

// The largest number after `letter` in the tape's blocks (comments skipped).
double largest(const std::string& tape, char letter)
{
    double most = 0;
    static const std::regex comment(R"(\([^)]*\)|;.*)");
    const std::string bare = std::regex_replace(tape, comment, "");
    const std::regex word(std::string("(^|[^A-Z])") + letter + "([0-9]+\\.?[0-9]*)");
    for (auto it = std::sregex_iterator(bare.begin(), bare.end(), word); it != std::sregex_iterator(); ++it)
        most = std::max(most, std::stod((*it)[2].str()));
    return most;
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
        // Issue 34, item 9: the NC view's colours come from the dialect's file, checked as the rest.
        QTest::newRow("highlighting typo") << "highlighting_typo" << "highlighting.keyword" << "not a key of highlighting";
        QTest::newRow("highlighting comment") << "highlighting_comment" << "highlighting.keywords" << "'L ;' must be a word of the tape";
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
        QTest::newRow("unknown key") << "unknown_key" << "maxSpindelSpeed" << "not a key of a machine definition (a typo?)";
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

    // Item 9: a shop machine of 3000 rpm and 1000 mm/min gets no automatic
    // S or F beyond them; the shipped vmc's tape of the same job has both
    // beyond (the negative control).
    void automaticSpeedsWithinTheMachine()
    {
        QTemporaryDir config;
        const QString folder = config.filePath("taiwa/machines");
        QVERIFY(QDir().mkpath(folder));
        QVERIFY(QFile::copy(hostile("machines/good.json"), folder + "/slow.json"));
        json job = json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
        QTemporaryDir dir;
        writeFile(dir.filePath("vmc.taiwa"), job.dump(2));
        job["machine"] = "shop-good";
        writeFile(dir.filePath("slow.taiwa"), job.dump(2));
        const QStringList env{"XDG_CONFIG_HOME=" + config.path()};
        for (const QString stem : {"vmc", "slow"}) {
            const auto r = runTaiwa({"export", dir.filePath(stem + ".taiwa"), "--out", dir.filePath("out"), "--no-pictures"}, env);
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        }
        const std::string vmc = readFile(dir.filePath("out/vmc.nc")), slow = readFile(dir.filePath("out/slow.nc"));
        QVERIFY2(largest(vmc, 'S') > 3000 && largest(vmc, 'F') > 1000, "the control: the vmc's tape runs faster");
        QVERIFY2(largest(slow, 'S') > 0 && largest(slow, 'S') <= 3000, qPrintable(QString::number(largest(slow, 'S'))));
        QVERIFY2(largest(slow, 'F') > 0 && largest(slow, 'F') <= 1000, qPrintable(QString::number(largest(slow, 'F'))));
    }

    // Item 12: a process killed between two renames of an export set leaves
    // half of each set (the control that the kill fell there), and the next
    // set opened for the stem finishes the switch: every file the new one,
    // the other dialect's file removed, no journal or temporary left.
    void killedSwitchIsFinishedByTheNextOpen()
    {
        QTemporaryDir dir;
        const std::string folder = dir.path().toStdString();
        for (const char* name : {"part.nc", "part.sheet.html", "part.steps.json", "part.mpf"}) writeFile(dir.filePath(name), "old");
        const pid_t child = ::fork();
        QVERIFY(child >= 0);
        if (child == 0) {
            auto set = FileSet::open(folder, "part");
            if (!set) ::_exit(2);
            for (const char* name : {"part.nc", "part.sheet.html", "part.steps.json"})
                if (!set->add(name, "new")) ::_exit(3);
            set->remove("part.mpf");
            static_cast<void>(set->commit([](std::size_t renamed) {
                if (renamed == 1) ::_exit(9);  // killed after the first rename
            }));
            ::_exit(4);
        }
        int status = 0;
        QCOMPARE(::waitpid(child, &status, 0), child);
        QVERIFY(WIFEXITED(status));
        QCOMPARE(WEXITSTATUS(status), 9);
        QCOMPARE(readFile(dir.filePath("part.nc")), std::string("new"));
        QCOMPARE(readFile(dir.filePath("part.sheet.html")), std::string("old"));  // mixed, for now
        QVERIFY(QFileInfo::exists(dir.filePath(".part.set")));
        {
            auto next = FileSet::open(folder, "part");
            QVERIFY(next.ok());
        }
        for (const char* name : {"part.nc", "part.sheet.html", "part.steps.json"}) QCOMPARE(readFile(dir.filePath(name)), std::string("new"));
        QVERIFY(!QFileInfo::exists(dir.filePath("part.mpf")));
        const QStringList left = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden, QDir::Name);
        QCOMPARE(left, (QStringList{"part.nc", "part.sheet.html", "part.steps.json"}));  // the lock lives elsewhere
    }

    // Item 12: linuxcnc, then sinumerik into one folder leaves the Siemens
    // set alone (no part.nc beside part.mpf); back to linuxcnc, no .mpf.
    void dialectChangeRemovesTheOtherTape()
    {
        QTemporaryDir dir;
        const QString job = sourcePath("resources/samples/m4-standard.taiwa"), out = dir.filePath("out");
        const QStringList common{"m4-standard.sheet.html", "m4-standard.sheet.pdf", "m4-standard.steps.json", "m4-standard.tape.txt"};
        for (const QString dialect : {"linuxcnc", "sinumerik", "linuxcnc"}) {
            const auto r = runTaiwa({"export", job, "--out", out, "--dialect", dialect, "--no-pictures"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            QStringList expected = common;
            expected << (dialect == "sinumerik" ? "m4-standard.mpf" : "m4-standard.nc");
            expected.sort();
            QCOMPARE(QDir(out).entryList(QDir::Files, QDir::Name), expected);
        }
    }

    // Item 13: numbers in messages: 1e308 as "1e+308", an angle just past
    // -360° with its own digits, a text in a tool's diameter named as such,
    // a folder given as the tool library named as a folder.
    void messagesShowTheNumbersGiven()
    {
        QTemporaryDir dir;
        const auto unitOf = [](json& job, const char* module) -> json& {
            for (json& u : job["units"])
                if (u["module"] == module) return u;
            return job["units"][0];
        };
        json face = json::parse(readFile(sourcePath("resources/samples/face-top.taiwa")));
        unitOf(face, "FACE")["angle"] = 1e308;
        writeFile(dir.filePath("face.taiwa"), face.dump(2));
        auto r = runTaiwa({"check", dir.filePath("face.taiwa")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("the angle 1e+308° lies beyond ±360°"), qPrintable(r.err));
        QVERIFY2(!r.err.contains(QRegularExpression("[0-9]{20}")), qPrintable(r.err));
        json probe = json::parse(readFile(sourcePath("resources/samples/probe-bore.taiwa")));
        unitOf(probe, "PROBE")["touches"][0] = json::array({1e308, 1e308});
        writeFile(dir.filePath("probe.taiwa"), probe.dump(2));
        r = runTaiwa({"check", dir.filePath("probe.taiwa")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("the X of P1 is 1e+308 mm"), qPrintable(r.err));
        QVERIFY2(!r.err.contains(QRegularExpression("[0-9]{20}")), qPrintable(r.err));
        json holes = json::parse(readFile(sourcePath("resources/samples/holes-grid.taiwa")));
        unitOf(holes, "HOLES")["angle"] = -360.0000001;
        writeFile(dir.filePath("holes.taiwa"), holes.dump(2));
        r = runTaiwa({"check", dir.filePath("holes.taiwa")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("the angle -360.0000001° must be from -360° to 360°"), qPrintable(r.err));

        // A folder as the tool library.
        QVERIFY(QDir().mkpath(dir.filePath("lib")));
        r = runTaiwa({"check", sourcePath("resources/samples/m4-standard.taiwa"), "--tools", dir.filePath("lib")});
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(dir.filePath("lib") + " is a folder, not a tool library"), qPrintable(r.err));
        // A diameter of 'abc': the library made by a first run, then damaged.
        const QString db = dir.filePath("tools.sqlite");
        QCOMPARE(runTaiwa({"check", sourcePath("resources/samples/m4-standard.taiwa"), "--tools", db}).exitCode, 0);
        sqlite3* handle = nullptr;
        QCOMPARE(sqlite3_open(QFile::encodeName(db).constData(), &handle), SQLITE_OK);
        QCOMPARE(sqlite3_exec(handle, "UPDATE tools SET diameter = 'abc' WHERE id = (SELECT min(id) FROM tools)", nullptr, nullptr, nullptr), SQLITE_OK);
        sqlite3_close(handle);
        r = runTaiwa({"check", sourcePath("resources/samples/m4-standard.taiwa"), "--tools", db});
        QVERIFY(r.exitCode != 0);
        QVERIFY2(r.err.contains(QRegularExpression(": tool [0-9]+: diameter is 'abc', not a number")), qPrintable(r.err));
        QVERIFY2(!r.err.contains("diameter 0 mm"), qPrintable(r.err));
    }
};

QTEST_APPLESS_MAIN(TestCliHostile)
#include "test_cli_hostile.moc"
