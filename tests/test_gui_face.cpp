// Module FACE in the station, on the offscreen platform: the face sample's
// form shows every field of the module's door by its widget name, each with
// its help line and its symbol marked in the drawing when it has the focus,
// the codes of U and the pattern with their meanings.
#include "support/support.h"
#include "ui/station_window.h"
#include "ui/unit_form.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa;

class TestGuiFace : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void formShowsTheFieldsWithHelpAndSymbols()
    {
        ui::StationWindow w(test::sourcePath("resources/samples/face-top.taiwa"));
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto* depth = w.findChild<QLineEdit*>("face.depth");
        QVERIFY(depth);
        QCOMPARE(depth->text(), QString("1.5"));
        for (const char* key : {"face.finish", "face.angle", "face.stepOver", "face.margin"})
            QVERIFY2(w.findChild<QLineEdit*>(key), key);
        auto* pattern = w.findChild<QComboBox*>("face.pattern");
        auto* use = w.findChild<QComboBox*>("face.U");
        QVERIFY(pattern && use);
        QCOMPARE(pattern->count(), 2);
        QCOMPARE(pattern->currentText(), QString("2 – zigzag, back and forth"));
        QCOMPARE(use->count(), 2);
        auto* unitForm = qobject_cast<ui::UnitForm*>(depth->parentWidget()->parentWidget());
        QVERIFY(unitForm);
        depth->setFocus();
        QCOMPARE(unitForm->highlightedSymbol(), QString("sym-depth"));
        QVERIFY(unitForm->helpText().startsWith("Stock taken off the top"));
        w.findChild<QLineEdit*>("face.margin")->setFocus();
        QCOMPARE(unitForm->highlightedSymbol(), QString("sym-margin"));
        QVERIFY(w.findChild<QLabel*>("face.drawing"));
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(TestGuiFace)
#include "test_gui_face.moc"
