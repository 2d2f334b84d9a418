// The station in Japanese and Chinese beyond its own texts: the core's
// messages (found from their English by their templates, translated, their
// arguments put back), tool names and kinds, the module drawings' labels and
// Qt's standard buttons; a check message typed into being in a Japanese form;
// the 3-D view's axes note, a refused job file, a broken tool library and the
// NC panel's heading of a Japanese station.
#include "check/messages.h"
#include "io/job_io.h"
#include "modules/probe/probe_fit.h"
#include "modules/region_messages.h"
#include "support/gui_fields.h"
#include "support/speak.h"
#include "support/support.h"
#include "ui/core_messages.h"
#include "ui/core_texts.h"
#include "ui/dxf_import_dialog.h"
#include "ui/figure_panel.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/language.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/station_window.h"
#include "ui/tool_library_dialog.h"
#include "viz/scene.h"

#include <QApplication>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QHash>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QTimer>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

using test::speak;

// The message of a line of tests/data/bad-jobs/*.expected, without the file, unit and field before it.
QString messageOf(const QString& line)
{
    static const QRegularExpression prefix(
        QStringLiteral(R"(^[^:]+\.taiwa: (?:unit \d+ \([^)]*\) \S+: |job \S+: )?)"));
    QString m = line;
    return m.remove(prefix);
}

} // namespace

class TestGuiLanguages : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

  private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }
    void cleanup() { speak("en"); }

    // The matching alone, on a made-up catalogue: the template with the most
    // words wins, the translation may put the arguments in another order
    // ({1} {0}), arguments that are words or messages (a tool's name) are
    // translated in turn, and a message no template made stays as it is.
    void templatesAreMatchedAndArgumentsTranslated()
    {
        const QStringList sources{"{}: {}",
                                  "{} is {}; it must be greater than zero",
                                  "the depth is {}; it must be greater than zero (measured down from the top face)",
                                  "the {} tool {} is too big for {} = {}; {}",
                                  "T{} ({} Ø{} mm)",
                                  "{} would fit"};
        const QHash<QString, QString> ja{
            {"{}: {}", "{}：{}"},
            {"{} is {}; it must be greater than zero", "{}が{}です"},
            {"the depth is {}; it must be greater than zero (measured down from the top face)", "深さが {} です"},
            {"the {} tool {} is too big for {} = {}; {}", "{2} = {3} に対して{0}の工具 {1} は大きすぎます。{4}"},
            {"T{} ({} Ø{} mm)", "T{} ({} Ø{} mm)"},
            {"{} would fit", "{} なら入ります"},
            {"flat end mill", "フラットエンドミル"},
            {"roughing", "荒加工"}};
        const auto tr = [&ja](const QString& s) { return ja.value(s, s); };
        QCOMPARE(translateMessage("the depth is 0 mm; it must be greater than zero (measured down from the top face)",
                                  sources, tr),
                 QString("深さが 0 mm です"));
        QCOMPARE(translateMessage("L1 is -2 mm; it must be greater than zero", sources, tr), QString("L1が-2 mmです"));
        QCOMPARE(translateMessage("the roughing tool T3 (flat end mill Ø10 mm) is too big for r1 = 2 mm; "
                                  "T4 (flat end mill Ø4 mm) would fit",
                                  sources, tr),
                 QString("r1 = 2 mm に対して荒加工の工具 T3 (フラットエンドミル Ø10 mm) は大きすぎます。"
                         "T4 (フラットエンドミル Ø4 mm) なら入ります"));
        QCOMPARE(translateMessage("roughing: T3 (flat end mill Ø10 mm)", sources, tr),
                 QString("荒加工：T3 (フラットエンドミル Ø10 mm)"));
        QCOMPARE(translateMessage("the file is empty", sources, tr), QString("the file is empty"));
    }

    // With the real catalogues: a message of the core's own making, in each language.
    void coreMessagesInJapaneseAndChinese()
    {
        const std::string depth = msg::depthNotPositive({0.0, LengthUnit::Millimetre});
        QCOMPARE(coreMessage(depth), QString::fromStdString(depth)); // English: as the core wrote it
        speak("ja");
        QCOMPARE(coreMessage(depth), QString("深さが 0 mm です。0 より大きくしてください (上面から下へ測ります)"));
        QCOMPARE(coreMessage(msg::contourOpen("K2", "pocket", "outline")),
                 QString("K2 は開いた輪郭です。ポケットの外形は閉じていなければなりません (始点と終点のない輪郭)"));
        // A verification finding: its step's label, place and kind each translated.
        QCOMPARE(coreMessage("step 2 (Roughing I, unit 1): rapid (G0) 1.000 mm into stock at X1.000 Y2.000 Z3.000, move 4, "
                             "tape line 20"),
                 QString("工程 2 (荒加工 I、ユニット 1): X1.000 Y2.000 Z3.000 で早送り (G0) が素材に 1.000 mm 入ります、"
                         "移動 4、テープ 20 行目"));
        // One on a program other than the tape (a probing unit's, a two-path lathe's), named by its file.
        QCOMPARE(coreMessage("the job: the tape has a rapid the plan does not, to X0.000 Y0.000 Z-50.000, 42.000 mm into "
                             "stock, in x.u1.probe.nc at line 7"),
                 QString("ジョブ: テープに計画にない rapid があります: X0.000 Y0.000 Z-50.000 へ、素材に 42.000 mm 入ります、"
                         "x.u1.probe.nc の 7 行目"));
        speak("zh");
        QCOMPARE(coreMessage(depth), QString("深度为 0 mm；必须大于零（自顶面向下测量）"));
        QCOMPARE(coreMessage("the job: the wait M102 is not met by the other path's program at its turn: both paths would "
                             "stop there (a deadlock), in part.p1.nc at line 30"),
                 QString("作业：%1，part.p1.nc 第 30 行").arg(coreMessage("the wait M102 is not met by the other path's program at "
                                                                       "its turn: both paths would stop there (a deadlock)")));
    }

    // Every message the bad jobs of tests/data/bad-jobs draw from the
    // reader and the checks is one the station shows translated.
    void everyBadJobMessageIsTranslated()
    {
        QStringList messages;
        for (const QString& name : QDir(test::sourcePath("tests/data/bad-jobs")).entryList({"*.expected"})) {
            const QString text =
                QString::fromStdString(test::readFile(test::sourcePath("tests/data/bad-jobs/" + name)));
            for (const QString& line : text.split('\n', Qt::SkipEmptyParts))
                messages << messageOf(line);
        }
        QVERIFY(messages.size() > 50);
        for (const char* language : {"ja", "zh"}) {
            speak(language);
            QStringList untranslated;
            for (const QString& m : messages)
                if (coreMessage(m.toStdString()) == m)
                    untranslated << m;
            for (const QString& m : untranslated) qWarning("%s: %s", language, qPrintable(m));
            QVERIFY2(untranslated.isEmpty(), qPrintable(QString("%1: %2 untranslated").arg(language).arg(untranslated.size())));
        }
    }

    // The figure panel of a Japanese station: a statement refused by the
    // parser, and one refused by the geometry, each listed as "line:column:"
    // and why in Japanese, the names and words of the text as typed.
    void figureRefusalsInJapanese()
    {
        speak("ja");
        StationWindow w(test::sourcePath("resources/samples/cp-islands.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.showFigure(true);
        QPlainTextEdit* editor = w.findChild<QPlainTextEdit*>("figure.text");
        QListWidget* refusals = w.findChild<QListWidget*>("figure.refusals");
        QVERIFY(editor && refusals);
        editor->moveCursor(QTextCursor::End);
        QTest::keyClick(editor, Qt::Key_Return);
        QTest::keyClicks(editor, "P10 = PIONT/1, 2");
        const int line = editor->textCursor().blockNumber() + 1;
        QTRY_COMPARE(refusals->count(), 1);
        QCOMPARE(refusals->item(0)->text(),
                 QString("%1:7: '=' の後には POINT、LINE、CIRCLE または CONTOUR が必要ですが、'PIONT' があります").arg(line));
        // Two points in one place: no line through them, said by the evaluation.
        for (int i = 0; i < 16; ++i) QTest::keyClick(editor, Qt::Key_Backspace);
        QTest::keyClicks(editor, "P10 = POINT/1, 2");
        QTest::keyClick(editor, Qt::Key_Return);
        QTest::keyClicks(editor, "P11 = POINT/1, 2");
        QTest::keyClick(editor, Qt::Key_Return);
        QTest::keyClicks(editor, "L20 = LINE/P10, P11");
        QTRY_COMPARE(refusals->count(), 1);
        QCOMPARE(refusals->item(0)->text(),
                 QString("%1:1: L20: P10 と P11 が一致しています: 両点を通る直線がありません").arg(line + 2));
    }

    // The DXF import's report in Japanese: a drawing without its units and
    // with a gap wider than the tolerance; the entities named as the
    // messages name them ("レイヤ OPEN の LINE (DXF 9 行目)").
    void dxfNotesInJapanese()
    {
        speak("ja");
        const QString path = dir_.filePath("gap.dxf");
        const auto line = [](double x1, double y1, double x2, double y2) {
            return QString("0\nLINE\n8\nOPEN\n10\n%1\n20\n%2\n30\n0\n11\n%3\n21\n%4\n31\n0\n")
                .arg(x1).arg(y1).arg(x2).arg(y2);
        };
        test::writeFile(path, ("0\nSECTION\n2\nENTITIES\n" + line(0, 0, 50, 0) + line(50.2, 0, 80, 20) +
                               "0\nENDSEC\n0\nEOF\n").toStdString());
        StationWindow w(test::sourcePath("resources/samples/cp-islands.taiwa"));
        DxfImportDialog d(w.document()->job(), &w);
        d.setPath(path);
        const QString report = d.findChild<QPlainTextEdit*>("dxf.report")->toPlainText();
        QVERIFY2(report.contains("図面に単位がありません ($INSUNITS が単位なしまたは未設定): mm として読み込みました"),
                 qPrintable(report));
        QVERIFY2(report.contains("隙間: (50.000, 0.000) で レイヤ OPEN の LINE (DXF 5 行目) と レイヤ OPEN の LINE (DXF 21 行目) "
                                 "(端点は (50.200, 0.000)) の間に 0.2 mm の隙間があります。隙間の許容値は 0.01 mm です"),
                 qPrintable(report));
        QVERIFY2(!report.contains(" on layer ") && !report.contains("units"), qPrintable(report));
        // A list of entities is translated item by item, not misread as one entity.
        QCOMPARE(coreMessage("3 ends meet at (50.000, 0.000): LINE on layer A (DXF line 5), LINE on layer A (DXF line 37), "
                             "ARC on layer B (DXF line 53); the nearest were joined, the rest left open"),
                 QString("(50.000, 0.000) で 3 個の端点が集まっています: レイヤ A の LINE (DXF 5 行目), レイヤ A の LINE (DXF 37 "
                         "行目), レイヤ B の ARC (DXF 53 行目)。最も近いものをつなぎ、残りは開いたままにしました"));
    }

    // Tools by their names and kinds as the step list and the tool library show them.
    void toolNamesAndKinds()
    {
        Tool t;
        t.id = 12;
        t.type = ToolType::FlatEndMill;
        t.diameter = 6.0;
        QCOMPARE(toolName(t), QString("T12 (flat end mill Ø6 mm)"));
        speak("ja");
        QCOMPARE(toolName(t), QString("T12 (フラットエンドミル Ø6 mm)"));
        QCOMPARE(toolKind(ToolType::TaperEndMill), QString("テーパエンドミル"));
        t.type = ToolType::TaperEndMill;
        t.taperAngle = 5.0;
        QCOMPARE(toolName(t), QString("T12 (テーパエンドミル Ø6 mm, 片側 5°)"));
        speak("zh");
        QCOMPARE(toolKind(ToolType::Drill), QString("钻头"));
    }

    // A drawing's labels in the station's language, its symbols as drawn.
    void drawingLabels()
    {
        QFile file(":/modules/m4.svg");
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray svg = file.readAll();
        QCOMPARE(translatedDrawing(svg), svg);
        speak("ja");
        const QString ja = QString::fromUtf8(translatedDrawing(svg));
        QVERIFY2(ja.contains(">M4 – 上面図</text>") && ja.contains(">断面</text>") &&
                     ja.contains(">P1…P4 の X, Y</text>"),
                 qPrintable(ja));
        QVERIFY(!ja.contains("top view"));
        QVERIFY(ja.contains(R"(id="sym-P1" x="10" y="188">P1</text>)"));
    }

    // English counts in words: every message of the station that counts
    // (numerus, as the Japanese catalogue lists them) reads "1 block" and
    // "2 blocks" in English, never "block(s)"; the NC view's count of a
    // real tape too.
    void englishCountsInWords()
    {
        speak("en");
        QFile ts(QStringLiteral(":/i18n/taiwa_ja.ts"));
        QVERIFY(ts.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&ts);
        QString context;
        int counted = 0;
        bool numerus = false;
        while (!xml.atEnd()) {
            xml.readNext();
            if (!xml.isStartElement()) continue;
            if (xml.name() == QLatin1String("name")) context = xml.readElementText();
            else if (xml.name() == QLatin1String("message")) numerus = xml.attributes().value("numerus") == QLatin1String("yes");
            else if (xml.name() == QLatin1String("source") && numerus) {
                const QByteArray source = xml.readElementText().toUtf8();
                for (const int n : {1, 2, 1084}) {
                    const QString text = QCoreApplication::translate(context.toUtf8().constData(), source.constData(), nullptr, n);
                    QVERIFY2(!text.contains("(s)") && !text.contains("%n"), qPrintable(context + ": " + text));
                }
                ++counted;
            }
        }
        QVERIFY(counted >= 9);
        QCOMPARE(QCoreApplication::translate("taiwa::ui::NcView", "%n block(s)", nullptr, 1), QString("1 block"));
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.planRunner()->flush();
        auto* blocks = w.findChild<QLabel*>("nc.blocks");
        QVERIFY(blocks);
        QTRY_VERIFY2(QRegularExpression("^\\d+ blocks$").match(blocks->text()).hasMatch(), qPrintable(blocks->text()));
    }

    // Qt's own buttons come from Qt's translations (qt6-translations-l10n).
    void standardButtons()
    {
        for (const auto& [language, cancel] : {std::pair{"ja", "キャンセル"}, std::pair{"zh", "取消"}}) {
            speak(language);
            QDialogButtonBox box(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
            QCOMPARE(box.button(QDialogButtonBox::Cancel)->text(), QString::fromUtf8(cancel));
        }
    }

    // The operator types a depth of 0 in a Japanese station: the form says
    // why in Japanese, with the 0 in its sentence.
    void checkMessageInTheJapaneseForm()
    {
        speak("ja");
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QLineEdit* depth = test::GuiFields::edit(w, "m4.depth");
        QVERIFY(depth);
        test::GuiFields::retype(depth, "0");
        QLabel* message = test::GuiFields::label(w, "m4.depth");
        QTRY_VERIFY(message->isVisible());
        QCOMPARE(message->text(), QString("深さが 0 mm です。0 より大きくしてください (上面から下へ測ります)"));
    }

    // The 3-D view's scale note in the station's language (where there is
    // OpenGL for a 3-D view); a scene of `taiwa render`'s, made in the same
    // process, stays English. A scene's note follows its text at once.
    void axesNoteInJapanese()
    {
        speak("ja");
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        if (w.preview())
            QTRY_COMPARE(QString::fromStdString(w.preview()->scene().scaleNote()), QString("軸 50 mm"));
        QTRY_VERIFY(w.planRunner()->fullPlan());
        viz::Scene scene;
        scene.setPlan(w.planRunner()->fullPlan());
        QCOMPARE(QString::fromStdString(scene.scaleNote()), QString("axes 50 mm"));
        scene.setScaleNoteText([](int mm) { return axesNote(mm).toStdString(); }, axesNoteFont().toStdString());
        QCOMPARE(QString::fromStdString(scene.scaleNote()), QString("軸 50 mm"));
    }

    // A job file the reader refuses, opened in a Japanese station: the
    // message box lists each problem in Japanese, with where it is.
    void jobReadErrorInJapanese()
    {
        speak("ja");
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QString shown;
        QTimer poll;
        connect(&poll, &QTimer::timeout, &w, [&] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                shown = box->text();
                box->close();
            }
        });
        poll.start(20);
        qunsetenv("TAIWA_NO_PROMPTS");
        const bool opened = w.fileActions()->openPath(test::sourcePath("tests/data/bad-jobs/bad-corners.taiwa"));
        qputenv("TAIWA_NO_PROMPTS", "1");
        QVERIFY(!opened);
        QVERIFY2(shown.contains("bad-corners.taiwa: ユニット 1 (M4) corners: ") &&
                     shown.contains("bad-corners.taiwa: ユニット 5 (M4) corners[1]: "),
                 qPrintable(shown));
        QVERIFY2(!shown.contains("unit ") && !shown.contains("needs exactly"), qPrintable(shown));
    }

    // A tool library that is not one (an empty file): the dialog says why in Japanese.
    void toolLibraryErrorInJapanese()
    {
        speak("ja");
        const QString path = dir_.filePath("empty-tools.sqlite");
        test::writeFile(path, "");
        const QByteArray before = qgetenv("TAIWA_TOOL_DB");
        qputenv("TAIWA_TOOL_DB", path.toUtf8());
        ToolLibraryDialog d;
        qputenv("TAIWA_TOOL_DB", before);
        QCOMPARE(d.status(), QString("工具ライブラリを読めません: %1 は空で、工具ライブラリではありません "
                                     "(削除すると既定のライブラリが作成されます)").arg(path));
    }

    // The core's refusals of a probing fit and of a file it cannot write,
    // as the station shows them (the unit's field, the export's and save's
    // message boxes): in Japanese, their numbers and paths kept.
    void probingAndWriteErrorsInJapanese()
    {
        speak("ja");
        const auto fit = probe::fitCircle({{{0, 0}, probe::Side::None}, {{10, 0}, probe::Side::None}}, {});
        QVERIFY(std::holds_alternative<probe::FitProblem>(fit));
        QCOMPARE(coreMessage(std::get<probe::FitProblem>(fit).message),
                 QString("円形のワークには 3 点以上のタッチ点が必要ですが、2 点です"));
        const auto rect = probe::fitRectangle({{{0, 0}, probe::Side::XMinus}, {{10, 0}, probe::Side::XPlus},
                                               {{5, -5}, probe::Side::YMinus}},
                                              {});
        QCOMPARE(coreMessage(std::get<probe::FitProblem>(rect).message),
                 QString("長方形のワークには各面にタッチが必要ですが、+Y にありません"));
        const QString path = dir_.filePath("no-such-folder/job.taiwa");
        const auto written = writeFileAtomically(path.toStdString(), "{}");
        QVERIFY(!written);
        QCOMPARE(coreMessage(written.error()),
                 QString("%1 にファイルを作成できません: No such file or directory").arg(dir_.filePath("no-such-folder")));
    }

    // The NC panel's heading at 1366 x 768 in Japanese and Chinese: the
    // label, the dialect and the block count each whole (their translations
    // are short; the English heading is as it was).
    void ncHeadingFitsAt1366()
    {
        for (const char* language : {"ja", "zh"}) {
            speak(language);
            QSettings().remove("station"); // the splits as a new station makes them
            StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
            w.resize(1366, 720);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            auto* label = w.ncView()->findChild<QLabel*>("nc.label");
            auto* blocks = w.ncView()->findChild<QLabel*>("nc.blocks");
            QVERIFY(label && blocks);
            QTRY_VERIFY(!blocks->text().isEmpty());
            QTest::qWait(50); // the layout after the count's text
            for (QLabel* l : {label, blocks})
                QVERIFY2(l->fontMetrics().horizontalAdvance(l->text().remove('&')) <= l->contentsRect().width(),
                         qPrintable(QString("%1: '%2' is %3 px wide in %4 px")
                                        .arg(language, l->text())
                                        .arg(l->fontMetrics().horizontalAdvance(l->text().remove('&')))
                                        .arg(l->contentsRect().width())));
        }
    }

    // The verification's summary at 1366 x 768 in Japanese and Chinese: on a
    // line of its own, its sentence fits the line whole (beside the Verify
    // button it was wrapped into a column a few characters wide).
    void verificationSummaryFitsAt1366()
    {
        for (const char* language : {"ja", "zh"}) {
            speak(language);
            QSettings().remove("station");
            StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
            w.resize(1366, 720);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            auto* summary = w.findChild<QLabel*>("verify.summary");
            QVERIFY(summary);
            QTRY_VERIFY(!summary->text().isEmpty());
            QTest::qWait(50);
            const int wide = summary->fontMetrics().horizontalAdvance(summary->text());
            QVERIFY2(wide <= summary->contentsRect().width(),
                     qPrintable(QString("%1: '%2' is %3 px wide in %4 px")
                                    .arg(language, summary->text())
                                    .arg(wide)
                                    .arg(summary->contentsRect().width())));
        }
    }
};

QTEST_MAIN(TestGuiLanguages)
#include "test_gui_languages.moc"
