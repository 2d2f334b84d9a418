// The relief grooves of the grinding allowance (seed 001, docs/turning.md
// "Relief grooves"; core/turning/allowance_grooves.cpp) worked by hand to
// 1 nm: each kind identified and typed; a groove only takes allowance off
// (issue 33, item 1): at a corner that is not square (a cylinder into a 45°
// or 60° cone or a convex arc, a taper into a shoulder) its bottom runs
// along the finished edge to the finished corner and the neighbour stays
// as drawn, a depth beyond the allowance stops at the finished surface, a
// groove typed into an edge with no allowance is refused; a ring groove's
// halves each take their own edge's allowance and row, both measured from
// the finished corner (item 2). Every deformed profile here is also
// checked not to lie inside the part (support/turned_generator.h).
//
// Outer profiles from the front face at the axis toward the chuck; in the
// comments (z, r) is a point with r the radius.
#include "support/allowance_cases.h"
#include "support/turned_generator.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace taiwa;
using namespace taiwa::turning;
using namespace taiwa::test;

namespace {

// How deep the deformed profile of `p` goes into the part (0: not at all).
double intoPart(const TurnedProfile& p, const Deformation& d)
{
    return deepestIntoPart(resolveProfile(p).profile, d.profile).depth;
}

const DeformedEdge* edgeNamed(const Deformation& d, const std::string& id)
{
    for (const auto& e : d.profile.edges)
        if (e.id == id) return &e;
    return nullptr;
}

}  // namespace

class TestReliefGrooves : public QObject {
    Q_OBJECT

private slots:
    // Lateral groove identified automatically: E2 runs along the axis, E3 is
    // not ground. Width 2, depth = the allowance 0.3, at the corner
    // (-50, 20.3): top from there to (-47.7, 20.3), bottom (-48, 20) to
    // (-50, 20); the groove's wall at Z-50 lies on E3, which goes on up.
    void lateralGrooveIdentified()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E2", 0.3)};
        p.allowances[0].grooveWidth = 2.0;
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 20}},
                        {"E2.start", Origin::Side, {0, 20}, {0, 20.3}},
                        {"E2.moved", Origin::Moved, {0, 20.3}, {-47.7, 20.3}},
                        {"E2.groove1", Origin::Groove, {-47.7, 20.3}, {-48, 20}},
                        {"E2.groove2", Origin::Groove, {-48, 20}, {-50, 20}},
                        {"E3", Origin::Original, {-50, 20}, {-50, 30}},
                        {"E4", Origin::Original, {-50, 30}, {-80, 30}}});
        const auto& g = d.profile.rows[0].end.groove;
        QVERIFY(g);
        QCOMPARE(g->kind, GrooveKind::Lateral);
        QVERIFY(g->identified);
        QCOMPARE(g->rule, std::string("E2 runs along the spindle axis"));
        QCOMPARE(g->depth, 0.3);
    }

    // Longitudinal groove identified automatically: only the shoulder face E3
    // (square to the axis) is ground, 0.2, groove width 1. The moved face
    // z = -49.8 meets E2 at (-49.8, 20); the groove is cut into the face:
    // bottom Z-50 from r 20 to 21, top at the face from r 20 to 21.2.
    void longitudinalGrooveIdentified()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E3", 0.2)};
        p.allowances[0].grooveWidth = 1.0;
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 20}},
                        {"E2", Origin::Original, {0, 20}, {-50, 20}},
                        {"E3.groove1", Origin::Groove, {-50, 20}, {-50, 21}},
                        {"E3.groove2", Origin::Groove, {-50, 21}, {-49.8, 21.2}},
                        {"E3.moved", Origin::Moved, {-49.8, 21.2}, {-49.8, 30}},
                        {"E3.end", Origin::Side, {-49.8, 30}, {-50, 30}},
                        {"E4", Origin::Original, {-50, 30}, {-80, 30}}});
        const auto& g = d.profile.rows[0].start.groove;
        QVERIFY(g);
        QCOMPARE(g->kind, GrooveKind::Longitudinal);
        QCOMPARE(g->rule, std::string("E3 is square to the spindle axis"));
    }

    // A cylinder E2 (Ø40, 0.3, groove width 2) running into a neighbour E3
    // that is not square to it: the moved cylinder meets E3 behind the
    // corner (-30, 20), and a groove square to E2 from there would cut E3's
    // finished material (0.21 mm deep at 45°, 0.15 at 60°, a 9 µm sliver
    // under the arc). The groove comes off the allowance only: its bottom
    // runs along E2 from 2 before the corner to the corner itself, its wall
    // rises at 45° to the moved cylinder 2.3 before the corner, and E3
    // stays as drawn from the corner on.
    void grooveAtACornerThatIsNotSquare_data()
    {
        QTest::addColumn<int>("neighbour");  // 0: 45° cone, 1: 60° cone, 2: convex arc R5 starting square
        QTest::newRow("45-degree cone") << 0;
        QTest::newRow("60-degree cone") << 1;
        QTest::newRow("arc") << 2;
    }
    void grooveAtACornerThatIsNotSquare()
    {
        QFETCH(int, neighbour);
        TurnedProfile p;
        const double z3 = neighbour == 1 ? -30.0 - 5.0 / std::tan(std::numbers::pi / 3.0) : -35.0;
        ProfileRow e3 = line(3, 50, z3);
        std::optional<ZR> centre;
        if (neighbour == 2) {
            e3.kind = ElementKind::ArcCCW;
            e3.radius = 5.0;
            centre = ZR{-35, 20};
        }
        p.rows = {line(1, 40, 0), line(2, 40, -30), e3, line(4, 50, -60)};
        p.allowances = {row("E2", 0.3)};
        p.allowances[0].grooveWidth = 2.0;
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 20}},
                        {"E2.start", Origin::Side, {0, 20}, {0, 20.3}},
                        {"E2.moved", Origin::Moved, {0, 20.3}, {-27.7, 20.3}},
                        {"E2.groove1", Origin::Groove, {-27.7, 20.3}, {-28, 20}},
                        {"E2.groove2", Origin::Groove, {-28, 20}, {-30, 20}},
                        {"E3", Origin::Original, {-30, 20}, {z3, 25}, centre},
                        {"E4", Origin::Original, {z3, 25}, {-60, 25}}});
        const auto& g = d.profile.rows[0].end.groove;
        QVERIFY(g);
        QCOMPARE(g->kind, GrooveKind::Lateral);
        QCOMPARE(g->inEdge, std::string("E2"));
        QVERIFY(intoPart(p, d) < 1e-7);
    }

    // A taper E2 (Ø40 to Ø44 over 30) into the shoulder E3 at Z-30 (the
    // part's angle 266.2°), 0.3 and a groove 2 wide: the groove's bottom
    // lies on the taper from 2 before the finished corner (-30, 22) to it,
    // its wall rises at 45° to the moved taper, and the shoulder is kept
    // whole from the corner up.
    void grooveInATaperAtAShoulder()
    {
        TurnedProfile p;
        p.rows = {line(1, 40, 0), line(2, 44, -30), line(3, 50, -30), line(4, 50, -60)};
        p.allowances = {row("E2", 0.3)};
        p.allowances[0].grooveWidth = 2.0;
        const Deformation d = deform(p);
        const ZR v{-30, 22}, u = unit(ZR{30, -2}), n = unit(ZR{2, 30});
        const ZR bottom = v + 2.0 * u, top = v + 2.3 * u + 0.3 * n;
        // At the front the face (93.8°: 90-180) is carried on up to the moved taper.
        const ZR start{0, 20 + 0.3 * std::hypot(30.0, 2.0) / 30.0};
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 20}},
                        {"E2.start", Origin::Side, {0, 20}, start},
                        {"E2.moved", Origin::Moved, start, top},
                        {"E2.groove1", Origin::Groove, top, bottom},
                        {"E2.groove2", Origin::Groove, bottom, v},
                        {"E3", Origin::Original, v, {-30, 25}},
                        {"E4", Origin::Original, {-30, 25}, {-60, 25}}});
        QCOMPARE(d.profile.rows[0].end.groove->rule, std::string("E2 is nearer to the axis direction"));
        QVERIFY(intoPart(p, d) < 1e-7);
    }

    // A depth typed beyond the allowance (0.5 on 0.3) stops at the finished
    // surface: the 45° wall from the bottom 2 from the corner 0.5 deep meets
    // the cylinder at 2.2 from the corner; from there to the shoulder the
    // finished cylinder is the deformed profile.
    void aDepthBeyondTheAllowanceStopsAtTheFinishedSurface()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E2", 0.3)};
        p.allowances[0].grooveWidth = 2.0;
        p.allowances[0].grooveDepth = 0.5;
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 20}},
                        {"E2.start", Origin::Side, {0, 20}, {0, 20.3}},
                        {"E2.moved", Origin::Moved, {0, 20.3}, {-47.5, 20.3}},
                        {"E2.groove1", Origin::Groove, {-47.5, 20.3}, {-47.8, 20}},
                        {"E2", Origin::Original, {-47.8, 20}, {-50, 20}},
                        {"E3", Origin::Original, {-50, 20}, {-50, 30}},
                        {"E4", Origin::Original, {-50, 30}, {-80, 30}}});
        QVERIFY(intoPart(p, d) < 1e-7);
    }

    // Ring groove identified automatically: E2 (0.3, groove width 1.5) and
    // the shoulder E3 (0.2) both ground. Each half takes its own edge's
    // allowance, its width measured from the finished corner (-50, 20): the
    // lateral half 0.3 deep in E2 (bottom on the finished cylinder from
    // Z-48.5 to the corner), the longitudinal half 0.2 deep in E3 (bottom on
    // the finished face from r 20 to 21.5), not 0.3 into the ground face.
    void ringGrooveTakesEachEdgesOwnAllowance()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E2", 0.3), row("E3", 0.2)};
        p.allowances[0].grooveWidth = 1.5;
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 20}},
                        {"E2.start", Origin::Side, {0, 20}, {0, 20.3}},
                        {"E2.moved", Origin::Moved, {0, 20.3}, {-48.2, 20.3}},
                        {"E2.groove1", Origin::Groove, {-48.2, 20.3}, {-48.5, 20}},
                        {"E2.groove2", Origin::Groove, {-48.5, 20}, {-50, 20}},
                        {"E2.groove3", Origin::Groove, {-50, 20}, {-50, 21.5}},
                        {"E2.groove4", Origin::Groove, {-50, 21.5}, {-49.8, 21.7}},
                        {"E3.moved", Origin::Moved, {-49.8, 21.7}, {-49.8, 30}},
                        {"E3.end", Origin::Side, {-49.8, 30}, {-50, 30}},
                        {"E4", Origin::Original, {-50, 30}, {-80, 30}}});
        const auto& g = d.profile.rows[0].end.groove;
        QVERIFY(g);
        QCOMPARE(g->kind, GrooveKind::Ring);
        QCOMPARE(g->rule, std::string("the neighbour E3 is ground too"));
        QCOMPARE(g->inEdge, std::string("E2, E3"));
        QCOMPARE(g->depth, 0.3);
        QVERIFY(intoPart(p, d) < 1e-7);
        // The face's row gives a width of its own (1): its half is 1 wide,
        // and the ring it makes from its side is the same groove.
        p.allowances[1].grooveWidth = 1.0;
        const Deformation both = deform(p);
        QVERIFY(both.ok());
        const DeformedEdge* face = edgeNamed(both, "E3.moved");
        QVERIFY(face);
        QVERIFY2(dist(face->geometry.a, {-49.8, 21.2}) < kTol, qPrintable(describe(both.profile)));
        QVERIFY(both.profile.rows[1].start.groove);
        QCOMPARE(both.profile.rows[1].start.groove->depth, 0.2);
        QVERIFY(intoPart(p, both) < 1e-7);
    }

    // A ring where the ground cylinder E2 (0.3) runs into a ground 45° cone
    // E3 (0.2): nothing of the finished part comes off, and the groove
    // reaches the finished corner (-30, 20).
    void ringGrooveAtACone()
    {
        TurnedProfile p;
        p.rows = {line(1, 40, 0), line(2, 40, -30), line(3, 50, -35), line(4, 50, -60)};
        p.allowances = {row("E2", 0.3), row("E3", 0.2)};
        p.allowances[0].grooveWidth = 1.5;
        const Deformation d = deform(p);
        QVERIFY2(d.ok(), d.problems.empty() ? "" : d.problems[0].message.c_str());
        QCOMPARE(d.profile.rows[0].end.groove->kind, GrooveKind::Ring);
        QVERIFY2(intoPart(p, d) < 1e-7, qPrintable(describe(d.profile)));
        bool corner = false;
        for (const auto& e : d.profile.edges) corner = corner || dist(e.geometry.b, {-30, 20}) < kTol;
        QVERIFY2(corner, qPrintable(describe(d.profile)));
    }

    // A kind typed overrides the rules: a lateral groove asked for where
    // the rules would make a ring (E3 ground too) is only the lateral half,
    // in E2 with E2's allowance; the face keeps its allowance above it.
    void typedKindIsKept()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E2", 0.3), row("E3", 0.2)};
        p.allowances[0].groove = GrooveKind::Lateral;
        p.allowances[0].grooveWidth = 1.0;
        const Deformation d = deform(p);
        QVERIFY(d.ok());
        const auto& g = d.profile.rows[0].end.groove;
        QVERIFY(g && !g->identified);
        QCOMPARE(g->kind, GrooveKind::Lateral);
        QCOMPARE(g->inEdge, std::string("E2"));
        const DeformedEdge* bottom = edgeNamed(d, "E2.groove2");
        QVERIFY(bottom);
        QVERIFY2(dist(bottom->geometry.a, {-49, 20}) < kTol && dist(bottom->geometry.b, {-50, 20}) < kTol,
                 qPrintable(describe(d.profile)));
        const DeformedEdge* face = edgeNamed(d, "E3.moved");
        QVERIFY(face);
        QVERIFY2(dist(face->geometry.a, {-49.8, 20.3}) < kTol, qPrintable(describe(d.profile)));
        QVERIFY(intoPart(p, d) < 1e-7);
    }

    // A groove typed into an edge that has no allowance would take only
    // finished material off: a lateral groove where only the shoulder face
    // E3 is ground lies in the cylinder E2, and is refused.
    void aGrooveInAnEdgeWithoutAllowanceIsRefused()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E3", 0.2)};
        p.allowances[0].groove = GrooveKind::Lateral;
        p.allowances[0].grooveWidth = 1.0;
        p.allowances[0].grooveDepth = 0.5;
        const auto* pr = problemOn(deform(p).problems, "allowances[1].groove");
        QVERIFY(pr);
        QCOMPARE(pr->message, std::string("allowance row 1: a lateral groove at the corner of E3 and E2 would lie in "
                                          "E2, which has no grinding allowance; a relief groove only takes allowance "
                                          "off"));
        p.allowances[0].groove = GrooveKind::Ring;  // the same for a ring's half
        QVERIFY(problemOn(deform(p).problems, "allowances[1].groove"));
    }
};

QTEST_APPLESS_MAIN(TestReliefGrooves)
#include "test_relief_grooves.moc"
