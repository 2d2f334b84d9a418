// The station window with its real 3-D preview, under X (xvfb-run, the xcb
// platform): the preview follows the step list and the play button, the
// stock switches show the part after and before the selected step, a click
// on an NC block highlights its move in 3-D (pixels checked at the move's
// projected midpoint), and a click on a move in 3-D puts the NC view's
// cursor on the block posted from it; the section bar cuts the stock open
// and the verification's colour map shows on the part; the window's picture
// (grabWithPreview, as the screenshots are taken) shows the 3-D view; after
// an edit the view's frame comes before the NC text. The GUI tests (test_gui_*) run
// offscreen without OpenGL and cannot see any of this.
#include "modules/m4/m4.h"
#include "support/images.h"
#include "support/speak.h"
#include "support/support.h"
#include "ui/job_document.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/section_bar.h"
#include "ui/station_window.h"
#include "ui/step_table.h"
#include "ui/step_panel.h"
#include "ui/verification_panel.h"
#include "viz/palette.h"
#include "viz/scene.h"

#include <QAction>
#include <QCheckBox>
#include <QToolButton>
#include <QComboBox>
#include <QSlider>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QScrollBar>
#include <QtTest>

#include <cmath>

using namespace taiwa;
using taiwa::test::differingPixels;
using namespace taiwa::ui;

class TestRenderStation : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::unique_ptr<StationWindow> w_;

    PreviewWidget* preview() const { return w_->preview(); }
    QImage frame() const { return preview()->grabImage().convertToFormat(QImage::Format_RGB32); }
    const Plan& plan() const { return *w_->planRunner()->fullPlan(); }

    // The first straight feed longer than 10 mm of a step, as a move index.
    int longFeed(int step) const
    {
        const ToolPath& path = *plan().steps[static_cast<std::size_t>(step)].path;
        Point3 from = path.start;
        for (std::size_t m = 0; m < path.moves.size(); ++m) {
            const Move& mv = path.moves[m];
            if (mv.kind == MoveKind::Feed && std::hypot(mv.end.x - from.x, mv.end.y - from.y) > 10 &&
                std::abs(mv.end.z - from.z) < 1e-9)
                return static_cast<int>(m);
            from = mv.end;
        }
        return -1;
    }
    Point3 midpoint(int step, int move) const
    {
        const ToolPath& path = *plan().steps[static_cast<std::size_t>(step)].path;
        const Point3 a = move == 0 ? path.start : path.moves[static_cast<std::size_t>(move - 1)].end;
        const Point3 b = path.moves[static_cast<std::size_t>(move)].end;
        return {(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2};
    }
    int firstStepOf(StepKind kind) const
    {
        for (std::size_t k = 0; k < plan().steps.size(); ++k)
            if (plan().steps[k].kind == kind && plan().steps[k].path) return static_cast<int>(k);
        return -1;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
        w_ = std::make_unique<StationWindow>(test::sourcePath("resources/samples/plate.taiwa"));
        w_->resize(1600, 940);
        w_->show();
        QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
        QVERIFY2(preview(), "the station has no 3-D preview: OpenGL missing under this display?");
        w_->planRunner()->flush();
        QVERIFY(w_->planRunner()->fullPlan());
        QTRY_VERIFY(preview()->scene().plan() == w_->planRunner()->fullPlan().get());
        // The finished part was simulated on the planning thread.
        QVERIFY(w_->planRunner()->stockSimulation());
        QCOMPARE(w_->planRunner()->stockSimulation()->stepCount(), static_cast<int>(plan().steps.size()));
    }
    void cleanupTestCase() { w_.reset(); }

    // The window's picture has the 3-D view at the preview's place: its
    // frame, pixel for pixel, with background and machined-part colours
    // (QWidget::grab alone leaves that rectangle to the window's grey).
    void grabbedWindowShowsTheView()
    {
        w_->findChild<QAbstractButton*>("step.all")->click();
        const QImage image = grabWithPreview(w_.get()).convertToFormat(QImage::Format_RGB32);
        QCOMPARE(image.size(), w_->size() * w_->devicePixelRatio());
        const QImage view = frame();
        const QRect at(preview()->mapTo(w_.get(), QPoint(0, 0)), preview()->size());
        QVERIFY2(at.width() > 300 && at.height() > 200, qPrintable(QString("%1 x %2").arg(at.width()).arg(at.height())));
        QCOMPARE(view.size(), at.size());
        int background = 0, green = 0;
        for (int y = 0; y < at.height(); ++y)
            for (int x = 0; x < at.width(); ++x) {
                const QRgb c = image.pixel(at.x() + x, at.y() + y);
                background += test::near(c, viz::palette::kBackground, 0) ? 1 : 0;
                green += qGreen(c) > qRed(c) + 30 && qGreen(c) > qBlue(c) + 10 ? 1 : 0;
            }
        const int area = at.width() * at.height();
        QVERIFY2(background > area / 10, qPrintable(QString("%1 of %2").arg(background).arg(area)));
        QVERIFY2(green > area / 50, qPrintable(QString("%1 of %2").arg(green).arg(area)));
        QCOMPARE(differingPixels(image.copy(at), view), 0);
    }

    void previewFollowsTheStepList()
    {
        const int k = firstStepOf(StepKind::Roughing);
        QVERIFY(k > 0);
        w_->stepPanel()->selectStep(k);
        QCOMPARE(preview()->scene().selectedStep(), k);
        w_->findChild<QAbstractButton*>("step.all")->click();
        QCOMPARE(preview()->scene().selectedStep(), -1);
    }

    void playWalksThroughEveryStep()
    {
        StepPanel* panel = w_->stepPanel();
        panel->setPlayInterval(20);
        std::vector<int> seen;
        auto* scene = &preview()->scene();
        QTimer probe;
        connect(&probe, &QTimer::timeout, this, [&] {
            if (seen.empty() || seen.back() != scene->selectedStep()) seen.push_back(scene->selectedStep());
        });
        probe.start(2);
        w_->findChild<QAbstractButton*>("step.play")->click();
        QTRY_VERIFY_WITH_TIMEOUT(!panel->isPlaying(), 20'000);
        probe.stop();
        QCOMPARE(scene->selectedStep(), -1);  // back to all steps at the end
        QVERIFY(seen.size() > plan().steps.size() / 2);  // most steps seen in between, in order
        for (std::size_t i = 1; i + 1 < seen.size(); ++i) QVERIFY(seen[i] > seen[i - 1]);
    }

    void stockBeforeAndAfterTheStep()
    {
        const int k = firstStepOf(StepKind::Roughing);
        auto* stock = w_->findChild<QCheckBox*>("view.stock");
        auto* before = w_->findChild<QCheckBox*>("view.before");
        QVERIFY(stock && before);
        QVERIFY(stock->isChecked());
        w_->stepPanel()->selectStep(k);
        const QImage after = frame();
        before->click();
        QVERIFY(preview()->scene().stockBefore());
        const QImage beforeImage = frame();
        // The pocket this step roughs out is open in one and closed in the
        // other: a large area differs.
        QVERIFY2(differingPixels(after, beforeImage) > 2000, qPrintable(QString::number(differingPixels(after, beforeImage))));
        before->click();
        QVERIFY(!preview()->scene().stockBefore());
        QCOMPARE(differingPixels(after, frame()), 0);
        stock->click();  // the glass block: the switch for before/after goes grey
        QVERIFY(!before->isEnabled());
        stock->click();
        QVERIFY(before->isEnabled());
    }

    // Issue 34, item 7: the View menu's "Tool paths" and the box under the
    // step list are one switch; off, the view draws no path (the picture
    // changes where the paths were), on again, the same picture as before.
    // "Zoom to step" frames the selected step: its path fills more of the
    // view than in the whole view.
    void pathsSwitchAndZoomToStep()
    {
        auto* box = w_->findChild<QCheckBox*>("view.paths");
        auto* menu = w_->findChild<QAction*>("menu.view.paths");
        QVERIFY(box && menu);
        QVERIFY(box->isChecked() && menu->isChecked());
        w_->stepPanel()->selectStep(-1);
        const QImage with = frame();
        menu->trigger();
        QVERIFY(!box->isChecked());
        QVERIFY(!preview()->scene().pathsShown());
        QCOMPARE(preview()->scene().drawnPathSegments(), std::size_t{0});
        const QImage without = frame();
        QVERIFY2(differingPixels(with, without) > 500, qPrintable(QString::number(differingPixels(with, without))));
        box->click();
        QVERIFY(menu->isChecked() && preview()->scene().pathsShown());
        QCOMPARE(differingPixels(with, frame()), 0);
        // The part's outlines switched off and on in the View menu.
        auto* part = w_->findChild<QAction*>("menu.view.part");
        QVERIFY(part && part->isChecked());
        part->trigger();
        QVERIFY(!preview()->scene().partShown());
        QVERIFY(differingPixels(with, frame()) > 200);
        part->trigger();
        QCOMPARE(differingPixels(with, frame()), 0);

        const int k = firstStepOf(StepKind::PilotHole);
        w_->stepPanel()->selectStep(k);
        const Step& step = w_->planRunner()->fullPlan()->steps[static_cast<std::size_t>(k)];
        const Point3 a = step.path->start, b{a.x + 5, a.y, a.z};
        const auto span = [&] {
            const auto pa = preview()->scene().toPixel(a, preview()->width(), preview()->height());
            const auto pb = preview()->scene().toPixel(b, preview()->width(), preview()->height());
            return std::hypot(pb[0] - pa[0], pb[1] - pa[1]);
        };
        const double whole = span();
        auto* zoom = w_->findChild<QToolButton*>("view.step");
        QVERIFY(zoom);
        zoom->click();
        QVERIFY2(span() > 2 * whole, qPrintable(QString("5 mm: %1 px, %2 px before").arg(span()).arg(whole)));
        preview()->setView(viz::ViewPreset::Iso);
        w_->stepPanel()->selectStep(-1);
    }

    // The section bar under the view: off at first; across X it cuts the
    // stock open at the slider's place and the face it cuts shows; off
    // again, the picture is what it was. The colour map ticked after a
    // verification colours the finished part; cleared, the stock is back.
    void sectionAndColourMapInTheView()
    {
        w_->findChild<QAbstractButton*>("step.all")->click();
        SectionBar* bar = w_->sectionBar();
        QVERIFY(bar && bar->isEnabled());
        QVERIFY(!preview()->scene().section());
        const QImage plain = frame();
        bar->axisChooser()->setCurrentIndex(1);
        QVERIFY(preview()->scene().section());
        const Stock& st = plan().mmJob.stock;
        QVERIFY(std::abs(preview()->scene().section()->origin.x - (st.x + st.width / 2)) < 0.2);
        bar->slider()->setValue(bar->slider()->maximum() / 4);
        QVERIFY(std::abs(preview()->scene().section()->origin.x - (st.x + st.width / 4)) < 0.2);
        const QImage cut = frame();
        int face = 0;
        for (int y = 0; y < cut.height(); ++y)
            for (int x = 0; x < cut.width(); ++x) face += test::near(cut.pixel(x, y), viz::palette::kSection, 6) ? 1 : 0;
        QVERIFY2(face > 2000, qPrintable(QString::number(face)));
        bar->axisChooser()->setCurrentIndex(0);
        QVERIFY(!preview()->scene().section());
        QCOMPARE(differingPixels(plain, frame()), 0);

        VerificationPanel* v = w_->verificationPanel();
        v->verifyNow();
        QVERIFY(v->colourMapBox()->isEnabled());
        v->colourMapBox()->click();
        QVERIFY(preview()->scene().showsDeviation());
        const QImage map = frame();
        int green = 0;
        for (int y = 0; y < map.height(); ++y)
            for (int x = 0; x < map.width(); ++x) green += test::near(map.pixel(x, y), viz::palette::kAtSize, 30) ? 1 : 0;
        QVERIFY2(green > 2000, qPrintable(QString::number(green)));
        v->colourMapBox()->click();
        QVERIFY(!preview()->scene().showsDeviation());
        QCOMPARE(differingPixels(plain, frame()), 0);
    }

    // The step list's columns fit without scrolling sideways in the window
    // opened on a 1600-pixel screen: No., unit, step, tool, S, F, depths,
    // time (here, with the X server's fonts and the 3-D view in its place).
    void stepColumnsFitAt1600()
    {
        StationWindow w(test::sourcePath("resources/samples/plate.taiwa"));
        w.resize(1600, 940);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.planRunner()->flush();
        QCoreApplication::processEvents();
        StepTable* table = w.stepTable();
        int columns = 0;
        for (int c = 0; c < table->columnCount(); ++c) columns += table->columnWidth(c);
        QVERIFY2(columns <= table->viewport()->width() && !table->horizontalScrollBar()->isVisible(),
                 qPrintable(QString("columns %1 px in a %2 px view").arg(columns).arg(table->viewport()->width())));
    }

    void ncBlockHighlightsItsMove()
    {
        const int k = firstStepOf(StepKind::Roughing);
        const int m = longFeed(k);
        QVERIFY(m >= 0);
        w_->stepPanel()->selectStep(k);
        NcView* nc = w_->ncView();
        // Scroll the block into view, put the cursor on the line before it,
        // then click the block as the operator would.
        QVERIFY(nc->selectMove(k, m));
        const QRect line = nc->text()->cursorRect();
        nc->text()->moveCursor(QTextCursor::PreviousBlock);
        QVERIFY(nc->currentSource().move != m);
        QTest::mouseClick(nc->text()->viewport(), Qt::LeftButton, {}, QPoint(8, line.center().y()));
        QCOMPARE(nc->currentSource().step, k);
        QCOMPARE(nc->currentSource().move, m);
        QCOMPARE(preview()->scene().highlightedMove(), (viz::MoveRef{k, m}));
        const auto at = preview()->scene().toPixel(midpoint(k, m), preview()->width(), preview()->height());
        QVERIFY(test::colourNear(frame(), at, viz::palette::kHighlight, 2, 40));
        // The block is a band across the NC view, and the tool stands where
        // the block leaves it; the arrow key walks on, block by block.
        const auto& moves = w_->planRunner()->fullPlan()->steps[static_cast<std::size_t>(k)].path->moves;
        QCOMPARE(nc->highlightedLine(), nc->text()->textCursor().blockNumber());
        QCOMPARE(preview()->scene().toolPosition(), std::optional<Point3>(moves[static_cast<std::size_t>(m)].end));
        const int band = nc->highlightedLine();
        nc->text()->setFocus();
        QTest::keyClick(nc->text(), Qt::Key_Down);
        QCOMPARE(nc->highlightedLine(), band + 1);
        const BlockSource next = nc->currentSource();
        QCOMPARE(next.step, k);
        QCOMPARE(preview()->scene().highlightedMove(), (viz::MoveRef{k, next.move}));
        QCOMPARE(preview()->scene().toolPosition(), std::optional<Point3>(moves[static_cast<std::size_t>(next.move)].end));
        QVERIFY(moves[static_cast<std::size_t>(next.move)].end != moves[static_cast<std::size_t>(m)].end);
    }

    void clickInThreeDSelectsTheBlock()
    {
        const int k = firstStepOf(StepKind::Roughing);
        const int m = longFeed(k);
        w_->stepPanel()->selectStep(k);
        w_->findChild<QAbstractButton*>("view.top")->click();
        const viz::Scene& scene = preview()->scene();
        const auto mid = scene.toPixel(midpoint(k, m), preview()->width(), preview()->height());
        // The pixel the click lands on (passes of one step lie close together in the top view).
        const std::array<double, 2> at{std::round(mid[0]), std::round(mid[1])};
        const auto picked = scene.pickMove(at[0], at[1], preview()->width(), preview()->height());
        QVERIFY(picked);
        QCOMPARE(picked->step, k);
        w_->ncView()->text()->moveCursor(QTextCursor::Start);
        preview()->highlightMove(-1, -1);
        QTest::mouseClick(preview(), Qt::LeftButton, {}, QPoint(qRound(at[0]), qRound(at[1])));
        QCOMPARE(w_->ncView()->currentSource().step, picked->step);
        QCOMPARE(w_->ncView()->currentSource().move, picked->move);
        QCOMPARE(scene.highlightedMove(), *picked);
    }

    // After an edit the 3-D view's frame of the new plan is on screen before
    // the NC text is laid out (the text waits for it): a 0 ms catch-up used
    // to run first and hold the frame up by its layout.
    void frameOfAnEditBeforeTheNcText()
    {
        QStringList order;
        auto c1 = connect(w_->planRunner(), &PlanRunner::programReady, this, [&] { order << "plan"; });
        auto c2 = connect(preview(), &PreviewWidget::frameShown, this, [&] { order << "frame"; });
        auto c3 = connect(w_->ncView()->text(), &QPlainTextEdit::textChanged, this, [&] { order << "nc"; });
        Job j = w_->document()->job();
        const double depth = j.units[0].module.as<M4Pocket>().depth;
        j.units[0].module.as<M4Pocket>().depth = depth + 0.5;
        w_->document()->edit(j, "deeper", "deeper");
        QTRY_VERIFY_WITH_TIMEOUT(order.contains("nc"), 10'000);
        disconnect(c1);
        disconnect(c2);
        disconnect(c3);
        const qsizetype plan = order.indexOf("plan");
        QVERIFY2(plan >= 0 && order.indexOf("frame", plan) > plan && order.indexOf("frame", plan) < order.indexOf("nc", plan),
                 qPrintable(order.join(", ")));
        j.units[0].module.as<M4Pocket>().depth = depth;
        w_->document()->edit(j, "back", "back");
        w_->planRunner()->flush();
    }

    // A Japanese station's 3-D view writes its scale note in Japanese; a
    // scene made beside it (as `taiwa render` makes one) keeps English.
    void axesNoteInTheStationsLanguage()
    {
        test::speak("ja");
        StationWindow ja(test::sourcePath("resources/samples/plate.taiwa"));
        ja.show();
        QVERIFY(QTest::qWaitForWindowExposed(&ja));
        QVERIFY(ja.preview());
        ja.planRunner()->flush();
        QTRY_COMPARE(QString::fromStdString(ja.preview()->scene().scaleNote()), QString("軸 50 mm"));
        viz::Scene other;
        other.setPlan(ja.planRunner()->fullPlan());
        QCOMPARE(QString::fromStdString(other.scaleNote()), QString("axes 50 mm"));
        test::speak("en");
    }
};

QTEST_MAIN(TestRenderStation)
#include "test_render_station.moc"
