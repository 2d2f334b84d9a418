// The Japanese and Simplified Chinese texts are complete: resources/i18n/update-ts.py run on a copy
// of each catalogue (lupdate over ui/ and core/modules/) finds no
// text of the sources without its translation and changes nothing, so a new
// tr() or module label left untranslated, or a catalogue not brought up to
// date, fails here.
#include "support/support.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace taiwa::test;

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void everyTextIsTranslated_data()
    {
        QTest::addColumn<QString>("catalogue");
        QTest::newRow("ja") << "resources/i18n/taiwa_ja.ts";
        QTest::newRow("zh") << "resources/i18n/taiwa_zh.ts";
    }
    void everyTextIsTranslated()
    {
        QFETCH(QString, catalogue);
        QTemporaryDir dir;
        const QString copy = dir.filePath("catalogue.ts");
        QVERIFY(QFile::copy(sourcePath(catalogue), copy));
        QProcess p;
        p.start("/usr/bin/python3", {sourcePath("resources/i18n/update-ts.py"), copy});
        QVERIFY(p.waitForFinished(120000));
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(p.exitCode() == 0, qPrintable(out + p.readAllStandardError()));
        QVERIFY2(out.contains(" 0 untranslated"), qPrintable(out + " — run resources/i18n/update-ts.py " + catalogue +
                                                             " and translate the texts marked unfinished"));
        QVERIFY2(readFile(copy) == readFile(sourcePath(catalogue)),
                 qPrintable(catalogue + " is not up to date with the sources: run resources/i18n/update-ts.py on it"));
    }
};

QTEST_APPLESS_MAIN(TestTranslations)
#include "test_translations.moc"
