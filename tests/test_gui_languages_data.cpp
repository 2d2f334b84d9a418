// The station in Japanese and Chinese: the names the data gives per
// language (a material's description and a machine's name in the job
// properties, the default tools' names in the tool library dialog and in a
// tool-choice refusal; a tool the shop named itself keeps its name), the
// offsets a controller offers, the STEP importer's refusals, and the shop
// server's texts (the job store's menu items and refusals, the tool store's
// failures and status).
#include "machine/machine.h"
#include "model/technology.h"
#include "post/post.h"
#include "support/speak.h"
#include "support/support.h"
#include "tools/tool_fit.h"
#include "tools/tool_library.h"
#include "ui/core_messages.h"
#include "ui/file_actions.h"
#include "ui/job_document.h"
#include "ui/job_properties.h"
#include "ui/language.h"
#include "ui/station_window.h"
#include "ui/store_actions.h"
#include "ui/tool_library_dialog.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTranslator>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

using test::speak;

// The text a chooser shows for the entry of `id`.
QString shown(const QComboBox* box, const char* id)
{
    const int i = box->findData(QString::fromLatin1(id));
    return i < 0 ? QString() : box->itemText(i);
}

// A cell of tool T`id` in the tool library dialog (by default its name).
QString nameCell(const ToolLibraryDialog& d, int id, int column = ToolLibraryDialog::Name)
{
    const auto* table = d.findChild<QTableWidget*>();
    for (int r = 0; table && r < table->rowCount(); ++r)
        if (table->item(r, 0)->text() == QString::number(id)) return table->item(r, column)->text();
    return {};
}

} // namespace

class TestGuiLanguagesData : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

  private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }
    void cleanup() { speak("en"); }

    // The job properties' material and machine choosers: the data's names in
    // the station's language, English in an English station.
    void choosersShowTheDataNames()
    {
        for (const char* language : {"en", "ja", "zh"}) {
            speak(language);
            JobDocument doc;
            JobProperties p(&doc);
            const auto* material = p.findChild<QComboBox*>("job.material");
            const auto* machine = p.findChild<QComboBox*>("job.machine");
            QVERIFY(material && machine);
            const QString l = QString::fromLatin1(language);
            QCOMPARE(shown(material, "aluminium-6061"), l == "ja"   ? QString("アルミニウム合金 A6061-T6")
                                                        : l == "zh" ? QString("铝合金 6061-T6")
                                                                    : QString("Aluminium alloy 6061-T6"));
            QCOMPARE(shown(material, "steel-s45c"), l == "ja"   ? QString("機械構造用炭素鋼 S45C (焼ならし)")
                                                    : l == "zh" ? QString("45钢（正火）")
                                                                : QString("Carbon steel S45C / C45 (normalised)"));
            QCOMPARE(shown(machine, "vmc"), l == "ja"   ? QString("vmc – 立形マシニングセンタ")
                                            : l == "zh" ? QString("vmc – 立式加工中心")
                                                        : QString("vmc – Vertical machining centre"));
        }
    }

    // The tool library dialog in Chinese: a default tool's Chinese name; a
    // tool the shop named itself (no names) its own name, in Japanese too.
    void toolLibraryDialogShowsLocalNames()
    {
        const QString path = dir_.filePath("names-tools.sqlite");
        const QByteArray before = qgetenv("TAIWA_TOOL_DB");
        qputenv("TAIWA_TOOL_DB", path.toUtf8());
        {
            auto lib = ToolLibrary::open(path.toStdString());
            QVERIFY(lib);
            Tool own = defaultToolLibrary()[0];
            own.id = 200;
            own.name = "Shop centre drill";
            own.names.clear();
            own.holder = "Shop collet chuck";
            QVERIFY(lib->save(own));
        }
        speak("zh");
        {
            ToolLibraryDialog d;
            QCOMPARE(nameCell(d, 10), QString("硬质合金麻花钻 10 mm 5xD"));
            QCOMPARE(nameCell(d, 101), QString("外圆粗加工 CNMG 120408，95° 刀杆"));
            QCOMPARE(nameCell(d, 200), QString("Shop centre drill"));
        }
        speak("ja");
        {
            ToolLibraryDialog d;
            QCOMPARE(nameCell(d, 21), QString("超硬スクエアエンドミル 2 mm"));
            QCOMPARE(nameCell(d, 200), QString("Shop centre drill"));
            // The built-in holders in Japanese, the codes kept; the shop's own as typed.
            QCOMPARE(nameCell(d, 10, ToolLibraryDialog::Holder), QString("ER32 コレットチャック"));
            QCOMPARE(nameCell(d, 106, ToolLibraryDialog::Holder), QString("GHDR 26-3 突切り"));
            QCOMPARE(nameCell(d, 80, ToolLibraryDialog::Holder), QString("HSK63 ボーリングヘッド"));
            QCOMPARE(nameCell(d, 31, ToolLibraryDialog::Holder), QString("HSK63 Weldon"));  // codes and a name only
            QCOMPARE(nameCell(d, 200, ToolLibraryDialog::Holder), QString("Shop collet chuck"));
        }
        qputenv("TAIWA_TOOL_DB", before);
    }

    // A tool-choice refusal quoting the nearest tool by name: its Japanese
    // name, the rest of the sentence translated.
    void toolChoiceQuotesTheLocalName()
    {
        tools::Fit fit;
        fit.type = ToolType::FlatEndMill;
        fit.cornerRadius = 0.5;
        const std::string english = tools::noFitMessage(defaultToolLibrary(), fit, "steel-s45c", "roughing");
        QVERIFY2(QString::fromStdString(english).contains("T21 (Flat end mill 2 mm carbide) is the nearest"), english.c_str());
        speak("ja");
        const QString ja = coreMessage(english);
        QVERIFY2(ja.contains("T21 (超硬スクエアエンドミル 2 mm)") && !ja.contains("Flat end mill") && !ja.contains("nearest"),
                 qPrintable(ja));
        // A shop's tool of no names: its own name, in Japanese as in English.
        std::vector<Tool> library = defaultToolLibrary();
        for (Tool& t : library)
            if (t.id == 21) t.name = "Shop mill 2", t.names.clear();
        knowToolNames(library);
        const QString own = coreMessage(tools::noFitMessage(library, fit, "steel-s45c", "roughing"));
        QVERIFY2(own.contains("T21 (Shop mill 2)") && !own.contains("nearest"), qPrintable(own));
        knowToolNames(defaultToolLibrary());
    }

    // The work offsets a controller offers: the refusal and its list (codes
    // kept, the joints "to" and "and" translated) as the job check shows it.
    void offsetsRefusalTranslated()
    {
        const auto problem = workOffsetProblem("linuxcnc", "G54.1 P7");
        QVERIFY(problem);
        QCOMPARE(QString::fromStdString(problem->message),
                 QString("work offset 'G54.1 P7' cannot be posted for linuxcnc: linuxcnc has no G54.1 P (FANUC's extended "
                         "work offsets); linuxcnc offers G54 to G59, G59.1, G59.2 and G59.3"));
        const auto fanuc = workOffsetProblem("fanuc", "G59.2");
        QVERIFY(fanuc);
        speak("ja");
        QCOMPARE(diagnosticText("plate.taiwa", *problem),
                 QString("plate.taiwa: ジョブ ワーク座標系: ワーク座標系 'G54.1 P7' は linuxcnc に出力できません: linuxcnc には "
                         "G54.1 P (FANUC の追加ワーク座標系) がありません。linuxcnc で使えるのは G54～G59, G59.1, G59.2、G59.3 です"));
        QCOMPARE(coreMessage(fanuc->message), QString("ワーク座標系 'G59.2' は fanuc に出力できません: fanuc には G59.2 "
                                                      "がありません。fanuc で使えるのは G54～G59、G54.1 P1～P48 です"));
        speak("zh");
        QCOMPARE(coreMessage(problem->message),
                 QString("工件坐标系 'G54.1 P7' 无法为 linuxcnc 输出：linuxcnc 没有 G54.1 P（FANUC 的扩展工件坐标系）；"
                         "linuxcnc 提供 G54 至 G59, G59.1, G59.2 和 G59.3"));
    }

    // A STEP file the importer refuses: the station's message in Japanese.
    void stepImportErrorTranslated()
    {
        const QString text = dir_.filePath("notes.step");
        test::writeFile(text, "ISO-10303-21;\nnot really\n");
        speak("ja");
        StationWindow w;
        QSignalSpy said(w.fileActions(), &FileActions::message);
        QVERIFY(!w.fileActions()->importStepPath(text));
        QVERIFY(!w.fileActions()->importStepPath(dir_.filePath("missing.step")));
        QCOMPARE(said.size(), 2);
        QCOMPARE(said[0][0].toString(), QString("%1: STEP ファイルでないか、壊れています").arg(text));
        QCOMPARE(said[1][0].toString(), QString("%1: 開けません (ファイルがありません)").arg(dir_.filePath("missing.step")));
    }

    // The shop server's texts (docs/shop-server.md): the File menu's job
    // store items, the store's refusal where the setting names a file, the
    // tool store's failures (their "saving tool T27" translated too), the
    // status while the server is away and a lock's refusal, in Japanese and
    // Chinese; English where the station speaks English.
    void shopServerTextsTranslated()
    {
        const std::string failed = "postgresql://office@crib:5432/taiwa: saving tool T27 failed (server closed the connection)";
        const std::string away = "tools as of 2026-11-29T07:40:12Z (read only: postgresql://office@crib:5432/taiwa cannot be reached)";
        const std::string held = "job 'plate' is open at station machine-2 (by machine2 since 2026-11-29T09:05:00Z) and that station is "
                                 "connected to the server now; its lock was not released";
        QCOMPARE(coreMessage(failed), QString::fromStdString(failed));
        const auto storeTexts = [&](QString* openText, QString* refusal) {
            StationWindow w;
            auto* open = w.findChild<QAction*>("action.openFromStore");
            QVERIFY(open && !open->isEnabled());  // the setting names a file
            *openText = open->text();
            QSignalSpy said(w.fileActions(), &FileActions::message);
            QVERIFY(!w.fileActions()->store()->openStored("plate"));
            QCOMPARE(said.size(), 1);
            *refusal = said[0][0].toString();
        };
        const QString file = qEnvironmentVariable("TAIWA_TOOL_DB");
        QString openText, refusal;
        storeTexts(&openText, &refusal);
        QCOMPARE(openText, QString("Open from the s&hop server…"));
        QCOMPARE(refusal, QString("The job store needs the shop server: TAIWA_TOOL_DB names the file %1, not a server").arg(file));

        speak("ja");
        storeTexts(&openText, &refusal);
        QCOMPARE(openText, QString("共有サーバーから開く(&H)…"));
        QCOMPARE(refusal, QString("ジョブストアには共有サーバーが必要です: TAIWA_TOOL_DB はサーバーではなくファイル %1 を指しています").arg(file));
        QCOMPARE(coreMessage(failed), QString("postgresql://office@crib:5432/taiwa: 工具 T27 の保存 に失敗しました（server closed the connection）"));
        QCOMPARE(coreMessage(away), QString("2026-11-29T07:40:12Z 時点の工具（読み取り専用: postgresql://office@crib:5432/taiwa に接続できません）"));
        QCOMPARE(coreMessage(held), QString("ジョブ 'plate' はステーション machine-2 で開かれており（machine2、2026-11-29T09:05:00Z から）、"
                                            "そのステーションは現在サーバーに接続しています。ロックは解除されませんでした"));

        speak("zh");
        storeTexts(&openText, &refusal);
        QCOMPARE(openText, QString("从车间服务器打开(&H)…"));
        QCOMPARE(refusal, QString("作业库需要车间服务器：TAIWA_TOOL_DB 指向的是文件 %1，而不是服务器").arg(file));
        QCOMPARE(coreMessage(failed), QString("postgresql://office@crib:5432/taiwa：保存刀具 T27 失败（server closed the connection）"));
        QCOMPARE(coreMessage(away), QString("2026-11-29T07:40:12Z 时的刀具（只读：无法连接 postgresql://office@crib:5432/taiwa）"));
        QCOMPARE(coreMessage(held), QString("作业 'plate' 正在工位 machine-2 打开（machine2，自 2026-11-29T09:05:00Z 起），该工位当前已连接服务器；其锁未被释放"));
    }
};

QTEST_MAIN(TestGuiLanguagesData)
#include "test_gui_languages_data.moc"
