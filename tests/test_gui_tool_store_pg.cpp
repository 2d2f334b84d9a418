// The station's plan runner on the shop server (a PostgreSQL 15 the test
// starts itself, support/pg_server.h; skipped, saying so, where the
// binaries are absent): another station's change reaches it by NOTIFY
// within seconds, re-reads the library and says which tool and who; the
// server going away leaves it on its copy, read-only, saying "tools as of";
// a change committed while the runner reads the library (its notification
// then comes back with the read's answer, not on the socket) is read at
// once, not left waiting for the next notification.
// The tool library dialog saving over another station's change asks, both
// shown: keep mine saves mine, take theirs drops mine.
#include "support/pg_server.h"
#include "support/support.h"
#include "tools/pg_tool_store.h"
#include "tools/tool_library.h"
#include "ui/plan_runner.h"
#include "ui/tool_library_dialog.h"

#include <QApplication>
#include <QMessageBox>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;
using taiwa::test::PgServer;

namespace {

// Clicks `button` of the conflict's message box once it is shown (a timer
// polling from within the box's own event loop); `asked` gets its text.
void answerConflict(const char* button, QString* asked)
{
    auto* timer = new QTimer(qApp);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, button, asked] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget()); box && box->objectName() == "tools.conflict") {
            *asked = box->text();
            timer->deleteLater();
            timer->stop();
            box->findChild<QPushButton*>(button)->click();
        }
    });
    timer->start(50);
}

// This process as station machine-2 on `server`, its data in `home`.
void stationOn(const PgServer& server, const QTemporaryDir& home)
{
    test::isolateStation(home.path());
    qputenv("XDG_DATA_HOME", home.path().toLocal8Bit());
    qputenv("TAIWA_TOOL_DB", QByteArray::fromStdString(server.uri()));
    qputenv("TAIWA_STATION", "machine-2");
}

std::string nameOnServer(PgToolStore& store, int id)
{
    const auto tools = store.tools();
    return tools ? findTool(*tools, id)->name : std::string();
}

}  // namespace

class TestGuiToolStorePg : public QObject {
    Q_OBJECT
private slots:
    void aChangeOnTheServerReachesThePlanRunner()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        stationOn(server, home);

        PlanRunner runner;
        QVERIFY2(runner.libraryError().isEmpty(), qPrintable(runner.libraryError()));
        QVERIFY(runner.libraryStatus().isEmpty());
        QCOMPARE(runner.library().size(), defaultToolLibrary().size());
        QSignalSpy spy(&runner, &PlanRunner::toolsChangedOnServer);

        auto office = PgToolStore::open(server.uri(), {home.filePath("office.sqlite").toStdString(), "office", 3});
        QVERIFY(office);
        std::int64_t version = 0;
        Tool t;
        const auto tools = (*office)->versionedTools();
        QVERIFY(tools);
        for (const auto& v : *tools)
            if (v.tool.id == 27) t = v.tool, version = v.version;
        t.name = "Flat end mill 10 mm, reground";
        QVERIFY((*office)->save(t, version)->saved());
        QVERIFY2(spy.wait(5000), "no NOTIFY reached the plan runner within 5 s");
        const QString message = spy.takeFirst().at(0).toString();
        QVERIFY2(message.contains("T27") && message.contains("station office"), qPrintable(message));
        QCOMPARE(findTool(runner.library(), 27)->name, t.name);
        QVERIFY(spy.isEmpty());  // one change, one message

        // The server goes: the runner is on its copy, read-only, and says so.
        QVERIFY(server.kill());
        QVERIFY2(spy.wait(5000), "the server's going was not noticed within 5 s");
        QVERIFY2(runner.libraryStatus().startsWith("tools as of "), qPrintable(runner.libraryStatus()));
        QCOMPARE(findTool(runner.library(), 27)->name, t.name);  // the copy has the change
        // Back: re-reading finds the server again.
        QVERIFY(server.restart());
        runner.reloadLibrary();
        QVERIFY2(runner.libraryStatus().isEmpty(), qPrintable(runner.libraryStatus()));
    }

    // The race of docs/shop-server.md: another station holds the tools
    // table locked while it changes T28, so the runner's read of the
    // library (woken by the office's change of T27) waits and ends with
    // T28's notification in libpq's queue, the socket silent. The runner
    // takes the queue after the read and reads again: T28 arrives without
    // any later notification.
    void aChangeDuringTheReadIsReadAtOnce()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        stationOn(server, home);
        PlanRunner runner;
        QVERIFY2(runner.libraryError().isEmpty(), qPrintable(runner.libraryError()));
        const std::string before = findTool(runner.library(), 28)->name;
        QSignalSpy spy(&runner, &PlanRunner::toolsChangedOnServer);

        // The office's change of T27: its notification waits on the runner's socket.
        auto office = PgToolStore::open(server.uri(), {home.filePath("office.sqlite").toStdString(), "office", 3});
        QVERIFY(office);
        const auto tools = (*office)->versionedTools();
        QVERIFY(tools);
        std::int64_t version = 0;
        Tool t;
        for (const auto& v : *tools)
            if (v.tool.id == 27) t = v.tool, version = v.version;
        t.name = "T27 at the office";
        QVERIFY((*office)->save(t, version)->saved());
        // The presetter: the table locked, T28 changed, committed 2 s later.
        auto presetter = server.psqlInBackground("BEGIN; LOCK TABLE tools IN ACCESS EXCLUSIVE MODE; "
                                                 "UPDATE tools SET name = 'T28 at the presetter' WHERE id = 28; "
                                                 "SELECT pg_sleep(2); COMMIT;");
        QVERIFY2(presetter, qPrintable(server.why()));
        // Until the lock is held (no event handled meanwhile: the runner must not read before).
        QString held;
        for (int i = 0; i < 100 && held.trimmed() != "1"; ++i)
            QVERIFY2(server.psql("SELECT count(*) FROM pg_locks WHERE relation = 'tools'::regclass AND mode = 'AccessExclusiveLock' AND granted",
                                 &held),
                     qPrintable(server.why()));
        QCOMPARE(held.trimmed(), QString("1"));

        QVERIFY2(spy.wait(10000), "no NOTIFY reached the plan runner within 10 s");
        QVERIFY(presetter->waitForFinished(10000));
        QCOMPARE(presetter->exitCode(), 0);
        QCOMPARE(findTool(runner.library(), 27)->name, t.name);
        const QString message = spy.takeFirst().at(0).toString();
        QVERIFY2(message.contains("T27"), qPrintable(message));
        // T28 read at once: within a second, with no other notification to come.
        QTRY_COMPARE_WITH_TIMEOUT(findTool(runner.library(), 28)->name, std::string("T28 at the presetter"), 1000);
        QVERIFY(before != "T28 at the presetter");
        QVERIFY2(message.contains("T28"), qPrintable(message));
    }

    void theDialogAsksOnAConflict()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        stationOn(server, home);
        auto office = PgToolStore::open(server.uri(), {home.filePath("office.sqlite").toStdString(), "office", 3});
        QVERIFY(office);
        const auto saveAtOffice = [&](const std::string& name) {
            std::int64_t version = 0;
            Tool t;
            const auto tools = (*office)->versionedTools();
            for (const auto& v : *tools)
                if (v.tool.id == 27) t = v.tool, version = v.version;
            t.name = name;
            return (*office)->save(t, version)->saved();
        };

        ToolLibraryDialog dialog;
        int row = -1;
        for (int r = 0; r < dialog.table()->rowCount(); ++r)
            if (dialog.table()->item(r, ToolLibraryDialog::Id)->text() == "27") row = r;
        QVERIFY(row >= 0);
        // Control: no change meanwhile, no question.
        dialog.table()->item(row, ToolLibraryDialog::Name)->setText("first edit");
        QTRY_COMPARE(nameOnServer(**office, 27), std::string("first edit"));
        QVERIFY(!QApplication::activeModalWidget());

        QVERIFY(saveAtOffice("renamed at the office"));
        QString asked;
        answerConflict("tools.keepMine", &asked);
        dialog.table()->item(row, ToolLibraryDialog::Name)->setText("renamed at machine 2");
        QTRY_VERIFY_WITH_TIMEOUT(!asked.isEmpty(), 5000);
        QVERIFY2(asked.contains("station office") && asked.contains("renamed at the office") && asked.contains("renamed at machine 2"),
                 qPrintable(asked));
        QTRY_COMPARE(nameOnServer(**office, 27), std::string("renamed at machine 2"));

        QVERIFY(saveAtOffice("the office again"));
        asked.clear();
        answerConflict("tools.takeTheirs", &asked);
        dialog.table()->item(row, ToolLibraryDialog::Name)->setText("machine 2 again");
        QTRY_VERIFY_WITH_TIMEOUT(!asked.isEmpty(), 5000);
        QTRY_VERIFY2(dialog.status().contains("theirs taken"), qPrintable(dialog.status()));
        QCOMPARE(nameOnServer(**office, 27), std::string("the office again"));
        QTRY_COMPARE(dialog.table()->item(row, ToolLibraryDialog::Name)->text(), QString("the office again"));
    }
};

QTEST_MAIN(TestGuiToolStorePg)
#include "test_gui_tool_store_pg.moc"
