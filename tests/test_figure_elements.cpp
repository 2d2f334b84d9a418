// Figure elements (core/figure/): every definition method evaluated against
// hand-computed coordinates, every modifier choosing its intersection or
// side, every refusal of the text and of the geometry with its line, column
// and message, round trips text → definitions → text, and re-evaluation
// after a change.
#include "figure/figure_eval.h"
#include "figure/figure_text.h"
#include "support/support.h"

#include <QtTest>

#include <cmath>
#include <string>
#include <string_view>

using namespace taiwa::figure;
using taiwa::Point2;

namespace QTest {
// Compared strings printed when they differ.
template <>
inline char* toString(const std::string& s)
{
    return qstrdup(s.c_str());
}
}  // namespace QTest

namespace {

constexpr double kExact = 1e-9;  // mm: the hand computations are exact

Evaluation run(const std::string& text)
{
    const ParseResult p = parseFigure(text);
    if (!p.ok()) qFatal("parse: %s", p.error->text().c_str());
    return evaluate(p.definitions);
}

bool near(double a, double b) { return std::abs(a - b) <= kExact; }

bool isPoint(const Evaluation& ev, const std::string& name, double x, double y)
{
    const Element* e = ev.find(name);
    if (!e || e->kind != Kind::Point) return false;
    if (!near(e->point.x, x) || !near(e->point.y, y)) {
        qWarning("%s = (%.12g, %.12g), expected (%.12g, %.12g)", name.c_str(), e->point.x, e->point.y, x, y);
        return false;
    }
    return true;
}

// A line given by its point and direction, both exact.
bool isLine(const Evaluation& ev, const std::string& name, Point2 p, Point2 dir)
{
    const Element* e = ev.find(name);
    if (!e || e->kind != Kind::Line) return false;
    const Line& l = e->line;
    if (!near(l.point.x, p.x) || !near(l.point.y, p.y) || !near(l.dir.x, dir.x) || !near(l.dir.y, dir.y)) {
        qWarning("%s = (%.12g, %.12g) dir (%.12g, %.12g)", name.c_str(), l.point.x, l.point.y, l.dir.x, l.dir.y);
        return false;
    }
    return true;
}

bool isCircle(const Evaluation& ev, const std::string& name, double x, double y, double r)
{
    const Element* e = ev.find(name);
    if (!e || e->kind != Kind::Circle) return false;
    const Circle& c = e->circle;
    if (!near(c.centre.x, x) || !near(c.centre.y, y) || !near(c.radius, r)) {
        qWarning("%s = (%.12g, %.12g) r %.12g", name.c_str(), c.centre.x, c.centre.y, c.radius);
        return false;
    }
    return true;
}

std::string parseError(const std::string& text)
{
    const ParseResult p = parseFigure(text);
    return p.ok() ? std::string("(parsed)") : p.error->text();
}

std::string evalError(const std::string& text)
{
    const Evaluation ev = run(text);
    return ev.errors.empty() ? std::string("(evaluated)") : ev.errors.front().text();
}

// Every method, with most modifiers; the hand computations are in the tests.
const char* const kEveryMethod = R"($$ every definition method
P1 = POINT/0, 0
P2 = POINT/4, 3
L1 = LINE/P1, P2
L2 = LINE/P2, ATANGL, 90
L3 = LINE/PARLEL, L2, XLARGE, 6
L4 = LINE/PARLEL, L2, XSMALL, 6
P3 = POINT/INTOF, L1, L3
C1 = CIRCLE/CENTER, P1, RADIUS, 5
P4 = POINT/YLARGE, INTOF, L2, C1
P5 = POINT/YSMALL, INTOF, C1, L2
P6 = POINT/8, 0
C2 = CIRCLE/CENTER, P6, RADIUS, 5
P7 = POINT/YSMALL, INTOF, C1, C2
P8 = POINT/XLARGE, INTOF, C1, L1
P9 = POINT/CENTER, C2
Q1 = POINT/5, 0
C3 = CIRCLE/CENTER, P1, RADIUS, 3
T1 = LINE/Q1, LEFT, TANTO, C3
T2 = LINE/Q1, RIGHT, TANTO, C3
Q2 = POINT/20, 0
C4 = CIRCLE/CENTER, Q2, RADIUS, 5
T3 = LINE/LEFT, TANTO, C1, LEFT, TANTO, C4
T4 = LINE/RIGHT, TANTO, C1, RIGHT, TANTO, C4
T5 = LINE/LEFT, TANTO, C1, RIGHT, TANTO, C4
Q3 = POINT/6, 0
Q4 = POINT/0, 8
C5 = CIRCLE/P1, Q3, Q4
LX = LINE/P1, ATANGL, 0
LY = LINE/P1, ATANGL, 90
C6 = CIRCLE/YLARGE, LX, XLARGE, LY, RADIUS, 2
C7 = CIRCLE/YSMALL, LX, XSMALL, LY, RADIUS, 2
Q5 = POINT/0, 8
C8 = CIRCLE/CENTER, Q5, RADIUS, 1
C9 = CIRCLE/YLARGE, LX, XLARGE, OUT, C8, RADIUS, 4
C10 = CIRCLE/YLARGE, LX, XSMALL, OUT, C8, RADIUS, 4
C11 = CIRCLE/CENTER, Q5, RADIUS, 10
C12 = CIRCLE/YLARGE, LX, XLARGE, IN, C11, RADIUS, 5
L5 = LINE/P1, ATANGL, 30
)";

}  // namespace

class TestFigureElements : public QObject {
    Q_OBJECT
private slots:
    void pointsByCoordinatesIntersectionAndCentre()
    {
        const Evaluation ev = run(kEveryMethod);
        QVERIFY2(ev.ok(), ev.ok() ? "" : ev.errors.front().text().c_str());
        QVERIFY(isPoint(ev, "P1", 0, 0));
        QVERIFY(isPoint(ev, "P2", 4, 3));
        // L1 from (0,0) along (0.8, 0.6); L3 is x = 10: 0.8 t = 10, t = 12.5, y = 0.6 * 12.5 = 7.5.
        QVERIFY(isPoint(ev, "P3", 10, 7.5));
        // L2 is x = 4; on x² + y² = 25, y = ±3.
        QVERIFY(isPoint(ev, "P4", 4, 3));
        QVERIFY(isPoint(ev, "P5", 4, -3));
        // C1 (0,0) r 5 and C2 (8,0) r 5: the chord at x = (64 + 25 − 25) / 16 = 4, half 3.
        QVERIFY(isPoint(ev, "P7", 4, -3));
        // C1 and L1 (through the centre along (0.8, 0.6)): ±5·(0.8, 0.6); XLARGE is (4, 3).
        QVERIFY(isPoint(ev, "P8", 4, 3));
        QVERIFY(isPoint(ev, "P9", 8, 0));
    }
    void linesThroughPointsAtAngleAndParallel()
    {
        const Evaluation ev = run(kEveryMethod);
        // (4,3) − (0,0) = (4,3), length 5.
        QVERIFY(isLine(ev, "L1", {0, 0}, {0.8, 0.6}));
        QVERIFY(isLine(ev, "L2", {4, 3}, {0, 1}));
        // Left normal of (0,1) is (−1,0); XLARGE takes (1,0): (4,3) + 6·(1,0).
        QVERIFY(isLine(ev, "L3", {10, 3}, {0, 1}));
        QVERIFY(isLine(ev, "L4", {-2, 3}, {0, 1}));
        QVERIFY(isLine(ev, "LX", {0, 0}, {1, 0}));
        // 30°: (cos 30°, sin 30°) = (√3/2, 1/2).
        QVERIFY(isLine(ev, "L5", {0, 0}, {std::sqrt(3.0) / 2, 0.5}));
    }
    void tangentFromAPoint()
    {
        const Evaluation ev = run(kEveryMethod);
        // From Q1 (5,0) to C3 (0,0) r 3: D = 5, tangent length 4, u = (−1,0),
        // its left (0,−1); cos = 4/5, sin = 3/5. LEFT: 0.8·(−1,0) + 0.6·(0,−1).
        QVERIFY(isLine(ev, "T1", {5, 0}, {-0.8, -0.6}));
        QVERIFY(isLine(ev, "T2", {5, 0}, {-0.8, 0.6}));
        // The contact point (5,0) + 4·(−0.8,−0.6) = (1.8,−2.4) lies on C3: 1.8² + 2.4² = 9.
        const Line& t1 = ev.find("T1")->line;
        const Point2 contact{t1.point.x + 4 * t1.dir.x, t1.point.y + 4 * t1.dir.y};
        QVERIFY(near(contact.x, 1.8) && near(contact.y, -2.4));
    }
    void tangentToTwoCircles()
    {
        const Evaluation ev = run(kEveryMethod);
        // C1 (0,0) r 5, C4 (20,0) r 5, u = (1,0). Same sides: m·u = 0, m = ±(0,1):
        // y = 5 (LEFT) and y = −5 (RIGHT), both directed +X.
        QVERIFY(isLine(ev, "T3", {0, 5}, {1, 0}));
        QVERIFY(isLine(ev, "T4", {0, -5}, {1, 0}));
        // Crossing: m·u = (5 + 5)/20 = 1/2, m = (1/2, √3/2); contact 5m = (2.5, 5√3/2);
        // direction (m.y, −m.x) = (√3/2, −1/2), through the midpoint (10, 0).
        const double s3 = std::sqrt(3.0);
        QVERIFY(isLine(ev, "T5", {2.5, 2.5 * s3}, {s3 / 2, -0.5}));
    }
    void circlesByCentreThreePointsAndTangents()
    {
        const Evaluation ev = run(kEveryMethod);
        QVERIFY(isCircle(ev, "C1", 0, 0, 5));
        // Right angle at (0,0): the centre is the hypotenuse's middle (3,4), r = 5.
        QVERIFY(isCircle(ev, "C5", 3, 4, 5));
        // Above the X axis and right of the Y axis at 2: (2,2); below and left: (−2,−2).
        QVERIFY(isCircle(ev, "C6", 2, 2, 2));
        QVERIFY(isCircle(ev, "C7", -2, -2, 2));
        // Centre on y = 4, at 1 + 4 = 5 from (0,8): x² + 4² = 25, x = ±3.
        QVERIFY(isCircle(ev, "C9", 3, 4, 4));
        QVERIFY(isCircle(ev, "C10", -3, 4, 4));
        // IN C11 (0,8) r 10 at r 5: centre on y = 5, at 10 − 5 = 5 from (0,8): x = ±4.
        QVERIFY(isCircle(ev, "C12", 4, 5, 5));
    }
    void modifiersChooseTheOtherIntersection()
    {
        const Evaluation ev = run("P1 = POINT/0, 0\nC1 = CIRCLE/CENTER, P1, RADIUS, 5\nL1 = LINE/P1, ATANGL, 0\n"
                                  "A = POINT/XLARGE, INTOF, L1, C1\nB = POINT/XSMALL, INTOF, L1, C1\n"
                                  "P2 = POINT/8, 0\nC2 = CIRCLE/CENTER, P2, RADIUS, 5\n"
                                  "C = POINT/YLARGE, INTOF, C1, C2\nD = POINT/YSMALL, INTOF, C2, C1\n");
        QVERIFY(ev.ok());
        QVERIFY(isPoint(ev, "A", 5, 0));
        QVERIFY(isPoint(ev, "B", -5, 0));
        QVERIFY(isPoint(ev, "C", 4, 3));
        QVERIFY(isPoint(ev, "D", 4, -3));
        // Parallels: LX along +X has left normal (0,1): YLARGE at 2 is y = 2,
        // YSMALL y = −2. L1 along (0.8,0.6) has left normal (−0.6,0.8); XLARGE
        // takes (0.6,−0.8): at 5, (3,−4).
        const Evaluation par = run("P1 = POINT/0, 0\nP2 = POINT/4, 3\nLX = LINE/P1, ATANGL, 0\nL1 = LINE/P1, P2\n"
                                   "A = LINE/PARLEL, LX, YLARGE, 2\nB = LINE/PARLEL, LX, YSMALL, 2\n"
                                   "C = LINE/PARLEL, L1, XLARGE, 5\nD = LINE/PARLEL, L1, XSMALL, 5\n");
        QVERIFY(isLine(par, "A", {0, 2}, {1, 0}));
        QVERIFY(isLine(par, "B", {0, -2}, {1, 0}));
        QVERIFY(isLine(par, "C", {3, -4}, {0.8, 0.6}));
        QVERIFY(isLine(par, "D", {-3, 4}, {0.8, 0.6}));
        // The other crossing tangent of C1 (0,0) r 5 and C2 (20,0) r 5: RIGHT on C1,
        // m = (1/2, −√3/2), contact (2.5, −5√3/2), direction −(m.y, −m.x) = (√3/2, 1/2).
        const Evaluation cross = run("P1 = POINT/0, 0\nC1 = CIRCLE/CENTER, P1, RADIUS, 5\nP2 = POINT/20, 0\n"
                                     "C2 = CIRCLE/CENTER, P2, RADIUS, 5\nT = LINE/RIGHT, TANTO, C1, LEFT, TANTO, C2\n");
        const double s3 = std::sqrt(3.0);
        QVERIFY(isLine(cross, "T", {2.5, -2.5 * s3}, {s3 / 2, 0.5}));
        // A line touching a circle has one intersection: any modifier takes it.
        const Evaluation touch = run("P1 = POINT/0, 0\nC1 = CIRCLE/CENTER, P1, RADIUS, 5\nP2 = POINT/0, 5\n"
                                     "L1 = LINE/P2, ATANGL, 0\nT = POINT/XLARGE, INTOF, L1, C1\n");
        QVERIFY(isPoint(touch, "T", 0, 5));
    }
    void numbersAsInApt()
    {
        const Evaluation ev = run("p1 = point/10., -.5 $$ lower case, trailing point, leading point\n"
                                  "P2=POINT/+3,-0.25\n\n   $$ only a comment\n");
        QVERIFY(isPoint(ev, "P1", 10, -0.5));
        QVERIFY(isPoint(ev, "P2", 3, -0.25));
    }
    void textRefusalsWithLineAndColumn()
    {
        QCOMPARE(parseError("P1 = POINT/10, 20\nC1 = CIRCLE/CENTER, P1, RADUIS, 5"),
                 std::string("2:25: expected RADIUS after ',', found 'RADUIS'"));
        QCOMPARE(parseError("L1 = LINE/P1, P2"),
                 std::string("1:11: in L1, P1 is not defined: an element must be defined before it is used"));
        QCOMPARE(parseError("P1 = POINT/1, 2\nP1 = POINT/3, 4"), std::string("2:1: P1 is already defined on line 1"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nL1 = LINE/P1, ATANGL, 0\nP2 = POINT/CENTER, L1"),
                 std::string("3:20: in P2, L1 is a line where a circle is needed"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nC1 = CIRCLE/CENTER, P1, RADIUS, 1\nL1 = LINE/PARLEL, C1, XLARGE, 1"),
                 std::string("3:19: in L1, C1 is a circle where a line is needed"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nC1 = CIRCLE/CENTER, P1, RADIUS, 1\nL1 = LINE/P1, ATANGL, 0\n"
                            "P2 = POINT/INTOF, L1, C1"),
                 std::string("4:23: in P2, L1 and C1 may meet twice: write XLARGE, XSMALL, YLARGE or YSMALL before "
                             "INTOF to choose"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nL1 = LINE/P1, ATANGL, 0\nL2 = LINE/P1, ATANGL, 90\n"
                            "P2 = POINT/XLARGE, INTOF, L1, L2"),
                 std::string("4:12: in P2, two lines meet once: no XLARGE before INTOF"));
        QCOMPARE(parseError("P1 = POINT/1; 2"), std::string("1:13: expected ',' after '1', found the character ';'"));
        QCOMPARE(parseError("P1 = POINT/1,"),
                 std::string("1:14: expected a number (the y coordinate) after ',', found the end of the text"));
        QCOMPARE(parseError("P1 = POINT/1, 2, 3"),
                 std::string("1:16: expected the end of the statement after '2', found ','"));
        QCOMPARE(parseError("LINE = POINT/1, 2"),
                 std::string("1:1: 'LINE' is a word of the language and cannot name an element"));
        QCOMPARE(parseError("P1 = PIONT/1, 2"),
                 std::string("1:6: expected POINT, LINE, CIRCLE or CONTOUR after '=', found 'PIONT'"));
        QCOMPARE(parseError("P1 POINT/1, 2"), std::string("1:4: expected '=' after 'P1', found 'POINT'"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nC1 = CIRCLE/CENTER, P1, RADIUS, -2"),
                 std::string("2:33: the radius must be greater than 0, found '-2'"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nL1 = LINE/P1, ATANGL, 0\nL2 = LINE/PARLEL, L1, LEFT, 2"),
                 std::string("3:23: expected XLARGE, XSMALL, YLARGE or YSMALL after ',', found 'LEFT'"));
        QCOMPARE(parseError("P1 = POINT/0, 2000000"),
                 std::string("1:15: the number '2000000' is out of range (at most 1000000 either way)"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nL1 = LINE/P1, SIDEWAYS"),
                 std::string("2:15: in L1, SIDEWAYS is not defined: an element must be defined before it is used"));
        QCOMPARE(parseError("P1 = POINT/0, 0\nL1 = LINE/P1, TANTO"),
                 std::string("2:15: expected a point name, ATANGL, LEFT or RIGHT after ',', found 'TANTO'"));
        QCOMPARE(parseError("P1 = POINT/\x01"), std::string("1:12: expected a number, CENTER, INTOF or "
                                                            "XLARGE/XSMALL/YLARGE/YSMALL after '/', found the "
                                                            "character '\\x01'"));
    }
    void geometricRefusalsNameTheElement()
    {
        const std::string base = "P1 = POINT/0, 0\nP2 = POINT/0, 5\nL1 = LINE/P1, ATANGL, 0\nL2 = LINE/P2, ATANGL, 180\n"
                                 "C1 = CIRCLE/CENTER, P1, RADIUS, 5\n";
        QCOMPARE(evalError(base + "P3 = POINT/INTOF, L1, L2"),
                 std::string("6:1: P3: L1 and L2 are parallel: they do not intersect"));
        QCOMPARE(evalError(base + "P3 = POINT/1, 1\nT1 = LINE/P3, LEFT, TANTO, C1"),
                 std::string("7:1: T1: P3 is inside C1: no tangent from it"));
        QCOMPARE(evalError(base + "P3 = POINT/0, 10\nC2 = CIRCLE/P1, P2, P3"),
                 std::string("7:1: C2: P1, P2 and P3 lie on one line: no circle through them"));
        QCOMPARE(evalError(base + "P3 = POINT/0, 5\nL3 = LINE/P2, P3"),
                 std::string("7:1: L3: P2 and P3 coincide: no line through them"));
        // Centre on y = 3 at 5 + 3 = 8 from (0,0) exists; on y = 1 at 6 from (0,20) it does not.
        QCOMPARE(evalError(base + "P3 = POINT/0, 20\nC2 = CIRCLE/CENTER, P3, RADIUS, 5\n"
                                  "C3 = CIRCLE/YLARGE, L1, XLARGE, OUT, C2, RADIUS, 1"),
                 std::string("8:1: C3: no circle of radius 1 on the YLARGE side of L1 touches C2 from outside (the "
                             "radius is too small or the side is wrong)"));
        QCOMPARE(evalError(base + "C2 = CIRCLE/YLARGE, L1, XLARGE, IN, C1, RADIUS, 5"),
                 std::string("6:1: C2: radius 5 is not smaller than C1's radius 5: no circle inside it"));
        QCOMPARE(evalError(base + "L3 = LINE/PARLEL, L1, XLARGE, 2"),
                 std::string("6:1: L3: XLARGE names no side of L1: it is parallel to the X axis; use YLARGE or "
                             "YSMALL"));
        QCOMPARE(evalError(base + "L3 = LINE/P1, ATANGL, 90\nP3 = POINT/XLARGE, INTOF, L3, C1"),
                 std::string("7:1: P3: XLARGE cannot choose between the two intersections of L3 and C1: both have "
                             "the same x; use YLARGE or YSMALL"));
        QCOMPARE(evalError(base + "P3 = POINT/20, 0\nC2 = CIRCLE/CENTER, P3, RADIUS, 1\nP4 = POINT/XLARGE, INTOF, C1, C2"),
                 std::string("8:1: P4: C1 and C2 do not meet"));
        QCOMPARE(evalError(base + "C2 = CIRCLE/CENTER, P1, RADIUS, 1\nT1 = LINE/LEFT, TANTO, C1, LEFT, TANTO, C2"),
                 std::string("7:1: T1: C1 and C2 are concentric: no common tangent"));
        QCOMPARE(evalError(base + "P3 = POINT/1, 0\nC2 = CIRCLE/CENTER, P3, RADIUS, 1\n"
                                  "T1 = LINE/LEFT, TANTO, C1, LEFT, TANTO, C2"),
                 std::string("8:1: T1: C1 and C2 lie one inside the other: no tangent on the same side of both"));
        QCOMPARE(evalError(base + "P3 = POINT/6, 0\nC2 = CIRCLE/CENTER, P3, RADIUS, 2\n"
                                  "T1 = LINE/LEFT, TANTO, C1, RIGHT, TANTO, C2"),
                 std::string("8:1: T1: C1 and C2 overlap: no tangent crossing between them"));
        QCOMPARE(evalError(base + "L3 = LINE/P2, ATANGL, 0\nC2 = CIRCLE/YLARGE, L1, YSMALL, L3, RADIUS, 1"),
                 std::string("7:1: C2: L1 and L3 are parallel: they do not intersect"));
    }
    void elementsFromARefusedOneAreNotEvaluatedNorReportedAgain()
    {
        const Evaluation ev = run("P1 = POINT/0, 0\nP2 = POINT/0, 0\nL1 = LINE/P1, P2\nL2 = LINE/PARLEL, L1, YLARGE, 1\n"
                                  "P3 = POINT/1, 1\n");
        QCOMPARE(ev.errors.size(), std::size_t(1));
        QVERIFY(!ev.find("L1") && !ev.find("L2"));
        QVERIFY(isPoint(ev, "P3", 1, 1));
    }
    void roundTripIsStable()
    {
        const ParseResult p = parseFigure(kEveryMethod);
        QVERIFY(p.ok());
        QCOMPARE(p.definitions.size(), std::size_t(38));
        const std::string written = writeFigure(p.definitions);
        const ParseResult again = parseFigure(written);
        QVERIFY(again.ok());
        QVERIFY(again.definitions == p.definitions);
        QCOMPARE(writeFigure(again.definitions), written);
        // The source is already canonical apart from its comment line.
        const std::string source = kEveryMethod;
        QCOMPARE(written, source.substr(source.find('\n') + 1));
        // Numbers: shortest form that reads back, no exponent.
        QCOMPARE(writeDefinition(parseFigure("p = point/10., -.5").definitions.at(0)), std::string("P = POINT/10, -0.5"));
        QCOMPARE(formatNumber(0.1), std::string("0.1"));
        QCOMPARE(formatNumber(1e-7), std::string("0.0000001"));
        QCOMPARE(formatNumber(-0.0), std::string("0"));
        QCOMPARE(formatNumber(1e6), std::string("1000000"));
    }
    void changingAnElementReevaluatesWhatIsDefinedFromIt()
    {
        ParseResult p = parseFigure(kEveryMethod);
        QVERIFY(p.ok());
        const std::vector<std::string> from = definedFrom(p.definitions, "P2");
        QCOMPARE(from, (std::vector<std::string>{"L1", "L2", "L3", "L4", "P3", "P4", "P5", "P8"}));
        // P2 moves from (4,3) to (3,4): L1 along (0.6,0.8); L2 is x = 3; L3 is x = 9;
        // P3: 0.6 t = 9, t = 15, y = 12; P4 on x = 3 and x² + y² = 25: (3,4).
        for (auto& d : p.definitions)
            if (d.name == "P2") d.numbers = {3, 4};
        const Evaluation ev = evaluate(p.definitions);
        QVERIFY(ev.ok());
        QVERIFY(isLine(ev, "L1", {0, 0}, {0.6, 0.8}));
        QVERIFY(isLine(ev, "L3", {9, 4}, {0, 1}));
        QVERIFY(isPoint(ev, "P3", 9, 12));
        QVERIFY(isPoint(ev, "P4", 3, 4));
        QVERIFY(isPoint(ev, "P8", 3, 4));
        // What is not defined from P2 is unchanged.
        QVERIFY(isPoint(ev, "P7", 4, -3));
        QVERIFY(isCircle(ev, "C9", 3, 4, 4));
        // And the change can make a definition impossible: P2 at the origin.
        for (auto& d : p.definitions)
            if (d.name == "P2") d.numbers = {0, 0};
        const Evaluation bad = evaluate(p.definitions);
        QCOMPARE(bad.errors.size(), std::size_t(1));
        QCOMPARE(bad.errors.front().text(), std::string("4:1: L1: P1 and P2 coincide: no line through them"));
    }
    // The fuzzer's seed corpus (tests/fuzz/corpus/figure_text/), replayed:
    // each text is read or refused with a place, and what is read round-trips.
    void fuzzCorpusRoundTrips()
    {
        const QDir dir(taiwa::test::sourcePath(QStringLiteral("tests/fuzz/corpus/figure_text")));
        const QStringList files = dir.entryList(QDir::Files);
        QVERIFY(files.size() >= 5);
        int read = 0;
        for (const QString& f : files) {
            QFile file(dir.filePath(f));
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QByteArray bytes = file.readAll();
            const ParseResult p = parseFigure(std::string_view(bytes.constData(), std::size_t(bytes.size())));
            if (!p.ok()) {
                QVERIFY2(p.error->line >= 1 && p.error->column >= 1, qPrintable(f));
                continue;
            }
            ++read;
            const Evaluation ev = evaluate(p.definitions);
            QVERIFY(ev.elements.size() + ev.errors.size() <= p.definitions.size());
            const std::string written = writeFigure(p.definitions);
            const ParseResult again = parseFigure(written);
            QVERIFY2(again.ok() && again.definitions == p.definitions, qPrintable(f));
            QCOMPARE(writeFigure(again.definitions), written);
        }
        QVERIFY(read >= 3);
    }
};

QTEST_APPLESS_MAIN(TestFigureElements)
#include "test_figure_elements.moc"
