// Contours to figure elements (core/figure/figure_from_contours.*): the text written for
// closed contours of lines and arcs (tangent and crossing junctions, the
// modifier that picks each, one that only Y can pick), full circles, open
// contours, merged lines and arcs, and the contours of a hand-written DXF,
// read back and evaluated to the same segments within 1e-6 mm; names that
// do not collide with a figure's own; contours the text cannot hold left out
// with the reason.
#include "figure/figure_from_contours.h"

#include "dxf/dxf_import.h"
#include "figure/figure_eval.h"
#include "figure/figure_text.h"

#include <QtTest>

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using namespace taiwa;

namespace QTest {
template <>
inline char* toString(const std::string& s)
{
    return qstrdup(s.c_str());
}
}  // namespace QTest

using Kind = ContourSegment::Kind;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kWithin = 1e-6;  // mm: the round trip

Point2 polar(Point2 c, double r, double a) { return {c.x + r * std::cos(a), c.y + r * std::sin(a)}; }

// A closed contour through `corners` (counter-clockwise) with every corner
// rounded by an arc of radius r tangent to both sides.
Contour roundedPolygon(const std::vector<Point2>& corners, double r)
{
    const std::size_t n = corners.size();
    std::vector<Point2> in(n), out(n), centre(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Point2 p = corners[(i + n - 1) % n], q = corners[i], s = corners[(i + 1) % n];
        const Point2 d1 = (1.0 / length(q - p)) * (q - p), d2 = (1.0 / length(s - q)) * (s - q);
        const double half = std::acos(std::clamp(dot(-1.0 * d1, d2), -1.0, 1.0)) / 2;  // half the inner angle
        const double back = r / std::tan(half);
        in[i] = q - back * d1;
        out[i] = q + back * d2;
        centre[i] = in[i] + r * Point2{-d1.y, d1.x};
    }
    Contour c;
    c.closed = true;
    for (std::size_t i = 0; i < n; ++i) {
        c.segments.push_back(ContourSegment::arc(in[i], out[i], centre[i], true));
        c.segments.push_back(ContourSegment::line(out[i], in[(i + 1) % n]));
    }
    return c;
}

// Parses and evaluates the whole text; every contour named comes back as
// figureReady(given) within kWithin, segment by segment.
QString roundTrip(const std::string& text, const FigureFromContours& written, const std::vector<Contour>& given)
{
    const figure::ParseResult read = figure::parseFigure(text);
    if (!read.ok()) return QString::fromStdString("refused: " + read.error->text());
    const figure::Evaluation ev = figure::evaluate(read.definitions);
    if (!ev.ok()) return QString::fromStdString("not evaluated: " + ev.errors.front().text());
    for (std::size_t i = 0; i < given.size(); ++i) {
        if (written.names[i].empty()) return QStringLiteral("contour %1 left out").arg(i + 1);
        const figure::EvaluatedContour* got = ev.findContour(written.names[i]);
        if (!got) return QStringLiteral("no contour %1").arg(QString::fromStdString(written.names[i]));
        const Contour want = figureReady(given[i]);
        if (got->contour.closed != want.closed || got->contour.segments.size() != want.segments.size())
            return QStringLiteral("contour %1: %2 segments, not %3")
                .arg(i + 1)
                .arg(got->contour.segments.size())
                .arg(want.segments.size());
        for (std::size_t k = 0; k < want.segments.size(); ++k) {
            const ContourSegment &g = got->contour.segments[k], &w = want.segments[k];
            const bool ok = g.kind == w.kind && distance(g.start, w.start) <= kWithin &&
                            distance(g.end, w.end) <= kWithin && (!w.isArc() || distance(g.centre, w.centre) <= kWithin);
            if (!ok)
                return QString::fromStdString(fmt::format(
                    "contour {} segment {}: kind {} ({:.9f}, {:.9f}) → ({:.9f}, {:.9f}) c ({:.9f}, {:.9f}); wanted "
                    "kind {} ({:.9f}, {:.9f}) → ({:.9f}, {:.9f}) c ({:.9f}, {:.9f})",
                    i + 1, k, static_cast<int>(g.kind), g.start.x, g.start.y, g.end.x, g.end.y, g.centre.x, g.centre.y,
                    static_cast<int>(w.kind), w.start.x, w.start.y, w.end.x, w.end.y, w.centre.x, w.centre.y));
        }
    }
    return {};
}

QString roundTrip(const std::vector<Contour>& given, const FigureNaming& naming = {})
{
    const FigureFromContours w = figureFromContours(given, naming);
    for (const auto& r : w.refusals) qWarning("%s", r.c_str());
    for (const auto& n : w.notes) qWarning("%s", n.c_str());
    const QString why = roundTrip(w.text, w, given);
    if (!why.isEmpty()) qWarning("%s", w.text.c_str());
    return why;
}

// The contour statement of a text (the last line that defines a CONTOUR).
std::string contourLine(const std::string& text)
{
    std::string last;
    std::size_t i = 0;
    while (i < text.size()) {
        const std::size_t eol = text.find('\n', i);
        const std::string line = text.substr(i, eol - i);
        if (line.find("CONTOUR/") != std::string::npos) last = line;
        i = eol == std::string::npos ? text.size() : eol + 1;
    }
    return last;
}

// The DXF of tests/test_dxf_import.cpp, in part: the outline of lines and a
// tangent arc, the slot of a bulged LWPOLYLINE, a rational quarter circle as
// a SPLINE (lines), an arc in a mirrored coordinate system.
std::string drawing()
{
    const double w = std::sqrt(0.5);
    std::string s =
        "0\nSECTION\n2\nHEADER\n9\n$INSUNITS\n70\n4\n0\nENDSEC\n0\nSECTION\n2\nENTITIES\n"
        "0\nLINE\n8\nOUTLINE\n10\n0\n20\n0\n30\n0\n11\n100\n21\n0\n31\n0\n"
        "0\nLINE\n8\nOUTLINE\n10\n100\n20\n0\n30\n0\n11\n100\n21\n40\n31\n0\n"
        "0\nARC\n8\nOUTLINE\n10\n80\n20\n40\n30\n0\n40\n20\n50\n0\n51\n90\n210\n0\n220\n0\n230\n1\n"
        "0\nLINE\n8\nOUTLINE\n10\n0\n20\n60\n30\n0\n11\n80\n21\n60\n31\n0\n"
        "0\nLINE\n8\nOUTLINE\n10\n0\n20\n60\n30\n0\n11\n0\n21\n0\n31\n0\n"
        "0\nLWPOLYLINE\n8\nISLAND\n90\n4\n70\n1\n10\n30\n20\n20\n42\n0\n10\n60\n20\n20\n42\n1\n10\n60\n20\n40\n42\n0\n"
        "10\n30\n20\n40\n42\n1\n"
        "0\nARC\n8\nMIRROR\n10\n-150\n20\n10\n30\n0\n40\n5\n50\n0\n51\n90\n210\n0\n220\n0\n230\n-1\n";
    s += "0\nSPLINE\n8\nCURVE\n210\n0\n220\n0\n230\n1\n70\n12\n71\n2\n72\n6\n73\n3\n74\n0\n";
    for (double k : {0, 0, 0, 1, 1, 1}) s += fmt::format("40\n{}\n", k);
    const Point2 ctrl[] = {{200, 0}, {200, 50}, {150, 50}};
    const double weights[] = {1, w, 1};
    for (int i = 0; i < 3; ++i) s += fmt::format("10\n{}\n20\n{}\n30\n0\n41\n{}\n", ctrl[i].x, ctrl[i].y, weights[i]);
    return s + "0\nENDSEC\n0\nEOF\n";
}

}  // namespace

class TestDxfFigure : public QObject {
    Q_OBJECT
private slots:
    void outlineWithTangentArcIsWrittenAndReadBack()
    {
        // The outline of the DXF test: its arc tangent to both lines.
        Contour c;
        c.closed = true;
        c.segments = {ContourSegment::line({0, 0}, {100, 0}), ContourSegment::line({100, 0}, {100, 40}),
                      ContourSegment::arc({100, 40}, {80, 60}, {80, 40}, true),
                      ContourSegment::line({80, 60}, {0, 60}), ContourSegment::line({0, 60}, {0, 0})};
        const FigureFromContours w = figureFromContours({c});
        QVERIFY(w.refusals.empty());
        QCOMPARE(w.names, std::vector<std::string>{"K1"});
        QCOMPARE(w.text, std::string("$$ contour 1: closed, 4 lines, 1 arc\n"
                                     "P1 = POINT/0, 0\n"
                                     "P2 = POINT/100, 0\n"
                                     "P3 = POINT/80, 40\n"
                                     "P4 = POINT/0, 60\n"
                                     "C1 = CIRCLE/CENTER, P3, RADIUS, 20\n"
                                     "L1 = LINE/P1, P2\n"
                                     "L2 = LINE/P2, RIGHT, TANTO, C1\n"
                                     "L3 = LINE/P4, LEFT, TANTO, C1\n"
                                     "L4 = LINE/P4, P1\n"
                                     "K1 = CONTOUR/L1, L2, CCLW, C1, L3, L4\n"));
        QVERIFY2(roundTrip({c}).isEmpty(), qPrintable(roundTrip({c})));
    }

    void tangentArcsAtOddCoordinatesComeBackExact()
    {
        // Rounded polygons turned and moved by irrational amounts: every
        // junction tangent, no coordinate a multiple of 1e-6 mm.
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int trial = 0; trial < 200; ++trial) {
            const double turn = u(rng) * 2 * kPi, size = 5 + 200 * u(rng);
            const Point2 shift{-300 + 600 * u(rng), -300 + 600 * u(rng)};
            std::vector<Point2> corners;
            const int n = 3 + trial % 5;
            for (int i = 0; i < n; ++i) {
                const double a = turn + 2 * kPi * (i + 0.3 * u(rng)) / n;
                corners.push_back(polar(shift, size * (0.7 + 0.3 * u(rng)), a));
            }
            const Contour c = roundedPolygon(corners, size * (0.01 + 0.1 * u(rng)));
            const QString why = roundTrip({c});
            QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("trial %1: %2").arg(trial).arg(why)));
        }
    }

    void crossingJunctionsGetTheModifierThatPicksThem()
    {
        // A pie slice: two radii and the arc between them, every junction a
        // crossing of a line and the circle; turned by an odd angle.
        std::mt19937 rng(11);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int trial = 0; trial < 200; ++trial) {
            const Point2 o{-100 + 200 * u(rng), -100 + 200 * u(rng)};
            const double r = 1 + 50 * u(rng), a1 = 2 * kPi * u(rng), a2 = a1 + 0.2 + 2.5 * u(rng);
            const bool ccw = trial % 2 == 0;
            Contour c;
            c.closed = true;
            const Point2 p1 = polar(o, r, a1), p2 = polar(o, r, a2);
            if (ccw)
                c.segments = {ContourSegment::line(o, p1), ContourSegment::arc(p1, p2, o, true),
                              ContourSegment::line(p2, o)};
            else
                c.segments = {ContourSegment::line(o, p2), ContourSegment::arc(p2, p1, o, false),
                              ContourSegment::line(p1, o)};
            const FigureFromContours w = figureFromContours({c});
            const std::string k = contourLine(w.text);
            QVERIFY2(k.find("LARGE") != std::string::npos || k.find("SMALL") != std::string::npos, k.c_str());
            const QString why = roundTrip({c});
            QVERIFY2(why.isEmpty(), qPrintable(QStringLiteral("trial %1: %2").arg(trial).arg(why)));
        }
    }

    void aJunctionOnlyYCanPick()
    {
        // A D: the chord x = 6 and the arc round the origin. Both crossings
        // of the chord and the circle have x = 6: only YLARGE/YSMALL choose.
        Contour c;
        c.closed = true;
        c.segments = {ContourSegment::line({6, -8}, {6, 8}), ContourSegment::arc({6, 8}, {6, -8}, {0, 0}, true)};
        const FigureFromContours w = figureFromContours({c});
        QCOMPARE(contourLine(w.text), std::string("K1 = CONTOUR/YSMALL, L1, YLARGE, CCLW, C1"));
        QVERIFY2(roundTrip({c}).isEmpty(), qPrintable(roundTrip({c})));
        // Written without the modifiers, the figure refuses the contour.
        std::string bare = w.text;
        for (const char* m : {"YSMALL, ", "YLARGE, "}) bare.erase(bare.find(m), std::string(m).size());
        const figure::Evaluation ev = figure::evaluate(figure::parseFigure(bare).definitions);
        QVERIFY(!ev.ok());
        QVERIFY2(ev.errors.front().message.find("meet twice") != std::string::npos, ev.errors.front().message.c_str());
    }

    void arcsMeetingArcs()
    {
        // A lens of two arcs crossing (circle–circle modifiers), and an S of
        // two tangent arcs closed by a line.
        Contour lens;
        lens.closed = true;
        const Point2 top{0, std::sqrt(100.0 - 36.0)}, bottom{0, -std::sqrt(100.0 - 36.0)};
        lens.segments = {ContourSegment::arc(bottom, top, {-6, 0}, true), ContourSegment::arc(top, bottom, {6, 0}, true)};
        Contour s;
        s.closed = true;
        s.segments = {ContourSegment::arc({0, 0}, {20, 0}, {10, 0}, true),
                      ContourSegment::arc({20, 0}, {40, 0}, {30, 0}, false), ContourSegment::line({40, 0}, {0, 0})};
        QVERIFY2(roundTrip({lens, s}).isEmpty(), qPrintable(roundTrip({lens, s})));
        // Both crossings of the lens's circles have x = 0.
        QCOMPARE(contourLine(figureTextFromContours({lens})), std::string("K1 = CONTOUR/YSMALL, CCLW, C1, YLARGE, CCLW, C2"));
    }

    void fullCirclesAndOpenContours()
    {
        Contour circle;  // drawn from its top: the figure starts it at angle 0
        circle.closed = true;
        circle.segments = {ContourSegment::arc({12.5, 7.25}, {12.5, 7.25}, {12.5, 3}, false)};
        Contour odd;  // a full circle at an odd place
        odd.closed = true;
        const Point2 oc{std::sqrt(2.0) * 10, -std::numbers::e};
        odd.segments = {ContourSegment::arc(polar(oc, kPi, 0), polar(oc, kPi, 0), oc, true)};
        Contour open;  // a line, a crossing arc, a tangent arc, a line
        const Point2 a{0, 0}, b{10, 0}, m{20, 10};
        open.segments = {ContourSegment::line(a, b), ContourSegment::arc(b, {20, 0}, {15, 0}, false),
                         ContourSegment::arc({20, 0}, {30, 0}, {25, 0}, true), ContourSegment::line({30, 0}, m)};
        Contour arcOnly;  // one arc, open, odd ends
        arcOnly.segments = {ContourSegment::arc(polar({3, 4}, 7.7, 0.3), polar({3, 4}, 7.7, 2.9), {3, 4}, true)};
        Contour zigzag;  // lines at odd angles
        for (int i = 0; i < 12; ++i)
            zigzag.segments.push_back(
                ContourSegment::line({i * 1.1 + 0.0000003 * i, std::sin(i) * 3}, {(i + 1) * 1.1 + 0.0000003 * (i + 1), std::sin(i + 1) * 3}));
        const std::vector<Contour> all{circle, odd, open, arcOnly, zigzag};
        QVERIFY2(roundTrip(all).isEmpty(), qPrintable(roundTrip(all)));
        const FigureFromContours w = figureFromContours(all);
        QVERIFY2(w.text.find("K1 = CONTOUR/CLW, C1\n") != std::string::npos, w.text.c_str());
        QVERIFY(distance(figureReady(circle).segments[0].start, {16.75, 3}) < 1e-12);
        // An open contour runs from a point to a point.
        QVERIFY2(w.text.find("K4 = CONTOUR/P") != std::string::npos, w.text.c_str());
    }

    void collinearLinesAndArcsOnOneCircleAreMerged()
    {
        Contour c;
        c.closed = true;
        c.segments = {ContourSegment::line({0, 0}, {10, 0}), ContourSegment::line({10, 0}, {30, 0}),
                      ContourSegment::arc({30, 0}, {40, 10}, {30, 10}, true),
                      ContourSegment::arc({40, 10}, {30, 20}, {30, 10}, true), ContourSegment::line({30, 20}, {0, 20}),
                      ContourSegment::line({0, 20}, {0, 5}), ContourSegment::line({0, 5}, {0, 0})};
        const Contour ready = figureReady(c);
        QCOMPARE(ready.segments.size(), std::size_t{4});
        QCOMPARE(ready.segments[0], ContourSegment::line({0, 0}, {30, 0}));
        QCOMPARE(ready.segments[1], ContourSegment::arc({30, 0}, {30, 20}, {30, 10}, true));
        QCOMPARE(ready.segments[3], ContourSegment::line({0, 20}, {0, 0}));
        // The closed contour's last and first line are one: it starts earlier.
        Contour wrap;
        wrap.closed = true;
        wrap.segments = {ContourSegment::line({5, 0}, {10, 0}), ContourSegment::line({10, 0}, {10, 10}),
                         ContourSegment::line({10, 10}, {0, 10}), ContourSegment::line({0, 10}, {0, 0}),
                         ContourSegment::line({0, 0}, {5, 0})};
        QCOMPARE(figureReady(wrap).segments.front(), ContourSegment::line({0, 0}, {10, 0}));
        QCOMPARE(figureReady(wrap).segments.size(), std::size_t{4});
        // Two halves of a circle: one full circle.
        Contour halves;
        halves.closed = true;
        halves.segments = {ContourSegment::arc({0, 5}, {0, -5}, {0, 0}, true), ContourSegment::arc({0, -5}, {0, 5}, {0, 0}, true)};
        QCOMPARE(figureReady(halves).segments, std::vector<ContourSegment>{ContourSegment::arc({5, 0}, {5, 0}, {0, 0}, true)});
        QVERIFY2(roundTrip({c, wrap, halves}).isEmpty(), qPrintable(roundTrip({c, wrap, halves})));
    }

    void theDxfDrawingComesBack()
    {
        const dxf::DxfReadResult r = dxf::readDxfBytes(drawing());
        QVERIFY2(r.ok(), r.error.value_or("").c_str());
        QCOMPARE(r.contours.size(), std::size_t{4});
        std::vector<Contour> contours;
        for (const auto& c : r.contours) contours.push_back(c.contour);
        const FigureFromContours w = figureFromContours(contours);
        QVERIFY(w.refusals.empty());
        QVERIFY(w.notes.empty());
        QVERIFY2(roundTrip(contours).isEmpty(), qPrintable(roundTrip(contours)));
        // The slot: two half circles, each tangent to both lines.
        QVERIFY2(w.text.find("= LINE/RIGHT, TANTO, C3, RIGHT, TANTO, C2\n") != std::string::npos, w.text.c_str());
    }

    void namesDoNotCollide()
    {
        const std::string existing = "P1 = POINT/0, 0\n"
                                     "p2 = POINT/10, 0\n"
                                     "L1 = LINE/P1, P2\n"
                                     "c1 = CIRCLE/CENTER, P1, RADIUS, 3\n"
                                     "K1 = CONTOUR/CCLW, C1\n"
                                     "  K3=CONTOUR/CLW, C1\n";
        const std::set<std::string> taken = figureNames(existing);
        QCOMPARE(taken, (std::set<std::string>{"P1", "P2", "L1", "C1", "K1", "K3"}));
        Contour c = roundedPolygon({{0, 0}, {50, 0}, {50, 30}, {0, 30}}, 4);
        Contour d = roundedPolygon({{10, 10}, {20, 10}, {15, 20}}, 1);
        const FigureFromContours w = figureFromContours({c, d}, {taken, ""});
        QCOMPARE(w.names, (std::vector<std::string>{"K2", "K4"}));
        // The job's figure and the new text together: every name once.
        const std::string both = existing + w.text;
        QVERIFY2(figure::parseFigure(both).ok(), figure::parseFigure(both).error->text().c_str());
        QVERIFY2(roundTrip(both, w, {c, d}).isEmpty(), qPrintable(roundTrip(both, w, {c, d})));
        // A prefix (read in either case).
        const FigureFromContours p = figureFromContours({c}, {taken, "dx"});
        QCOMPARE(p.names, std::vector<std::string>{"DXK1"});
        QVERIFY(p.text.find("DXP1 = POINT/") != std::string::npos);
        QVERIFY(p.text.find("DXC4 = CIRCLE/") != std::string::npos);
        QVERIFY_THROWS_EXCEPTION(std::logic_error, figureFromContours({c}, {{}, "1A"}));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, figureFromContours({c}, {{}, "A-"}));
    }

    // A circle of 20,000 lines, r 4 mm: to 1e-6 mm the two sides that meet
    // at (4, 0) both round to vertical lines, which no longer cross, so the
    // writer refuses that attempt before making a statement, and the
    // contour is written to 1e-7 mm. The names it was given stay given: the
    // next contour's start after its 20,000.
    void aPolygonOfManyShortSidesGetsMoreDecimals()
    {
        constexpr int kSides = 20000;
        Contour circle;
        circle.closed = true;
        for (int i = 0; i < kSides; ++i)
            circle.segments.push_back(ContourSegment::line(polar({0, 0}, 4, 2 * kPi * i / kSides),
                                                           polar({0, 0}, 4, 2 * kPi * (i + 1) / kSides)));
        circle.segments.back().end = circle.segments.front().start;
        Contour square;
        square.closed = true;
        square.segments = {ContourSegment::line({10, 0}, {12, 0}), ContourSegment::line({12, 0}, {12, 2}),
                           ContourSegment::line({12, 2}, {10, 2}), ContourSegment::line({10, 2}, {10, 0})};
        const FigureFromContours w = figureFromContours({circle, square});
        QVERIFY(w.refusals.empty());
        QCOMPARE(w.names, (std::vector<std::string>{"K1", "K2"}));
        QCOMPARE(w.notes, std::vector<std::string>{"contour 1 (K1) is written to 0.0000001 mm: to 0.000001 mm two of its "
                                                   "lines no longer meet at (4.000, 0.000) once written to 1e-06 mm"});
        QVERIFY2(w.text.find("\nP2 = POINT/3.9999998, 0.0012566\n") != std::string::npos, w.text.substr(0, 200).c_str());
        QVERIFY2(w.text.find("\nP20001 = POINT/10, 0\n") != std::string::npos, contourLine(w.text).c_str());
        QVERIFY2(w.text.find("\nK2 = CONTOUR/L20001, L20002, L20003, L20004\n") != std::string::npos, contourLine(w.text).c_str());
        QVERIFY2(roundTrip(w.text, w, {circle, square}).isEmpty(), qPrintable(roundTrip(w.text, w, {circle, square})));
    }

    void contoursTheTextCannotHoldAreLeftOut()
    {
        Contour far;
        far.segments = {ContourSegment::line({0, 0}, {2e6, 0})};
        Contour ok;
        ok.segments = {ContourSegment::line({0, 0}, {1, 0})};
        const FigureFromContours w = figureFromContours({far, ok});
        QCOMPARE(w.names, (std::vector<std::string>{"", "K1"}));
        QCOMPARE(w.refusals.size(), std::size_t{1});
        QVERIFY2(w.refusals[0].find("contour 1 is left out: it reaches (2000000.000, 0.000)") == 0,
                 w.refusals[0].c_str());
        // Its names were not used up: the next contour's points start at P1.
        QVERIFY2(w.text.find("$$ contour 1 (open, 1 line, 0 arcs) left out: ") == 0, w.text.c_str());
        QVERIFY(w.text.find("P1 = POINT/0, 0\nP2 = POINT/1, 0\nL1 = LINE/P1, P2\nK1 = CONTOUR/P1, L1, P2\n") !=
                std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestDxfFigure)
#include "test_dxf_figure.moc"
