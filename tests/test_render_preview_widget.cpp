// The preview scene inside the station's Qt widget (PreviewWidget, VTK in a
// QOpenGLWindow held in a window container) under X: the hand-built plan's
// path, rapid and tool at their pixels, the selected step and highlighted
// move; the frame is put, opaque, into a picture of the window holding it
// (grabWithPreview, as the station's screenshots are taken); the sample
// m4-standard.taiwa shows background and path; a click on a path reports
// its move and a left drag turns the camera without clicking, both sent to
// the widget and to its GL window (as the window system delivers them). A
// new plan is one frame, drawn in the next pass of the event loop; taking
// away a colour map that is not there draws none.
// Needs an X display (xvfb-run -a).
#include "support/hand_plan.h"
#include "support/images.h"
#include "ui/preview_widget.h"
#include "verify/deviation.h"
#include "viz/palette.h"
#include "viz/scene.h"

#include <QApplication>
#include <QSignalSpy>
#include <QVBoxLayout>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkRenderer.h>

using namespace taiwa;
using namespace taiwa::test;
using namespace taiwa::viz;
using taiwa::ui::PreviewWidget;

class TestRenderPreviewWidget : public QObject {
    Q_OBJECT
    Plan plan_ = handPlan();

    // The hand-built plan in the widget, kW x kH, top view, shown.
    void showFromTop(PreviewWidget& w)
    {
        w.resize(kW, kH);
        w.setPlan(std::make_shared<const Plan>(plan_));
        w.setView(ViewPreset::Top);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
    }

private slots:
    void widgetShowsTheScene()
    {
        PreviewWidget w;
        showFromTop(w);
        if (QTest::currentTestFailed()) return;
        QImage img = w.grabImage().convertToFormat(QImage::Format_RGB32);
        const QByteArray shots = qgetenv("TAIWA_SCREENSHOTS");
        if (!shots.isEmpty()) img.save(shots + "/preview-widget-top.png");
        QCOMPARE(img.size(), QSize(kW, kH));
        const auto& scene = w.scene();
        QVERIFY(near(img.pixel(3, 3), palette::kBackground, 0));
        QVERIFY(colourNear(img, scene.toPixel({50, 40, -5}, kW, kH), palette::kFeed));
        QVERIFY(colourNear(img, scene.toPixel({82.5, 55, 5}, kW, kH), palette::kRapid));
        const auto start = scene.toPixel({40, 40, 5}, kW, kH);
        QVERIFY(goldish(img.pixel(int(start[0]), int(start[1]))));

        w.setSelectedStep(kRoughing);
        w.highlightMove(kRoughing, kSlotMove);
        img = w.grabImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY(colourNear(img, scene.toPixel({55, 40, -5}, kW, kH), palette::kHighlight));

        w.setShowStock(true);
        w.setView(ViewPreset::Iso);
        img = w.grabImage().convertToFormat(QImage::Format_RGB32);
        if (!shots.isEmpty()) img.save(shots + "/preview-widget.png");
        // The pocket floor, lit obliquely: darker than the palette; cut by
        // the selected step, in its orange; with all steps, machined green.
        const auto floor = scene.toPixel({27.5, 40, -5}, kW, kH);
        const QRgb c = img.pixel(int(floor[0]), int(floor[1]));
        QVERIFY2(qRed(c) > qGreen(c) + 30 && qGreen(c) > qBlue(c) + 30, qPrintable(QString::number(c, 16)));
        w.setSelectedStep(-1);
        img = w.grabImage().convertToFormat(QImage::Format_RGB32);
        const QRgb g = img.pixel(int(floor[0]), int(floor[1]));
        QVERIFY2(qGreen(g) > qRed(g) + 30 && qGreen(g) > qBlue(g) + 10, qPrintable(QString::number(g, 16)));
    }

    // An edit of the job (a new plan on the same stock) keeps the camera the
    // operator turned; another stock is fitted anew.
    // A new plan is one frame, drawn at the next pass of the event loop
    // (not on the platform's update timer, and not twice); taking away a
    // colour map that is not there draws none (the verification panel does
    // on every edit); one that is there draws one.
    void newPlanIsOneFrameAtOnce()
    {
        PreviewWidget w;
        showFromTop(w);
        if (QTest::currentTestFailed()) return;
        QTest::qWait(100);  // the frames of showing it
        QSignalSpy frames(&w, &PreviewWidget::frameShown);
        w.setDeviationMap(nullptr);
        QTest::qWait(100);
        QCOMPARE(frames.count(), 0);
        w.setPlan(std::make_shared<const Plan>(plan_));
        QCoreApplication::processEvents();  // one pass: the frame is drawn in it
        QCOMPARE(frames.count(), 1);
        QTest::qWait(100);
        QCOMPARE(frames.count(), 1);
        const verify::Report r = verify::verifyPlan(plan_, {0.5, 0});
        w.setDeviationMap(std::make_shared<const verify::DeviationMap>(verify::deviationMap(plan_, r)));
        QTest::qWait(100);
        QCOMPARE(frames.count(), 2);
        w.setDeviationMap(nullptr);
        QTest::qWait(100);
        QCOMPARE(frames.count(), 3);
    }

    void cameraStaysPutAcrossEdits()
    {
        PreviewWidget w;
        showFromTop(w);
        if (QTest::currentTestFailed()) return;
        vtkCamera* cam = w.scene().renderer()->GetActiveCamera();
        cam->Azimuth(40);
        cam->Elevation(20);
        double turned[3];
        cam->GetPosition(turned);
        w.setPlan(std::make_shared<const Plan>(plan_));
        double after[3];
        cam->GetPosition(after);
        for (int i = 0; i < 3; ++i) QCOMPARE(after[i], turned[i]);
        Plan bigger = plan_;
        bigger.mmJob.stock.width *= 2;
        w.setPlan(std::make_shared<const Plan>(bigger));
        cam->GetPosition(after);
        QVERIFY(std::abs(after[0] - turned[0]) + std::abs(after[1] - turned[1]) + std::abs(after[2] - turned[2]) > 1.0);
    }

    // Grabbed as part of a window (how the station's screenshots are taken)
    // the frame is there, at the widget's place, and opaque: no alpha is left
    // for the grab to darken the background and the translucent stock into
    // near-black. (QWidget::grab alone shows the window's grey there: the
    // GL window is not in the widgets' backing store.)
    void grabbedInAWindowIsOpaque()
    {
        QWidget host;
        auto* w = new PreviewWidget(&host);
        (new QVBoxLayout(&host))->addWidget(w);
        host.resize(kW, kH);
        w->setPlan(std::make_shared<const Plan>(plan_));
        w->setShowStock(true);
        host.show();
        QVERIFY(QTest::qWaitForWindowExposed(&host));
        // The layout has given the widget its place before the grab.
        QTRY_VERIFY(w->geometry().size() == host.contentsRect().size() - QSize(2 * host.layout()->contentsMargins().left(), 2 * host.layout()->contentsMargins().top()));
        const QImage img = ui::grabWithPreview(&host).convertToFormat(QImage::Format_RGB32);
        QCOMPARE(img.size(), host.size() * host.devicePixelRatio());
        for (const QPoint corner : {w->geometry().topLeft() + QPoint(3, 3), w->geometry().bottomRight() - QPoint(3, 3)})
            QVERIFY2(near(img.pixel(corner), palette::kBackground, 0), qPrintable(QString::number(img.pixel(corner), 16)));
        // Outside the view, the window's own widgets as QWidget::grab has them.
        QCOMPARE(img.pixel(1, 1), host.grab().toImage().convertToFormat(QImage::Format_RGB32).pixel(1, 1));
    }

    void widgetShowsTheSamplePlan()
    {
        PreviewWidget w;
        w.resize(400, 300);
        w.setPlan(std::make_shared<const Plan>(samplePlan("m4-standard.taiwa")));
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QImage img = w.grabImage().convertToFormat(QImage::Format_RGB32);
        QCOMPARE(img.size(), QSize(400, 300));
        int background = 0, blue = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x) {
                const QRgb c = img.pixel(x, y);
                background += near(c, palette::kBackground, 0) ? 1 : 0;
                blue += qBlue(c) > 180 && qBlue(c) > qRed(c) + 100 ? 1 : 0;
            }
        QVERIFY2(background > 400 * 300 / 10, qPrintable(QString::number(background)));
        QVERIFY2(blue > 300, qPrintable(QString::number(blue)));
    }

    void widgetClickPicksAndDragRotates()
    {
        PreviewWidget w;
        showFromTop(w);
        if (QTest::currentTestFailed()) return;
        QSignalSpy clicked(&w, &PreviewWidget::moveClicked);
        const auto at = w.scene().toPixel({55, 40, -5}, kW, kH);
        QTest::mouseClick(&w, Qt::LeftButton, {}, QPoint(int(at[0]), int(at[1])));
        QCOMPARE(clicked.size(), 1);
        QCOMPARE(clicked[0][0].toInt(), kRoughing);
        QCOMPARE(clicked[0][1].toInt(), kSlotMove);

        // A left drag turns the camera and clicks nothing.
        vtkCamera* cam = w.scene().renderer()->GetActiveCamera();
        double before[3], after[3];
        cam->GetPosition(before);
        const QPointF from(400, 300), to(520, 260);
        QMouseEvent press(QEvent::MouseButtonPress, from, w.mapToGlobal(from), Qt::LeftButton, Qt::LeftButton, {});
        QApplication::sendEvent(&w, &press);
        for (int k = 1; k <= 6; ++k) {
            const QPointF p = from + (to - from) * (k / 6.0);
            QMouseEvent move(QEvent::MouseMove, p, w.mapToGlobal(p), Qt::NoButton, Qt::LeftButton, {});
            QApplication::sendEvent(&w, &move);
        }
        QMouseEvent release(QEvent::MouseButtonRelease, to, w.mapToGlobal(to), Qt::LeftButton, Qt::NoButton, {});
        QApplication::sendEvent(&w, &release);
        cam->GetPosition(after);
        QVERIFY(std::abs(after[0] - before[0]) + std::abs(after[1] - before[1]) + std::abs(after[2] - before[2]) > 1.0);
        QCOMPARE(clicked.size(), 1);
    }

    // The window system delivers the mouse to the GL window, not to the
    // widget: a click there picks the same move and takes the keyboard focus
    // to the widget, a drag there turns the camera, the wheel zooms about
    // the pointer.
    void eventsOnTheGlWindowReachTheView()
    {
        QWidget host;
        auto* w = new PreviewWidget(&host);
        auto* layout = new QVBoxLayout(&host);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->addWidget(w);
        host.resize(kW, kH);
        w->setPlan(std::make_shared<const Plan>(plan_));
        w->setView(ViewPreset::Top);
        host.show();
        QVERIFY(QTest::qWaitForWindowExposed(&host));
        QWindow* gl = w->glWindow();
        QVERIFY(gl && gl != host.windowHandle());
        QTRY_COMPARE(gl->size(), QSize(kW, kH));
        QVERIFY(host.focusWidget() != w);

        QSignalSpy clicked(w, &PreviewWidget::moveClicked);
        const auto at = w->scene().toPixel({55, 40, -5}, kW, kH);
        QTest::mouseClick(gl, Qt::LeftButton, {}, QPoint(int(at[0]), int(at[1])));
        QTRY_COMPARE(clicked.size(), 1);
        QCOMPARE(clicked[0][0].toInt(), kRoughing);
        QCOMPARE(clicked[0][1].toInt(), kSlotMove);
        QCOMPARE(host.focusWidget(), w);

        vtkCamera* cam = w->scene().renderer()->GetActiveCamera();
        double before[3], after[3];
        cam->GetPosition(before);
        const QPoint from(400, 300), to(520, 260);
        QTest::mousePress(gl, Qt::LeftButton, {}, from);
        for (int k = 1; k <= 6; ++k) QTest::mouseMove(gl, from + (to - from) * k / 6);
        QTest::mouseRelease(gl, Qt::LeftButton, {}, to);
        cam->GetPosition(after);
        QVERIFY(std::abs(after[0] - before[0]) + std::abs(after[1] - before[1]) + std::abs(after[2] - before[2]) > 1.0);
        QCOMPARE(clicked.size(), 1);

        // The zoom: the view's height in mm (parallel projection) or the distance.
        const auto zoom = [cam] { return cam->GetParallelProjection() ? cam->GetParallelScale() : cam->GetDistance(); };
        const double distance = zoom();
        // About the pointer (issue 34, item 7): the stock's corner under it stays under it.
        const auto corner = w->scene().toPixel({0, 0, 0}, kW, kH);
        const QPointF pointer(corner[0], corner[1]);
        QWheelEvent wheel(pointer, gl->mapToGlobal(pointer), {}, QPoint(0, 120), Qt::NoButton, {}, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(gl, &wheel);
        QVERIFY2(std::abs(zoom() - distance / 1.2) < 1e-9 * distance, qPrintable(QString("%1 then %2").arg(distance).arg(zoom())));
        const auto still = w->scene().toPixel({0, 0, 0}, kW, kH);
        QVERIFY2(std::hypot(still[0] - corner[0], still[1] - corner[1]) < 1e-6,
                 qPrintable(QString("(%1, %2) then (%3, %4)").arg(corner[0]).arg(corner[1]).arg(still[0]).arg(still[1])));
    }
};

QTEST_MAIN(TestRenderPreviewWidget)
#include "test_render_preview_widget.moc"
