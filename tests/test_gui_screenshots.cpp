// The station on the sample plate.taiwa: it opens with every unit listed,
// the step list and the NC program filled, and each step can be selected;
// in Japanese, the compiled-in translation is used.
// With TAIWA_SCREENSHOTS_DIR set (run under `xvfb-run -a` so that the 3-D
// view renders) it also writes the PNGs of docs/screenshots/: the whole
// window, the window with single steps selected, and a contact sheet of the
// 3-D view with each step selected in turn (simulated stock after it), and
// a verification finding chosen (station-verification.png) and its colour
// map with the stock cut open (station-colour-map.png); every module's form
// at 1280 x 720 and 1366 x 768 in each language (forms/).
#include "modules/m2d/m2d.h"
#include "modules/m4/m4.h"
#include "modules/registry.h"
#include "support/support.h"
#include "ui/job_document.h"
#include "ui/language.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/section_bar.h"
#include "ui/station_window.h"
#include "ui/verification_panel.h"
#include "ui/step_panel.h"
#include "ui/step_table.h"
#include "ui/unit_list_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QSlider>
#include <QToolButton>
#include <QMenuBar>
#include <QPainter>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSet>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTranslator>
#include <QListWidget>
#include <QtTest>

using namespace taiwa;
using namespace taiwa::ui;

// The station in `language` alone: the translations of the rows before are
// taken out, then the language's installed (none for English).
static bool onlyLanguage(const QString& language)
{
    for (auto* t : QCoreApplication::instance()->findChildren<QTranslator*>()) {
        QCoreApplication::removeTranslator(t);
        delete t;
    }
    qputenv("TAIWA_LANG", language.toUtf8());
    return installTranslator(*QCoreApplication::instance()) == (language != "en");
}

class TestGuiScreenshots : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // A sample by its path in the project, from the project's folder: the
    // pictures show "resources/samples/plate.taiwa", never a path of the
    // machine they were made on.
    static QString sample(const QString& file)
    {
        QDir::setCurrent(test::sourcePath(""));
        return "resources/samples/" + file;
    }

    static void settle(StationWindow& w)
    {
        w.planRunner()->flush();
        QTRY_VERIFY(!w.planRunner()->isBusy());
        QCoreApplication::sendPostedEvents();  // layout
    }
    // The window as a picture: its full size and not blank (a window grabbed
    // before it was laid out or painted is one flat colour). Saved when
    // TAIWA_SCREENSHOTS_DIR names a folder.
    static void save(StationWindow& w, const QString& name)
    {
        QVERIFY2(!w.statusBar()->currentMessage().contains(QDir(test::sourcePath("")).absolutePath()),
                 qPrintable(w.statusBar()->currentMessage()));
        QVERIFY2(!w.windowTitle().contains(QDir(test::sourcePath("")).absolutePath()), qPrintable(w.windowTitle()));
        const QImage image = grabWithPreview(&w);  // QWidget::grab lacks the GL view
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), w.size() * w.devicePixelRatio());
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 7)
            for (int x = 0; x < image.width(); x += 7) colours.insert(image.pixel(x, y));
        QVERIFY2(colours.size() > 50, qPrintable(name + ": " + QString::number(colours.size()) + " colours"));
        const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
        if (out.isEmpty()) return;
        QDir().mkpath(out);
        QVERIFY(image.save(QDir(out).filePath(name)));
    }

    // Every step selected in turn: the 3-D view as a tile with the step's
    // number, unit and label, six tiles a row.
    static void contactSheet(StationWindow& w)
    {
        constexpr int kTileW = 400, kTileH = 260, kColumns = 6, kCaption = 22;
        const QStringList labels = w.stepTable()->stepLabels();
        const int steps = static_cast<int>(labels.size());
        const int rows = (steps + kColumns - 1) / kColumns;
        QImage sheet(kColumns * kTileW, rows * (kTileH + kCaption), QImage::Format_RGB32);
        sheet.fill(QColor(238, 238, 238));
        QPainter painter(&sheet);
        QFont font = painter.font();
        font.setPixelSize(14);
        painter.setFont(font);
        const auto& plan = *w.planRunner()->fullPlan();
        for (int k = 0; k < steps; ++k) {
            w.stepPanel()->selectStep(k);
            QCoreApplication::processEvents();
            const QImage view = w.preview()->grabImage().scaled(kTileW, kTileH, Qt::KeepAspectRatio, Qt::SmoothTransformation);
            const int x = (k % kColumns) * kTileW, y = (k / kColumns) * (kTileH + kCaption);
            painter.drawImage(x + (kTileW - view.width()) / 2, y + kCaption, view);
            const Step& s = plan.steps[static_cast<std::size_t>(k)];
            painter.setPen(Qt::black);
            painter.drawText(QRect(x + 6, y, kTileW - 12, kCaption), Qt::AlignVCenter | Qt::AlignLeft,
                             QStringLiteral("%1. unit %2: %3").arg(k + 1).arg(s.unit + 1).arg(labels[k]));
        }
        painter.end();
        QVERIFY(sheet.save(QDir(qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR")).filePath("station-plate-steps.png")));
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
    }

    void plate()
    {
        StationWindow w(sample("plate.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(!w.document()->job().units.empty());
        settle(w);
        QVERIFY(w.planRunner()->fullPlan());
        const int steps = w.stepTable()->rowCount();
        QCOMPARE(steps, static_cast<int>(w.planRunner()->fullPlan()->steps.size()));
        QCOMPARE(steps, 29);  // plate.taiwa: 6 units (the README's contact sheet shows each)
        QCOMPARE(w.stepTable()->stepLabels().size(), 29);
        QVERIFY(w.ncView()->text()->toPlainText().startsWith("%") ||
                w.ncView()->text()->toPlainText().contains("G21"));
        save(w, "station-plate.png");

        const int shown[] = {0, 1, steps - 1};
        for (int k : shown) {
            w.stepPanel()->selectStep(k);
            QCOMPARE(w.stepPanel()->selectedStep(), k);
            settle(w);
            save(w, QStringLiteral("station-plate-step%1.png").arg(k + 1));
        }
        if (w.preview() && !qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR").isEmpty()) contactSheet(w);

        // The M2D unit's form with its drawing.
        const auto& units = w.document()->job().units;
        for (std::size_t i = 0; i < units.size(); ++i)
            if ((units[i].module).is<M2DPocket>()) {
                w.unitList()->selectUnit(static_cast<int>(i));
                break;
            }
        w.stepPanel()->selectStep(-1);
        settle(w);
        save(w, "station-plate-m2d.png");
    }

    // A verification finding chosen: a floor pass put 0.3 mm too deep by
    // the test (no real job gouges), listed in red, its step selected, its
    // block in the tape, its point marked in the 3-D view.
    void verificationFinding()
    {
        StationWindow w(sample("m4-standard.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        settle(w);
        auto plan = std::make_shared<Plan>(*w.planRunner()->fullPlan());
        for (Step& s : plan->steps) {
            if (s.kind != StepKind::FloorFinishing) continue;
            for (std::size_t i = 2; i < s.path->moves.size(); ++i)
                if (s.path->moves[i].kind == MoveKind::Feed) {
                    s.path->moves[i].end.z -= 0.3;
                    break;
                }
            break;
        }
        w.verificationPanel()->setPlan(plan);
        w.verificationPanel()->verifyNow();
        QVERIFY(w.verificationPanel()->list()->count() > 0);
        w.verificationPanel()->list()->setCurrentRow(0);
        settle(w);
        save(w, "station-verification.png");

        // The same verification's colour map, the stock cut open across Y
        // through the gouge and seen from the front side (the gouge red,
        // the finished floors and walls green, the face cut in violet).
        w.verificationPanel()->colourMapBox()->click();
        QVERIFY(w.verificationPanel()->colourMapBox()->isChecked());
        if (SectionBar* bar = w.sectionBar()) {
            const Stock& st = plan->mmJob.stock;
            const double y = w.verificationPanel()->report().findings.front().position.y;
            bar->axisChooser()->setCurrentIndex(2);
            bar->slider()->setValue(static_cast<int>(std::lround((y - st.y) / st.length * bar->slider()->maximum())));
            bar->flip()->click();
        }
        settle(w);
        save(w, "station-colour-map.png");
    }

    void japanese()
    {
        qputenv("TAIWA_LANG", "ja");
        QVERIFY(installTranslator(*QCoreApplication::instance()));
        StationWindow w(sample("plate.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QStringList menus;
        for (QAction* a : w.menuBar()->actions()) menus << a->text();
        QCOMPARE(menus.first(), QString("ファイル(&F)"));
        settle(w);
        save(w, "station-plate-ja.png");
    }

    // Simplified Chinese, on a lathe job (the turned-profile editor).
    void chinese()
    {
        qputenv("TAIWA_LANG", "zh");
        QVERIFY(installTranslator(*QCoreApplication::instance()));
        StationWindow w(sample("lathe-shaft-grinding.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QStringList menus;
        for (QAction* a : w.menuBar()->actions()) menus << a->text();
        QCOMPARE(menus.first(), QString("文件(&F)"));
        w.unitList()->selectUnit(0);
        auto* add = w.findChild<QPushButton*>("turn.addRow");
        QVERIFY(add);
        QCOMPARE(add->text(), QString("添加行"));
        settle(w);
        save(w, "station-lathe-zh.png");
    }

    // The station at the two common screen sizes, in each language, on the
    // plate with its second step selected: station-1366x768-en.png ...
    // station-1920x1080-zh.png (the window as the screen's free area leaves
    // it: the height less a 48-pixel panel).
    void screenSizes_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("size");
        for (const char* language : {"en", "ja", "zh"})
            for (const QSize size : {QSize(1366, 720), QSize(1920, 1032)})
                QTest::newRow(qPrintable(QString("%1 %2").arg(language).arg(size.width()))) << QString(language) << size;
    }
    void screenSizes()
    {
        QFETCH(QString, language);
        QFETCH(QSize, size);
        QVERIFY(onlyLanguage(language));
        StationWindow w(sample("plate.taiwa"));
        w.resize(size);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.size(), size);
        settle(w);
        w.stepPanel()->selectStep(1);
        settle(w);
        const int screenHeight = size.width() == 1366 ? 768 : 1080;
        save(w, QStringLiteral("station-%1x%2-%3.png").arg(size.width()).arg(screenHeight).arg(language));
    }

    // Every module's form at 1280 x 720 and 1366 x 768 (the window at the
    // screen's free area), in each language, its first field focused:
    // docs/screenshots/forms/FORM-WIDTHxHEIGHT-LANG.png, the unit column only
    // (M4 and the other milling modules on a new job, TURN on
    // lathe-turned-shaft.taiwa).
    void moduleForms_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QSize>("size");
        for (const char* language : {"en", "ja", "zh"})
            for (const QSize size : {QSize(1280, 672), QSize(1366, 720)})
                QTest::newRow(qPrintable(QString("%1 %2").arg(language).arg(size.width()))) << QString(language) << size;
    }
    void moduleForms()
    {
        QFETCH(QString, language);
        QFETCH(QSize, size);
        QVERIFY(onlyLanguage(language));
        const int screenHeight = size.width() == 1366 ? 768 : 720;
        const auto shoot = [&](StationWindow& w, const QString& module) {
            auto* unit = w.findChild<QWidget*>("unit.scroll")->parentWidget();
            QCoreApplication::sendPostedEvents();
            QCoreApplication::processEvents();
            const QImage image = unit->grab().toImage();
            QVERIFY(!image.isNull() && image.width() > 200);
            const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
            if (out.isEmpty()) return;
            QDir(out).mkpath("forms");
            QVERIFY(image.save(QDir(out).filePath(
                QStringLiteral("forms/%1-%2x%3-%4.png").arg(module.toLower()).arg(size.width()).arg(screenHeight).arg(language))));
        };
        {
            StationWindow w;
            w.resize(size);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            Job j = w.document()->job();
            for (const ModuleKind* kind : moduleKinds()) {
                if (kind->machineKind() != MachineKind::Mill) continue;
                if (j.figure.empty()) j.figure = kind->defaultFigure(j.stock);
                j.units.push_back(MachiningUnit{"", kind->makeDefault(toMillimetres(j).stock)});
            }
            w.document()->edit(j, "every module", {}, 0);
            settle(w);
            for (int u = 0; u < static_cast<int>(j.units.size()); ++u) {
                w.unitList()->selectUnit(u);
                settle(w);
                shoot(w, QString::fromStdString(j.units[static_cast<std::size_t>(u)].module.name()));
            }
        }
        StationWindow w(sample("lathe-turned-shaft.taiwa"));
        w.resize(size);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        settle(w);
        w.unitList()->selectUnit(0);
        settle(w);
        shoot(w, "TURN");
    }
};

QTEST_MAIN(TestGuiScreenshots)
#include "test_gui_screenshots.moc"
