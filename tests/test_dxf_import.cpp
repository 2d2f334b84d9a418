// DXF import (core/dxf/): DXF files written by hand here (R2000 ASCII) read to
// the expected contours — lines and an arc chained into a closed outline, a
// bulged LWPOLYLINE slot with its arc centres, an R12 POLYLINE, a mirrored
// (extrusion 0, 0, -1) arc, splines within the tolerance of the true curve —
// layer selection, inch units, a gap reported with its position and size,
// small gaps closed, a branch, hostile and garbage files refused with a
// message, and 10,000 shuffled entities chained.
#include "dxf/dxf_import.h"

#include <QtTest>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace taiwa::dxf;
using taiwa::Contour;
using taiwa::ContourSegment;
using taiwa::Point2;

namespace {

constexpr double kExact = 1e-9;  // mm: the hand computations are exact
using Kind = ContourSegment::Kind;

bool near(double a, double b, double tol = kExact) { return std::abs(a - b) <= tol; }
bool near(Point2 a, Point2 b, double tol = kExact) { return taiwa::distance(a, b) <= tol; }

// The pieces of a hand-written DXF.
std::string header(int insunits = 4)
{
    return fmt::format(
        "999\nwritten by test_dxf_import\n0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$INSUNITS\n70\n{}\n0\nENDSEC\n"
        "0\nSECTION\n2\nTABLES\n0\nTABLE\n2\nLAYER\n70\n1\n0\nLAYER\n2\nEMPTY\n70\n0\n62\n7\n6\nCONTINUOUS\n0\nENDTAB\n0\nENDSEC\n"
        "0\nSECTION\n2\nENTITIES\n",
        insunits);
}
const std::string kFooter = "0\nENDSEC\n0\nEOF\n";

std::string line(const std::string& layer, double x1, double y1, double x2, double y2)
{
    return fmt::format("0\nLINE\n8\n{}\n10\n{}\n20\n{}\n30\n0\n11\n{}\n21\n{}\n31\n0\n", layer, x1, y1, x2, y2);
}
std::string arc(const std::string& layer, double cx, double cy, double r, double a1, double a2, double extrusionZ = 1)
{
    return fmt::format("0\nARC\n8\n{}\n10\n{}\n20\n{}\n30\n0\n40\n{}\n50\n{}\n51\n{}\n210\n0\n220\n0\n230\n{}\n", layer, cx, cy,
                       r, a1, a2, extrusionZ);
}
struct V {
    double x, y, bulge;
};
std::string lwpolyline(const std::string& layer, bool closed, const std::vector<V>& vs)
{
    std::string s = fmt::format("0\nLWPOLYLINE\n8\n{}\n90\n{}\n70\n{}\n", layer, vs.size(), closed ? 1 : 0);
    for (const V& v : vs) s += fmt::format("10\n{}\n20\n{}\n42\n{}\n", v.x, v.y, v.bulge);
    return s;
}
std::string spline(const std::string& layer, int degree, const std::vector<double>& knots, const std::vector<Point2>& ctrl,
                   const std::vector<double>& weights = {})
{
    std::string s = fmt::format("0\nSPLINE\n8\n{}\n210\n0\n220\n0\n230\n1\n70\n{}\n71\n{}\n72\n{}\n73\n{}\n74\n0\n", layer,
                                weights.empty() ? 8 : 12, degree, knots.size(), ctrl.size());
    for (double k : knots) s += fmt::format("40\n{}\n", k);
    for (std::size_t i = 0; i < ctrl.size(); ++i) {
        s += fmt::format("10\n{}\n20\n{}\n30\n0\n", ctrl[i].x, ctrl[i].y);
        if (!weights.empty()) s += fmt::format("41\n{}\n", weights[i]);
    }
    return s;
}

// The cubic Bézier of the curve layer.
const std::vector<Point2> kBezier{{0, 100}, {30, 140}, {70, 60}, {100, 100}};
Point2 bezier(double t)
{
    const double u = 1 - t;
    const double b0 = u * u * u, b1 = 3 * u * u * t, b2 = 3 * u * t * t, b3 = t * t * t;
    return {b0 * kBezier[0].x + b1 * kBezier[1].x + b2 * kBezier[2].x + b3 * kBezier[3].x,
            b0 * kBezier[0].y + b1 * kBezier[1].y + b2 * kBezier[2].y + b3 * kBezier[3].y};
}

// The drawing: an outline of lines and an arc (one line drawn backwards), a
// slot island as a bulged LWPOLYLINE, a Bézier and a rational quarter circle
// as SPLINEs, an arc in a mirrored object coordinate system.
std::string drawing()
{
    const double w = std::sqrt(0.5);
    return header() + line("OUTLINE", 0, 0, 100, 0) + line("OUTLINE", 100, 0, 100, 40) + arc("OUTLINE", 80, 40, 20, 0, 90) +
           line("OUTLINE", 0, 60, 80, 60) + line("OUTLINE", 0, 60, 0, 0) +
           lwpolyline("ISLAND", true, {{30, 20, 0}, {60, 20, 1}, {60, 40, 0}, {30, 40, 1}}) +
           spline("CURVE", 3, {0, 0, 0, 0, 1, 1, 1, 1}, kBezier) +
           spline("CURVE", 2, {0, 0, 0, 1, 1, 1}, {{200, 0}, {200, 50}, {150, 50}}, {1, w, 1}) +
           arc("MIRROR", -150, 10, 5, 0, 90, -1) + kFooter;
}

std::string writeTemp(const QTemporaryDir& dir, const std::string& name, const std::string& text)
{
    const std::string path = dir.filePath(QString::fromStdString(name)).toStdString();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

const DxfContour* onLayer(const DxfReadResult& r, const std::string& layer, std::size_t nth = 0)
{
    for (const DxfContour& c : r.contours)
        if (!c.sources.empty() && c.sources.front().layer == layer && nth-- == 0) return &c;
    return nullptr;
}

bool isArc(const ContourSegment& s, Kind kind, Point2 start, Point2 end, Point2 centre, double radius)
{
    const bool ok = s.kind == kind && near(s.start, start) && near(s.end, end) && near(s.centre, centre) &&
                    near(s.radius(), radius) && near(taiwa::distance(s.end, s.centre), radius);
    if (!ok)
        qWarning("arc %d (%.12g, %.12g) → (%.12g, %.12g) around (%.12g, %.12g)", static_cast<int>(s.kind), s.start.x,
                 s.start.y, s.end.x, s.end.y, s.centre.x, s.centre.y);
    return ok;
}

bool isLine(const ContourSegment& s, Point2 a, Point2 b) { return s.kind == Kind::Line && near(s.start, a) && near(s.end, b); }

}  // namespace

class TestDxfImport : public QObject {
    Q_OBJECT
private slots:
    void outlineIslandSplinesAndMirroredArc()
    {
        QTemporaryDir dir;
        const DxfReadResult r = readDxf(writeTemp(dir, "part.dxf", drawing()));
        QVERIFY2(r.ok(), r.error.value_or("").c_str());
        QCOMPARE(r.units, std::string("mm"));
        QCOMPARE(r.contours.size(), std::size_t{5});
        QCOMPARE(r.closedCount(), 2);
        QVERIFY(r.gaps.empty());
        QVERIFY(r.branches.empty());
        QCOMPARE(r.smallGapsClosed, 0);

        // The outline: closed, the backwards line reversed, the arc exact.
        const DxfContour* outline = onLayer(r, "OUTLINE");
        QVERIFY(outline);
        const auto& o = outline->contour.segments;
        QVERIFY(outline->contour.closed);
        QCOMPARE(o.size(), std::size_t{5});
        QVERIFY(isLine(o[0], {0, 0}, {100, 0}));
        QVERIFY(isLine(o[1], {100, 0}, {100, 40}));
        QVERIFY(isArc(o[2], Kind::ArcCCW, {100, 40}, {80, 60}, {80, 40}, 20));
        QVERIFY(isLine(o[3], {80, 60}, {0, 60}));
        QVERIFY(isLine(o[4], {0, 60}, {0, 0}));
        QCOMPARE(outline->sources[2].type, std::string("ARC"));
        QVERIFY(near(taiwa::signedArea(outline->contour), 6000 - 400 + 100 * std::numbers::pi));
        QCOMPARE(taiwa::largestGap(outline->contour), 0.0);

        // The slot: bulge 1 → half circles around the ends' centres.
        const DxfContour* slot = onLayer(r, "ISLAND");
        QVERIFY(slot);
        const auto& s = slot->contour.segments;
        QVERIFY(slot->contour.closed);
        QCOMPARE(s.size(), std::size_t{4});
        QVERIFY(isLine(s[0], {30, 20}, {60, 20}));
        QVERIFY(isArc(s[1], Kind::ArcCCW, {60, 20}, {60, 40}, {60, 30}, 10));
        QVERIFY(isLine(s[2], {60, 40}, {30, 40}));
        QVERIFY(isArc(s[3], Kind::ArcCCW, {30, 40}, {30, 20}, {30, 30}, 10));
        QVERIFY(near(taiwa::signedArea(slot->contour), 600 + 100 * std::numbers::pi));

        // The Bézier: lines whose corners lie on the curve and which stray
        // from it by at most the spline tolerance.
        const DxfContour* curve = onLayer(r, "CURVE");
        QVERIFY(curve);
        QVERIFY(!curve->contour.closed);
        const auto& c = curve->contour.segments;
        QVERIFY(c.size() > 8);
        QVERIFY(std::all_of(c.begin(), c.end(), [](const ContourSegment& x) { return x.kind == Kind::Line; }));
        QVERIFY(near(curve->contour.start(), {0, 100}) && near(curve->contour.end(), {100, 100}));
        for (int i = 0; i <= 2000; ++i) {
            const Point2 p = bezier(i / 2000.0);
            QVERIFY2(taiwa::distanceTo(curve->contour, p) <= 0.01 + kExact, qPrintable(QString::number(i)));
        }
        for (const ContourSegment& x : c) {  // every corner is a point of the curve
            double best = 1e9;
            for (int i = 0; i <= 20000; ++i) best = std::min(best, taiwa::distance(bezier(i / 20000.0), x.end));
            QVERIFY(best < 0.005);
        }

        // The rational quarter circle: weights read, corners on the circle.
        const DxfContour* quarter = onLayer(r, "CURVE", 1);
        QVERIFY(quarter);
        QVERIFY(near(quarter->contour.start(), {200, 0}) && near(quarter->contour.end(), {150, 50}));
        for (const ContourSegment& x : quarter->contour.segments) {
            QVERIFY(near(taiwa::distance(x.end, {150, 0}), 50));
            QVERIFY(50 - taiwa::distance(x.at(0.5), {150, 0}) <= 0.01 + kExact);
        }

        // The arc drawn with extrusion (0, 0, -1): mirrored in X, clockwise.
        const DxfContour* mirrored = onLayer(r, "MIRROR");
        QVERIFY(mirrored);
        QCOMPARE(mirrored->contour.segments.size(), std::size_t{1});
        QVERIFY(isArc(mirrored->contour.segments[0], Kind::ArcCW, {145, 10}, {150, 15}, {150, 10}, 5));

        // The layers, the table's empty one included.
        QCOMPARE(r.layers.size(), std::size_t{5});
        const auto layer = [&](const std::string& n) {
            return *std::find_if(r.layers.begin(), r.layers.end(), [&](const LayerInfo& l) { return l.name == n; });
        };
        QCOMPARE(layer("OUTLINE").entities, 5);
        QCOMPARE(layer("ISLAND").entities, 1);
        QCOMPARE(layer("CURVE").entities, 2);
        QCOMPARE(layer("EMPTY").entities, 0);
        QVERIFY(layer("EMPTY").selected);
    }

    void layerSelection()
    {
        DxfOptions o;
        o.layers = {"island", "curve"};  // DXF layer names ignore case
        const DxfReadResult r = readDxfBytes(drawing(), o);
        QVERIFY2(r.ok(), r.error.value_or("").c_str());
        QCOMPARE(r.contours.size(), std::size_t{3});
        QVERIFY(onLayer(r, "ISLAND") && onLayer(r, "CURVE") && !onLayer(r, "OUTLINE"));
        QCOMPARE(r.layers.size(), std::size_t{5});  // all listed, two selected
        QCOMPARE(std::count_if(r.layers.begin(), r.layers.end(), [](const LayerInfo& l) { return l.selected; }), 2);

        o.layers = {"EMPTY"};
        const DxfReadResult none = readDxfBytes(drawing(), o);
        QVERIFY(!none.ok());
        QVERIFY2(none.error->find("no lines, arcs") != std::string::npos, none.error->c_str());
        QVERIFY2(none.error->find("OUTLINE (5)") != std::string::npos, none.error->c_str());
    }

    void inchUnits()
    {
        const std::string text = header(1) + line("0", 0, 0, 1, 0) + arc("0", 1, 0.5, 0.5, 270, 90) + kFooter;
        const DxfReadResult r = readDxfBytes(text);
        QVERIFY2(r.ok(), r.error.value_or("").c_str());
        QCOMPARE(r.units, std::string("inch"));
        QCOMPARE(r.unitScale, 25.4);
        QCOMPARE(r.contours.size(), std::size_t{1});
        const auto& s = r.contours[0].contour.segments;
        QCOMPARE(s.size(), std::size_t{2});
        QVERIFY(isLine(s[0], {0, 0}, {25.4, 0}));
        QVERIFY(isArc(s[1], Kind::ArcCCW, {25.4, 0}, {25.4, 25.4}, {25.4, 12.7}, 12.7));

        DxfOptions mm;
        mm.units = Units::Millimetres;  // the operator overrides the file
        const DxfReadResult m = readDxfBytes(text, mm);
        QVERIFY(isLine(m.contours[0].contour.segments[0], {0, 0}, {1, 0}));
        QVERIFY(std::any_of(m.warnings.begin(), m.warnings.end(), [](const std::string& w) { return w.find("inch") != std::string::npos; }));

        const DxfReadResult unitless = readDxfBytes(header(0) + line("0", 0, 0, 1, 0) + kFooter);
        QCOMPARE(unitless.unitScale, 1.0);
        QVERIFY(std::any_of(unitless.warnings.begin(), unitless.warnings.end(),
                            [](const std::string& w) { return w.find("read as mm") != std::string::npos; }));
    }

    void gapBeyondTheToleranceIsReported()
    {
        // A line ends 0.2 mm before the arc that should continue it.
        const std::string text = header() + line("OUTLINE", 0, 0, 35, 12.5) + arc("OUTLINE", 45.2, 12.5, 10, 180, 0) +
                                 line("OUTLINE", 55.2, 12.5, 0, 0) + kFooter;
        const DxfReadResult r = readDxfBytes(text);
        QVERIFY2(r.ok(), r.error.value_or("").c_str());
        QCOMPARE(r.contours.size(), std::size_t{1});
        QVERIFY(!r.contours[0].contour.closed);
        QCOMPARE(r.gaps.size(), std::size_t{1});
        const DxfGap& g = r.gaps[0];
        QVERIFY(near(g.size, 0.2));
        QVERIFY(near(g.at, {35, 12.5}));
        QVERIFY(near(g.other, {35.2, 12.5}));
        QCOMPARE(g.a.type, std::string("LINE"));
        QCOMPARE(g.b.type, std::string("ARC"));
        QCOMPARE(g.a.layer, std::string("OUTLINE"));
        QVERIFY2(g.message.find("gap of 0.2 mm at (35.000, 12.500) between LINE on layer OUTLINE (DXF line") == 0,
                 g.message.c_str());
        QVERIFY2(g.message.find("and ARC on layer OUTLINE") != std::string::npos, g.message.c_str());

        // With a tolerance over the gap it is closed, counted, and the line
        // moved to the arc, which stays exact.
        DxfOptions loose;
        loose.gapTolerance = 0.5;
        const DxfReadResult c = readDxfBytes(text, loose);
        QCOMPARE(c.contours.size(), std::size_t{1});
        QVERIFY(c.contours[0].contour.closed);
        QVERIFY(c.gaps.empty());
        QCOMPARE(c.smallGapsClosed, 1);
        QVERIFY(near(c.largestGapClosed, 0.2));
        QCOMPARE(taiwa::largestGap(c.contours[0].contour), 0.0);
        for (const ContourSegment& s : c.contours[0].contour.segments)
            if (s.isArc()) QVERIFY(isArc(s, Kind::ArcCCW, {35.2, 12.5}, {55.2, 12.5}, {45.2, 12.5}, 10));
    }

    void polylineR12AndBranch()
    {
        // An R12 POLYLINE with VERTEX entities and a bulge, closed by its flag.
        std::string text = header() + "0\nPOLYLINE\n8\nP\n66\n1\n70\n1\n";
        for (const V& v : std::vector<V>{{0, 0, 0}, {10, 0, 1}, {10, 10, 0}, {0, 10, 0}})
            text += fmt::format("0\nVERTEX\n8\nP\n10\n{}\n20\n{}\n42\n{}\n", v.x, v.y, v.bulge);
        text += "0\nSEQEND\n";
        // Three lines meeting at one point.
        text += line("B", 50, 0, 60, 0) + line("B", 60, 0, 70, 5) + line("B", 60, 0, 70, -5) + kFooter;
        const DxfReadResult r = readDxfBytes(text);
        QVERIFY2(r.ok(), r.error.value_or("").c_str());
        const DxfContour* p = onLayer(r, "P");
        QVERIFY(p && p->contour.closed);
        QCOMPARE(p->contour.segments.size(), std::size_t{4});
        QVERIFY(isArc(p->contour.segments[1], Kind::ArcCCW, {10, 0}, {10, 10}, {10, 5}, 5));
        QCOMPARE(p->sources[0].type, std::string("POLYLINE"));
        QCOMPARE(r.branches.size(), std::size_t{1});
        QCOMPARE(r.branches[0].ends, 3);
        QVERIFY(near(r.branches[0].at, {60, 0}));
        QVERIFY2(r.branches[0].message.find("3 ends meet at (60.000, 0.000)") == 0, r.branches[0].message.c_str());
    }

    void garbageAndHostileFilesGiveMessages()
    {
        const auto error = [](const std::string& bytes) { return readDxfBytes(bytes).error.value_or("(read)"); };
        QVERIFY(readDxf("/nonexistent/part.dxf").error->find("cannot read") == 0);
        QCOMPARE(error(""), std::string("the file is empty"));
        QVERIFY2(error("hello\nworld\n").find("not a DXF") != std::string::npos, error("hello\nworld\n").c_str());
        QVERIFY(error(std::string("0\nSECTION\n\0\1\2", 13)).find("binary") != std::string::npos);
        QVERIFY(error("AutoCAD Binary DXF\r\n\x1a").find("binary DXF") != std::string::npos);
        QVERIFY(error("0\nSECTION\n2\nHEADER\n0\nENDSEC\n0\nEOF\n").find("no ENTITIES") != std::string::npos);

        // Counts far beyond the vertices present (dxflib alone crashes on
        // these), NaN and infinite coordinates, a degenerate arc, a line
        // longer than dxflib's buffer: messages, no crash, no hang.
        const std::string hostile = header() +
                                    "0\nLWPOLYLINE\n8\nH\n90\n1073741824\n70\n0\n42\n5\n10\n0\n20\n0\n10\n1\n20\n1\n" +
                                    "0\nSPLINE\n8\nH\n70\n8\n71\n3\n72\n2147483647\n73\n1073741824\n40\n0\n10\n0\n20\n0\n" +
                                    "0\nLINE\n8\nH\n10\nnan\n20\n0\n11\n1\n21\ninf\n" + "0\nLINE\n8\nH\n10\n1e400\n20\n0\n11\n1\n21\n1\n" +
                                    arc("H", 0, 0, 0, 0, 90) + "0\nLINE\n8\n" + std::string(5000, 'L') +
                                    "\n10\n0\n20\n0\n11\n-1\n21\n-1\n" + kFooter;
        const DxfReadResult h = readDxfBytes(hostile);
        QVERIFY2(h.ok(), h.error.value_or("").c_str());
        QCOMPARE(h.contours.size(), std::size_t{1});  // the two-vertex LWPOLYLINE and the long-layer line
        const auto warned = [&](const char* what) {
            return std::any_of(h.warnings.begin(), h.warnings.end(), [&](const std::string& w) { return w.find(what) != std::string::npos; });
        };
        QVERIFY(warned("'nan' is not a finite number"));
        QVERIFY(warned("'1e400' is not a finite number"));
        QVERIFY(warned("its radius 0 is not positive"));
        QVERIFY(warned("SPLINE on layer H"));  // 1 knot for 1 control point

        DxfOptions bad;
        bad.gapTolerance = std::nan("");
        QVERIFY(readDxfBytes(drawing(), bad).error->find("gap tolerance") != std::string::npos);
    }

    void tenThousandShuffledEntitiesChainFast()
    {
        // A 10,000-gon of LINEs in random order, half of them drawn backwards.
        constexpr int n = 10000;
        std::vector<std::string> lines;
        const auto corner = [](int i) {
            const double a = 2 * std::numbers::pi * i / n;
            return Point2{1000 * std::cos(a), 1000 * std::sin(a)};
        };
        std::mt19937 rng(7);
        for (int i = 0; i < n; ++i) {
            Point2 a = corner(i), b = corner((i + 1) % n);
            if (rng() % 2) std::swap(a, b);
            lines.push_back(line("0", a.x, a.y, b.x, b.y));
        }
        std::shuffle(lines.begin(), lines.end(), rng);
        std::string text = header();
        for (const std::string& l : lines) text += l;
        text += kFooter;
        const auto t0 = std::chrono::steady_clock::now();
        const DxfReadResult r = readDxfBytes(text);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        qInfo("10,000 LINEs read and chained in %.0f ms", ms);
        QVERIFY2(r.ok(), r.error.value_or("").c_str());
        QCOMPARE(r.contours.size(), std::size_t{1});
        QVERIFY(r.contours[0].contour.closed);
        QCOMPARE(r.contours[0].contour.segments.size(), std::size_t{n});
        QVERIFY(near(std::abs(taiwa::signedArea(r.contours[0].contour)), 0.5 * n * 1e6 * std::sin(2 * std::numbers::pi / n), 1e-6));
        QVERIFY(ms < 3000);
    }
};

QTEST_APPLESS_MAIN(TestDxfImport)
#include "test_dxf_import.moc"
