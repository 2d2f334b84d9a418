// The station's plan runner on the shop server (a PostgreSQL 15 the test
// starts itself, support/pg_server.h; skipped, saying so, where the
// binaries are absent): another station's change reaches it by NOTIFY
// within seconds, re-reads the library and says which tool and who; the
// server going away leaves it on its copy, read-only, saying "tools as of".
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
        if (PgServer::binaries().isEmpty())
            QSKIP("no PostgreSQL 15 here (/usr/lib/postgresql/15/bin/pg_ctl is absent); packaging/install-deps.sh installs postgresql-15");
        PgServer server;
        QVERIFY2(server.start(), qPrintable(server.why()));
        QTemporaryDir home;
        test::isolateStation(home.path());
        qputenv("XDG_DATA_HOME", home.path().toLocal8Bit());
        qputenv("TAIWA_TOOL_DB", QByteArray::fromStdString(server.uri()));
        qputenv("TAIWA_STATION", "machine-2");

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

    void theDialogAsksOnAConflict()
    {
        if (PgServer::binaries().isEmpty())
            QSKIP("no PostgreSQL 15 here (/usr/lib/postgresql/15/bin/pg_ctl is absent); packaging/install-deps.sh installs postgresql-15");
        PgServer server;
        QVERIFY2(server.start(), qPrintable(server.why()));
        QTemporaryDir home;
        test::isolateStation(home.path());
        qputenv("XDG_DATA_HOME", home.path().toLocal8Bit());
        qputenv("TAIWA_TOOL_DB", QByteArray::fromStdString(server.uri()));
        qputenv("TAIWA_STATION", "machine-2");
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
