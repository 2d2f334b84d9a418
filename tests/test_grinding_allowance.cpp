// The grinding allowance of seed 001 (core/turning/allowance.h) on profiles
// small enough to work out by hand: every angle case of the neighbour rules
// (0-90°, 90-180°, 180° with the adjustment typed or taken from the tool's
// nose radius, above 180°, both neighbours ground at a convex corner), with
// the exact vertices and arc centres of the deformed profile to 1 µm (the
// relief grooves: test_relief_grooves.cpp); the profile
// table's own geometry (chamfers, roundings, arcs by radius and by centre);
// and the refusals, each naming its row and field.
//
// All profiles are outer (OD) profiles drawn from the front face at the axis
// toward the chuck: Z decreasing, X (diameter) growing at the shoulders. In
// the comments (z, r) is a point with r the radius.
#include "support/allowance_cases.h"

#include "modules/turn/turn_deform.h"
#include "tools/tool_library.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace taiwa;
using namespace taiwa::turning;
using namespace taiwa::test;

class TestGrindingAllowance : public QObject {
    Q_OBJECT

private slots:
    // The table's own geometry: a rounding R3 between the Ø30 cylinder and
    // its shoulder (a right turn): tangent points 3 mm back from the corner
    // (-20, 15), centre (-17, 18), clockwise; a chamfer 1 on the front edge.
    void chamfersAndRoundingsAreCutIntoTheTable()
    {
        TurnedProfile p;
        p.rows = {line(1, 30, 0, CornerKind::Chamfer, 1.0), line(2, 30, -20, CornerKind::Rounding, 3.0),
                  line(3, 50, -20), line(4, 50, -40)};
        const Resolution r = resolveProfile(p);
        QVERIFY(r.ok());
        QCOMPARE(r.profile.edges.size(), std::size_t(6));
        const auto& e = r.profile.edges;
        QCOMPARE(e[1].id, std::string("E1.c"));
        QVERIFY(dist(e[0].geometry.b, {0, 14}) < kTol);   // the face ends 1 below the corner (0, 15)
        QVERIFY(dist(e[1].geometry.b, {-1, 15}) < kTol);  // the chamfer runs to 1 along the cylinder
        QCOMPARE(e[3].id, std::string("E2.c"));
        QVERIFY(e[3].geometry.arc && !e[3].geometry.ccw);
        QVERIFY(dist(e[3].geometry.a, {-17, 15}) < kTol);
        QVERIFY(dist(e[3].geometry.b, {-20, 18}) < kTol);
        QVERIFY(dist(e[3].geometry.centre, {-17, 18}) < kTol);
    }

    // An arc by its radius (the shorter arc) and the same arc by its centre:
    // R10 from (-10, 10) to (-20, 20). Clockwise (G2) puts the centre right
    // of the chord, at (-10, 20): a concave fillet into the shoulder.
    void arcsByRadiusAndByCentre()
    {
        TurnedProfile p;
        p.rows = {line(1, 20, 0), line(2, 20, -10)};
        ProfileRow a;
        a.id = 3;
        a.kind = ElementKind::ArcCW;
        a.x = 40;
        a.z = -20;
        a.radius = 10.0;
        p.rows.push_back(a);
        const Resolution byRadius = resolveProfile(p);
        QVERIFY(byRadius.ok());
        QVERIFY(dist(byRadius.profile.edges[2].geometry.centre, {-10, 20}) < kTol);
        p.rows[2].radius.reset();
        p.rows[2].centreX = 40.0;  // the centre's diameter: radius 20
        p.rows[2].centreZ = -10.0;
        const Resolution byCentre = resolveProfile(p);
        QVERIFY(byCentre.ok());
        QCOMPARE(byCentre.profile.edges[2].geometry, byRadius.profile.edges[2].geometry);
    }

    // 0-90° at the start (the front face meets the Ø40 cylinder at 90°): the
    // new edge runs square to E2 from the vertex (0, 20) up to (0, 20.3).
    // Above 180° at the end (the shoulder E3, 270°): the moved cylinder meets
    // E3 itself at (-50, 20.3); E3 is trimmed to start there.
    void upTo90AndAbove180()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E2", 0.3)};
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 20}},
                        {"E2.start", Origin::Side, {0, 20}, {0, 20.3}},
                        {"E2.moved", Origin::Moved, {0, 20.3}, {-50, 20.3}},
                        {"E3", Origin::Original, {-50, 20.3}, {-50, 30}},
                        {"E4", Origin::Original, {-50, 30}, {-80, 30}}});
        QCOMPARE(d.profile.rows.size(), std::size_t(1));
        QCOMPARE(d.profile.rows[0].start.joint, Joint::UpTo90);
        QCOMPARE(d.profile.rows[0].start.angle, 90.0);
        QCOMPARE(d.profile.rows[0].end.joint, Joint::Concave);
        QCOMPARE(d.profile.rows[0].end.angle, 270.0);
        QCOMPARE(d.profile.rows[0].end.grooveNote, std::string("none: no groove width given"));
    }

    // 90-180°: a 45° cone E2 from (0, 15) to (-5, 20) leads into the Ø40
    // cylinder E3 (the part's angle there is 135°). The new edge follows E2's
    // tangent past (-5, 20) until the moved cylinder r = 20.5: (-5.5, 20.5).
    void obtuseFollowsTheNeighboursTangent()
    {
        TurnedProfile p;
        p.rows = {line(1, 30, 0), line(2, 40, -5), line(3, 40, -40), line(4, 60, -40), line(5, 60, -60)};
        p.allowances = {row("E3", 0.5)};
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 15}},
                        {"E2", Origin::Original, {0, 15}, {-5, 20}},
                        {"E3.start", Origin::Side, {-5, 20}, {-5.5, 20.5}},
                        {"E3.moved", Origin::Moved, {-5.5, 20.5}, {-40, 20.5}},
                        {"E4", Origin::Original, {-40, 20.5}, {-40, 30}},
                        {"E5", Origin::Original, {-40, 30}, {-60, 30}}});
        QCOMPARE(d.profile.rows[0].start.joint, Joint::Obtuse);
        QVERIFY(std::abs(d.profile.rows[0].start.angle - 135.0) < 1e-9);
    }

    // 180°: the Ø30 cylinder E2 runs tangent into the rounding E2.c (R3,
    // centre (-17, 18)) at (-17, 15). With the adjustment 0.8 typed, the
    // allowance ends square to E2 at 0.8 before the tangent point: the step
    // at Z-16.2 from r 15.2 down to 15, then E2's last 0.8 unchanged.
    void tangentJointIsShortenedByTheTypedAdjustment()
    {
        TurnedProfile p;
        p.rows = {line(1, 30, 0), line(2, 30, -20, CornerKind::Rounding, 3.0), line(3, 50, -20), line(4, 50, -40)};
        p.allowances = {row("E2", 0.2)};
        p.allowances[0].adjustment = 0.8;
        const Deformation d = deform(p);
        expectChain(d, {{"E1", Origin::Original, {0, 0}, {0, 15}},
                        {"E2.start", Origin::Side, {0, 15}, {0, 15.2}},
                        {"E2.moved", Origin::Moved, {0, 15.2}, {-16.2, 15.2}},
                        {"E2.end", Origin::Side, {-16.2, 15.2}, {-16.2, 15}},
                        {"E2", Origin::Original, {-16.2, 15}, {-17, 15}},
                        {"E2.c", Origin::Original, {-17, 15}, {-20, 18}, ZR{-17, 18}},
                        {"E3", Origin::Original, {-20, 18}, {-20, 25}},
                        {"E4", Origin::Original, {-20, 25}, {-40, 25}}});
        QCOMPARE(d.profile.rows[0].end.joint, Joint::Tangent);
        QCOMPARE(d.profile.rows[0].end.adjustment, 0.8);
        QCOMPARE(d.profile.rows[0].end.adjustmentFrom, std::string("typed"));
    }

    // The same with no adjustment typed: the finishing tool's nose radius
    // 0.4 is taken, the step moves to Z-16.6.
    void tangentJointTakesTheNoseRadiusFromTheTool()
    {
        TurnedProfile p;
        p.rows = {line(1, 30, 0), line(2, 30, -20, CornerKind::Rounding, 3.0), line(3, 50, -20), line(4, 50, -40)};
        p.allowances = {row("E2", 0.2)};
        AllowanceOptions o;
        o.noseRadius = 0.4;
        o.toolName = "T102";
        const Deformation d = deform(p, o);
        QVERIFY(d.ok());
        QCOMPARE(d.profile.edges[3].id, std::string("E2.end"));
        QVERIFY(dist(d.profile.edges[3].geometry.a, {-16.6, 15.2}) < kTol);
        QVERIFY(dist(d.profile.edges[3].geometry.b, {-16.6, 15}) < kTol);
        QCOMPARE(d.profile.rows[0].end.adjustmentFrom, std::string("nose radius of T102"));
        // Without a tool nor a typed value, the row is refused on its adjustment.
        const Deformation none = deform(p);
        QVERIFY(!none.ok());
        QVERIFY(problemOn(none.problems, "allowances[1].adjustment"));
    }

    // The nose radius is the finishing insert's that the plan takes, not
    // merely the smallest (issue 32): with T101 (CNMG, r 0.8) pinned for
    // the finishing, the step stands 0.8 before the tangent point (-17), at
    // Z-16.2; with nothing pinned the plan takes T102 (r 0.4), Z-16.6. The check, the plan's turned part and the
    // station's profile editor all deform through deformTurned.
    void tangentJointTakesTheNoseRadiusOfTheFinishingInsert()
    {
        TurnedProfile p;
        p.rows = {line(1, 30, 0), line(2, 30, -20, CornerKind::Rounding, 3.0), line(3, 50, -20), line(4, 50, -40)};
        p.allowances = {row("E2", 0.2)};
        const Resolution r = resolveProfile(p);
        QVERIFY(r.ok());
        const std::vector<Tool> library = defaultToolLibrary();
        BarStock bar;
        bar.diameter = 55;
        bar.length = 60;
        const auto stepAt = [&](const ToolPins& pins, const std::vector<std::string>& skip) {
            const TurnDeformation t = deformTurned(p, r.profile, pins, skip, library, &bar, LengthUnit::Millimetre);
            [&] { QVERIFY(t.deformation.ok()); }();
            return std::pair{t.deformation.profile.edges[3].geometry.a.z, t.noseRadiusTool};
        };
        const auto [plain, plainTool] = stepAt({}, {});
        QVERIFY2(std::abs(plain - -16.6) < kTol, std::to_string(plain).c_str());
        QVERIFY2(plainTool.starts_with("T102"), plainTool.c_str());
        const auto [pinned, pinnedTool] = stepAt({{"turn-finish", 101}}, {});
        QVERIFY2(std::abs(pinned - -16.2) < kTol, std::to_string(pinned).c_str());
        QVERIFY2(pinnedTool.starts_with("T101"), pinnedTool.c_str());
        // Finishing turned off: no insert finishes; the smallest one's radius.
        const auto [skipped, skippedTool] = stepAt({{"turn-finish", 101}}, {"turn-finish"});
        QVERIFY(std::abs(skipped - -16.6) < kTol);
        QVERIFY(skippedTool.starts_with("T102"));
        // Without the bar (refused): the smallest insert's radius too.
        const TurnDeformation noBar = deformTurned(p, r.profile, {{"turn-finish", 101}}, {}, library, nullptr, LengthUnit::Millimetre);
        QVERIFY(std::abs(noBar.deformation.profile.edges[3].geometry.a.z - -16.6) < kTol);
    }

    // 90° with both edges ground (seed Fig. 7(e)): the front face E1 (0.2)
    // and the cylinder E2 (0.3) both move; they meet at (0.2, 20.3). The
    // face's free end on the axis closes along the axis: the chain starts at
    // (0.2, 0).
    void convexCornerWithBothGroundMeetsAtTheMovedEdges()
    {
        TurnedProfile p = steppedShaft();
        p.allowances = {row("E1", 0.2), row("E2", 0.3)};
        const Deformation d = deform(p);
        expectChain(d, {{"E1.moved", Origin::Moved, {0.2, 0}, {0.2, 20.3}},
                        {"E2.moved", Origin::Moved, {0.2, 20.3}, {-50, 20.3}},
                        {"E3", Origin::Original, {-50, 20.3}, {-50, 30}},
                        {"E4", Origin::Original, {-50, 30}, {-80, 30}}});
        QCOMPARE(d.profile.rows[0].end.joint, Joint::BothSet);
        QCOMPARE(d.profile.rows[1].start.joint, Joint::BothSet);
        QCOMPARE(d.profile.rows[0].start.joint, Joint::FreeEnd);
    }

    // An arc moves concentrically. A ball end: E1 is the quarter circle R10
    // about (-10, 0) from the axis (0, 0) up to (-10, 10), counter-clockwise,
    // tangent there to the Ø20 cylinder E2. With 0.5 it becomes R10.5 from
    // (0.5, 0) (its free end on the axis closes along the axis); at the
    // tangent end the adjustment 0.4 is arc length: the foot lies 0.4/10 rad
    // before 90°, the new edge runs radially out to R10.5 there, and E1's
    // last 0.4 stays as drawn.
    void arcEdgeMovesConcentrically()
    {
        TurnedProfile p;
        ProfileRow dome;
        dome.id = 1;
        dome.kind = ElementKind::ArcCCW;
        dome.x = 20;
        dome.z = -10;
        dome.radius = 10.0;
        p.rows = {dome, line(2, 20, -30), line(3, 30, -30), line(4, 30, -50)};
        p.allowances = {row("E1", 0.5)};
        p.allowances[0].adjustment = 0.4;
        const double a = std::numbers::pi / 2 - 0.04;  // the foot's angle about the centre
        const ZR c{-10, 0}, foot{-10 + 10 * std::cos(a), 10 * std::sin(a)}, out{-10 + 10.5 * std::cos(a), 10.5 * std::sin(a)};
        const Deformation d = deform(p);
        expectChain(d, {{"E1.moved", Origin::Moved, {0.5, 0}, out, c},
                        {"E1.end", Origin::Side, out, foot},
                        {"E1", Origin::Original, foot, {-10, 10}, c},
                        {"E2", Origin::Original, {-10, 10}, {-30, 10}},
                        {"E3", Origin::Original, {-30, 10}, {-30, 15}},
                        {"E4", Origin::Original, {-30, 15}, {-50, 15}}});
        QVERIFY(d.profile.edges[0].geometry.ccw);
        QVERIFY(std::abs(d.profile.edges[0].geometry.radius - 10.5) < kTol);
        QCOMPARE(d.profile.rows[0].end.joint, Joint::Tangent);
        // A concave arc loses radius: R10 with 10 or more is refused.
        TurnedProfile q;
        ProfileRow fillet;
        fillet.id = 2;
        fillet.kind = ElementKind::ArcCW;
        fillet.x = 40;
        fillet.z = -30;
        fillet.radius = 10.0;
        q.rows = {line(1, 20, 0), line(3, 20, -20), fillet, line(4, 40, -50)};
        q.rows[1].id = 3;
        q.rows[2].id = 2;
        q.allowances = {row("E2", 10.0)};
        const Deformation refused = deform(q);
        const auto* pr = problemOn(refused.problems, "allowances[1].allowance");
        QVERIFY(pr);
        QCOMPARE(pr->message, std::string("allowance row 1: E2 is an arc of radius 10 mm; an allowance of 10 mm leaves it no radius"));
        q.allowances[0].allowance = 0.5;  // R9.5 about the same centre (-20, 20)
        q.allowances[0].adjustment = 0.0;  // tangent into E3 at its start: no shortening typed
        const Deformation fine = deform(q);
        QVERIFY(fine.ok());
        const auto moved = std::find_if(fine.profile.edges.begin(), fine.profile.edges.end(),
                                        [](const DeformedEdge& e) { return e.id == "E2.moved"; });
        QVERIFY(moved != fine.profile.edges.end());
        QVERIFY(dist(moved->geometry.centre, {-20, 20}) < kTol);
        QVERIFY(std::abs(moved->geometry.radius - 9.5) < kTol);
    }

    // Roughness and tolerance of a picked edge go with its moved edge.
    void attributesStayWithTheMovedEdge()
    {
        TurnedProfile p = steppedShaft();
        p.rows[1].attributes.roughness = 0.4;
        p.rows[1].attributes.tolerance = "h6";
        p.allowances = {row("E2", 0.3)};
        const Deformation d = deform(p);
        QVERIFY(d.ok());
        QCOMPARE(d.profile.edges[2].id, std::string("E2.moved"));
        QCOMPARE(d.profile.edges[2].attributes.roughness, std::optional<double>(0.4));
        QCOMPARE(d.profile.edges[2].attributes.tolerance, std::string("h6"));
        QVERIFY(d.profile.edges[1].attributes.empty());  // the side edge carries none
    }

    void refusalsNameTheRowAndField()
    {
        {  // an allowance higher than its concave neighbour: the edges would cross
            TurnedProfile p;
            p.rows = {line(1, 40, 0), line(2, 40, -50), line(3, 40.4, -50), line(4, 40.4, -80)};
            p.allowances = {row("E2", 0.3)};
            const Deformation d = deform(p);
            const auto* pr = problemOn(d.problems, "allowances[1].allowance");
            QVERIFY(pr);
            QCOMPARE(pr->message, std::string("allowance row 1: an allowance of 0.3 mm on E2 reaches past the end of "
                                              "its neighbour E3 (0.2 mm long); the edges would cross"));
        }
        {  // a groove wider than its edge
            TurnedProfile p = steppedShaft();
            p.allowances = {row("E2", 0.3)};
            p.allowances[0].grooveWidth = 60.0;
            const auto* pr = problemOn(deform(p).problems, "allowances[1].grooveWidth");
            QVERIFY(pr);
            QCOMPARE(pr->message, std::string("allowance row 1: a lateral groove 60 mm wide and 0.3 mm deep takes 60.3 mm "
                                              "of E2, which is 50 mm long"));
        }
        {  // a groove deeper than the part allows
            TurnedProfile p = steppedShaft();
            p.allowances = {row("E2", 0.3)};
            p.allowances[0].grooveWidth = 2.0;
            p.allowances[0].grooveDepth = 25.0;
            const auto* pr = problemOn(deform(p).problems, "allowances[1].grooveDepth");
            QVERIFY(pr);
            QCOMPARE(pr->message, std::string("allowance row 1: a groove 25 mm deep at E2 reaches the axis; it is deeper "
                                              "than the part allows"));
        }
        {  // an edge that does not exist
            TurnedProfile p = steppedShaft();
            p.allowances = {row("E9", 0.3)};
            const auto* pr = problemOn(deform(p).problems, "allowances[1].edge");
            QVERIFY(pr);
            QCOMPARE(pr->message, std::string("allowance row 1: there is no edge E9 in the profile"));
        }
        {  // a profile that is not one chain: row 4 comes back across the front face
            TurnedProfile p;
            p.rows = {line(1, 40, 0), line(2, 40, -50), line(3, 20, -50), line(4, 20, 10)};
            const Resolution r = resolveProfile(p);
            QVERIFY(!r.ok());
            QCOMPARE(r.problems[0].field, std::string("rows[4].x"));
            QVERIFY2(r.problems[0].message.starts_with("the profile is not one chain: E4 (row 4) meets E1 (row 1)"),
                     r.problems[0].message.c_str());
        }
        {  // a diameter below zero
            TurnedProfile p;
            p.rows = {line(1, 40, 0), line(2, -4, -50)};
            const Resolution r = resolveProfile(p);
            QCOMPARE(r.problems.size(), std::size_t(1));
            QCOMPARE(r.problems[0].field, std::string("rows[2].x"));
            QCOMPARE(r.problems[0].message, std::string("row 2: the end diameter is -4 mm; a diameter cannot be below zero"));
        }
        {  // an arc whose radius cannot reach its end point
            TurnedProfile p;
            p.rows = {line(1, 20, 0)};
            ProfileRow a;
            a.id = 2;
            a.kind = ElementKind::ArcCW;
            a.x = 40;
            a.z = -20;
            a.radius = 5.0;
            p.rows.push_back(a);
            const Resolution r = resolveProfile(p);
            QCOMPARE(r.problems.size(), std::size_t(1));
            QCOMPARE(r.problems[0].field, std::string("rows[2].radius"));
            QVERIFY2(r.problems[0].message.starts_with("row 2: a radius of 5 mm cannot reach the end point, which is "
                                                       "22.36"),
                     r.problems[0].message.c_str());
        }
    }
};

QTEST_APPLESS_MAIN(TestGrindingAllowance)
#include "test_grinding_allowance.moc"
