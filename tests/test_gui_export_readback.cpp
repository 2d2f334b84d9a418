// The station's export reads its tape back as `taiwa export` does
// (verify/tape_readback.h): a shop dialect whose retract word the loader
// lets through ("G0 Z-50" after "G53 G0 Z0") sends the tool 50 mm down
// into the block; the station writes nothing and says why, naming the tape
// line; the shipped linuxcnc dialect exports the same job (control), its
// tape the one that was read back. Offscreen, prompts off.
#include "support/support.h"
#include "ui/export_dialog.h"
#include "ui/file_actions.h"
#include "ui/plan_runner.h"
#include "ui/station_window.h"

#include <QDir>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

class TestGuiExportReadback : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
        // The shop's dialect, before anything reads the dialects.
        const QString home = dir_.filePath("config");
        QVERIFY(QDir().mkpath(home + "/taiwa/dialects"));
        qputenv("XDG_CONFIG_HOME", home.toUtf8());
        std::string linuxcnc = test::readFile(test::sourcePath("resources/dialects/linuxcnc.json"));
        const auto name = linuxcnc.find("\"name\": \"linuxcnc\"");
        QVERIFY(name != std::string::npos);
        linuxcnc.replace(name, 18, "\"name\": \"sinking\"");
        const auto retract = linuxcnc.find("\"retract\": [\"G53 G0 Z0\"]");
        QVERIFY(retract != std::string::npos);
        linuxcnc.replace(retract, 24, "\"retract\": [\"G53 G0 Z0\", \"G0 Z-50\"]");
        test::writeFile(home + "/taiwa/dialects/sinking.json", linuxcnc);
    }

    void aWordIntoStockIsNotExported()
    {
        StationWindow w(test::sourcePath("resources/samples/m4-standard.taiwa"));
        w.planRunner()->flush();
        QSignalSpy said(w.fileActions(), &FileActions::message);
        QTemporaryDir out;
        ExportChoice c;
        c.folder = out.path();
        c.dialect = "sinking";
        c.pictures = false;
        c.resolution = 1.0;
        QVERIFY(!w.fileActions()->exportTo(c));
        QVERIFY(QDir(out.path()).entryList(QDir::Files).isEmpty());
        QVERIFY(!said.isEmpty());
        const QString why = said.last().at(0).toString();
        QVERIFY2(why.contains("the plan does not") && why.contains("into stock"), qPrintable(why));
        // Control: the shipped dialect writes the set.
        c.dialect = "linuxcnc";
        QVERIFY(w.fileActions()->exportTo(c));
        QVERIFY(QDir(out.path()).entryList(QDir::Files).contains("m4-standard.nc"));
    }
};

QTEST_MAIN(TestGuiExportReadback)
#include "test_gui_export_readback.moc"
