// The Japanese and Simplified Chinese texts are complete: resources/i18n/update-ts.py run on a copy
// of each catalogue (lupdate over ui/ and core/, the module descriptions'
// texts, the module drawings' labels)
// finds no text of the sources without its translation and changes nothing,
// so a new tr(), module label, core message template, tool kind or drawing
// label left untranslated, or a catalogue not brought up to date, fails
// here. A core message's translation keeps every argument of its template.
#include "support/support.h"

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QXmlStreamReader>
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

    // Each translation of a core message template ("the depth is {}; ...")
    // takes its arguments as the template does: as many "{}", or "{0}".."{N-1}"
    // each once when it puts them in another order.
    void coreMessagesKeepTheirArguments_data() { everyTextIsTranslated_data(); }
    void coreMessagesKeepTheirArguments()
    {
        QFETCH(QString, catalogue);
        QFile file(sourcePath(catalogue));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QRegularExpression field(QStringLiteral(R"(\{[^{}]*\})"));
        const auto fields = [&field](const QString& s) {
            QStringList out;
            for (auto it = field.globalMatch(s); it.hasNext();)
                out << it.next().captured().mid(1).chopped(1);
            return out;
        };
        QXmlStreamReader xml(&file);
        QString context, source;
        int templates = 0;
        while (!xml.atEnd()) {
            if (!xml.readNextStartElement())
                continue;
            if (xml.name() == QLatin1String("name"))
                context = xml.readElementText();
            else if (xml.name() == QLatin1String("source"))
                source = xml.readElementText();
            else if (xml.name() == QLatin1String("translation") && context == "taiwa::msg") {
                const QString translation = xml.readElementText();
                const qsizetype n = fields(source).size();
                QStringList got = fields(translation);
                bool indexed = false;
                if (!got.isEmpty())
                    got.first().toInt(&indexed);
                QStringList expected;
                for (qsizetype i = 0; i < n; ++i)
                    expected << (indexed ? QString::number(i) : QString());
                if (indexed)
                    got.sort();
                else
                    for (QString& g : got)
                        g.clear(); // "{}" as "{:g}" is: the station formats nothing
                QVERIFY2(got == expected, qPrintable(catalogue + ": " + source + " → " + translation));
                ++templates;
            }
        }
        QVERIFY(templates > 300);
    }
};

QTEST_APPLESS_MAIN(TestTranslations)
#include "test_translations.moc"
