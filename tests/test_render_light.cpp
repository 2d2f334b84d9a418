// The stock surface lit on the processor (viz/surface_light.h, the scene's
// default) draws VTK's own picture: the simulated stock of plate.taiwa and
// the verification's colour map, lit per pixel by VTK and per quad on the
// processor, compared pixel by pixel through the same cameras: the
// presets, the camera turned round to the bottom and the back, in
// perspective, cut open by a section (the cut face drawn over it), after
// a step is selected (a new surface) and after the camera turns again (lit
// anew, not kept from the last frame). Needs an X display (xvfb-run -a).
#include "support/hand_plan.h"
#include "support/images.h"
#include "support/scene_picture.h"
#include "verify/deviation.h"
#include "viz/render.h"
#include "viz/scene.h"

#include <QImage>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <memory>
#include <set>

using namespace taiwa;
using namespace taiwa::test;
using namespace taiwa::viz;

namespace {

constexpr int kWidth = 640, kHeight = 400;

// The scene's picture through the camera it is given.
QImage picture(Scene& scene, vtkCamera* camera) { return scenePicture(scene, camera, kWidth, kHeight); }

// How two pictures differ: how many pixels differ by more than one level
// of a colour channel, and by more than two.
struct Difference {
    int pixels = 0;
    int far = 0;
};

Difference difference(const QImage& a, const QImage& b)
{
    Difference d;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            const int m = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)), std::abs(qBlue(p) - qBlue(q))});
            d.pixels += m > 1 ? 1 : 0;
            d.far += m > 2 ? 1 : 0;
        }
    return d;
}

// Shades of the stock's grey and of the cut, as lit: at least this many
// colours in the picture show the faces apart.
int colours(const QImage& img)
{
    std::set<QRgb> seen;
    for (int y = 0; y < img.height(); y += 2)
        for (int x = 0; x < img.width(); x += 2) seen.insert(img.pixel(x, y));
    return static_cast<int>(seen.size());
}

}  // namespace

class TestRenderLight : public QObject {
    Q_OBJECT
    std::shared_ptr<const Plan> plan_;
    Scene processor_, vtk_;

    // Both scenes' pictures through the processor scene's camera.
    void compare(const char* what)
    {
        vtkCamera* camera = processor_.renderer()->GetActiveCamera();
        const QImage lit = picture(processor_, camera), byVtk = picture(vtk_, camera);
        QVERIFY2(!lit.isNull() && !byVtk.isNull(), "no offscreen window");
        const Difference d = difference(lit, byVtk);
        // Rounding: the processor's colour is one byte per channel before
        // the rasteriser interpolates it. And a quad bent across a step,
        // seen edge on, can have one triangle facing away: VTK lights that
        // triangle's back, the processor lights the quad as its normal
        // faces (the iso view has 8 such pixels).
        QVERIFY2(d.pixels < kWidth * kHeight / 1000 && d.far <= 30,
                 qPrintable(QString("%1: %2 pixels differ by more than 1 level, %3 by more than 2").arg(what).arg(d.pixels).arg(d.far)));
        QVERIFY2(colours(lit) > 20, what);
    }

    void both(const std::function<void(Scene&)>& f)
    {
        f(processor_);
        f(vtk_);
    }

private slots:
    void initTestCase()
    {
        plan_ = std::make_shared<const Plan>(samplePlan("plate.taiwa"));
        QVERIFY(!plan_->steps.empty());
        vtk_.setLightOnProcessor(false);
        // One near plane for both (VTK picks it from the first window's
        // depth bits): lines on a floor win or lose against it alike.
        both([](Scene& s) { s.renderer()->SetNearClippingPlaneTolerance(0.001); });
        QVERIFY(processor_.lightOnProcessor() && !vtk_.lightOnProcessor());
        both([&](Scene& s) {
            s.setPlan(plan_);
            s.setShowStock(true);
        });
    }

    void presets()
    {
        for (ViewPreset v : {ViewPreset::Iso, ViewPreset::Top, ViewPreset::Front}) {
            processor_.setView(v, static_cast<double>(kWidth) / kHeight);
            compare(v == ViewPreset::Iso ? "iso" : v == ViewPreset::Top ? "top" : "front");
        }
    }

    void turnedRoundAndInPerspective()
    {
        processor_.setView(ViewPreset::Iso, static_cast<double>(kWidth) / kHeight);
        vtkCamera* camera = processor_.renderer()->GetActiveCamera();
        camera->Azimuth(150);
        camera->Elevation(-60);  // from below and behind: bottom and back walls
        camera->OrthogonalizeViewUp();
        compare("from below behind");
        camera->Elevation(70);
        camera->OrthogonalizeViewUp();
        compare("turned again");
        processor_.setView(ViewPreset::Iso, static_cast<double>(kWidth) / kHeight);
        camera->ParallelProjectionOff();
        camera->Dolly(1.5);
        compare("perspective");
    }

    void sectionSeenInside()
    {
        both([&](Scene& s) { s.setSection(SectionPlane{{60, 40, -5}, {1, 1, 0}}); });
        processor_.setView(ViewPreset::Iso, static_cast<double>(kWidth) / kHeight);
        processor_.renderer()->GetActiveCamera()->Azimuth(180);
        compare("section");
        both([&](Scene& s) { s.setSection(std::nullopt); });
    }

    void stepSelectedAndColourMap()
    {
        processor_.setView(ViewPreset::Iso, static_cast<double>(kWidth) / kHeight);
        both([&](Scene& s) { s.setSelectedStep(2); });
        compare("a step's cut");
        both([&](Scene& s) { s.setSelectedStep(-1); });
        const verify::Report r = verify::verifyPlan(*plan_, {0.25, 0});
        const auto map = std::make_shared<const verify::DeviationMap>(verify::deviationMap(*plan_, r));
        both([&](Scene& s) { s.setDeviationMap(map); });
        compare("colour map");
        both([&](Scene& s) { s.setDeviationMap(nullptr); });
    }

    // The setting goes back and forth on one scene with the same picture.
    void switchedBack()
    {
        processor_.setView(ViewPreset::Iso, static_cast<double>(kWidth) / kHeight);
        vtkCamera* camera = processor_.renderer()->GetActiveCamera();
        const QImage before = picture(processor_, camera);
        processor_.setLightOnProcessor(false);
        processor_.setLightOnProcessor(true);
        QCOMPARE(differingPixels(before, picture(processor_, camera)), 0);
    }
};

QTEST_GUILESS_MAIN(TestRenderLight)
#include "test_render_light.moc"
