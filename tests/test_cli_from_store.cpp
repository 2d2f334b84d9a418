// `taiwa export --from-store NAME` against a PostgreSQL 15 the test starts
// itself (support/pg_server.h; skipped, saying so, where the binaries are
// absent): the stored plate.taiwa exported as from its file, and the
// refusals (no such job, a tool setting that is a file, both a file and
// --from-store).
#include "support/pg_server.h"
#include "support/support.h"
#include "tools/pg_job_store.h"
#include "tools/tool_library.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using taiwa::test::PgServer;
using taiwa::test::runTaiwa;

class TestCliFromStore : public QObject {
    Q_OBJECT
private slots:
    void exportsTheStoredJob()
    {
        if (PgServer::binaries().isEmpty())
            QSKIP("no PostgreSQL 15 here (/usr/lib/postgresql/15/bin/pg_ctl is absent); packaging/install-deps.sh installs postgresql-15");
        PgServer server;
        QVERIFY2(server.start(), qPrintable(server.why()));
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
        if (PgServer::binaries().isEmpty())
            QSKIP("no PostgreSQL 15 here (/usr/lib/postgresql/15/bin/pg_ctl is absent); packaging/install-deps.sh installs postgresql-15");
        PgServer server;
        QVERIFY2(server.start(), qPrintable(server.why()));
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
};

QTEST_GUILESS_MAIN(TestCliFromStore)
#include "test_cli_from_store.moc"
