// The shop server on the command line, against a PostgreSQL 15 the test
// starts itself (support/pg_server.h; skipped, saying so, where the
// binaries are absent): `taiwa export --from-store NAME` (the stored
// plate.taiwa exported as from its file, and the refusals: no such job, a
// tool setting that is a file, both a file and --from-store); `taiwa
// import-tools`; `taiwa store list` and `taiwa store history NAME`; and the
// sheet saying where its tools came from (the server's library, or its copy
// while the server is away); `taiwa store locks` and `taiwa store unlock`.
#include "support/pg_server.h"
#include "support/support.h"
#include "tools/pg_job_store.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <sqlite3.h>

using namespace taiwa;
using taiwa::test::PgServer;
using taiwa::test::runTaiwa;

namespace {

// The text of a PDF (pdftotext), its white space made single spaces.
QString pdfText(const QString& pdf)
{
    QProcess p;
    p.start("pdftotext", {pdf, "-"});
    if (!p.waitForFinished(60000)) return {};
    return QString::fromUtf8(p.readAllStandardOutput()).simplified();
}

// When the station's copy of the server's library was taken (its table server_copy).
QString copyTakenAt(const QString& path)
{
    sqlite3* db = nullptr;
    QString at;
    sqlite3_stmt* s = nullptr;
    if (sqlite3_open_v2(path.toUtf8().constData(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK &&
        sqlite3_prepare_v2(db, "SELECT synced_at FROM server_copy", -1, &s, nullptr) == SQLITE_OK && sqlite3_step(s) == SQLITE_ROW)
        at = QString::fromUtf8(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)));
    sqlite3_finalize(s);
    sqlite3_close(db);
    return at;
}

}  // namespace

class TestCliFromStore : public QObject {
    Q_OBJECT
private slots:
    void exportsTheStoredJob()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        const QStringList env{"TAIWA_TOOL_DB=" + QString::fromStdString(server.uri()), "XDG_DATA_HOME=" + home.path(), "TAIWA_STATION=office"};
        QFile plate(test::sourcePath("resources/samples/plate.taiwa"));
        QVERIFY(plate.open(QIODevice::ReadOnly));
        {
            auto store = PgToolStore::open(server.uri(), {home.filePath("copy.sqlite").toStdString(), "office", 3});
            QVERIFY2(store, store.ok() ? "" : store.error().c_str());
            PgJobStore jobs(**store);
            QCOMPARE(*jobs.save("plate", "not a job"), 1);
            QCOMPARE(*jobs.save("plate", plate.readAll().toStdString()), 2);
        }
        const QString out = home.filePath("out");
        const auto r = runTaiwa({"export", "--from-store", "plate", "--out", out, "--no-pictures"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        for (const char* f : {"plate.nc", "plate.sheet.html", "plate.steps.json"}) QVERIFY2(QFile::exists(QDir(out).filePath(f)), f);
        // The same tape as exporting the file itself.
        const QString fromFile = home.filePath("file");
        QCOMPARE(runTaiwa({"export", test::sourcePath("resources/samples/plate.taiwa"), "--out", fromFile, "--no-pictures"}, env).exitCode, 0);
        QFile a(QDir(out).filePath("plate.nc")), b(QDir(fromFile).filePath("plate.nc"));
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());

        const auto missing = runTaiwa({"export", "--from-store", "nothing", "--out", home.filePath("none")}, env);
        QCOMPARE(missing.exitCode, 1);
        QVERIFY2(missing.err.contains("has no job 'nothing'"), qPrintable(missing.err));
        const auto file = runTaiwa({"export", "--from-store", "plate", "--out", home.filePath("none")},
                                   {"TAIWA_TOOL_DB=" + home.filePath("tools.sqlite")});
        QCOMPARE(file.exitCode, 1);
        QVERIFY2(file.err.contains("--from-store needs the shop server"), qPrintable(file.err));
        const auto both = runTaiwa({"export", "x.taiwa", "--from-store", "plate", "--out", home.filePath("none")}, env);
        QCOMPARE(both.exitCode, 2);
        QVERIFY2(both.err.contains("not both"), qPrintable(both.err));
    }

    // `taiwa import-tools FILE`: a station's SQLite library (made by a first
    // run, one tool renamed) becomes the server's, the file unchanged; the
    // refusals leave the server as it was.
    void importsAnSqliteLibrary()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        const QStringList env{"TAIWA_TOOL_DB=" + QString::fromStdString(server.uri()), "XDG_DATA_HOME=" + home.path(),
                              "TAIWA_STATION=office"};
        const QString lib = home.filePath("station.sqlite");
        QCOMPARE(runTaiwa({"check", test::sourcePath("resources/samples/plate.taiwa")}, {"TAIWA_TOOL_DB=" + lib}).exitCode, 0);
        {
            auto store = ToolLibrary::open(lib.toStdString());
            QVERIFY2(store, store.ok() ? "" : store.error().c_str());
            auto tools = store->tools();
            QVERIFY(tools && !tools->empty());
            Tool t = tools->front();
            t.name = "Renamed on the station";
            QVERIFY(store->save(t));
        }
        QFile before(lib);
        QVERIFY(before.open(QIODevice::ReadOnly));
        const QByteArray bytes = before.readAll();
        before.close();
        const auto r = runTaiwa({"import-tools", lib}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(" tools of " + lib + " are now the library of "), qPrintable(r.out));
        QFile after(lib);
        QVERIFY(after.open(QIODevice::ReadOnly));
        QCOMPARE(after.readAll(), bytes);
        auto store = PgToolStore::open(server.uri(), {home.filePath("copy.sqlite").toStdString(), "office", 3});
        QVERIFY2(store, store.ok() ? "" : store.error().c_str());
        auto tools = (*store)->tools();
        QVERIFY(tools && !tools->empty());
        QCOMPARE(QString::fromStdString(tools->front().name), QString("Renamed on the station"));

        // Refusals: no server named, not a library, no file.
        const auto toFile = runTaiwa({"import-tools", lib}, {"TAIWA_TOOL_DB=" + home.filePath("other.sqlite")});
        QCOMPARE(toFile.exitCode, 2);
        QVERIFY2(toFile.err.contains("not a server") && toFile.err.contains("nothing was changed"), qPrintable(toFile.err));
        const QString junk = home.filePath("junk.sqlite");
        test::writeFile(junk, std::string(4096, 'x'));
        const auto notLib = runTaiwa({"import-tools", junk}, env);
        QCOMPARE(notLib.exitCode, 2);
        QVERIFY2(notLib.err.contains("is not a tool library"), qPrintable(notLib.err));
        QCOMPARE(runTaiwa({"import-tools", home.filePath("none.sqlite")}, env).exitCode, 2);
        QCOMPARE(runTaiwa({"import-tools"}, env).exitCode, 2);
        auto still = (*store)->tools();
        QVERIFY(still && still->size() == tools->size());
    }

    // The sheet says where its tools came from: the server's library and the
    // time it was read; while the server is away, the time of the station's
    // copy; nothing for the station's own file (the goldens' case).
    void theSheetSaysWhereTheToolsCameFrom()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        const QString uri = QString::fromStdString(server.uri());
        const QStringList env{"TAIWA_TOOL_DB=" + uri, "XDG_DATA_HOME=" + home.path(), "XDG_CACHE_HOME=" + home.filePath("cache"),
                              "TAIWA_STATION=machine-2"};
        const QString plate = test::sourcePath("resources/samples/plate.taiwa");
        const auto sheets = [&](const QString& dir) {
            return std::pair{QString::fromStdString(test::readFile(QDir(dir).filePath("plate.sheet.html"))),
                             pdfText(QDir(dir).filePath("plate.sheet.pdf"))};
        };

        // Online (the first export also takes the station's copy).
        const QString online = home.filePath("online");
        auto r = runTaiwa({"export", plate, "--out", online, "--no-pictures"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QRegularExpression fromServer("Tools from the library of " + QRegularExpression::escape(uri) +
                                            " as of \\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ");
        auto [html, pdf] = sheets(online);
        QVERIFY2(html.contains(QRegularExpression("<p>" + fromServer.pattern() + "</p>")), qPrintable(html.left(3000)));
        QVERIFY2(pdf.contains(fromServer), qPrintable(pdf.left(3000)));
        QVERIFY(!html.contains("read-only copy"));

        // The server away: the copy, and its time.
        const QString takenAt = copyTakenAt(home.filePath("taiwa/tools-server-copy.sqlite"));
        QVERIFY2(!takenAt.isEmpty(), "the first export took no copy of the server's library");
        QVERIFY(server.stop());
        const QString away = home.filePath("away");
        r = runTaiwa({"export", plate, "--out", away, "--no-pictures"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString line = "Tools as of " + takenAt + " (server " + uri + " away, read-only copy)";
        std::tie(html, pdf) = sheets(away);
        QVERIFY2(html.contains("<p>" + line + "</p>"), qPrintable(html.left(3000)));
        QVERIFY2(pdf.contains(line), qPrintable(pdf.left(3000)));
        QVERIFY(!html.contains("Tools from the library"));

        // The station's own file: the sheet says nothing of its tools' origin.
        const QString own = home.filePath("own");
        r = runTaiwa({"export", plate, "--out", own, "--no-pictures"}, {"TAIWA_TOOL_DB=" + home.filePath("tools.sqlite"),
                                                                        "XDG_CACHE_HOME=" + home.filePath("cache")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        std::tie(html, pdf) = sheets(own);
        QVERIFY(html.contains("Process steps"));
        QVERIFY2(!html.contains("Tools as of") && !html.contains("Tools from the library"), qPrintable(html.left(3000)));
        QVERIFY(!pdf.contains("Tools as of") && !pdf.contains("Tools from the library"));
    }

    // `taiwa store list` and `taiwa store history NAME`: the jobs with their
    // newest version, who saved it where and when, and the lock's holder;
    // a job's versions; exit 2 with the reason for a bad name, a setting
    // that names no server, a server away and a wrong call.
    void listsTheStoreAndAJobsHistory()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        const QString uri = QString::fromStdString(server.uri());
        const QStringList env{"TAIWA_TOOL_DB=" + uri, "XDG_DATA_HOME=" + home.path(), "TAIWA_STATION=office"};
        {
            auto office = PgToolStore::open(server.uri(), {home.filePath("office.sqlite").toStdString(), "office", 3});
            auto machine = PgToolStore::open(server.uri(), {home.filePath("machine.sqlite").toStdString(), "machine-2", 3});
            QVERIFY(office && machine);
            PgJobStore atOffice(**office), atMachine(**machine);
            QCOMPARE(*atOffice.save("plate", "one"), 1);
            QCOMPARE(*atOffice.save("plate", "two"), 2);
            QCOMPARE(*atMachine.save("bracket", "three"), 1);
            QVERIFY(atMachine.lock("plate"));
        }
        const QString when = "\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ";
        auto r = runTaiwa({"store", "list"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList jobs = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(jobs.size(), 2);
        QVERIFY2(QRegularExpression("^bracket\t1\ttaiwa_admin\tmachine-2\t" + when + "\t-$").match(jobs[0]).hasMatch(), qPrintable(jobs[0]));
        QVERIFY2(QRegularExpression("^plate\t2\ttaiwa_admin\toffice\t" + when + "\topen at station machine-2 by taiwa_admin since " + when + "$")
                     .match(jobs[1])
                     .hasMatch(),
                 qPrintable(jobs[1]));

        r = runTaiwa({"store", "history", "plate"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList versions = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(versions.size(), 2);
        for (int v = 0; v < 2; ++v)
            QVERIFY2(QRegularExpression(QString("^%1\ttaiwa_admin\toffice\t").arg(v + 1) + when + "$").match(versions[v]).hasMatch(),
                     qPrintable(versions[v]));

        // Refused, exit 2, saying why.
        r = runTaiwa({"store", "history", "nothing"}, env);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(uri + " has no job 'nothing'") && r.out.isEmpty(), qPrintable(r.err));
        r = runTaiwa({"store", "list"}, {"TAIWA_TOOL_DB=" + home.filePath("tools.sqlite")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("store list: the job store needs the shop server") && r.err.contains("not a server"), qPrintable(r.err));
        for (const QStringList& call : {QStringList{"store"}, QStringList{"store", "remove"}, QStringList{"store", "history"},
                                        QStringList{"store", "list", "plate"}, QStringList{"store", "list", "--out", "x"}}) {
            r = runTaiwa(call, env);
            QVERIFY2(r.exitCode == 2 && r.err.contains("Try 'taiwa --help'"), qPrintable(call.join(' ') + ": " + r.err));
        }
        QVERIFY(server.stop());
        r = runTaiwa({"store", "list"}, env);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(uri + " cannot be reached") && r.out.isEmpty(), qPrintable(r.err));
        r = runTaiwa({"store", "history", "plate"}, env);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(uri + " cannot be reached"), qPrintable(r.err));
    }

    // `taiwa store locks` and `taiwa store unlock NAME [--force]`: the locks
    // with their holders and whether each holder is connected; a stale lock
    // (its station gone) released, saying whose it was and since when; a
    // connected station's lock refused, saying what --force means, and
    // released with it; the calls that are not one refused. The command
    // runs as a station's role, not the superuser: pg_stat_activity must
    // show it the other roles' stations.
    void releasesAStaleLockAndRefusesALiveOne()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        auto office = PgToolStore::open(server.uri(), {home.filePath("office.sqlite").toStdString(), "office", 3});
        QVERIFY2(office, office.ok() ? "" : office.error().c_str());
        QVERIFY2(server.psql(QString::fromStdString(test::readFile(test::sourcePath("resources/db/roles.sql")))), qPrintable(server.why()));
        QVERIFY(server.psql("CREATE ROLE foreman LOGIN IN ROLE taiwa_tool_reader, taiwa_job_writer"));
        const QString uri = QString::fromStdString(server.uri("foreman"));
        const QStringList env{"TAIWA_TOOL_DB=" + uri, "XDG_DATA_HOME=" + home.path(), "TAIWA_STATION=office"};
        PgJobStore atOffice(**office);
        QCOMPARE(*atOffice.save("plate", "one"), 1);
        QCOMPARE(*atOffice.save("bracket", "two"), 1);
        QCOMPARE(*atOffice.save("flange", "three"), 1);
        // machine-2 holds plate and stays connected; lathe-1 holds bracket and goes (a crash).
        auto machine = PgToolStore::open(server.uri(), {home.filePath("machine.sqlite").toStdString(), "machine-2", 3});
        QVERIFY(machine);
        PgJobStore atMachine(**machine);
        QVERIFY(atMachine.lock("plate"));
        {
            auto lathe = PgToolStore::open(server.uri(), {home.filePath("lathe.sqlite").toStdString(), "lathe-1", 3});
            QVERIFY(lathe);
            QVERIFY(PgJobStore(**lathe).lock("bracket"));
            const auto locks = atOffice.locks();
            QVERIFY(locks && locks->size() == 2 && (*locks)[0].stationConnected);  // lathe-1 still there
        }
        // Its session ends a moment after the connection is closed.
        QTRY_VERIFY_WITH_TIMEOUT(!atOffice.locks()->front().stationConnected, 5000);

        const QString when = "\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ";
        auto r = runTaiwa({"store", "locks"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList locks = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(locks.size(), 2);
        QVERIFY2(QRegularExpression("^bracket\tlathe-1\ttaiwa_admin\t" + when + "\tstation not connected$").match(locks[0]).hasMatch(),
                 qPrintable(locks[0]));
        QVERIFY2(QRegularExpression("^plate\tmachine-2\ttaiwa_admin\t" + when + "\tstation connected$").match(locks[1]).hasMatch(),
                 qPrintable(locks[1]));
        const QString plateSince = locks[1].split('\t')[3], bracketSince = locks[0].split('\t')[3];

        // The connected station's lock: refused, the holder and what --force means said, the lock kept.
        r = runTaiwa({"store", "unlock", "plate"}, env);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("taiwa: store unlock: job 'plate' is open at station machine-2 (by taiwa_admin since " + plateSince +
                                ") and that station is connected to the server now; its lock was not released. --force releases it "
                                "all the same: that station keeps the job open without the lock") &&
                     r.err.contains("nothing is overwritten") && r.out.isEmpty(),
                 qPrintable(r.err));
        QCOMPARE(QString::fromStdString(atOffice.list()->at(1).name), QString("flange"));
        QCOMPARE(QString::fromStdString(atOffice.list()->at(2).lockedStation), QString("machine-2"));
        QVERIFY(!atOffice.lock("plate"));

        // The stale one: released, saying whose it was; run at the crashed station
        // itself (its own session is not a connected holder).
        r = runTaiwa({"store", "unlock", "bracket"}, {"TAIWA_TOOL_DB=" + uri, "XDG_DATA_HOME=" + home.path(), "TAIWA_STATION=lathe-1"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.out, "taiwa: released the lock of job 'bracket' held by station lathe-1 (taiwa_admin) since " + bracketSince + "\n");
        QVERIFY(atOffice.list()->at(0).lockedStation.empty());
        QVERIFY(atOffice.lock("bracket"));  // free for another station now
        QVERIFY(atOffice.unlock("bracket"));
        r = runTaiwa({"store", "unlock", "bracket"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.startsWith("taiwa: job 'bracket' of postgresql://foreman@") && r.out.contains(" was not locked; nothing was changed"),
                 qPrintable(r.out));
        r = runTaiwa({"store", "unlock", "nothing"}, env);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("has no job 'nothing'") && r.out.isEmpty(), qPrintable(r.err));

        // Forced: released, and the station told it edits without the lock; its save still goes in as a version.
        r = runTaiwa({"store", "unlock", "plate", "--force"}, env);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(r.out, "taiwa: released the lock of job 'plate' held by station machine-2 (taiwa_admin) since " + plateSince +
                            "; the station is connected and now edits the job without the lock\n");
        QVERIFY(atOffice.list()->at(2).lockedStation.empty());
        QCOMPARE(*atMachine.save("plate", "four"), 2);
        QVERIFY(atOffice.lock("plate"));
        QVERIFY(!atMachine.save("plate", "five"));  // the office holds it now
        r = runTaiwa({"store", "locks"}, env);
        QVERIFY2(r.exitCode == 0 && r.out.startsWith("plate\toffice\t"), qPrintable(r.out));
        QVERIFY2(r.out.endsWith("\tstation connected\n"), qPrintable(r.out));  // this test's own connection as office

        for (const QStringList& call : {QStringList{"store", "unlock"}, QStringList{"store", "locks", "plate"},
                                        QStringList{"store", "list", "--force"}, QStringList{"store", "history", "plate", "--force"},
                                        QStringList{"store", "unlock", "plate", "bracket"}}) {
            r = runTaiwa(call, env);
            QVERIFY2(r.exitCode == 2 && r.err.contains("Try 'taiwa --help'"), qPrintable(call.join(' ') + ": " + r.err));
        }
        r = runTaiwa({"store", "unlock", "plate"}, {"TAIWA_TOOL_DB=" + home.filePath("tools.sqlite")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("store unlock: the job store needs the shop server"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliFromStore)
#include "test_cli_from_store.moc"
