// The command line of interfaces.md, run as a real process: exit codes,
// one stderr line per input error naming unit, module and field, nothing
// written on refusal, the five export files, --help and --version.
#include "support/support.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <nlohmann/json.hpp>

using namespace taiwa::test;
using nlohmann::json;

namespace {

QStringList samples()
{
    QStringList out;
    for (const auto& f : QDir(sourcePath("resources/samples")).entryInfoList({"*.taiwa"}, QDir::Files, QDir::Name))
        out << f.absoluteFilePath();
    return out;
}

// A valid one-unit M4 job to break one field at a time.
json baseJob()
{
    json unit = {{"module", "M4"}, {"name", "A"}, {"cornerRadius", 8}, {"depth", 12}, {"taper", 0},
                 {"U", 1}, {"F", 1}, {"H", 0}};
    unit["corners"] = json::array({json::array({20, 20}), json::array({120, 20}), json::array({120, 80}),
                                   json::array({20, 80})});
    json job = {{"format", "taiwa-job"}, {"version", 1}, {"name", "cli"}, {"lengthUnit", "mm"},
                {"material", "aluminium-6061"}, {"machine", "vmc"}, {"workOffset", "G54"}};
    job["stock"] = {{"shape", "block"}, {"x", 0}, {"y", 0}, {"width", 200}, {"length", 150}, {"height", 40}};
    job["units"] = json::array({unit});
    return job;
}

// What --list-machines and --list-dialects print of the shipped files:
// every one, in the listing order, read from resources/ itself.
QString shippedListing(const QString& folder, const QStringList& stems, const std::vector<const char*>& keys)
{
    QString out;
    for (const QString& stem : stems) {
        const json j = json::parse(readFile(sourcePath("resources/" + folder + "/" + stem + ".json")));
        for (const char* key : keys) out += QString::fromStdString(j.at(key).get<std::string>()) + '\t';
        out += "built in: " + folder + "/" + stem + ".json\n";
    }
    return out;
}

}  // namespace

class TestCli : public QObject {
    Q_OBJECT
    // `job` with `value` put at `pointer`, written to `file`: `taiwa check`
    // refuses it with a first line starting with `prefix`.
    static void expectRefused(json job, const QString& pointer, const QString& value, const QString& prefix,
                              const QString& file)
    {
        job[json::json_pointer(pointer.toStdString())] = json::parse(value.toStdString());
        writeFile(file, job.dump(2));
        const auto r = runTaiwa({"check", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith(prefix), qPrintable(r.err));
    }

private slots:
    void versionAndHelp()
    {
        const auto v = runTaiwa({"--version"});
        QCOMPARE(v.exitCode, 0);
        QVERIFY(v.out.startsWith("taiwa "));
        const auto h = runTaiwa({"--help"});
        QCOMPARE(h.exitCode, 0);
        for (const char* word : {"check JOB", "export JOB", "render JOB", "--dialect", "--units"})
            QVERIFY2(h.out.contains(QLatin1String(word)), word);
    }

    void badArgumentsAreInputErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no job") << QStringList{"check"} << "no job file given";
        QTest::newRow("unknown option") << QStringList{"check", "a.taiwa", "--frobnicate"} << "unknown option '--frobnicate'";
        QTest::newRow("export without out") << QStringList{"export", "a.taiwa"} << "--out is required";
        QTest::newRow("bad dialect") << QStringList{"export", "a.taiwa", "--out", "x", "--dialect", "heidenhain-klartext"}
                                     << "unknown dialect 'heidenhain-klartext'";
        QTest::newRow("bad units") << QStringList{"export", "a.taiwa", "--out", "x", "--units", "cubits"} << "--units is mm or inch";
        QTest::newRow("bad size") << QStringList{"render", "a.taiwa", "--out", "x.png", "--size", "big"} << "--size wants";
    }
    void badArgumentsAreInputErrors()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const auto r = runTaiwa(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }

    void everySamplePassesCheck()
    {
        const QStringList files = samples();
        QVERIFY2(files.size() >= 10, "the samples are missing");
        for (const auto& f : files) {
            const auto r = runTaiwa({"check", f});
            QVERIFY2(r.exitCode == 0, qPrintable(f + ": " + r.err));
            // Nothing but the plan's notes (a relief groove no insert follows,
            // left; what drawn passes leave unswept, shown on purpose).
            for (const auto& line : r.err.split('\n', Qt::SkipEmptyParts))
                QVERIFY2(line.contains(": warning: ") &&
                             (line.contains("grinding allowance") || line.contains("(AREA) points: warning: the passes leave")),
                         qPrintable(f + ": " + line));
        }
    }

    // Each refusal of the spec: exit code 2 and the field named in the line
    // "JOB: unit N (MODULE) field: message".
    void refusalsNameTheField_data()
    {
        QTest::addColumn<QString>("pointer");  // JSON pointer into the base job
        QTest::addColumn<QString>("value");    // JSON text to put there
        QTest::addColumn<QString>("prefix");   // expected start of the stderr line
        const QString u = "bad.taiwa: unit 1 (M4) ";
        QTest::newRow("depth zero") << "/units/0/depth" << "0" << u + "depth:";
        QTest::newRow("depth negative") << "/units/0/depth" << "-3" << u + "depth:";
        QTest::newRow("three corners") << "/units/0/corners" << "[[20,20],[120,20],[120,80]]" << u + "corners";
        QTest::newRow("duplicate corner") << "/units/0/corners" << "[[20,20],[120,20],[120,20],[20,80]]" << u + "corners";
        QTest::newRow("self-intersecting") << "/units/0/corners" << "[[20,20],[120,80],[120,20],[20,80]]" << u + "corners";
        QTest::newRow("non-convex") << "/units/0/corners" << "[[20,20],[120,20],[60,40],[20,80]]" << u + "corners";
        QTest::newRow("r1 over half side") << "/units/0/cornerRadius" << "31" << u + "cornerRadius:";
        QTest::newRow("taper over 30") << "/units/0/taper" << "31" << u + "taper:";
        QTest::newRow("U undefined") << "/units/0/U" << "3" << u + "U:";
        QTest::newRow("F undefined") << "/units/0/F" << "4" << u + "F:";
        QTest::newRow("H undefined") << "/units/0/H" << "1" << u + "H:";
        QTest::newRow("missing tool") << "/units/0/tools" << "{\"roughing\": 9999}" << u + "tools.roughing:";
        QTest::newRow("alpha1 >= T") << "/technology" << "{\"alpha1\": 12}" << "bad.taiwa: job technology.alpha1:";
        QTest::newRow("beta2 >= T") << "/technology" << "{\"beta2\": 12}" << "bad.taiwa: job technology.beta2:";
        QTest::newRow("wrong type") << "/units/0/depth" << "\"deep\"" << u + "depth:";
        QTest::newRow("unknown material") << "/material" << "\"unobtainium\"" << "bad.taiwa: job material:";
    }
    void refusalsNameTheField()
    {
        QFETCH(QString, pointer);
        QFETCH(QString, value);
        QFETCH(QString, prefix);
        QTemporaryDir dir;
        const QString file = dir.filePath("bad.taiwa");
        expectRefused(baseJob(), pointer, value, prefix, file);
        // export refuses the same job and writes nothing
        const QString out = dir.filePath("out");
        const auto e = runTaiwa({"export", file, "--out", out});
        QCOMPARE(e.exitCode, 2);
        QVERIFY(!QFileInfo::exists(out) || QDir(out).isEmpty());
    }

    void overlappingFiguresAreRefusedTouchingAreNot()
    {
        json job = baseJob();
        json second = job["units"][0];
        second["corners"] = json::parse("[[120,20],[180,20],[180,80],[120,80]]");  // shares the edge x = 120
        job["units"].push_back(second);
        QTemporaryDir dir;
        const QString file = dir.filePath("two.taiwa");
        writeFile(file, job.dump());
        QCOMPARE(runTaiwa({"check", file}).exitCode, 0);
        job["units"][1]["corners"] = json::parse("[[110,20],[180,20],[180,80],[110,80]]");
        writeFile(file, job.dump());
        const auto r = runTaiwa({"check", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("unit 2 (M4)") || r.err.contains("unit 1 (M4)"), qPrintable(r.err));
    }

    // The job's own dialect (format version 2): exported without --dialect,
    // overridden by it; an unknown one, or one whose controller lacks the
    // job's work offset, is refused on input.
    void theJobsDialectIsExported()
    {
        json job = baseJob();
        job["version"] = 2;
        job["dialect"] = "fanuc";
        QTemporaryDir dir;
        const QString file = dir.filePath("fanuc-job.taiwa");
        writeFile(file, job.dump());
        QCOMPARE(runTaiwa({"export", file, "--out", dir.filePath("a")}).exitCode, 0);
        QVERIFY(readFile(dir.filePath("a/fanuc-job.nc")).starts_with("%\nO1000"));
        QCOMPARE(runTaiwa({"export", file, "--out", dir.filePath("b"), "--dialect", "linuxcnc"}).exitCode, 0);
        QVERIFY(!readFile(dir.filePath("b/fanuc-job.nc")).starts_with("%"));
        job["dialect"] = "mazatrol";
        writeFile(file, job.dump());
        auto r = runTaiwa({"check", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("job dialect: unknown dialect 'mazatrol'; this program posts " + shippedDialects().join(", ")),
                 qPrintable(r.err));
        job["dialect"] = "fanuc";
        job["workOffset"] = "G59.1";
        writeFile(file, job.dump());
        r = runTaiwa({"check", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("workOffset") && r.err.contains("fanuc"), qPrintable(r.err));
    }

    void corruptFilesAreRefusedCleanly_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("truncated") << QByteArray("{\"format\": \"taiwa-job\", \"version\": 1, \"units\": [{\"mod");
        QTest::newRow("not json") << QByteArray("G0 X10 Y10\nM30\n");
        QTest::newRow("binary") << QByteArray("\x00\xff\xfe\x13\x37", 5);
        QTest::newRow("future version") << QByteArray("{\"format\": \"taiwa-job\", \"version\": 99, \"units\": []}");
    }
    void corruptFilesAreRefusedCleanly()
    {
        QFETCH(QByteArray, content);
        QTemporaryDir dir;
        const QString file = dir.filePath("corrupt.taiwa");
        writeFile(file, content.toStdString());
        const auto r = runTaiwa({"check", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("corrupt.taiwa: "), qPrintable(r.err));
    }

    void hugeFileIsRefusedBySize()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath("huge.taiwa");
        QFile f(file);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QVERIFY(f.resize(100LL * 1024 * 1024));  // 100 MB, sparse
        f.close();
        const auto r = runTaiwa({"check", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("huge.taiwa: "), qPrintable(r.err));
    }

    void missingFileIsAnInputError()
    {
        const auto r = runTaiwa({"check", "/nonexistent/nothing.taiwa"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("nothing.taiwa: "), qPrintable(r.err));
    }

    // Lathe jobs: the refusals of a turned profile and of the bar, each on
    // its field; machine and stock of different kinds refused.
    void latheRefusalsNameTheField_data()
    {
        QTest::addColumn<QString>("pointer");
        QTest::addColumn<QString>("value");
        QTest::addColumn<QString>("prefix");
        const QString u = "bad.taiwa: unit 1 (TURN) ";
        QTest::newRow("diameter below zero") << "/units/0/rows/1/x" << "-30" << u + "rows[2].x: row 2: the end diameter is -30 mm";
        QTest::newRow("radius cannot reach") << "/units/0/rows/1"
                                             << R"({"id": 2, "kind": "cw", "x": 30, "z": -40, "radius": 5})"
                                             << u + "rows[2].radius: row 2: a radius of 5 mm cannot reach the end point";
        QTest::newRow("not one chain") << "/units/0/rows/6" << R"({"id": 7, "kind": "line", "x": 20, "z": 5})"
                                       << u + "rows[7].x: the profile is not one chain: E7 (row 7) meets";
        QTest::newRow("edge not there") << "/units/0/allowances/0/edge" << "\"E42\""
                                        << u + "allowances[1].edge: allowance row 1: there is no edge E42 in the profile";
        QTest::newRow("groove too wide") << "/units/0/allowances/0/grooveWidth" << "40"
                                         << u + "allowances[1].grooveWidth: allowance row 1: a lateral groove 40 mm wide";
        QTest::newRow("groove too deep") << "/units/0/allowances/0/grooveDepth" << "16"
                                         << u + "allowances[1].grooveDepth: allowance row 1: a groove 16 mm deep at E3 reaches the axis";
        QTest::newRow("edges would cross") << "/units/0/allowances/0/allowance" << "6"
                                           << u + "allowances[1].allowance: allowance row 1: an allowance of 6 mm on E3 reaches past the end of its neighbour E4";
        QTest::newRow("profile beyond the bar") << "/stock/diameter" << "42"
                                                << u + "rows: the profile with its grinding allowances reaches Ø46 mm, more than the bar's Ø42 mm";
        QTest::newRow("bore wider than the bar") << "/stock/bore" << "50" << "bad.taiwa: job stock.bore: the bar's bore is Ø50 mm";
        QTest::newRow("bar beyond the spindle") << "/stock/diameter" << "80"
                                                << "bad.taiwa: job stock.diameter: a bar of Ø80 mm does not pass the spindle of machine lathe";
        QTest::newRow("bar on a mill") << "/machine" << "\"vmc\"" << "bad.taiwa: job stock.shape: a bar is stock for a lathe";
        QTest::newRow("unknown machine") << "/machine" << "\"vtl\"" << "bad.taiwa: job machine: unknown machine 'vtl'";
        QString many = "[";
        for (int i = 1; i <= 1001; ++i) many += QString("%1{\"id\": %2, \"x\": %3, \"z\": %4}").arg(i > 1 ? "," : "").arg(i).arg(10 + i % 2).arg(-i);
        QTest::newRow("too many rows") << "/units/0/rows" << many + "]"
                                       << u + "rows: the profile table has 1001 rows; a turned profile has at most 1000";
    }
    void latheRefusalsNameTheField()
    {
        QFETCH(QString, pointer);
        QFETCH(QString, value);
        QFETCH(QString, prefix);
        QTemporaryDir dir;
        expectRefused(json::parse(readFile(sourcePath("resources/samples/lathe-shaft-grinding.taiwa"))), pointer, value,
                      prefix, dir.filePath("bad.taiwa"));
    }

    // Machines as data: the shipped ones listed with their source; a shop's
    // own file in the config folder replaces one or adds one; a broken one
    // is left out naming file, line and key, the shipped ones keep working.
    void machinesAreDataTheShopCanEdit()
    {
        QTemporaryDir config;
        const QStringList env{"XDG_CONFIG_HOME=" + config.path()};
        auto r = runTaiwa({"--list-machines"}, env);
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out, shippedListing("machines", shippedMachines(), {"id", "kind", "name"}));
        QVERIFY(r.out.contains("vmc\tmill\tVertical machining centre\tbuilt in: machines/vmc.json\n"));
        const QString folder = config.filePath("taiwa/machines");
        QVERIFY(QDir().mkpath(folder));
        json big = json::parse(readFile(sourcePath("resources/machines/lathe.json")));
        big["id"] = "lathe";
        big["name"] = "Big-bore lathe";
        big["chuck"]["maxBarDiameter"] = 100;
        writeFile(folder + "/lathe.json", big.dump(2));
        json broken = json::parse(readFile(sourcePath("resources/machines/vmc.json")));
        broken["id"] = "hmc";
        broken["maxSpindleSpeed"] = -5;
        writeFile(folder + "/hmc.json", broken.dump(2));
        writeFile(folder + "/notes.json", "{ \"format\": \"taiwa-machine\",\n  \"version\": 1,\n  oops }\n");
        r = runTaiwa({"--list-machines"}, env);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("lathe\tlathe\tBig-bore lathe\t" + folder + "/lathe.json\n"), qPrintable(r.out));
        QVERIFY(r.out.startsWith("vmc\tmill\tVertical machining centre\tbuilt in"));
        QVERIFY(!r.out.contains("hmc"));
        const QStringList err = r.err.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(err.size(), 2);
        QVERIFY2(err[0].startsWith("taiwa: " + folder + "/hmc.json:") && err[0].contains(": maxSpindleSpeed: must be a number above zero (left out; the shipped machines stay)"),
                 qPrintable(err[0]));
        QCOMPARE(err[1], "taiwa: " + folder + "/notes.json:3: not valid JSON (left out; the shipped machines stay)");
        // The shop's lathe takes a Ø80 bar the shipped one refuses.
        json job = json::parse(readFile(sourcePath("resources/samples/lathe-shaft-grinding.taiwa")));
        job["stock"]["diameter"] = 80;
        QTemporaryDir dir;
        writeFile(dir.filePath("big.taiwa"), job.dump(2));
        QCOMPARE(runTaiwa({"check", dir.filePath("big.taiwa"), "--tools", dir.filePath("t.sqlite")}, env).exitCode, 0);
        QCOMPARE(runTaiwa({"check", dir.filePath("big.taiwa"), "--tools", dir.filePath("t.sqlite")}, {"XDG_CONFIG_HOME=" + dir.path()}).exitCode, 2);
    }

    // Dialects as data: a shop's own file posts a program the way it says
    // (a FANUC-like control without the % framing, under a name of its own);
    // a broken one is refused naming file, line and key.
    void dialectsAreDataTheShopCanEdit()
    {
        QTemporaryDir config;
        const QStringList env{"XDG_CONFIG_HOME=" + config.path()};
        auto r = runTaiwa({"--list-dialects"}, env);
        QCOMPARE(r.out, shippedListing("dialects", shippedDialects(), {"name", "description"}));
        QVERIFY(r.out.startsWith("fanuc\tFANUC 0i/30i-style ISO G-code (machining centre)\tbuilt in: dialects/fanuc.json\n"));
        const QString folder = config.filePath("taiwa/dialects");
        QVERIFY(QDir().mkpath(folder));
        json shop = json::parse(readFile(sourcePath("resources/dialects/fanuc.json")));
        shop["name"] = "shop-fanuc";
        shop["description"] = "our old control";
        shop["percentFraming"] = false;
        writeFile(folder + "/shop.json", shop.dump(2));
        json bad = shop;
        bad["name"] = "bad";
        bad["toolChange"] = "T{tol} M6";
        writeFile(folder + "/bad.json", bad.dump(2));
        r = runTaiwa({"--list-dialects"}, env);
        QVERIFY2(r.out.endsWith("shop-fanuc\tour old control\t" + folder + "/shop.json\n"), qPrintable(r.out));
        QVERIFY2(r.err.startsWith("taiwa: " + folder + "/bad.json:") &&
                     r.err.contains(": toolChange: not a template this program can fill"),
                 qPrintable(r.err));
        QTemporaryDir out;
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        r = runTaiwa({"export", job, "--out", out.filePath("shop"), "--dialect", "shop-fanuc"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runTaiwa({"export", job, "--out", out.filePath("fanuc"), "--dialect", "fanuc"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const std::string shopTape = readFile(out.filePath("shop/m4-standard.nc"));
        const std::string fanucTape = readFile(out.filePath("fanuc/m4-standard.nc"));
        QVERIFY(fanucTape.starts_with("%\n"));
        QVERIFY(shopTape.starts_with("O1000 (COVER PLATE: STANDARD POCKET)\n"));
        QVERIFY(shopTape.find("DIALECT SHOP-FANUC") != std::string::npos);
        // Without the shop's folder the name is unknown.
        r = runTaiwa({"export", job, "--out", out.filePath("x"), "--dialect", "shop-fanuc"});
        QCOMPARE(r.exitCode, 2);
    }

    void millingModuleOnALatheIsRefused()
    {
        json job = json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
        job["machine"] = "lathe";
        job["stock"] = {{"shape", "bar"}, {"diameter", 50}, {"length", 100}};
        QTemporaryDir dir;
        const QString file = dir.filePath("mixed.taiwa");
        writeFile(file, job.dump(2));
        const auto r = runTaiwa({"check", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("mixed.taiwa: unit 1 (M4) module: module M4 runs on a mill; this job's machine lathe is a lathe"),
                 qPrintable(r.err));
    }

    // The operator's S and F per step kind of a unit ("cutting") reach the
    // tape in place of the tool's cutting data, marked on the sheet; on a
    // lathe F is per revolution and S a surface speed (drills: rpm); keys
    // that are no step of the module, values out of the machine's range and
    // a PROBE unit's "cutting" are refused naming the field.
    void cuttingOverridesReachTheTape()
    {
        QTemporaryDir dir;
        json lathe = json::parse(readFile(sourcePath("resources/samples/lathe-turned-shaft.taiwa")));
        lathe["units"][0]["cutting"] = {{"turn-finish", {{"S", 180}, {"F", 0.08}}}, {"part", {{"F", 0.04}}}};
        writeFile(dir.filePath("lathe.taiwa"), lathe.dump(2));
        auto r = runTaiwa({"export", dir.filePath("lathe.taiwa"), "--out", dir.filePath("l"), "--dialect", "fanuc"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString tape = QString::fromStdString(readFile(dir.filePath("l/lathe.nc")));
        const qsizetype finishing = tape.indexOf("TURN FINISHING");
        QVERIFY(finishing > 0);
        QVERIFY2(tape.indexOf("G96 S180 M3", finishing) > 0 && tape.indexOf(" F0.08\n", finishing) > 0, qPrintable(tape.mid(finishing, 400)));
        QVERIFY(tape.indexOf(" F0.04\n", tape.indexOf("PARTING")) > 0);
        const QString sheet = QString::fromStdString(readFile(dir.filePath("l/lathe.sheet.html")));
        QVERIFY2(sheet.contains("vc 180*") && sheet.contains("S or F set by the operator"), qPrintable(sheet.left(200)));

        json bad = json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
        bad["units"][0]["cutting"] = {{"rough", {{"S", 8000}}}, {"wall", {{"S", 20000}, {"F", 20000}}}, {"floor", {{"F", 0.5}}}};
        writeFile(dir.filePath("bad.taiwa"), bad.dump(2));
        r = runTaiwa({"check", dir.filePath("bad.taiwa")});
        QCOMPARE(r.exitCode, 2);
        for (const char* expected : {
                 "bad.taiwa: unit 1 (M4) cutting.rough: \"rough\" is not a step of module M4; its steps are pilot, roughing, floor, wall, inclined",
                 "bad.taiwa: unit 1 (M4) cutting.wall.S: the spindle speed S 20000 rpm is out of range: give 1 to 12000 rpm (the spindle limit of vmc)",
                 "bad.taiwa: unit 1 (M4) cutting.wall.F: the feed F 20000 mm/min is out of range: give 1 to 10000 mm/min (the feed limit of vmc)",
                 "bad.taiwa: unit 1 (M4) cutting.floor.F: the feed F 0.5 mm/min is out of range"})
            QVERIFY2(r.err.contains(expected), qPrintable(r.err));
        json probe = json::parse(readFile(sourcePath("resources/samples/probe-bore.taiwa")));
        probe["units"][0]["cutting"] = {{"roughing", {{"S", 1000}}}};
        writeFile(dir.filePath("probe.taiwa"), probe.dump(2));
        r = runTaiwa({"check", dir.filePath("probe.taiwa")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("cutting"), qPrintable(r.err));
        json empty = json::parse(readFile(sourcePath("resources/samples/m4-standard.taiwa")));
        empty["units"][0]["cutting"] = {{"roughing", json::object()}};
        writeFile(dir.filePath("empty.taiwa"), empty.dump(2));
        r = runTaiwa({"check", dir.filePath("empty.taiwa")});
        QVERIFY2(r.exitCode == 2 && r.err.contains("unit 1 (M4) cutting.roughing: give S, F or both"), qPrintable(r.err));
    }

    // What a dialect does not write is refused by name, on the job's dialect
    // (check) and on --dialect (export, nothing written): a lathe tape in
    // HEIDENHAIN's Klartext, a probing unit's programs for Siemens or
    // HEIDENHAIN; a tape is the control's own kind of file. A shop's dialect with a syntax this
    // program has no writer for is left out naming file, line and key.
    void millingOnlyDialectsRefuseLatheAndProbing()
    {
        QTemporaryDir dir;
        const QString lathe = sourcePath("resources/samples/lathe-turned-shaft.taiwa");
        auto r = runTaiwa({"export", lathe, "--out", dir.filePath("l"), "--dialect", "heidenhain"});
        QCOMPARE(r.exitCode, 2);  // a refusal by design, as when the job names the dialect (issue 39)
        QVERIFY2(r.err.contains("the heidenhain dialect writes no lathe tapes (Klartext is a milling control's language); " +
                                shippedDialectsWriting(DialectWrites::LatheTapes).join(", ") + " can; nothing was written"),
                 qPrintable(r.err));
        QVERIFY(!QDir(dir.filePath("l")).exists() || QDir(dir.filePath("l")).isEmpty());
        json probe = json::parse(readFile(sourcePath("resources/samples/probe-bore.taiwa")));
        probe["dialect"] = "heidenhain";
        writeFile(dir.filePath("probe.taiwa"), probe.dump(2));
        r = runTaiwa({"check", dir.filePath("probe.taiwa")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("job dialect: the heidenhain dialect writes no probing unit's programs; " +
                                shippedDialectsWriting(DialectWrites::ProbingPrograms).join(", ") + " can"),
                 qPrintable(r.err));
        r = runTaiwa({"export", sourcePath("resources/samples/probe-bore.taiwa"), "--out", dir.filePath("p"), "--dialect", "heidenhain"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("writes no probing unit's programs"), qPrintable(r.err));
        r = runTaiwa({"export", lathe, "--out", dir.filePath("s"), "--dialect", "sinumerik"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(readFile(dir.filePath("s/lathe-turned-shaft.mpf")).find("G18 DIAMON G710") != std::string::npos);
        r = runTaiwa({"export", sourcePath("resources/samples/m4-standard.taiwa"), "--out", dir.filePath("m"), "--dialect", "heidenhain"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(readFile(dir.filePath("m/m4-standard.h")).starts_with("0 BEGIN PGM m4-standard MM\n"));
        QVERIFY(!QFileInfo::exists(dir.filePath("m/m4-standard.nc")));

        QTemporaryDir config;
        const QString folder = config.filePath("taiwa/dialects");
        QVERIFY(QDir().mkpath(folder));
        json bad = json::parse(readFile(sourcePath("resources/dialects/sinumerik.json")));
        bad["name"] = "mazak";
        bad["syntax"] = "mazatrol";
        writeFile(folder + "/mazak.json", bad.dump(2));
        json range = json::parse(readFile(sourcePath("resources/dialects/sinumerik.json")));
        range["name"] = "siemens-old";
        range["moreWorkOffsets"] = json::array({"G505-G599"});
        writeFile(folder + "/old.json", range.dump(2));
        r = runTaiwa({"--list-dialects"}, {"XDG_CONFIG_HOME=" + config.path()});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("sinumerik\t") && !r.out.contains("mazak") && !r.out.contains("siemens-old"), qPrintable(r.out));
        QVERIFY2(r.err.contains(QRegularExpression(QRegularExpression::escape(folder + "/mazak.json:") +
                                                   "[0-9]+: syntax: must be \"iso\", \"sinumerik\" or \"klartext\"")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(folder + "/old.json:") &&
                     r.err.contains(": moreWorkOffsets: 'G505-G599' is neither a G code (\"G59.1\") nor a range (\"G505..G599\")"),
                 qPrintable(r.err));
    }

    // A lathe job exports the five files: the lathe tape (G18, diameters,
    // feed per revolution) beside the sheet and steps.json with the profile;
    // for LinuxCNC (the default dialect) a sixth, the tape's tool table.
    void latheExportWritesTheLatheTape()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const auto r = runTaiwa({"export", sourcePath("resources/samples/lathe-shaft-grinding.taiwa"), "--out", out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList expected{"lathe-shaft-grinding.nc", "lathe-shaft-grinding.sheet.html", "lathe-shaft-grinding.sheet.pdf",
                                   "lathe-shaft-grinding.steps.json", "lathe-shaft-grinding.tape.txt", "lathe-shaft-grinding.tbl"};
        QCOMPARE(QDir(out).entryList(QDir::Files, QDir::Name), expected);
        const std::string nc = readFile(QDir(out).filePath("lathe-shaft-grinding.nc"));
        QVERIFY(nc.find("G18 G7 G21 G40 G80 G90 G54 G95") != std::string::npos);
        QVERIFY(nc.find("G96 D4500 S") != std::string::npos);  // constant surface speed under the lathe's limit
        QVERIFY(nc.find("G42 G1") != std::string::npos && nc.find("G40 G1") != std::string::npos);
        const std::string html = readFile(QDir(out).filePath("lathe-shaft-grinding.sheet.html"));
        QVERIFY(html.find("<h2>Grinding allowances</h2>") != std::string::npos);
        QVERIFY(html.find("<td>Ra 0.4, h6</td>") != std::string::npos);  // the seat's attributes, on its row and its moved edge
        QVERIFY(html.find("lateral 2.000 x 0.300 in E3 (identified: E3 runs along the spindle axis)") != std::string::npos);
        const json steps = json::parse(readFile(QDir(out).filePath("lathe-shaft-grinding.steps.json")));
        const auto& moved = steps["turnedProfiles"][0]["deformed"][3];
        QCOMPARE(moved["id"].get<std::string>(), std::string("E3.moved"));
        QCOMPARE(moved["start"][0].get<double>(), 30.6);  // Ø30 h6 + 2 x 0.3
        QCOMPARE(moved["tolerance"].get<std::string>(), std::string("h6"));
    }

    void exportWritesTheFiveFiles()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("out");
        const auto r = runTaiwa({"export", sourcePath("resources/samples/m4-standard.taiwa"), "--out", out});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList expected{"m4-standard.nc", "m4-standard.sheet.html", "m4-standard.sheet.pdf",
                                   "m4-standard.steps.json", "m4-standard.tape.txt"};
        QCOMPARE(QDir(out).entryList(QDir::Files, QDir::Name), expected);  // no temporary files left
        for (const auto& f : expected) QVERIFY2(QFileInfo(QDir(out).filePath(f)).size() > 100, qPrintable(f));
        QVERIFY(r.out.contains(out));
        const json steps = json::parse(readFile(QDir(out).filePath("m4-standard.steps.json")));
        QVERIFY(steps["steps"].size() >= 3);
        for (const auto& s : steps["steps"]) {
            QVERIFY(s.contains("tool"));
            QVERIFY(s["pathLength"]["feed"].get<double>() > 0);
            QVERIFY(s["minutes"].get<double>() > 0);
        }
    }

    // The job's work offset is the tape's (it once always said G54); one the
    // chosen controller lacks stops the export with what it offers, nothing written.
    void exportSelectsTheJobsWorkOffset()
    {
        QTemporaryDir dir;
        json job = baseJob();
        job["workOffset"] = "G57";
        const QString file = dir.filePath("g57.taiwa");
        writeFile(file, job.dump());
        for (const char* dialect : {"linuxcnc", "fanuc"}) {
            const QString out = dir.filePath(QString("out-") + dialect);
            const auto r = runTaiwa({"export", file, "--out", out, "--dialect", dialect});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const QString nc = QString::fromStdString(readFile(QDir(out).filePath("g57.nc")));
            QVERIFY2(nc.contains(QRegularExpression("\\bG0 G57 X")) && !nc.contains("G54"), qPrintable(nc.left(600)));
        }
        job["workOffset"] = "G54.1 P3";
        writeFile(file, job.dump());
        const auto fanuc = runTaiwa({"export", file, "--out", dir.filePath("out-p3"), "--dialect", "fanuc"});
        QVERIFY2(fanuc.exitCode == 0, qPrintable(fanuc.err));
        QVERIFY(QString::fromStdString(readFile(dir.filePath("out-p3/g57.nc"))).contains(" G0 G54.1 P3 X"));
        const QString out = dir.filePath("out-refused");
        const auto lcnc = runTaiwa({"export", file, "--out", out, "--dialect", "linuxcnc"});
        QCOMPARE(lcnc.exitCode, 2);
        QVERIFY2(lcnc.err.contains("g57.taiwa: job workOffset: work offset 'G54.1 P3' cannot be posted for linuxcnc") &&
                     lcnc.err.contains("G59.1, G59.2 and G59.3"),
                 qPrintable(lcnc.err));
        QVERIFY(!QFileInfo::exists(out));
        // What no controller has is refused by the check itself.
        job["workOffset"] = "G99";
        writeFile(file, job.dump());
        const auto check = runTaiwa({"check", file});
        QCOMPARE(check.exitCode, 2);
        QVERIFY2(check.err.contains("g57.taiwa: job workOffset: 'G99' is not a work offset"), qPrintable(check.err));
    }

    void optionsAreGivenOnceAndNotEmpty()
    {
        const QString job = sourcePath("resources/samples/m4-standard.taiwa");
        QTemporaryDir dir;
        const auto twice = runTaiwa({"export", job, "--out", dir.filePath("a"), "--out", dir.filePath("b")});
        QCOMPARE(twice.exitCode, 2);
        QVERIFY2(twice.err.contains("option --out is given twice"), qPrintable(twice.err));
        QVERIFY(!QFileInfo::exists(dir.filePath("a")) && !QFileInfo::exists(dir.filePath("b")));
        const auto empty = runTaiwa({"check", job, "--tools", ""});
        QCOMPARE(empty.exitCode, 2);
        QVERIFY2(empty.err.contains("option --tools needs a value, not an empty one"), qPrintable(empty.err));
        const auto huge = runTaiwa({"render", job, "--out", dir.filePath("x.png"), "--size", "8192x8192"});
        QCOMPARE(huge.exitCode, 2);
        QVERIFY2(huge.err.contains("larger than 4096x4096"), qPrintable(huge.err));
        const auto noFolder = runTaiwa({"render", job, "--out", dir.filePath("no/such/x.png")});
        QCOMPARE(noFolder.exitCode, 1);
        QVERIFY2(noFolder.err.contains("no folder") && !noFolder.err.contains("disk space"), qPrintable(noFolder.err));
    }

    void wholeNumbersFollowOneRule()
    {
        // "version": 1.0 was refused while "U": 1.0 was accepted: 1.0 is the whole number 1 in both.
        QTemporaryDir dir;
        json job = baseJob();
        job["version"] = 1.0;
        job["units"][0]["U"] = 1.0;
        const QString file = dir.filePath("whole.taiwa");
        writeFile(file, job.dump());
        const auto ok = runTaiwa({"check", file});
        QVERIFY2(ok.exitCode == 0, qPrintable(ok.err));
        job["version"] = 1.5;
        writeFile(file, job.dump());
        const auto half = runTaiwa({"check", file});
        QCOMPARE(half.exitCode, 2);
        QVERIFY2(half.err.contains("job version:"), qPrintable(half.err));
    }

    void toolLibraryThatCannotBeOpenedIsReported()
    {
        QTemporaryDir dir;
        const QString db = dir.filePath("tools.sqlite");
        writeFile(db, std::string(4096, 'x'));
        const auto r = runTaiwa({"check", sourcePath("resources/samples/m4-standard.taiwa")}, {"TAIWA_TOOL_DB=" + db});
        QCOMPARE(r.exitCode, 2);  // the shop's data refused, as a job is: an input error
        QVERIFY2(r.err.contains("tool library") && r.err.contains(db) && r.err.contains("nothing was written"),
                 qPrintable(r.err));
        const auto folder = runTaiwa({"export", sourcePath("resources/samples/m4-standard.taiwa"), "--out",
                                      dir.filePath("out"), "--tools", dir.path()});
        QCOMPARE(folder.exitCode, 2);
        QVERIFY2(folder.err.contains("is a folder, not a tool library"), qPrintable(folder.err));
        QVERIFY(!QFileInfo::exists(dir.filePath("out")));
        QCOMPARE(readFile(db), std::string(4096, 'x'));  // the operator's file is not overwritten
    }
};

QTEST_APPLESS_MAIN(TestCli)
#include "test_cli.moc"
