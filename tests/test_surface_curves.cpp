// Space curves and ruled surfaces (core/occt/surface_curves.h): a helix-like
// curve rebuilt from its XY and YZ projections, sampled differently, matches
// the true curve within 1 µm at every point (and does not when the
// projections are joined by straight lines: the negative control); a
// projection whose shared coordinate turns back, projections that share no
// range and two projections in one plane are refused naming which; the
// ruled surface between two coplanar lines is their plane (and between two
// skew lines is none); N ≥ M is refused; the roughing surface's division
// points are every (M/N)-th of the finishing surface's; a step-over gives
// the pieces it implies.
#include "occt/surface_curves.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace taiwa;
using namespace taiwa::surface;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 20.0;     // the helix' radius
constexpr double kPitch = 8.0;  // y per radian

// The helix x = R cos t, y = p t, z = R sin t, t from a to b, n points, seen
// in the XY or the YZ plane.
Projection helixProjection(ProjectionPlane plane, double a, double b, int n, bool smooth = true)
{
    Projection p{plane, {}, smooth};
    for (int i = 0; i < n; ++i) {
        const double t = a + (b - a) * i / (n - 1);
        if (plane == ProjectionPlane::XY)
            p.points.push_back({kR * std::cos(t), kPitch * t});
        else
            p.points.push_back({kPitch * t, kR * std::sin(t)});
    }
    return p;
}

// The largest distance of the curve's points from the true helix at their Y.
double helixError(const SpaceCurve& c)
{
    double worst = 0.0;
    for (const Point3& p : c.points) {
        const double t = p.y / kPitch;
        worst = std::max(worst, std::hypot(p.x - kR * std::cos(t), p.z - kR * std::sin(t)));
    }
    return worst;
}

SpaceCurve line(Point3 a, Point3 b) { return SpaceCurve{{a, b}, false}; }

}  // namespace

class TestSurfaceCurves : public QObject {
    Q_OBJECT

private slots:
    void helixFromTwoProjections()
    {
        // XY over one turn in 181 points, YZ over a little more in 157
        // points: no sample of one falls on a sample of the other.
        const Projection xy = helixProjection(ProjectionPlane::XY, 0.0, 2 * kPi, 181);
        const Projection yz = helixProjection(ProjectionPlane::YZ, -0.1, 2 * kPi + 0.1, 157);
        const auto curve = spaceCurveFromProjections(xy, yz, 0.5);
        QVERIFY2(curve.ok(), curve.ok() ? "" : curve.error().c_str());
        QVERIFY(curve->points.size() > 180);  // 0.5 mm pieces along the 91 mm long XY curve
        QCOMPARE(curve->points.front().y, 0.0);
        QVERIFY(std::abs(curve->points.back().y - kPitch * 2 * kPi) < 1e-9);
        for (std::size_t i = 1; i < curve->points.size(); ++i) {
            const Point3 &p = curve->points[i - 1], &q = curve->points[i];
            QVERIFY(std::hypot(q.x - p.x, q.y - p.y) <= 0.5 + 1e-9);
        }
        const double error = helixError(*curve);
        qInfo("helix from two projections: %zu points, largest error %.3g mm", curve->points.size(), error);
        QVERIFY2(error < 1e-3, qPrintable(QString::number(error)));

        // Negative control: the same samples joined by straight lines miss
        // the helix by their sag, far more than 1 µm.
        const auto straight = spaceCurveFromProjections(helixProjection(ProjectionPlane::XY, 0.0, 2 * kPi, 181, false),
                                                        helixProjection(ProjectionPlane::YZ, -0.1, 2 * kPi + 0.1, 157, false),
                                                        0.5);
        QVERIFY(straight.ok());
        QVERIFY(helixError(*straight) > 1e-3);
    }

    void sharedAxisInEitherPosition()
    {
        // ZX (z, x) and XY (x, y) share X, first in the second coordinate,
        // then in the first: the line (x, 2x, 3x).
        const Projection zx{ProjectionPlane::ZX, {{0, 0}, {30, 10}}, false};
        const Projection xy{ProjectionPlane::XY, {{0, 0}, {10, 20}}, false};
        const auto c = spaceCurveFromProjections(zx, xy, 1.0);
        QVERIFY2(c.ok(), c.ok() ? "" : c.error().c_str());
        for (const Point3& p : c->points) {
            QVERIFY(std::abs(p.y - 2 * p.x) < 1e-9);
            QVERIFY(std::abs(p.z - 3 * p.x) < 1e-9);
        }
        QVERIFY(std::abs(c->points.back().x - 10) < 1e-9);
    }

    void refusals()
    {
        const Projection xy = helixProjection(ProjectionPlane::XY, 0.0, 2 * kPi, 50);
        // The shared Y turns back at the YZ curve's fifth point.
        Projection back{ProjectionPlane::YZ, {{0, 0}, {1, 1}, {2, 1}, {3, 2}, {2.5, 3}, {4, 3}}, true};
        auto r = spaceCurveFromProjections(xy, back, 1.0);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().find("projection 2 (YZ), point 5 (Y 2.5000)") != std::string::npos, r.error().c_str());
        QVERIFY2(r.error().find("turns back after point 4") != std::string::npos, r.error().c_str());
        // Standing still is refused the same way.
        Projection still{ProjectionPlane::YZ, {{0, 0}, {1, 1}, {1, 2}}, true};
        r = spaceCurveFromProjections(xy, still, 1.0);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().find("point 3 (Y 1.0000)") != std::string::npos, r.error().c_str());
        QVERIFY2(r.error().find("stands still") != std::string::npos, r.error().c_str());
        // No shared range: the helix' Y runs 0 to 50, this one 60 to 80.
        Projection far{ProjectionPlane::YZ, {{60, 0}, {70, 1}, {80, 0}}, true};
        r = spaceCurveFromProjections(xy, far, 1.0);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().find("projection 2 (YZ): its Y range 60.0000 to 80.0000 does not overlap") !=
                     std::string::npos,
                 r.error().c_str());
        // One plane twice.
        r = spaceCurveFromProjections(xy, xy, 1.0);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().find("same plane (XY)") != std::string::npos, r.error().c_str());
    }

    void ruledSurfaceBetweenTwoLinesIsThePlane()
    {
        // Two coplanar lines: the plane through (0,0,0), (100,0,10), (0,50,20),
        // normal (−500, −2000, 5000).
        const SpaceCurve a = line({0, 0, 0}, {100, 0, 10});
        const SpaceCurve b = line({0, 50, 20}, {100, 50, 30});
        const auto s = ruledSurface(a, b, 4);
        QVERIFY2(s.ok(), s.ok() ? "" : s.error().c_str());
        QCOMPARE(s->pieces(), 4);
        for (int i = 0; i <= 4; ++i) {
            const Point3 p = s->first[static_cast<std::size_t>(i)];
            QVERIFY(std::abs(p.x - 25 * i) < 1e-9 && std::abs(p.y) < 1e-9 && std::abs(p.z - 2.5 * i) < 1e-9);
        }
        const auto plane = planeOf(*s, 1e-7);
        QVERIFY2(plane.ok(), plane.ok() ? "" : plane.error().c_str());
        const double len = std::sqrt(500.0 * 500 + 2000.0 * 2000 + 5000.0 * 5000);
        QVERIFY(std::abs(plane->normal[0] + 500 / len) < 1e-9);
        QVERIFY(std::abs(plane->normal[1] + 2000 / len) < 1e-9);
        QVERIFY(std::abs(plane->normal[2] - 5000 / len) < 1e-9);
        const auto onPlane = [&](const Point3& p) {
            return plane->normal[0] * (p.x - plane->origin.x) + plane->normal[1] * (p.y - plane->origin.y) +
                   plane->normal[2] * (p.z - plane->origin.z);
        };
        for (double u = 0; u <= 4; u += 0.25)
            for (double v = 0; v <= 1; v += 0.125) QVERIFY(std::abs(onPlane(s->point(u, v))) < 1e-9);

        // Negative control: skew lines make a twisted surface, no plane.
        const auto twisted = ruledSurface(a, line({0, 50, 20}, {100, 50, 40}), 4);
        QVERIFY(twisted.ok());
        QVERIFY(!planeOf(*twisted, 1e-7).ok());
    }

    void roughingAndFinishingSurfaces()
    {
        const auto c1 = spaceCurveFromProjections(helixProjection(ProjectionPlane::XY, 0.0, kPi, 91),
                                                  helixProjection(ProjectionPlane::YZ, 0.0, kPi, 91), 0.5);
        QVERIFY(c1.ok());
        const SpaceCurve c2 = line({-30, 0, -10}, {-30, 40, -10});
        auto r = roughAndFinishSurfaces(*c1, c2, 8, 8);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().find("M: the finishing surface's pieces (M = 8) must be more than the roughing "
                                "surface's (N = 8)") != std::string::npos,
                 r.error().c_str());
        r = roughAndFinishSurfaces(*c1, c2, 0, 8);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().rfind("N: ", 0) == 0, r.error().c_str());

        r = roughAndFinishSurfaces(*c1, c2, 4, 12);
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().c_str());
        QCOMPARE(r->roughing.pieces(), 4);
        QCOMPARE(r->finishing.pieces(), 12);
        // Equal lengths along the same curves: roughing point i is
        // finishing point 3i.
        for (std::size_t i = 0; i <= 4; ++i) {
            const Point3 &p = r->roughing.first[i], &q = r->finishing.first[3 * i];
            QVERIFY2(std::hypot(p.x - q.x, p.y - q.y, p.z - q.z) < 1e-6, qPrintable(QString::number(i)));
            const Point3 &p2 = r->roughing.second[i], &q2 = r->finishing.second[3 * i];
            QVERIFY(std::hypot(p2.x - q2.x, p2.y - q2.y, p2.z - q2.z) < 1e-6);
        }
        // The division points lie on the helix, equally spaced along it
        // (chords of equal arcs are equal).
        const auto& f = r->finishing.first;
        const double chord0 = std::hypot(f[1].x - f[0].x, f[1].y - f[0].y, f[1].z - f[0].z);
        for (std::size_t i = 1; i < f.size(); ++i)
            QVERIFY(std::abs(std::hypot(f[i].x - f[i - 1].x, f[i].y - f[i - 1].y, f[i].z - f[i - 1].z) - chord0) <
                    1e-4);
        // A step-over implies the pieces: the longer curve (100.5) over it.
        const SpaceCurve longer = line({0, 0, 0}, {100.5, 0, 0}), shorter = line({0, 20, 0}, {50, 20, 0});
        const auto pieces = piecesForStepOver(longer, shorter, 10);
        QVERIFY(pieces.ok());
        QCOMPARE(*pieces, 11);
        QCOMPARE(*piecesForStepOver(shorter, longer, 0.5), 201);
        QVERIFY(!piecesForStepOver(longer, shorter, 0).ok());
        // A curve of one point is refused naming it.
        const auto bad = ruledSurface(*c1, SpaceCurve{{{0, 0, 0}}, false}, 4);
        QVERIFY(!bad.ok());
        QVERIFY2(bad.error().rfind("curve 2:", 0) == 0, bad.error().c_str());
    }
};

QTEST_GUILESS_MAIN(TestSurfaceCurves)
#include "test_surface_curves.moc"
