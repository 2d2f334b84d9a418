// The 3-D view's section bar (QTest, offscreen): no plane until an axis is
// chosen; the slider moves the plane across the stock from face to face, the
// angle turns a plane across X or Y about Z, Flip turns its normal; the
// place is shown in the job's unit; without a stock (a lathe job) the bar
// is disabled and announces no plane. Its pictures: test_render_scene and
// test_render_station.
#include "ui/section_bar.h"

#include <QComboBox>
#include <QLabel>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>
#include <QtTest>

#include <cmath>
#include <vector>

using namespace taiwa;
using namespace taiwa::ui;

namespace {

bool near(const Point3& a, const Point3& b, double tol = 1e-9)
{
    return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

}  // namespace

class TestGuiSectionBar : public QObject {
    Q_OBJECT
private slots:
    void planeFollowsTheControls()
    {
        SectionBar bar;
        bar.show();
        std::vector<std::optional<viz::SectionPlane>> announced;
        connect(&bar, &SectionBar::sectionChanged, this, [&](std::optional<viz::SectionPlane> p) { announced.push_back(p); });
        QVERIFY(!bar.isEnabled());
        bar.setStock(Stock{10, 20, 100, 80, 30});
        QVERIFY(bar.isEnabled());
        QVERIFY(announced.empty());  // still no section
        QVERIFY(!bar.slider()->isEnabled());

        bar.axisChooser()->setCurrentIndex(1);  // across X, in the middle
        QCOMPARE(announced.size(), std::size_t{1});
        QVERIFY(announced.back() && near(announced.back()->origin, {60, 60, -15}) && near(announced.back()->normal, {1, 0, 0}));
        QCOMPARE(bar.findChild<QLabel*>("section.value")->text(), QString("X 60.0 mm"));
        bar.slider()->setValue(0);
        QVERIFY(near(announced.back()->origin, {10, 60, -15}));
        bar.slider()->setValue(bar.slider()->maximum());
        QVERIFY(near(announced.back()->origin, {110, 60, -15}));
        bar.angle()->setValue(90);  // turned a quarter: across Y, its extent now the stock's length
        QVERIFY(near(announced.back()->normal, {0, 1, 0}, 1e-12));
        QVERIFY(near(announced.back()->origin, {60, 100, -15}, 1e-9));
        bar.angle()->setValue(0);
        bar.flip()->click();
        QVERIFY(near(announced.back()->normal, {-1, 0, 0}));
        QVERIFY(near(announced.back()->origin, {110, 60, -15}));
        bar.flip()->click();

        bar.axisChooser()->setCurrentIndex(3);  // level
        QVERIFY(near(announced.back()->normal, {0, 0, 1}));
        QVERIFY(near(announced.back()->origin, {60, 60, 0}));
        QVERIFY(!bar.angle()->isEnabled());
        bar.slider()->setValue(bar.slider()->maximum() / 2);
        QVERIFY(near(announced.back()->origin, {60, 60, -15}));

        // An inch job: the place in inches.
        bar.setStock(Stock{0, 0, 25.4, 25.4, 25.4}, LengthUnit::Inch);
        QCOMPARE(bar.findChild<QLabel*>("section.value")->text(), QString("Z -0.500 in"));

        // A lathe job: no plane.
        const std::size_t before = announced.size();
        bar.setStock(std::nullopt);
        QVERIFY(!bar.isEnabled());
        QCOMPARE(announced.size(), before + 1);
        QVERIFY(!announced.back());
        QVERIFY(!bar.plane());

        bar.setStock(Stock{0, 0, 100, 80, 30});
        bar.axisChooser()->setCurrentIndex(0);
        QVERIFY(!announced.back());
    }
};

QTEST_MAIN(TestGuiSectionBar)
#include "test_gui_section_bar.moc"
