// The station's export (issue 34 item 1): one dialog asks for the folder,
// the dialect, the units, the pictures and the verification's grid; the
// sheet it writes carries the setup picture and one picture per step, the
// same bytes as `taiwa export` draws without a display; a cancelled dialog
// writes nothing; the folder holds the export's files and no lock file.
#include "support/station_fixture.h"
#include "support/support.h"
#include "ui/export_dialog.h"
#include "ui/file_actions.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"
#include "ui/verification_panel.h"
#include "verify/verify.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <nlohmann/json.hpp>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

// The sheet's pictures, PNG bytes in order (the setup's first).
QList<QByteArray> picturesOf(const QString& html)
{
    QList<QByteArray> out;
    static const QRegularExpression png("data:image/png;base64,([A-Za-z0-9+/=]+)");
    for (auto it = png.globalMatch(html); it.hasNext();) out << QByteArray::fromBase64(it.next().captured(1).toLatin1());
    return out;
}

QString htmlIn(const QString& folder, const QString& stem)
{
    return QString::fromStdString(test::readFile(QDir(folder).filePath(stem + ".sheet.html")));
}

}  // namespace

class TestGuiExport : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // Runs `fill` on the export dialog once it is open, then triggers the
    // station's export; whether the dialog was seen.
    bool exportWith(StationWindow& w, const std::function<void(ExportDialog*)>& fill)
    {
        bool seen = false;
        QTimer::singleShot(0, this, [&] {
            auto* d = qobject_cast<ExportDialog*>(QApplication::activeModalWidget());
            if (!d) return;
            seen = true;
            fill(d);
            if (d->isVisible()) d->reject();  // a check that failed in `fill` leaves it open
        });
        w.fileActions()->exportJob();
        return seen;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
        qputenv("XDG_RUNTIME_DIR", QDir(dir_.path()).filePath("run").toUtf8());
        QDir().mkpath(QDir(dir_.path()).filePath("run"));
        QSettings().remove("export");  // no folder or choice remembered from an earlier run
    }

    void oneDialogAsksForEverything()
    {
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        const QString out = QDir(dir_.path()).filePath("cancelled");
        const bool seen = exportWith(w, [&](ExportDialog* d) {
            auto* folder = d->findChild<QLineEdit*>("export.folder");
            auto* dialect = d->findChild<QComboBox*>("export.dialect");
            auto* units = d->findChild<QComboBox*>("export.units");
            auto* pictures = d->findChild<QCheckBox*>("export.pictures");
            auto* resolution = d->findChild<QDoubleSpinBox*>("export.resolution");
            auto* buttons = d->findChild<QDialogButtonBox*>("export.buttons");
            QVERIFY(folder && dialect && units && pictures && resolution && buttons);
            QCOMPARE(dialect->currentText(), w.planRunner()->dialect());  // the job's dialect first
            QVERIFY(dialect->count() >= 5);
            QCOMPARE(units->count(), 3);
            QVERIFY(pictures->isChecked());
            QVERIFY(resolution->value() > 0);
            folder->clear();
            QVERIFY(!buttons->button(QDialogButtonBox::Ok)->isEnabled());  // no folder, no export
            folder->setText(out);
            QVERIFY(buttons->button(QDialogButtonBox::Ok)->isEnabled());
            d->reject();
        });
        QVERIFY(seen);
        QVERIFY(!QDir(out).exists());  // cancelled: nothing written
    }

    // One verification per export (issue 35 item 3): the station's Verify
    // stores its report, and the export of the same plan at the same grid
    // reads it instead of verifying again. Shown by a finding planted in the
    // stored report: the export refuses on it; the report gone, it verifies
    // afresh and writes.
    void theStationsVerifyServesItsExport()
    {
        const QString cache = qEnvironmentVariable("TAIWA_CACHE_DIR");
        QVERIFY(!cache.isEmpty());
        QDir(cache).removeRecursively();
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.show();
        test::settle(w);  // the plan made
        w.verificationPanel()->verifyNow();
        const QStringList stored = QDir(cache).entryList({"*.json"}, QDir::Files);
        QCOMPARE(stored.size(), 1);
        const QString file = QDir(cache).filePath(stored.front());
        auto report = nlohmann::json::parse(test::readFile(file));
        QVERIFY(report["findings"].empty());
        report["findings"].push_back({{"kind", 3}, {"step", -1}, {"move", -1}, {"position", {0, 0, 0}},
                                      {"size", 5.0}, {"area", 0.0}, {"part", "x"}});  // a travel limit, planted
        test::writeFile(file, report.dump());
        QString said;
        connect(w.fileActions(), &FileActions::message, this, [&](const QString& m) { said = m; });
        const double grid = verify::defaultResolution(*w.planRunner()->fullPlan());
        const QString out = QDir(dir_.path()).filePath("cached");
        const auto exportAtTheDefaultGrid = [&] {
            return exportWith(w, [&](ExportDialog* d) {
                d->findChild<QLineEdit*>("export.folder")->setText(out);
                d->findChild<QDoubleSpinBox*>("export.resolution")->setValue(grid);
                d->accept();
            });
        };
        QVERIFY(exportAtTheDefaultGrid());
        QVERIFY2(said.startsWith("The verification found 1 "), qPrintable(said));
        QVERIFY(!QDir(out).exists());
        QVERIFY(QFile::remove(file));
        QVERIFY(exportAtTheDefaultGrid());
        QVERIFY2(said.startsWith("Exported 5 files"), qPrintable(said));
    }

    void theStationsSheetHasTheSamePicturesAsTheCommandLines()
    {
        const QString job = test::sourcePath("resources/samples/plate.taiwa");
        const QString cli = QDir(dir_.path()).filePath("cli"), station = QDir(dir_.path()).filePath("station");
        const auto r = test::runTaiwa({"export", job, "--out", cli, "--dialect", "fanuc", "--resolution", "0.25"},
                                      {"DISPLAY=", "QT_QPA_PLATFORM=offscreen"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));

        StationWindow w(job);
        QString said;
        connect(w.fileActions(), &FileActions::message, this, [&](const QString& m) { said = m; });
        const bool seen = exportWith(w, [&](ExportDialog* d) {
            d->findChild<QLineEdit*>("export.folder")->setText(station);
            d->findChild<QComboBox*>("export.dialect")->setCurrentText("fanuc");
            d->findChild<QComboBox*>("export.units")->setCurrentIndex(1);  // millimetres
            d->findChild<QDoubleSpinBox*>("export.resolution")->setValue(0.25);
            d->accept();
        });
        QVERIFY(seen);
        QVERIFY2(said.startsWith("Exported 5 files"), qPrintable(said));

        const QList<QByteArray> fromCli = picturesOf(htmlIn(cli, "plate")), fromStation = picturesOf(htmlIn(station, "plate"));
        QCOMPARE(fromStation.size(), 1 + static_cast<qsizetype>(w.planRunner()->fullPlan()->steps.size()));
        QCOMPARE(fromStation.size(), fromCli.size());
        for (qsizetype k = 0; k < fromCli.size(); ++k) QVERIFY2(fromStation[k] == fromCli[k], qPrintable(QString("picture %1").arg(k)));
        QCOMPARE(QDir(station).entryList(QDir::Files | QDir::Hidden | QDir::System),
                 (QStringList{"plate.nc", "plate.sheet.html", "plate.sheet.pdf", "plate.steps.json", "plate.tape.txt"}));

        // Pictures off: a sheet without them.
        const QString bare = QDir(dir_.path()).filePath("bare");
        exportWith(w, [&](ExportDialog* d) {
            d->findChild<QLineEdit*>("export.folder")->setText(bare);
            d->findChild<QComboBox*>("export.dialect")->setCurrentText("fanuc");
            d->findChild<QCheckBox*>("export.pictures")->setChecked(false);
            d->findChild<QDoubleSpinBox*>("export.resolution")->setValue(0.25);
            d->accept();
        });
        QVERIFY(picturesOf(htmlIn(bare, "plate")).isEmpty());
    }
};

QTEST_MAIN(TestGuiExport)
#include "test_gui_export.moc"
