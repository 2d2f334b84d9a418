// The station's File menu on the shop server's job store, against a
// PostgreSQL 15 the test starts itself (support/pg_server.h; skipped,
// saying so, where the binaries are absent): a job the office stored is
// opened from the store through the menu's dialog (the station takes its
// lock), a depth typed into the form, saved back (a new version by this
// station in the history, the lock held meanwhile, the office's save
// refused), exported through the export dialog (the tape named after the
// stored job, the new depth on it, the same bytes as `taiwa export
// --from-store`, its pocket 2 mm deeper than the sample's as rs274 reads them), and the lock given back when the station
// opens another job or closes.
#include "support/gui_fields.h"
#include "support/pg_server.h"
#include "support/rs274.h"
#include "support/station_fixture.h"
#include "support/support.h"
#include "tools/pg_job_store.h"
#include "ui/export_dialog.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/station_window.h"
#include "ui/store_actions.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QInputDialog>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;
using taiwa::test::PgServer;

namespace {

// Who holds the lock of job `name`: its station, empty when no one does.
std::string lockHolder(PgJobStore& jobs, const std::string& name)
{
    const auto list = jobs.list();
    if (list)
        for (const StoredJob& j : *list)
            if (j.name == name) return j.lockedStation;
    return "(no job " + name + ")";
}

// The depth of the first unit of a job's text ("depth": N,).
QString firstDepth(const std::string& text)
{
    const QString t = QString::fromStdString(text);
    const qsizetype at = t.indexOf("\"depth\": ");
    return at < 0 ? QString() : t.mid(at + 9, t.indexOf(',', at) - at - 9);
}

}  // namespace

class TestGuiJobStorePg : public QObject {
    Q_OBJECT
private slots:
    void opensSavesAndExportsAStoredJob()
    {
        TAIWA_START_PG_SERVER(server);
        QTemporaryDir home;
        test::isolateStation(home.path());
        qputenv("XDG_DATA_HOME", home.path().toLocal8Bit());
        qputenv("TAIWA_TOOL_DB", QByteArray::fromStdString(server.uri()));
        qputenv("TAIWA_STATION", "machine-2");
        auto office = PgToolStore::open(server.uri(), {home.filePath("office.sqlite").toStdString(), "office", 3});
        QVERIFY2(office, office.ok() ? "" : office.error().c_str());
        PgJobStore atOffice(**office);
        const std::string plate = test::readFile(test::sourcePath("resources/samples/plate.taiwa"));
        QCOMPARE(*atOffice.save("plate", plate), 1);
        QCOMPARE(*atOffice.save("bracket", plate), 1);
        QCOMPARE(firstDepth(plate), QString("10"));

        {
            StationWindow w;
            w.show();
            auto* open = w.findChild<QAction*>("action.openFromStore");
            auto* save = w.findChild<QAction*>("action.saveToStore");
            QVERIFY(open && save && open->isEnabled() && save->isEnabled());
            // The menu's dialog lists the store's jobs; plate is chosen.
            QStringList offered;
            QTimer::singleShot(0, this, [&] {
                auto* d = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
                if (!d) return;
                offered = d->comboBoxItems();
                d->setTextValue("plate");
                d->accept();
            });
            open->trigger();
            QCOMPARE(offered, (QStringList{"bracket", "plate"}));
            QCOMPARE(w.fileActions()->store()->storedName(), QString("plate"));
            QVERIFY2(w.windowTitle().startsWith("plate (shop server) — "), qPrintable(w.windowTitle()));
            QCOMPARE(lockHolder(atOffice, "plate"), std::string("machine-2"));
            QCOMPARE(w.document()->job().units[0].name, std::string("Locator pocket"));
            test::settle(w);

            // The first unit's depth typed over, as an operator would.
            QLineEdit* depth = test::GuiFields::edit(w, "m4.depth");
            QVERIFY(depth);
            test::GuiFields::retype(depth, "11");
            QTest::keyClick(depth, Qt::Key_Tab);
            QVERIFY(w.document()->isModified());
            QVERIFY(w.windowTitle().startsWith("plate (shop server)* — "));

            // Saved back: version 2 by machine-2, with the new depth; the lock still held.
            save->trigger();
            QVERIFY(!w.document()->isModified());
            const auto history = atOffice.history("plate");
            QVERIFY(history && history->size() == 2);
            QCOMPARE(history->back().version, 2);
            QCOMPARE(history->back().station, std::string("machine-2"));
            QCOMPARE(history->front().station, std::string("office"));
            QCOMPARE(firstDepth(*atOffice.load("plate")), QString("11"));
            QCOMPARE(firstDepth(*atOffice.load("plate", 1)), QString("10"));
            QCOMPARE(lockHolder(atOffice, "plate"), std::string("machine-2"));
            const auto refused = atOffice.save("plate", plate);
            QVERIFY(!refused);
            QVERIFY2(refused.error().starts_with("job 'plate' is open at station machine-2 (by taiwa_admin since "), refused.error().c_str());
            // Ctrl+S saves a stored job to the store too (no file dialog).
            test::GuiFields::retype(depth, "12");
            QTest::keyClick(depth, Qt::Key_Tab);
            QVERIFY(w.fileActions()->save());
            QCOMPARE(atOffice.history("plate")->size(), std::size_t(3));
            QCOMPARE(firstDepth(*atOffice.load("plate")), QString("12"));

            // Exported through the dialog: the files named after the stored job.
            test::settle(w);
            const QString out = home.filePath("station");
            bool seen = false;
            QTimer::singleShot(0, this, [&] {
                auto* d = qobject_cast<ExportDialog*>(QApplication::activeModalWidget());
                if (!d) return;
                seen = true;
                d->findChild<QLineEdit*>("export.folder")->setText(out);
                d->findChild<QCheckBox*>("export.pictures")->setChecked(false);
                d->accept();
            });
            w.fileActions()->exportJob();
            QVERIFY(seen);
            const QString tape = QDir(out).filePath("plate.nc");
            QVERIFY2(QFile::exists(tape), qPrintable(QDir(out).entryList().join(' ')));
            const std::string ngc = test::readFile(tape);
            // The same bytes as the command line's export of the stored job.
            const QString fromStore = home.filePath("cli");
            const auto cli = test::runTaiwa({"export", "--from-store", "plate", "--out", fromStore, "--no-pictures"},
                                            {"TAIWA_TOOL_DB=" + QString::fromStdString(server.uri()), "XDG_DATA_HOME=" + home.path(),
                                             "TAIWA_STATION=office"});
            QVERIFY2(cli.exitCode == 0, qPrintable(cli.err));
            QCOMPARE(QString::fromStdString(ngc), QString::fromStdString(test::readFile(QDir(fromStore).filePath("plate.nc"))));
            // The locator pocket 2 mm deeper than in the sample's own file: rs274 reads both tapes.
            const QString fromFile = home.filePath("file");
            QCOMPARE(test::runTaiwa({"export", test::sourcePath("resources/samples/plate.taiwa"), "--out", fromFile, "--no-pictures"},
                                    {"TAIWA_TOOL_DB=" + QString::fromStdString(server.uri()), "XDG_DATA_HOME=" + home.path()})
                         .exitCode,
                     0);
            const auto deepestInThePocket = [](const std::string& text, double* z) {
                const auto run = test::runRs274(text);
                QVERIFY2(run.ok, qPrintable(run.errors));
                *z = 1e9;
                for (const auto& m : run.moves)
                    if (m.kind != test::CanonMove::Traverse && m.end.x > 15 && m.end.x < 70 && m.end.y > 15 && m.end.y < 60)
                        *z = std::min(*z, m.end.z);
            };
            double edited = 0, sample = 0;
            deepestInThePocket(ngc, &edited);
            deepestInThePocket(test::readFile(QDir(fromFile).filePath("plate.nc")), &sample);
            QVERIFY2(sample < 1e9, "no cut in the locator pocket");
            QCOMPARE(edited, sample - 2.0);

            // Another job opened: plate's lock goes back, bracket's is taken.
            QVERIFY(w.fileActions()->store()->openStored("bracket"));
            QCOMPARE(lockHolder(atOffice, "plate"), std::string());
            QCOMPARE(lockHolder(atOffice, "bracket"), std::string("machine-2"));
            // The office holds plate now: the station's open is refused, naming it, bracket kept.
            QVERIFY(atOffice.lock("plate"));
            QVERIFY(!w.fileActions()->store()->openStored("plate"));
            QCOMPARE(w.fileActions()->store()->storedName(), QString("bracket"));
            QCOMPARE(lockHolder(atOffice, "bracket"), std::string("machine-2"));
            // A new job: bracket's lock goes back.
            QVERIFY(w.fileActions()->newJob());
            QVERIFY(w.fileActions()->store()->storedName().isEmpty());
            QCOMPARE(lockHolder(atOffice, "bracket"), std::string());
            QVERIFY(w.fileActions()->store()->openStored("bracket"));
            QCOMPARE(lockHolder(atOffice, "bracket"), std::string("machine-2"));
            QVERIFY(w.close());
        }
        // The window gone: its lock given back.
        QCOMPARE(lockHolder(atOffice, "bracket"), std::string());
        QCOMPARE(lockHolder(atOffice, "plate"), std::string("office"));
    }
};

QTEST_MAIN(TestGuiJobStorePg)
#include "test_gui_job_store_pg.moc"
