// Tool-nose points and paths over tessellated surfaces
// (core/occt/surface_mesh.h, surface_paths.h), against closed-form answers:
// on a sphere the ball's centre is R + r from the sphere's centre and the
// bull-nose's ring R + r too, within 1 µm (a coarse mesh misses by more: the
// negative control); a path on an inclined plane stops exactly on a vertical
// boundary plane, and runs whole past a boundary it never meets; the
// scallop between the finishing paths on a cylinder stays within the set
// height (a fixed pick-feed exceeds it on the flanks), and in a trough when
// the spacing allows for its concave radius (the plane's does not); Z-level roughing
// leaves the allowance along the normal and rides on it at the last level;
// two surfaces combine into the higher or lower of them; a ruled surface
// tessellated once drops the cutter onto its plane; the drop's pruning
// gives the maximum over every triangle taken alone, bit for bit. The unit's checks: an
// overhang is an undercut (a vertical wall and a sphere are not), a trough's
// concave radius is found (a cylinder's top has none), a boundary meets
// the surface or does not. STEP: the sphere's paths written as one B-spline
// face and read back as a face set, meshed to 0.3 µm, still put the ball
// 55 mm from the centre within 1 µm; paths of unequal lengths and a text
// file are refused.
#include "occt/surface_checks.h"
#include "occt/surface_curves.h"
#include "occt/surface_mesh.h"
#include "occt/surface_paths.h"
#include "occt/surface_step.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>
#include <random>

using namespace taiwa;
using namespace taiwa::surface;

namespace {

constexpr double kSphere = 50.0;   // the sphere's radius, centre at the origin
constexpr double kCylinder = 40.0; // the cylinder's radius, axis along X through the origin

// The sphere's top over [−h, h]², as paths along X `spacing` apart.
TriangleMesh sphereCap(double half, double spacing)
{
    std::vector<std::vector<Point3>> paths;
    const int n = static_cast<int>(std::lround(2 * half / spacing));
    for (int i = 0; i <= n; ++i) {
        const double y = -half + 2 * half * i / n;
        std::vector<Point3> path;
        for (int j = 0; j <= n; ++j) {
            const double x = -half + 2 * half * j / n;
            path.push_back({x, y, std::sqrt(kSphere * kSphere - x * x - y * y)});
        }
        paths.push_back(std::move(path));
    }
    return meshFromPaths(paths);
}

// The cylinder's top over x in [0, 60], |y| ≤ 30.
TriangleMesh cylinderTop()
{
    std::vector<std::vector<Point3>> paths;
    for (int i = 0; i <= 600; ++i) {
        const double y = -30 + 0.1 * i;
        std::vector<Point3> path;
        for (int j = 0; j <= 12; ++j) path.push_back({5.0 * j, y, std::sqrt(kCylinder * kCylinder - y * y)});
        paths.push_back(std::move(path));
    }
    return meshFromPaths(paths);
}

// A planar rectangle as two triangles.
TriangleMesh quad(Point3 a, Point3 b, Point3 c, Point3 d) { return meshFromPaths({{a, b}, {d, c}}); }

// The largest error of the nose points over [−20, 20]² on the sphere: the
// distance of the cutter's ring (a ball's centre) from the sphere's centre
// against R + r; a bull-nose whose axis passes within its flat bottom's
// radius of the top rests on the top.
double sphereError(const MeshIndex& index, Cutter cutter)
{
    DropCutter drop(index, cutter);
    const double ring = cutter.diameter / 2 - cutter.cornerRadius;
    double worst = 0.0;
    for (double x = -20; x <= 20; x += 2.5)
        for (double y = -20; y <= 20; y += 2.5) {
            const auto z = drop.noseZ(x, y);
            if (!z) return 1e9;
            const double rho = std::hypot(x, y);
            if (rho <= ring) {  // the flat bottom rests on the sphere's top
                worst = std::max(worst, std::abs(*z - kSphere));
                continue;
            }
            const double d = std::hypot(rho - ring, *z + cutter.cornerRadius);
            worst = std::max(worst, std::abs(d - (kSphere + cutter.cornerRadius)));
        }
    return worst;
}

// The cusp between two neighbouring ball positions in the cylinder's
// section (centres (y, z) r apart from the surface): its height above the
// cylinder.
double cusp(double y1, double z1, double y2, double z2, double r)
{
    const double my = 0.5 * (y1 + y2), mz = 0.5 * (z1 + z2);
    const double dy = y2 - y1, dz = z2 - z1, d = std::hypot(dy, dz);
    const double h = std::sqrt(std::max(0.0, r * r - d * d / 4));
    const double wy = -dz / d, wz = dy / d;
    const double a = std::hypot(my + h * wy, mz + h * wz), b = std::hypot(my - h * wy, mz - h * wz);
    return std::min(a, b) - kCylinder;  // the cusp towards the axis is the material's
}

// The largest scallop between the paths at X = 30.
double largestScallop(const FinishingPaths& f, DropCutter& drop)
{
    const double r = drop.cutter().cornerRadius;
    double worst = 0.0;
    for (std::size_t i = 1; i < f.ys.size(); ++i) {
        const double z1 = *drop.noseZ(30, f.ys[i - 1]) + r, z2 = *drop.noseZ(30, f.ys[i]) + r;
        worst = std::max(worst, cusp(f.ys[i - 1], z1, f.ys[i], z2, r));
    }
    return worst;
}

}  // namespace

class TestSurfacePaths : public QObject {
    Q_OBJECT

    std::unique_ptr<MeshIndex> sphere_;
    std::unique_ptr<MeshIndex> cylinder_;

private slots:
    void initTestCase()
    {
        sphere_ = std::make_unique<MeshIndex>(sphereCap(30, 0.25));  // sag under 0.3 µm
        cylinder_ = std::make_unique<MeshIndex>(cylinderTop());
    }

    void noseOnSphere()
    {
        const double ball = sphereError(*sphere_, Cutter{10, 5});
        const double bull = sphereError(*sphere_, Cutter{10, 2});
        qInfo("sphere: ball error %.3g mm, bull-nose error %.3g mm", ball, bull);
        QVERIFY2(ball < 1e-3, qPrintable(QString::number(ball)));
        QVERIFY2(bull < 1e-3, qPrintable(QString::number(bull)));
        // Negative control: a mesh of 3 mm has a sag of tens of µm.
        const MeshIndex coarse(sphereCap(30, 3.0));
        QVERIFY(sphereError(coarse, Cutter{10, 5}) > 1e-3);
        // Nothing under the cutter: no nose point; nor on an empty mesh
        // (ragged paths make none).
        DropCutter drop(*sphere_, Cutter{10, 5});
        QVERIFY(!drop.noseZ(100, 0));
        const MeshIndex empty(meshFromPaths({{{0, 0, 0}, {1, 0, 0}}, {{0, 1, 0}}}));
        QVERIFY(empty.mesh().triangles.empty());
        DropCutter none(empty, Cutter{10, 5});
        QVERIFY(!none.noseZ(0, 0));
        QVERIFY(!none.surfaceZ(0, 0));
    }

    // The drop skips the cells and triangles whose bound the contact found
    // so far reaches (surface_mesh.cpp). On bumpy and stepped random meshes
    // its answer must be the maximum over every triangle taken alone (each
    // in a mesh of its own: nothing pruned), bit for bit, for a ball, a
    // bull-nose and a flat end mill.
    void dropIsTheMaximumOverEveryTriangle()
    {
        std::mt19937 rng(1130);
        std::uniform_real_distribution<double> noise(-0.4, 0.4), at(-2.0, 42.0);
        for (const bool stepped : {false, true}) {
            std::vector<std::vector<Point3>> paths;
            for (int i = 0; i <= 20; ++i) {
                std::vector<Point3> row;
                for (int j = 0; j <= 20; ++j) {
                    const double x = 2.0 * j + noise(rng), y = 2.0 * i + noise(rng);
                    double z = 3 * std::sin(x / 5) * std::cos(y / 7) + noise(rng);
                    if (stepped && x > 20) z += 6;  // a wall across the middle
                    row.push_back({x, y, z});
                }
                paths.push_back(std::move(row));
            }
            const TriangleMesh mesh = meshFromPaths(paths);
            const MeshIndex index(mesh);
            std::vector<std::unique_ptr<MeshIndex>> alone;
            for (const auto& t : mesh.triangles) {
                TriangleMesh one;
                for (const int v : t) one.vertices.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
                one.triangles = {{0, 1, 2}};
                alone.push_back(std::make_unique<MeshIndex>(std::move(one)));
            }
            for (const Cutter cutter : {Cutter{10, 5}, Cutter{12, 2}, Cutter{8, 0}}) {
                DropCutter drop(index, cutter);
                std::vector<DropCutter> each;
                for (const auto& a : alone) each.emplace_back(*a, cutter);
                for (int k = 0; k < 150; ++k) {
                    const double x = at(rng), y = at(rng);
                    std::optional<double> all;
                    for (DropCutter& d : each)
                        if (const auto z = d.noseZ(x, y)) all = std::max(all.value_or(*z), *z);
                    const std::optional<double> pruned = drop.noseZ(x, y);
                    QCOMPARE(pruned.has_value(), all.has_value());
                    if (all) QVERIFY2(*pruned == *all, qPrintable(QString("(%1, %2): %3 against %4").arg(x).arg(y).arg(*pruned, 0, 'g', 17).arg(*all, 0, 'g', 17)));
                }
            }
        }
    }

    void pathStopsOnVerticalBoundary()
    {
        // The plane z = 0.5 x − 10 and the vertical boundary plane x = 40.5.
        const MeshIndex plane(quad({0, 0, -10}, {100, 0, 40}, {100, 50, 40}, {0, 50, -10}));
        const MeshIndex boundary(quad({40.5, -10, -50}, {40.5, 60, -50}, {40.5, 60, 50}, {40.5, -10, 50}));
        DropCutter drop(plane, Cutter{10, 5});
        const auto pieces = dropLine(drop, 25, 10, 90, 1.3);
        QCOMPARE(pieces.size(), std::size_t{1});
        const StoppedPath s = stopAtBoundary(pieces[0], boundary);
        QVERIFY(s.stopped);
        const Point3 end = s.points.back();
        QVERIFY2(std::abs(end.x - 40.5) < 1e-9, qPrintable(QString::number(end.x, 'g', 12)));
        // On the ball's nose plane: z = 0.5 x − 10 + r (√(1 + 0.25) − 1).
        const double expected = 0.5 * 40.5 - 10 + 5 * (std::sqrt(1.25) - 1);
        QVERIFY2(std::abs(end.z - expected) < 1e-9, qPrintable(QString::number(end.z - expected)));
        for (std::size_t i = 0; i + 1 < s.points.size(); ++i) QVERIFY(s.points[i].x < 40.5);
        // A boundary the path never meets leaves it whole.
        const MeshIndex far(quad({200, -10, -50}, {200, 60, -50}, {200, 60, 50}, {200, -10, 50}));
        const StoppedPath whole = stopAtBoundary(pieces[0], far);
        QVERIFY(!whole.stopped);
        QCOMPARE(whole.points.size(), pieces[0].size());
    }

    void scallopOnCylinder()
    {
        DropCutter drop(*cylinder_, Cutter{10, 5});
        // The ball's centre is R + r from the axis.
        for (double y = -20; y <= 20; y += 5) {
            const double z = *drop.noseZ(30, y) + 5;
            QVERIFY(std::abs(std::hypot(y, z) - (kCylinder + 5)) < 1e-3);
        }
        const double height = 0.01;
        const Area area{20, -20, 40, 20};
        const FinishingPaths f = finishingPaths(drop, area, 2.0, height);
        QVERIFY(f.ys.size() > 10);
        QCOMPARE(f.ys.front(), -20.0);
        QCOMPARE(f.ys.back(), 20.0);
        const double scallop = largestScallop(f, drop);
        qInfo("cylinder: %zu paths, largest scallop %.4f mm (set %.4f)", f.ys.size(), scallop, height);
        QVERIFY2(scallop <= height + 1e-6, qPrintable(QString::number(scallop)));
        QVERIFY(scallop > 0.5 * height);  // not needlessly fine
        // Negative control: the plane's pick-feed everywhere leaves more on
        // the flanks.
        const FinishingPaths fixed = parallelPaths(drop, area, 2.0, scallopSpacing(drop.cutter(), height));
        QVERIFY(largestScallop(fixed, drop) > height);
    }

    void scallopInATrough()
    {
        // A trough of radius 40 along X (axis at y 0, z 40), |y| ≤ 30: the
        // plane's spacing leaves more than the height in it; the spacing for
        // its concave radius does not.
        std::vector<std::vector<Point3>> paths;
        for (int i = 0; i <= 600; ++i) {
            const double y = -30 + 0.1 * i;
            std::vector<Point3> path;
            for (int j = 0; j <= 12; ++j) path.push_back({5.0 * j, y, 40 - std::sqrt(1600 - y * y)});
            paths.push_back(std::move(path));
        }
        const MeshIndex trough(meshFromPaths(paths));
        DropCutter drop(trough, Cutter{10, 5});
        const double radius = smallestConcaveRadius(paths).radius;
        QVERIFY(std::abs(radius - 40) < 1e-6);
        // The scallop between two ball positions in the section: how far
        // the cusp nearer the trough's wall lies inside the radius.
        const auto largest = [&](const FinishingPaths& f) {
            double worst = 0.0;
            for (std::size_t i = 1; i < f.ys.size(); ++i) {
                const double y1 = f.ys[i - 1], y2 = f.ys[i];
                const double z1 = *drop.noseZ(30, y1) + 5 - 40, z2 = *drop.noseZ(30, y2) + 5 - 40;
                const double my = 0.5 * (y1 + y2), mz = 0.5 * (z1 + z2);
                const double d = std::hypot(y2 - y1, z2 - z1), h = std::sqrt(25 - d * d / 4);
                const double wy = -(z2 - z1) / d, wz = (y2 - y1) / d;
                const double far = std::max(std::hypot(my + h * wy, mz + h * wz), std::hypot(my - h * wy, mz - h * wz));
                worst = std::max(worst, 40 - far);
            }
            return worst;
        };
        const Area area{20, -20, 40, 20};
        const double plane = largest(finishingPaths(drop, area, 2.0, 0.01));
        const double bent = largest(finishingPaths(drop, area, 2.0, 0.01, radius));
        qInfo("trough: largest scallop %.4f mm with the plane's spacing, %.4f mm with the concave radius's", plane, bent);
        QVERIFY(plane > 0.01);
        // Within the height and the mesh's sag (0.1² / (8 · 40) = 0.03 µm:
        // the chords lie above a concave surface, and the balls with them).
        QVERIFY2(bent <= 0.01 + 5e-5, qPrintable(QString::number(bent)));
        QVERIFY(bent > 0.005);
        QCOMPARE(scallopSpacing(Cutter{10, 5}, 0.01, 4.0), 0.0);  // a bend tighter than the ball
    }

    void zLevelRoughingLeavesTheAllowance()
    {
        const Cutter ball{10, 5};
        ZLevelOptions o;
        o.top = 52;
        o.depth = 2;
        o.stepOver = 4;
        o.step = 1;
        o.allowance = 0.5;
        const auto passes = zLevelRoughing(*sphere_, ball, Area{-20, -20, 20, 20}, o);
        QVERIFY(!passes.empty());
        double lowest = 1e9;
        int riding = 0;
        for (const RoughingPass& p : passes) {
            lowest = std::min(lowest, p.level);
            QVERIFY(p.level < o.top);
            for (const Point3& q : p.points) {
                const double d = std::hypot(q.x, q.y, q.z + 5);
                QVERIFY2(d >= kSphere + 5 + 0.5 - 1e-3, qPrintable(QString::number(d)));
                QVERIFY(q.z >= p.level - 1e-12);
                if (q.z > p.level + 1e-6) {
                    ++riding;
                    QVERIFY2(std::abs(d - (kSphere + 5.5)) < 1e-3, qPrintable(QString::number(d)));
                }
            }
        }
        QVERIFY(riding > 0);
        // The last level is the allowance surface's lowest sample: the ball
        // at (±20, ±20) on the sphere grown by 5.5.
        const double corner = std::sqrt(55.5 * 55.5 - 800) - 5;
        QVERIFY2(std::abs(lowest - corner) < 1e-3, qPrintable(QString::number(lowest - corner)));
    }

    void combineTwoSurfaces()
    {
        // First: the plane z = 5; second: paths on z = 0.2 x, x 0 … 50.
        const MeshIndex first(quad({-10, -10, 5}, {60, -10, 5}, {60, 60, 5}, {-10, 60, 5}));
        std::vector<std::vector<Point3>> second;
        for (int i = 0; i <= 5; ++i) {
            std::vector<Point3> path;
            for (int j = 0; j <= 50; ++j) path.push_back({1.0 * j, 10.0 * i, 0.2 * j});
            second.push_back(std::move(path));
        }
        const auto above = combineSurfaces(first, second, KeepSide::Above);
        const auto below = combineSurfaces(first, second, KeepSide::Below);
        for (std::size_t i = 0; i < second.size(); ++i) {
            QCOMPARE(above[i].size(), second[i].size());
            for (std::size_t j = 0; j < second[i].size(); ++j) {
                const Point3& q = second[i][j];
                QVERIFY(std::abs(above[i][j].z - std::max(q.z, 5.0)) < 1e-12);
                QVERIFY(std::abs(below[i][j].z - std::min(q.z, 5.0)) < 1e-12);
                QCOMPARE(above[i][j].x, q.x);
            }
        }
    }

    void ruledSurfaceTessellatedOnce()
    {
        // The ruled plane between two lines, z = 0.1 x + 0.4 y: a ball on it
        // rests with its nose on the plane lifted by r (√(1 + 0.17) − 1).
        const auto s = ruledSurface(SpaceCurve{{{0, 0, 0}, {100, 0, 10}}, false},
                                    SpaceCurve{{{0, 50, 20}, {100, 50, 30}}, false}, 8);
        QVERIFY(s.ok());
        const MeshIndex index(meshRuled(*s, 4, 2));
        QCOMPARE(index.mesh().triangles.size(), std::size_t{2 * 4 * 16});
        DropCutter drop(index, Cutter{8, 4});
        for (double x = 10; x <= 90; x += 7)
            for (double y = 10; y <= 40; y += 6) {
                const double expected = 0.1 * x + 0.4 * y + 4 * (std::sqrt(1.17) - 1);
                QVERIFY(std::abs(*drop.noseZ(x, y) - expected) < 1e-9);
                QVERIFY(std::abs(*drop.surfaceZ(x, y) - (0.1 * x + 0.4 * y)) < 1e-9);
            }
    }
    void stepExportAndFaceSetImport()
    {
        constexpr double kDeflection = 3e-4;
        std::vector<std::vector<Point3>> cap;
        for (int i = 0; i <= 30; ++i) {
            std::vector<Point3> path;
            for (int j = 0; j <= 30; ++j) {
                const double x = -30 + 2.0 * j, y = -30 + 2.0 * i;
                path.push_back({x, y, std::sqrt(kSphere * kSphere - x * x - y * y)});
            }
            cap.push_back(std::move(path));
        }
        QTemporaryDir dir;
        const std::string file = dir.filePath("cap.step").toStdString();
        const auto written = exportSurfaceStep(cap, file);
        QVERIFY2(written.ok(), written.ok() ? "" : written.error().c_str());
        const auto mesh = importStepFaces(file, kDeflection);
        QVERIFY2(mesh.ok(), mesh.ok() ? "" : mesh.error().c_str());
        const MeshIndex index(std::move(*mesh));
        const double error = sphereError(index, Cutter{10, 5});
        qInfo("STEP round trip: %zu triangles, ball error %.3g mm", index.mesh().triangles.size(), error);
        QVERIFY2(error < 1e-3, qPrintable(QString::number(error)));

        // Refusals: paths of different lengths, a file that is not STEP.
        auto ragged = cap;
        ragged[3].pop_back();
        const auto r = exportSurfaceStep(ragged, file);
        QVERIFY(!r.ok());
        QVERIFY2(r.error().find("path 4 has 30 points, path 1 has 31") != std::string::npos, r.error().c_str());
        const QString text = dir.filePath("note.step");
        QFile f(text);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("not a STEP file\n");
        f.close();
        const auto bad = importStepFaces(text.toStdString(), 1e-3);
        QVERIFY(!bad.ok());
        QVERIFY2(bad.error().find("note.step") != std::string::npos, bad.error().c_str());
    }

    void undercutsRefused()
    {
        // Paths along X whose fourth point goes back under the third.
        const auto profile = [](std::vector<std::pair<double, double>> xz) {
            std::vector<std::vector<Point3>> paths;
            for (double y : {0.0, 10.0, 20.0}) {
                std::vector<Point3> path;
                for (auto [x, z] : xz) path.push_back({x, y, z});
                paths.push_back(std::move(path));
            }
            return paths;
        };
        const auto overhang = findUndercut(profile({{0, 0}, {10, 0}, {20, 5}, {15, 10}, {25, 10}}));
        QVERIFY(overhang);
        QVERIFY2(overhang->find("paths 1 and 2, points 3 to 4 (X 20.000 Y 0.000 Z 5.000)") != std::string::npos,
                 overhang->c_str());
        QVERIFY2(overhang->find("height field") != std::string::npos, overhang->c_str());
        QVERIFY(!findUndercut(profile({{0, 0}, {10, 0}, {20, 5}, {20, 10}, {25, 10}})));  // a vertical wall
        std::vector<std::vector<Point3>> cap;
        for (int i = 0; i <= 20; ++i) {
            std::vector<Point3> path;
            for (int j = 0; j <= 20; ++j) {
                const double x = -20 + 2.0 * j, y = -20 + 2.0 * i;
                path.push_back({x, y, std::sqrt(kSphere * kSphere - x * x - y * y)});
            }
            cap.push_back(std::move(path));
        }
        QVERIFY(!findUndercut(cap));
    }

    void smallestConcaveRadiusOfATrough()
    {
        // Two troughs side by side, radius 40 then 12, along X; the
        // cylinder's top bends the other way only.
        std::vector<std::vector<Point3>> paths;
        for (int i = 0; i <= 120; ++i) {
            const double y = -30 + 0.5 * i;
            const double z = y < 0 ? 40 - std::sqrt(1600 - y * y) : 12 - std::sqrt(144 - std::min(y, 11.9) * std::min(y, 11.9));
            std::vector<Point3> path;
            for (int j = 0; j <= 4; ++j) path.push_back({10.0 * j, y, z});
            paths.push_back(std::move(path));
        }
        const ConcaveRadius r = smallestConcaveRadius(paths);
        QVERIFY2(std::abs(r.radius - 12) < 1e-6, qPrintable(QString::number(r.radius, 'g', 10)));
        QVERIFY2(r.where.rfind("path ", 0) == 0, r.where.c_str());
        std::vector<std::vector<Point3>> top;
        for (int i = 0; i <= 60; ++i) {
            const double y = -30 + 1.0 * i;
            top.push_back({{0, y, std::sqrt(1600 - y * y)}, {10, y, std::sqrt(1600 - y * y)}});
        }
        QVERIFY(std::isinf(smallestConcaveRadius(top).radius));
    }

    void boundaryMeetsOrNot()
    {
        const std::vector<std::vector<Point3>> plane{{{0, 0, -10}, {50, 0, 15}, {100, 0, 40}},
                                                     {{0, 50, -10}, {50, 50, 15}, {100, 50, 40}}};
        const MeshIndex wall(quad({40.5, -10, -50}, {40.5, 60, -50}, {40.5, 60, 50}, {40.5, -10, 50}));
        const MeshIndex far(quad({200, -10, -50}, {200, 60, -50}, {200, 60, 50}, {200, -10, 50}));
        QVERIFY(boundaryMeetsSurface(plane, wall));
        QVERIFY(!boundaryMeetsSurface(plane, far));
    }
};

QTEST_GUILESS_MAIN(TestSurfacePaths)
#include "test_surface_paths.moc"
