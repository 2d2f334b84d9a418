// Figure contours (core/figure/figure_contour.*): CONTOUR statements
// evaluated against hand-computed segments (lines run in the chain's
// direction, circles as arcs the way written, junctions chosen by modifiers,
// ROUND fillets and CHAMF lines cut into the corners), every refusal with
// its line, column and message, the canonical round trip, definedFrom, and
// the corner revision that changes one value in the text.
#include "figure/figure_contour.h"
#include "figure/figure_eval.h"
#include "figure/figure_text.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <string>

using namespace taiwa::figure;
using taiwa::ContourSegment;
using taiwa::Point2;

namespace QTest {
template <>
inline char* toString(const std::string& s)
{
    return qstrdup(s.c_str());
}
}  // namespace QTest

namespace {

constexpr double kExact = 1e-9;
constexpr double kPi = std::numbers::pi;

// Elements for every test; contours go on line 20 and after.
const std::string kBase = "P1 = POINT/0, 0\n"                    // 1
                          "P2 = POINT/40, 0\n"                   // 2
                          "P3 = POINT/40, 20\n"                  // 3
                          "P4 = POINT/0, 20\n"                   // 4
                          "L1 = LINE/P1, P2\n"                   // 5: y = 0, along +X
                          "L2 = LINE/P2, P3\n"                   // 6: x = 40, along +Y
                          "L3 = LINE/P4, P3\n"                   // 7: y = 20, along +X
                          "L4 = LINE/P1, P4\n"                   // 8: x = 0, along +Y
                          "C1 = CIRCLE/CENTER, P1, RADIUS, 5\n"  // 9
                          "PA = POINT/-10, 3\n"                  // 10
                          "LA = LINE/PA, ATANGL, 0\n"            // 11: y = 3
                          "PB = POINT/3, -10\n"                  // 12
                          "LB = LINE/PB, ATANGL, 90\n"           // 13: x = 3
                          "Q = POINT/8, 0\n"                     // 14
                          "C2 = CIRCLE/CENTER, Q, RADIUS, 5\n"   // 15
                          "R = POINT/18, 0\n"                    // 16
                          "C3 = CIRCLE/CENTER, R, RADIUS, 5\n"   // 17: touches C2 at (13, 0)
                          "Q1 = POINT/8, 5\n"                    // 18
                          "Q2 = POINT/18, -5\n";                 // 19

Evaluation run(const std::string& contours)
{
    const ParseResult p = parseFigure(kBase + contours);
    if (!p.ok()) qFatal("parse: %s", p.error->text().c_str());
    return evaluate(p.definitions);
}

EvaluatedContour contourOf(const Evaluation& ev, const std::string& name)
{
    if (!ev.errors.empty()) qFatal("evaluate: %s", ev.errors.front().text().c_str());
    const EvaluatedContour* c = ev.findContour(name);
    if (!c) qFatal("no contour %s", name.c_str());
    return *c;
}

bool near(Point2 a, Point2 b) { return std::abs(a.x - b.x) <= kExact && std::abs(a.y - b.y) <= kExact; }

bool isLine(const ContourSegment& s, Point2 a, Point2 b)
{
    if (s.kind == ContourSegment::Kind::Line && near(s.start, a) && near(s.end, b)) return true;
    qWarning("segment (%.12g, %.12g) -> (%.12g, %.12g), kind %d", s.start.x, s.start.y, s.end.x, s.end.y,
             static_cast<int>(s.kind));
    return false;
}

bool isArc(const ContourSegment& s, Point2 a, Point2 b, Point2 c, bool ccw)
{
    const auto kind = ccw ? ContourSegment::Kind::ArcCCW : ContourSegment::Kind::ArcCW;
    if (s.kind == kind && near(s.start, a) && near(s.end, b) && near(s.centre, c)) return true;
    qWarning("segment (%.12g, %.12g) -> (%.12g, %.12g) about (%.12g, %.12g), kind %d", s.start.x, s.start.y, s.end.x,
             s.end.y, s.centre.x, s.centre.y, static_cast<int>(s.kind));
    return false;
}

std::string parseError(const std::string& contours)
{
    const ParseResult p = parseFigure(kBase + contours);
    return p.ok() ? std::string("(parsed)") : p.error->text();
}

std::string evalError(const std::string& contours)
{
    const ParseResult p = parseFigure(kBase + contours);
    if (!p.ok()) return "parse: " + p.error->text();
    const Evaluation ev = evaluate(p.definitions);
    return ev.errors.empty() ? std::string("(evaluated)") : ev.errors.front().text();
}

}  // namespace

class TestFigureContours : public QObject {
    Q_OBJECT
private slots:
    void rectangleWithARoundAndAChamfer()
    {
        // Counter-clockwise round the 40 × 20 rectangle; L3 and L4 are run
        // against their own direction. ROUND 5 at (40,0): centre (35,5),
        // touching L1 at (35,0) and L2 at (40,5). CHAMF 2 at (0,20): (2,20) to (0,18).
        const Evaluation ev = run("K1 = CONTOUR/L1, ROUND, 5, L2, L3, CHAMF, 2, L4\n");
        const EvaluatedContour k = contourOf(ev, "K1");
        QVERIFY(k.contour.closed);
        const auto& s = k.contour.segments;
        QCOMPARE(s.size(), std::size_t(6));
        QVERIFY(isLine(s[0], {0, 0}, {35, 0}));
        QVERIFY(isArc(s[1], {35, 0}, {40, 5}, {35, 5}, true));
        QVERIFY(isLine(s[2], {40, 5}, {40, 20}));
        QVERIFY(isLine(s[3], {40, 20}, {2, 20}));
        QVERIFY(isLine(s[4], {2, 20}, {0, 18}));
        QVERIFY(isLine(s[5], {0, 18}, {0, 0}));
        QVERIFY(taiwa::largestGap(k.contour) <= kExact);
        // 800 less the corner square 25 plus the quarter disc 25π/4, less the triangle 2.
        QVERIFY(std::abs(taiwa::signedArea(k.contour) - (773 + 25 * kPi / 4)) <= 1e-9);
        QCOMPARE(k.elements, (std::vector<std::string>{"L1", "", "L2", "L3", "", "L4"}));
        QCOMPARE(k.corners.size(), std::size_t(2));
        QVERIFY(k.corners[0].kind == ContourCorner::Kind::Round);
        QCOMPARE(k.corners[0].value, 5.0);
        QCOMPARE(k.corners[0].segment, 1);
        QCOMPARE(k.corners[0].line, 20);
        QCOMPARE(k.corners[0].column, 25);
        QCOMPARE(k.corners[0].between[0], std::string("L1"));
        QCOMPARE(k.corners[0].between[1], std::string("L2"));
        QVERIFY(k.corners[1].kind == ContourCorner::Kind::Chamfer);
        QCOMPARE(k.corners[1].value, 2.0);
        QCOMPARE(k.corners[1].segment, 4);
        QCOMPARE(k.corners[1].column, 43);
        QCOMPARE(k.corners[1].between[0], std::string("L3"));
        QCOMPARE(k.corners[1].between[1], std::string("L4"));
        QCOMPARE(k.cornerAt(4), &k.corners[1]);
        QVERIFY(!k.cornerAt(0));
        // Run the other way (clockwise): the area changes sign, the corner on the closing junction.
        const EvaluatedContour r = contourOf(run("K2 = CONTOUR/L4, L3, L2, ROUND, 5, L1, CHAMF, 2\n"), "K2");
        QCOMPARE(r.contour.segments.size(), std::size_t(6));
        QVERIFY(isLine(r.contour.segments[0], {0, 2}, {0, 20}));  // the closing CHAMF 2 at (0,0) trims L4
        QVERIFY(isLine(r.contour.segments[1], {0, 20}, {40, 20}));
        QVERIFY(isLine(r.contour.segments[2], {40, 20}, {40, 5}));
        QVERIFY(isArc(r.contour.segments[3], {40, 5}, {35, 0}, {35, 5}, false));
        QVERIFY(isLine(r.contour.segments[4], {35, 0}, {2, 0}));
        QVERIFY(isLine(r.contour.segments[5], {2, 0}, {0, 2}));
        QVERIFY(std::abs(taiwa::signedArea(r.contour) + (773 + 25 * kPi / 4)) <= 1e-9);
        QCOMPARE(r.corners[0].segment, 3);
        QCOMPARE(r.corners[1].segment, 5);
    }
    void lineCircleLineWithModifiers()
    {
        // LA (y = 3) meets C1 at (±4, 3): XLARGE takes (4,3); C1 clockwise to
        // LB (x = 3) at (3, −4) (YSMALL; XLARGE could not choose). Open from PA to PB.
        const EvaluatedContour k = contourOf(run("K1 = CONTOUR/PA, LA, XLARGE, CLW, C1, YSMALL, LB, PB\n"), "K1");
        QVERIFY(!k.contour.closed);
        const auto& s = k.contour.segments;
        QCOMPARE(s.size(), std::size_t(3));
        QVERIFY(isLine(s[0], {-10, 3}, {4, 3}));
        QVERIFY(isArc(s[1], {4, 3}, {3, -4}, {0, 0}, false));
        QVERIFY(std::abs(s[1].sweep() - -kPi / 2) <= 1e-12);  // 36.87° down to −53.13°
        QVERIFY(isLine(s[2], {3, -4}, {3, -10}));
        QCOMPARE(k.elements, (std::vector<std::string>{"LA", "C1", "LB"}));
        // XSMALL: the far junction (−4,3), and counter-clockwise round the left to (3,−4).
        const EvaluatedContour o = contourOf(run("K1 = CONTOUR/PA, LA, XSMALL, CCLW, C1, YSMALL, LB, PB\n"), "K1");
        QVERIFY(isLine(o.contour.segments[0], {-10, 3}, {-4, 3}));
        QVERIFY(isArc(o.contour.segments[1], {-4, 3}, {3, -4}, {0, 0}, true));
    }
    void openContourFromPointToPoint()
    {
        // From (40,20) back along L3 (against its direction) to (0,0) down L4.
        const EvaluatedContour k = contourOf(run("K1 = CONTOUR/P3, L3, L4, ROUND, 4, L1, P2\n"), "K1");
        const auto& s = k.contour.segments;
        QCOMPARE(s.size(), std::size_t(4));
        QVERIFY(isLine(s[0], {40, 20}, {0, 20}));
        QVERIFY(isLine(s[1], {0, 20}, {0, 4}));
        QVERIFY(isArc(s[2], {0, 4}, {4, 0}, {4, 4}, true));
        QVERIFY(isLine(s[3], {4, 0}, {40, 0}));
        QVERIFY(std::abs(taiwa::length(k.contour) - (40 + 16 + 2 * kPi + 36)) <= 1e-9);
        // A single element, an arc: C1 clockwise from (4,3) to (3,−4).
        const EvaluatedContour a =
            contourOf(run("T1 = POINT/4, 3\nT2 = POINT/3, -4\nK2 = CONTOUR/T1, CLW, C1, T2\n"), "K2");
        QCOMPARE(a.contour.segments.size(), std::size_t(1));
        QVERIFY(isArc(a.contour.segments[0], {4, 3}, {3, -4}, {0, 0}, false));
    }
    void fullCircle()
    {
        const EvaluatedContour k = contourOf(run("K1 = CONTOUR/CCLW, C2\nK2 = CONTOUR/CLW, C2\n"), "K1");
        QCOMPARE(k.contour.segments.size(), std::size_t(1));
        QVERIFY(isArc(k.contour.segments[0], {13, 0}, {13, 0}, {8, 0}, true));
        QVERIFY(std::abs(taiwa::signedArea(k.contour) - 25 * kPi) <= 1e-9);
        const EvaluatedContour c = contourOf(run("K1 = CONTOUR/CCLW, C2\nK2 = CONTOUR/CLW, C2\n"), "K2");
        QVERIFY(std::abs(taiwa::signedArea(c.contour) + 25 * kPi) <= 1e-9);
    }
    void circleCircleJunctions()
    {
        // C1 (0,0) and C2 (8,0), both r 5, cross at (4, ±3): the lens between
        // them, counter-clockwise: C1's right part from (4,−3) up to (4,3), C2's
        // left part down again. Its area: twice the segment 25/2 (θ − sin θ),
        // θ = 2 atan(3/4), sin θ = 24/25.
        const EvaluatedContour k = contourOf(run("K1 = CONTOUR/YSMALL, CCLW, C1, YLARGE, CCLW, C2\n"), "K1");
        const auto& s = k.contour.segments;
        QCOMPARE(s.size(), std::size_t(2));
        QVERIFY(isArc(s[0], {4, -3}, {4, 3}, {0, 0}, true));
        QVERIFY(isArc(s[1], {4, 3}, {4, -3}, {8, 0}, true));
        const double theta = 2 * std::atan2(3.0, 4.0);
        QVERIFY(std::abs(taiwa::signedArea(k.contour) - 25 * (theta - 0.96)) <= 1e-9);
        // C2 clockwise touches C3 counter-clockwise at (13,0): one junction, no modifier,
        // an S from (8,5) to (18,−5).
        const EvaluatedContour t = contourOf(run("K2 = CONTOUR/Q1, CLW, C2, CCLW, C3, Q2\n"), "K2");
        QCOMPARE(t.contour.segments.size(), std::size_t(2));
        QVERIFY(isArc(t.contour.segments[0], {8, 5}, {13, 0}, {8, 0}, false));
        QVERIFY(isArc(t.contour.segments[1], {13, 0}, {18, -5}, {18, 0}, true));
        // ROUND 0.5 in the lens's top corner: centres on the circles of radius 4.5
        // about (0,0) and (8,0): (4, √17/2); touching C1 at 5/4.5 of it, (40/9, 5√17/9),
        // and C2 at (32/9, 5√17/9).
        const EvaluatedContour r =
            contourOf(run("K3 = CONTOUR/YSMALL, CCLW, C1, ROUND, 0.5, YLARGE, CCLW, C2\n"), "K3");
        const double s17 = std::sqrt(17.0);
        QCOMPARE(r.contour.segments.size(), std::size_t(3));
        QVERIFY(isArc(r.contour.segments[0], {4, -3}, {40.0 / 9, 5 * s17 / 9}, {0, 0}, true));
        QVERIFY(isArc(r.contour.segments[1], {40.0 / 9, 5 * s17 / 9}, {32.0 / 9, 5 * s17 / 9}, {4, s17 / 2}, true));
        QVERIFY(isArc(r.contour.segments[2], {32.0 / 9, 5 * s17 / 9}, {4, -3}, {8, 0}, true));
    }
    void roundLineCircle()
    {
        // LA (y = 3, run +X) into C1 clockwise at (4,3): a right turn. The fillet
        // of radius 1 lies below LA and inside C1: centre on y = 2 at 5 − 1 = 4
        // from the origin, (2√3, 2); touching LA at (2√3, 3) and C1 at
        // 5/4 (2√3, 2) = (2.5√3, 2.5); clockwise.
        const EvaluatedContour k =
            contourOf(run("K1 = CONTOUR/PA, LA, ROUND, 1, XLARGE, CLW, C1, YSMALL, LB, PB\n"), "K1");
        const double s3 = std::sqrt(3.0);
        const auto& s = k.contour.segments;
        QCOMPARE(s.size(), std::size_t(4));
        QVERIFY(isLine(s[0], {-10, 3}, {2 * s3, 3}));
        QVERIFY(isArc(s[1], {2 * s3, 3}, {2.5 * s3, 2.5}, {2 * s3, 2}, false));
        QVERIFY(std::abs(s[1].sweep() - -kPi / 3) <= 1e-12);
        QVERIFY(isArc(s[2], {2.5 * s3, 2.5}, {3, -4}, {0, 0}, false));
        QVERIFY(isLine(s[3], {3, -4}, {3, -10}));
        // The other way round, circle then line: C1 counter-clockwise from (3,−4)
        // to (4,3), then LA back to PA: a left turn, the same fillet reversed.
        const EvaluatedContour b =
            contourOf(run("K2 = CONTOUR/PB, LB, YSMALL, CCLW, C1, ROUND, 1, XLARGE, LA, PA\n"), "K2");
        QVERIFY(isArc(b.contour.segments[1], {3, -4}, {2.5 * s3, 2.5}, {0, 0}, true));
        QVERIFY(isArc(b.contour.segments[2], {2.5 * s3, 2.5}, {2 * s3, 3}, {2 * s3, 2}, true));
        QVERIFY(isLine(b.contour.segments[3], {2 * s3, 3}, {-10, 3}));
        // CHAMF on an arc: d measured along it. CHAMF 1 at (4,3): (3,3) on LA and
        // on C1 clockwise 1/5 rad on from 36.87°.
        const EvaluatedContour c =
            contourOf(run("K3 = CONTOUR/PA, LA, CHAMF, 1, XLARGE, CLW, C1, YSMALL, LB, PB\n"), "K3");
        const double a = std::atan2(3.0, 4.0) - 0.2;
        QVERIFY(isLine(c.contour.segments[1], {3, 3}, {5 * std::cos(a), 5 * std::sin(a)}));
    }
    void textRefusalsWithLineAndColumn()
    {
        QCOMPARE(parseError("K1 = CONTOUR/L1, C1, L2\n"),
                 std::string("20:18: in K1, C1 is a circle: write CLW or CCLW before it"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, CLW, L2\n"),
                 std::string("20:18: in K1, L2 is a line: no CLW before it (CLW and CCLW are for circles)"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, XLARGE, L2, L3\n"),
                 std::string("20:18: in K1, two lines meet once: no XLARGE before L2"));
        QCOMPARE(parseError("K1 = CONTOUR/XLARGE, L1, L2, L3\n"),
                 std::string("20:14: in K1, two lines meet once: no XLARGE before L1"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, L1, L2\n"),
                 std::string("20:18: in K1, L1 follows itself: the same element twice in a row"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, L2, L1\n"),
                 std::string("20:22: in K1, L1 follows itself: the same element twice in a row (the last element "
                             "joins the first)"));
        QCOMPARE(parseError("K1 = CONTOUR/L1\n"),
                 std::string("20:14: in K1, a closed contour needs two elements or more, or a single circle"));
        QCOMPARE(parseError("K1 = CONTOUR/CCLW, C1, ROUND, 1\n"),
                 std::string("20:24: in K1, C1 alone is a full circle: no ROUND on it"));
        QCOMPARE(parseError("K1 = CONTOUR/YLARGE, CCLW, C1\n"),
                 std::string("20:14: in K1, C1 alone is a full circle: no YLARGE before it"));
        QCOMPARE(parseError("K1 = CONTOUR/P1, L1, L2, ROUND, 1, P3\n"),
                 std::string("20:26: in K1, ROUND after L2 is not between two elements: the contour ends at P3"));
        QCOMPARE(parseError("K1 = CONTOUR/P1, XLARGE, L1, L2, P3\n"),
                 std::string("20:18: in K1, L1 starts at P1: no XLARGE before it"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, L2, P3\n"),
                 std::string("20:22: in K1, P3 ends the contour but no point starts it: an open contour runs from "
                             "a point to a point"));
        QCOMPARE(parseError("K1 = CONTOUR/P1, L1, L2\n"),
                 std::string("20:24: in K1, the contour starts at P1 and needs a point at its end, on L2"));
        QCOMPARE(parseError("K1 = CONTOUR/P1, L1, P2, L2, P3\n"),
                 std::string("20:22: in K1, P2 is a point: only the first and the last item of a contour may be "
                             "points"));
        QCOMPARE(parseError("K1 = CONTOUR/P1, P2\n"),
                 std::string("20:18: in K1, P2 is a point where a line or a circle is needed"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, ROUND, 0, L2\n"),
                 std::string("20:25: the radius must be greater than 0, found '0'"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, CHAMF, -1, L2\n"),
                 std::string("20:25: the chamfer must be greater than 0, found '-1'"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, ROUND, L2\n"),
                 std::string("20:25: expected a number (the radius) after ',', found 'L2'"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, L9\n"),
                 std::string("20:18: in K1, L9 is not defined: an element must be defined before it is used"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, 5\n"),
                 std::string("20:18: expected an element name, XLARGE/XSMALL/YLARGE/YSMALL, CLW or CCLW after ',', "
                             "found '5'"));
        QCOMPARE(parseError("K1 = CONTOUR/L1, CLW, 5\n"),
                 std::string("20:23: expected a circle name after ',', found '5'"));
        // A contour is a name like any other, and nothing is defined from it.
        QCOMPARE(parseError("K1 = CONTOUR/CCLW, C1\nK1 = CONTOUR/CCLW, C2\n"),
                 std::string("21:1: K1 is already defined on line 20"));
        QCOMPARE(parseError("K1 = CONTOUR/CCLW, C1\nP9 = POINT/CENTER, K1\n"),
                 std::string("21:20: in P9, K1 is a contour where a circle is needed"));
        QCOMPARE(parseError("K1 = CONTOUR/CCLW, C1\nK2 = CONTOUR/L1, K1\n"),
                 std::string("21:18: in K2, K1 is a contour where a line or a circle is needed"));
        QCOMPARE(parseError("K1 = CONTOUR/CCLW, C1\nP9 = POINT/XLARGE, INTOF, L1, K1\n"),
                 std::string("21:31: in P9, K1 is a contour where a line or a circle is needed"));
        QCOMPARE(parseError("CLW = POINT/1, 2\n"),
                 std::string("20:1: 'CLW' is a word of the language and cannot name an element"));
        QCOMPARE(parseError("K1 = CONTUOR/L1, L2\n"),
                 std::string("20:6: expected POINT, LINE, CIRCLE or CONTOUR after '=', found 'CONTUOR'"));
    }
    void geometricRefusalsAtTheItem()
    {
        QCOMPARE(evalError("K1 = CONTOUR/L1, L3, L2\n"),
                 std::string("20:18: K1: L1 and L3 are parallel: they do not meet"));
        QCOMPARE(evalError("K1 = CONTOUR/P4, L3, CCLW, C3, Q2\n"), std::string("20:28: K1: L3 and C3 do not meet"));
        // The closing junction (the last element to the first) is checked first, at the first element.
        QCOMPARE(evalError("K1 = CONTOUR/CCLW, C1, CLW, C3\n"), std::string("20:20: K1: C3 and C1 do not meet"));
        QCOMPARE(evalError("C9 = CIRCLE/CENTER, P1, RADIUS, 2\nT1 = POINT/5, 0\nT2 = POINT/2, 0\n"
                           "K1 = CONTOUR/T1, CCLW, C1, CLW, C9, T2\n"),
                 std::string("23:33: K1: C1 and C9 are concentric: they do not meet"));
        QCOMPARE(evalError("K1 = CONTOUR/PA, LA, CLW, C1, YSMALL, LB, PB\n"),
                 std::string("20:27: K1: LA and C1 meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before C1 to "
                             "choose"));
        QCOMPARE(evalError("K1 = CONTOUR/PA, LA, XLARGE, CLW, C1, XLARGE, LB, PB\n"),
                 std::string("20:47: K1: XLARGE cannot choose between the two junctions of C1 and LB: both have the "
                             "same x; use YLARGE or YSMALL"));
        QCOMPARE(evalError("K1 = CONTOUR/PA, L1, L2, P3\n"),
                 std::string("20:14: K1: PA is not on L1: an open contour starts on its first element"));
        QCOMPARE(evalError("K1 = CONTOUR/P1, L1, L2, PA\n"),
                 std::string("20:26: K1: PA is not on L2: an open contour ends on its last element"));
        // D1 runs through the origin where L1 and L4 meet: nothing of it between them.
        QCOMPARE(evalError("D1 = LINE/P1, ATANGL, 45\nK1 = CONTOUR/P2, L1, D1, L4, P4\n"),
                 std::string("21:22: K1: D1 is of zero length between L1 and L4"));
        QCOMPARE(evalError("K1 = CONTOUR/P1, L1, P1\n"), std::string("20:18: K1: L1 is of zero length between P1 and P1"));
        // ROUND 8 after L1 in an open contour starting 5 mm before the corner.
        QCOMPARE(evalError("T1 = POINT/35, 0\nK1 = CONTOUR/T1, L1, ROUND, 8, L2, P3\n"),
                 std::string("21:29: K1: ROUND 8 between L1 and L2 does not fit: L1 is 5 mm long from the start T1"));
        // L2 is 20 mm long; the first ROUND 12 takes 12 of it.
        QCOMPARE(evalError("K1 = CONTOUR/L1, ROUND, 12, L2, ROUND, 12, L3, L4\n"),
                 std::string("20:40: K1: ROUND 12 between L2 and L3 does not fit: L2 is 8 mm long from the previous "
                             "corner"));
        QCOMPARE(evalError("T1 = POINT/40, 3\nK1 = CONTOUR/P1, L1, CHAMF, 4, L2, T1\n"),
                 std::string("21:29: K1: CHAMF 4 between L1 and L2 does not fit: L2 is 3 mm long to the end T1"));
        QCOMPARE(evalError("K1 = CONTOUR/L1, ROUND, 30, L2, L3, L4\n"),
                 std::string("20:25: K1: ROUND 30 between L1 and L2 does not fit: L2 is 20 mm long to the next corner"));
        QCOMPARE(evalError("K1 = CONTOUR/Q1, CLW, C2, ROUND, 1, CCLW, C3, Q2\n"),
                 std::string("20:34: K1: ROUND 1 between C2 and C3: they meet tangentially, there is no corner"));
        // In the lens (2 mm wide) the circles of radius 3.5 about (0,0) and (8,0) do not meet.
        QCOMPARE(evalError("K1 = CONTOUR/YSMALL, CCLW, C1, ROUND, 1.5, YLARGE, CCLW, C2\n"),
                 std::string("20:39: K1: ROUND 1.5 between C1 and C2 does not fit: no circle of radius 1.5 touches "
                             "both in the corner"));
        QCOMPARE(evalError("K1 = CONTOUR/PA, LA, ROUND, 6, XLARGE, CLW, C1, YSMALL, LB, PB\n"),
                 std::string("20:29: K1: ROUND 6 between LA and C1 does not fit: it is not smaller than C1's radius 5"));
    }
    void roundTripIsCanonical()
    {
        const std::string contours = "K1 = CONTOUR/L1, ROUND, 5, L2, L3, CHAMF, 2.5, L4\n"
                                     "K2 = CONTOUR/PA, LA, ROUND, 1, XLARGE, CLW, C1, YSMALL, LB, PB\n"
                                     "K3 = CONTOUR/CCLW, C2\n"
                                     "K4 = CONTOUR/YSMALL, CCLW, C1, YLARGE, CCLW, C2, ROUND, 0.5\n";
        const ParseResult p = parseFigure(kBase + contours);
        QVERIFY(p.ok());
        const std::string written = writeFigure(p.definitions);
        QCOMPARE(written, kBase + contours);
        const ParseResult again = parseFigure(written);
        QVERIFY(again.ok() && again.definitions == p.definitions);
        // Lower case, spacing and number forms are written canonically.
        const ParseResult loose = parseFigure(kBase + "k1=contour/ l1,round,5.,L2 ,l3 , chamf,+2.50,l4 $$ note\n");
        QVERIFY(loose.ok());
        QCOMPARE(writeDefinition(loose.definitions.back()), std::string("K1 = CONTOUR/L1, ROUND, 5, L2, L3, CHAMF, 2.5, L4"));
        QVERIFY(loose.definitions.back() == p.definitions.at(19));
    }
    void definedFromIncludesContours()
    {
        const ParseResult p =
            parseFigure(kBase + "K1 = CONTOUR/L1, L2, L3, L4\nK2 = CONTOUR/PA, LA, XLARGE, CLW, C1, YSMALL, LB, PB\n");
        QVERIFY(p.ok());
        QCOMPARE(definedFrom(p.definitions, "P2"), (std::vector<std::string>{"L1", "L2", "K1"}));
        QCOMPARE(definedFrom(p.definitions, "PB"), (std::vector<std::string>{"LB", "K2"}));
        QCOMPARE(definedFrom(p.definitions, "C1"), (std::vector<std::string>{"K2"}));
        // A contour from a refused element is left out without a further message.
        const Evaluation ev = run("X1 = POINT/40, 0\nLX = LINE/P2, X1\nK1 = CONTOUR/L1, LX, L3\n");
        QCOMPARE(ev.errors.size(), std::size_t(1));
        QVERIFY(!ev.findContour("K1"));
        // Moving P3 to (40,30) moves the contour's corners.
        ParseResult moved = p;
        for (auto& d : moved.definitions)
            if (d.name == "P3") d.numbers = {40, 30};
        const EvaluatedContour k = contourOf(evaluate(moved.definitions), "K1");
        QVERIFY(isLine(k.contour.segments[1], {40, 0}, {40, 30}));
    }
    void reviseOneCornerKeepsTheRest()
    {
        const std::string text = kBase + "K1 = CONTOUR/L1,ROUND, 5 ,L2, L3, chamf, +2.50, L4 $$ keep this\nK2 = CONTOUR/CCLW, C2\n";
        const auto r = reviseCorner(text, "K1", 1, 1.25);
        QVERIFY(r.has_value());
        QCOMPARE(*r, kBase + "K1 = CONTOUR/L1,ROUND, 5 ,L2, L3, chamf, 1.25, L4 $$ keep this\nK2 = CONTOUR/CCLW, C2\n");
        const auto r0 = reviseCorner(*r, "K1", 0, 7);
        QVERIFY(r0.has_value());
        QCOMPARE(*r0, kBase + "K1 = CONTOUR/L1,ROUND, 7 ,L2, L3, chamf, 1.25, L4 $$ keep this\nK2 = CONTOUR/CCLW, C2\n");
        // The revised text evaluates with the new corner.
        const EvaluatedContour k = contourOf(evaluate(parseFigure(*r0).definitions), "K1");
        QCOMPARE(k.corners[0].value, 7.0);
        QVERIFY(isArc(k.contour.segments[1], {33, 0}, {40, 7}, {33, 7}, true));
        QVERIFY(isLine(k.contour.segments[4], {1.25, 20}, {0, 18.75}));
        // Nothing to revise: no such corner or contour, a bad value, a refused text.
        QVERIFY(!reviseCorner(text, "K1", 2, 1));
        QVERIFY(!reviseCorner(text, "K2", 0, 1));
        QVERIFY(!reviseCorner(text, "K3", 0, 1));
        QVERIFY(!reviseCorner(text, "L1", 0, 1));
        QVERIFY(!reviseCorner(text, "K1", 0, 0));
        QVERIFY(!reviseCorner(text, "K1", 0, 2e6));
        QVERIFY(!reviseCorner(text, "K1", -1, 1));
        QVERIFY(!reviseCorner("K1 = CONTOUR/", "K1", 0, 1));
    }
};

QTEST_APPLESS_MAIN(TestFigureContours)
#include "test_figure_contours.moc"
