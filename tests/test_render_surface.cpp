// Module SURFACE in the station's real 3-D view, under X (xvfb-run -a)
// (issue 36): the finishing surface is drawn, tessellated from the plan's
// finishing step, under its paths (the picture changes where it is hidden),
// and hidden under the verification's colour map; a click on a finishing
// move in the view puts the NC view's cursor on the block posted from it,
// whose X and Y are the move's end. With TAIWA_SCREENSHOTS_DIR set it writes
// docs/screenshots/station-surface.png: the station with the unit's form,
// its roughing step selected and its passes over the surface, and
// station-surface-view.png, the 3-D view with the finishing paths.
#include "support/images.h"
#include "support/support.h"
#include "ui/nc_view.h"
#include "ui/plan_runner.h"
#include "ui/preview_widget.h"
#include "ui/station_window.h"
#include "ui/step_panel.h"
#include "ui/verification_panel.h"
#include "viz/scene.h"

#include <QCheckBox>
#include <QDir>
#include <QPlainTextEdit>
#include <QTemporaryDir>
#include <QTextBlock>
#include <QtTest>

#include <vtkActor.h>

#include <cmath>

using namespace taiwa;
using namespace taiwa::ui;

class TestRenderSurface : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    std::unique_ptr<StationWindow> w_;

    PreviewWidget* preview() const { return w_->preview(); }
    QImage frame() const { return preview()->grabImage().convertToFormat(QImage::Format_RGB32); }
    const Plan& plan() const { return *w_->planRunner()->fullPlan(); }
    int finishingStep() const
    {
        for (std::size_t k = 0; k < plan().steps.size(); ++k)
            if (plan().steps[k].machiningType == MachiningType::SurfaceFinishing && plan().steps[k].path)
                return static_cast<int>(k);
        return -1;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(dir_.isValid());
        test::isolateStation(dir_.path());
        w_ = std::make_unique<StationWindow>(test::sourcePath("tests/data/surface-ruled.taiwa"));
        w_->resize(1600, 940);
        w_->show();
        QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
        QVERIFY2(preview(), "the station has no 3-D preview: OpenGL missing under this display?");
        w_->planRunner()->flush();
        QVERIFY(w_->planRunner()->fullPlan());
        QTRY_VERIFY_WITH_TIMEOUT(preview()->scene().plan() == w_->planRunner()->fullPlan().get(), 60'000);
        QVERIFY(plan().ok());
        QVERIFY(finishingStep() >= 0);
    }
    void cleanupTestCase() { w_.reset(); }

    // The surface's actor holds the finishing surface's triangles, and it
    // shows: hiding it changes a large part of the picture.
    void surfaceIsDrawnUnderItsPaths()
    {
        const viz::Scene& scene = preview()->scene();
        auto* surface = const_cast<vtkActor*>(scene.machinedSurfaceActor());
        QVERIFY(surface);
        QVERIFY2(scene.machinedSurfaceTriangles() > 1000, qPrintable(QString::number(scene.machinedSurfaceTriangles())));
        QVERIFY(surface->GetVisibility());
        w_->findChild<QAbstractButton*>("step.all")->click();
        w_->findChild<QAbstractButton*>("view.iso")->click();
        const QImage shown = frame();
        surface->SetVisibility(false);
        preview()->update();
        const QImage hidden = frame();
        surface->SetVisibility(true);
        preview()->update();
        const int differ = test::differingPixels(shown, hidden);
        qInfo("surface: %zu triangles; hiding it changes %d of %d pixels", scene.machinedSurfaceTriangles(), differ,
              shown.width() * shown.height());
        QVERIFY2(differ > shown.width() * shown.height() / 50,
                 qPrintable(QString("%1 of %2 pixels").arg(differ).arg(shown.width() * shown.height())));
        QCOMPARE(test::differingPixels(shown, frame()), 0);
        // The colour map shows the part itself: the surface steps aside.
        VerificationPanel* v = w_->verificationPanel();
        v->verifyNow();
        QVERIFY(v->colourMapBox()->isEnabled());
        v->colourMapBox()->click();
        QVERIFY(preview()->scene().showsDeviation());
        QVERIFY(!surface->GetVisibility());
        v->colourMapBox()->click();
        QVERIFY(surface->GetVisibility());
    }

    // A click on a finishing move in the top view selects its NC block.
    void clickOnAFinishingMoveSelectsItsBlock()
    {
        const int k = finishingStep();
        w_->stepPanel()->selectStep(k);
        w_->findChild<QAbstractButton*>("view.top")->click();
        const ToolPath& path = *plan().steps[static_cast<std::size_t>(k)].path;
        // A feed in the middle of the program, along a path (not a plunge).
        int m = static_cast<int>(path.moves.size() / 2);
        const auto start = [&](int i) { return i == 0 ? path.start : path.moves[static_cast<std::size_t>(i - 1)].end; };
        while (m < static_cast<int>(path.moves.size()) &&
               !(path.moves[static_cast<std::size_t>(m)].kind == MoveKind::Feed &&
                 std::hypot(path.moves[static_cast<std::size_t>(m)].end.x - start(m).x,
                            path.moves[static_cast<std::size_t>(m)].end.y - start(m).y) > 0.1))
            ++m;
        QVERIFY(m < static_cast<int>(path.moves.size()));
        const Point3 a = start(m), b = path.moves[static_cast<std::size_t>(m)].end;
        const viz::Scene& scene = preview()->scene();
        const auto at = scene.toPixel({(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2}, preview()->width(),
                                      preview()->height());
        const QPoint click(qRound(at[0]), qRound(at[1]));
        const auto picked = scene.pickMove(click.x(), click.y(), preview()->width(), preview()->height());
        QVERIFY(picked);
        QCOMPARE(picked->step, k);
        w_->ncView()->text()->moveCursor(QTextCursor::Start);
        preview()->highlightMove(-1, -1);
        QTest::mouseClick(preview(), Qt::LeftButton, {}, click);
        QCOMPARE(w_->ncView()->currentSource().step, k);
        QCOMPARE(w_->ncView()->currentSource().move, picked->move);
        QCOMPARE(scene.highlightedMove(), *picked);
        // The block under the cursor is the move's: its X and Y (those it
        // writes) are the picked move's end, a few pixels from the click.
        const Point3 end = path.moves[static_cast<std::size_t>(picked->move)].end;
        const QString block = w_->ncView()->text()->textCursor().block().text();
        const auto has = [&](char axis, double v) {
            const qsizetype i = block.indexOf(QChar(axis));
            return i < 0 || std::abs(block.mid(i + 1).section(' ', 0, 0).toDouble() - v) < 1e-3;
        };
        QVERIFY2(block.contains('X') || block.contains('Y'), qPrintable(block));
        QVERIFY2(has('X', end.x) && has('Y', end.y), qPrintable(block + QString(" against X%1 Y%2").arg(end.x).arg(end.y)));
        const auto endAt = scene.toPixel(end, preview()->width(), preview()->height());
        QVERIFY(std::hypot(endAt[0] - click.x(), endAt[1] - click.y()) < 10);
    }

    // The station's pictures with the surface unit, for docs/surfaces.md,
    // over the glass stock (the surface in its colour between the paths):
    // the window with the roughing step selected (its Z-level passes leave
    // the surface to see), and the 3-D view alone with the finishing step's.
    void screenshot()
    {
        const QString out = qEnvironmentVariable("TAIWA_SCREENSHOTS_DIR");
        if (out.isEmpty()) QSKIP("TAIWA_SCREENSHOTS_DIR not set");
        auto* stock = w_->findChild<QCheckBox*>("view.stock");
        QVERIFY(stock);
        if (stock->isChecked()) stock->click();
        w_->findChild<QAbstractButton*>("view.iso")->click();
        preview()->highlightMove(-1, -1);
        QDir().mkpath(out);
        w_->stepPanel()->selectStep(finishingStep() == 0 ? 1 : 0);
        QCoreApplication::processEvents();
        const QImage image = grabWithPreview(w_.get());
        QVERIFY(!image.isNull());
        QVERIFY(image.save(QDir(out).filePath("station-surface.png")));
        w_->stepPanel()->selectStep(finishingStep());
        QCoreApplication::processEvents();
        QVERIFY(frame().save(QDir(out).filePath("station-surface-view.png")));
        stock->click();
    }
};

QTEST_MAIN(TestRenderSurface)
#include "test_render_surface.moc"
