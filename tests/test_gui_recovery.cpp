// Crash recovery. A window with unsaved edits is destroyed without closing
// (what a kill -9 leaves behind on disk: the autosaved recovery file and
// nothing else) after the autosave timer ran; the next window started on the
// same job offers the recovery file and restores the typed values. A
// recovery file older than the job file is not offered; a clean close
// removes it. And with the real executable: `taiwa JOB` started on a job
// with a newer recovery file adopts it and keeps autosaving it; killed with
// SIGKILL, it leaves the recovery file whole and the job file untouched, and
// the next start restores it.
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "io/job_io.h"
#include "job/job_file.h"
#include "support/support.h"
#include "ui/autosave.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/station_window.h"

#include <QAbstractButton>
#include <QElapsedTimer>
#include <QFile>
#include <QLineEdit>
#include <QProcess>
#include <QTemporaryDir>
#include <QStatusBar>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiRecovery : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    static void type(QWidget& w, const char* name, const QString& text)
    {
        auto* e = w.findChild<QLineEdit*>(name);
        QVERIFY(e);
        e->setFocus();
        e->selectAll();
        QTest::keyClicks(e, text);
    }

    // The name an older Taiwa gave a job's recovery file (no owner in it):
    // taken as left by an owner that is gone.
    static QString legacyRecoveryPath(const QString& job)
    {
        StationWindow probe;
        const QString own = probe.autosaver()->recoveryPath(job);
        return own.left(own.lastIndexOf('.', own.size() - 7)) + ".taiwa";
    }

    static Job sampleJob(double depth)
    {
        Job j;
        j.name = "shared";
        M4Pocket p;
        p.corners = {Point2{10, 10}, Point2{60, 10}, Point2{60, 40}, Point2{10, 40}};
        p.cornerRadius = 5;
        p.depth = depth;
        j.units.push_back(MachiningUnit{"A", p});
        return j;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void untitledJobRestoredAfterAKill()
    {
        QVERIFY(Autosaver::recoveryFiles({}).isEmpty());
        QString recovery;
        QElapsedTimer sinceLastEdit;
        {
            auto* w = new StationWindow;
            recovery = w->autosaver()->recoveryPath({});
            QVERIFY(recovery.startsWith(dir_.path()));
            QTest::mouseClick(w->findChild<QAbstractButton*>("unit.addM4"), Qt::LeftButton);
            type(*w, "m4.depth", "7.25");
            type(*w, "m4.r1", "6.5");
            sinceLastEdit.start();
            QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(recovery), 2 * Autosaver::kIntervalMs);
            delete w;  // no close event, no save: as after kill -9
        }
        // The edits reached the disk within one autosave interval.
        QVERIFY2(sinceLastEdit.elapsed() <= Autosaver::kIntervalMs + 500,
                 qPrintable(QString::number(sinceLastEdit.elapsed())));
        QVERIFY(QFile::exists(recovery));
        StationWindow w2;
        QCOMPARE(w2.document()->job().units.size(), std::size_t(1));
        const auto& m4 = (w2.document()->job().units[0].module).as<M4Pocket>();
        QCOMPARE(m4.depth, 7.25);
        QCOMPARE(m4.cornerRadius, 6.5);
        QCOMPARE(w2.findChild<QLineEdit*>("m4.depth")->text(), QString("7.25"));
        QVERIFY(w2.document()->isModified());
        QVERIFY(w2.windowTitle().contains('*'));
        QVERIFY(!QFile::exists(recovery));  // restored: the dead window's file is gone
        QVERIFY(w2.close());                // prompts are off: the changes are dropped
        QVERIFY(Autosaver::recoveryFiles({}).isEmpty());
    }

    void savedJobRestoredOnlyWhenTheRecoveryIsNewer()
    {
        const QString job = dir_.filePath("plate.taiwa");
        Job j;
        j.name = "plate";
        M4Pocket p;
        p.corners = {Point2{10, 10}, Point2{60, 10}, Point2{60, 40}, Point2{10, 40}};
        p.cornerRadius = 5;
        p.depth = 8;
        j.units.push_back(MachiningUnit{"A", p});
        QVERIFY(writeFileAtomically(job.toStdString(), writeJob(j)));
        QString recovery;
        {
            auto* w = new StationWindow(job);
            recovery = w->autosaver()->recoveryPath(job);
            QCOMPARE(w->document()->job(), j);
            type(*w, "m4.depth", "11");
            w->autosaver()->saveNow();  // what the timer does every 3 s
            QVERIFY(QFile::exists(recovery));
            delete w;
        }
        {
            StationWindow w(job);  // the recovery is newer than the file: restored, still modified
            QCOMPARE((w.document()->job().units[0].module).as<M4Pocket>().depth, 11.0);
            QCOMPARE(w.document()->path(), job);
            QVERIFY(w.document()->isModified());
            QVERIFY(w.fileActions()->save());  // saved: the recovery files go
            QVERIFY(Autosaver::recoveryFiles(job).isEmpty());
        }
        // A stale recovery file (older than the job file) is not offered.
        Job stale = j;
        (stale.units[0].module).as<M4Pocket>().depth = 3;
        QVERIFY(writeFileAtomically(recovery.toStdString(), writeJob(stale)));
        QFile f(recovery);
        QVERIFY(f.open(QIODevice::ReadWrite));
        QVERIFY(f.setFileTime(QDateTime::currentDateTime().addSecs(-3600), QFileDevice::FileModificationTime));
        f.close();
        StationWindow w(job);
        QCOMPARE((w.document()->job().units[0].module).as<M4Pocket>().depth, 11.0);
        QVERIFY(!w.document()->isModified());
    }

    void twoWindowsOnOneJobKeepTheirOwnRecovery()
    {
        const QString job = dir_.filePath("shared.taiwa");
        QVERIFY(writeFileAtomically(job.toStdString(), writeJob(sampleJob(8))));
        StationWindow a(job);
        type(a, "m4.depth", "9");
        a.autosaver()->saveNow();
        const QString aRecovery = a.autosaver()->recoveryPath(job);
        QVERIFY(QFile::exists(aRecovery));
        // B opens the job A is editing: no "not closed properly" (A is alive),
        // and A's recovery file is left alone.
        StationWindow b(job);
        QCOMPARE((b.document()->job().units[0].module).as<M4Pocket>().depth, 8.0);
        QVERIFY(!b.document()->isModified());
        QVERIFY(QFile::exists(aRecovery));
        // B is told that A has the job open.
        QTRY_VERIFY2(b.statusBar()->currentMessage().contains("also open in 1 other window"),
                     qPrintable(b.statusBar()->currentMessage()));
        QVERIFY(!a.statusBar()->currentMessage().contains("also open"));
        // Both edit: each keeps a recovery file of its own.
        type(b, "m4.depth", "10");
        b.autosaver()->saveNow();
        QCOMPARE(Autosaver::recoveryFiles(job).size(), 2);
        QVERIFY(b.autosaver()->recoveryPath(job) != aRecovery);
        QCOMPARE((readJobFile(aRecovery.toStdString()).job->units[0].module).as<M4Pocket>().depth, 9.0);
        a.autosaver()->saveNow();
        QVERIFY(b.close() && a.close());  // prompts off: changes dropped, own files removed
        QVERIFY(Autosaver::recoveryFiles(job).isEmpty());
    }

    void aSaveDoesNotOverwriteWhatAnotherWindowSaved()
    {
        const QString job = dir_.filePath("both.taiwa");
        QVERIFY(writeFileAtomically(job.toStdString(), writeJob(sampleJob(8))));
        StationWindow a(job), b(job);
        type(b, "m4.depth", "12");
        QVERIFY(b.fileActions()->save());
        type(a, "m4.depth", "7");
        QVERIFY(!a.fileActions()->save());  // prompts off: refused, not overwritten
        QCOMPARE((readJobFile(job.toStdString()).job->units[0].module).as<M4Pocket>().depth, 12.0);
        QVERIFY(a.document()->isModified());  // A's edit is kept in the window
        // B, which wrote it last, saves again without a question.
        type(b, "m4.depth", "13");
        QVERIFY(b.fileActions()->save());
    }

    void realProcessKilled()
    {
        QVERIFY2(QFile::exists(taiwa::test::taiwaBinary()), "build the taiwa executable first");
        const QString job = dir_.filePath("killed.taiwa");
        Job saved;
        M4Pocket p;
        p.corners = {Point2{10, 10}, Point2{60, 10}, Point2{60, 40}, Point2{10, 40}};
        p.cornerRadius = 5;
        p.depth = 8;
        saved.units.push_back(MachiningUnit{"A", p});
        const std::string savedText = writeJob(saved);
        QVERIFY(writeFileAtomically(job.toStdString(), savedText));
        Job edited = saved;
        (edited.units[0].module).as<M4Pocket>().depth = 11;
        // Left by an owner that is gone (an older Taiwa named no owner).
        const QString recovery = legacyRecoveryPath(job);
        QVERIFY(writeFileAtomically(recovery.toStdString(), writeJob(edited)));
        const QDateTime before = QDateTime::currentDateTime();
        auto age = [](const QString& path, int seconds) {
            QFile f(path);
            return f.open(QIODevice::ReadWrite) &&
                   f.setFileTime(QDateTime::currentDateTime().addSecs(seconds), QFileDevice::FileModificationTime);
        };
        QVERIFY(age(job, -60));
        QVERIFY(age(recovery, -30));  // older than now, newer than the job

        QProcess taiwa;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        env.insert("TAIWA_AUTOSAVE_DIR", qEnvironmentVariable("TAIWA_AUTOSAVE_DIR"));
        env.insert("TAIWA_TOOL_DB", qEnvironmentVariable("TAIWA_TOOL_DB"));
        env.insert("TAIWA_NO_PROMPTS", "1");  // restore without asking
        taiwa.setProcessEnvironment(env);
        taiwa.start(taiwa::test::taiwaBinary(), {job});
        QVERIFY(taiwa.waitForStarted());
        // The process restored the recovery file and writes its own within an
        // autosave interval.
        const auto itsOwn = [&] {
            for (const QString& f : Autosaver::recoveryFiles(job))
                if (f != recovery && QFileInfo(f).lastModified() >= before) return f;
            return QString();
        };
        QTRY_VERIFY_WITH_TIMEOUT(!itsOwn().isEmpty(), 3 * Autosaver::kIntervalMs);
        const QString childsRecovery = itsOwn();
        QVERIFY(!QFile::exists(recovery));
        QCOMPARE(taiwa.state(), QProcess::Running);
        taiwa.kill();  // SIGKILL
        QVERIFY(taiwa.waitForFinished());
        QCOMPARE(taiwa.exitStatus(), QProcess::CrashExit);

        QCOMPARE(test::readFile(job), savedText);  // the job file was never touched
        const JobReadResult r = readJobFile(childsRecovery.toStdString());
        QVERIFY(r.job);
        QCOMPARE(*r.job, edited);
        StationWindow w(job);
        QCOMPARE(w.document()->job(), edited);
        QVERIFY(w.document()->isModified());
    }
};

QTEST_MAIN(TestGuiRecovery)
#include "test_gui_recovery.moc"
