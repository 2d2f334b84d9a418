// Module SIDE (side milling along an open or closed contour): the open
// offset on hand-computed cases, the decomposition of both samples, the
// refusals with their messages, the job file's round trip and inch
// conversion, and the geometric oracle (support/side_oracle.h: exact
// distances to the contour's lines and arcs, not Clipper) on the rs274
// moves of both samples' linuxcnc tapes: no cut across the wall (1 µm), the
// finishing pass touches every point of the wall at R at each of its
// depths, roughing leaves exactly α2, the band W is swept at T, layers at
// their depths, no rapid below the top, arcs on the tape as G2/G3. A
// semicircular notch into the material is milled with the largest end mill
// its radius takes; where none fits, the arc or channel is named (issue 33).
#include "modules/side/side.h"
#include "paths/contour_offset.h"
#include "support/rs274.h"
#include "support/side_oracle.h"
#include "support/support.h"

#include "job/job_check.h"
#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "verify/verify.h"

#include <nlohmann/json.hpp>

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

using namespace taiwa;
using namespace taiwa::test;

namespace {

constexpr double kTol = 1e-3;  // 1 µm

Job sampleJob(const char* name)
{
    auto read = readJobFile(sourcePath(QString("resources/samples/") + name).toStdString());
    if (!read.job) throw std::runtime_error("sample not read");
    return *read.job;
}

std::string messages(const Diagnostics& ds)
{
    std::string s;
    for (const auto& d : ds) s += d.field + ": " + d.message + "\n";
    return s;
}

Contour chain(std::vector<ContourSegment> s)
{
    Contour c;
    c.segments = std::move(s);
    return c;
}

bool near(Point2 a, Point2 b) { return distance(a, b) < 1e-9; }

double segmentDistance(Point2 p, Point2 a, Point2 b)
{
    const Point2 d = b - a;
    const double l2 = dot(d, d);
    const double t = l2 > 0 ? std::clamp(dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
    return distance(p, a + t * d);
}

// The XY pieces of the cutting moves of one step at one Z, as segments
// (arcs sampled every 0.01 mm).
std::vector<std::pair<Point2, Point2>> piecesAt(const std::vector<CanonMove>& moves, int step, double z)
{
    std::vector<std::pair<Point2, Point2>> out;
    for (const auto& m : moves) {
        if (m.step != step || m.kind == CanonMove::Traverse) continue;
        if (std::abs(m.start.z - z) > 1e-6 || std::abs(m.end.z - z) > 1e-6) continue;
        std::vector<Point3> pts{m.start};
        if (m.kind == CanonMove::Arc) {
            const auto s = sampleArc(m, 0.01);
            pts.insert(pts.end(), s.begin(), s.end());
        } else {
            pts.push_back(m.end);
        }
        for (std::size_t i = 1; i < pts.size(); ++i) out.push_back({{pts[i - 1].x, pts[i - 1].y}, {pts[i].x, pts[i].y}});
    }
    return out;
}

double nearestPiece(const std::vector<std::pair<Point2, Point2>>& pieces, Point2 p)
{
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : pieces) best = std::min(best, segmentDistance(p, a, b));
    return best;
}

// The open sample's shoulder replaced by `figure` (contour K1), W and T.
Job withFigure(const std::string& figure, double width, double depth)
{
    Job job = sampleJob("side-open-contour.taiwa");
    job.figure = figure;
    SideMill& u = job.units[0].module.as<SideMill>();
    u.width = width;
    u.depth = depth;
    return job;
}

// A straight run along y = 60 with a half circle of radius r at x = 60 cut
// down into the material (the tool on the left, above the run).
std::string notchFigure(double r)
{
    return "P1 = POINT/-15, 60\nP2 = POINT/135, 60\nP3 = POINT/60, 60\nL1 = LINE/P1, ATANGL, 0\n"
           "C1 = CIRCLE/CENTER, P3, RADIUS, " + std::to_string(r) + "\n"
           "K1 = CONTOUR/P1, L1, XSMALL, CCLW, C1, XLARGE, L1, P2";
}

}  // namespace

class TestSideMilling : public QObject {
    Q_OBJECT
private slots:
    // A line: its parallel.
    void openOffsetOfALine()
    {
        const auto c = paths::offsetOpen(chain({ContourSegment::line({0, 0}, {10, 0})}), true, 2);
        QVERIFY(c);
        QCOMPARE(c->segments.size(), std::size_t{1});
        QVERIFY(near(c->segments[0].start, {0, 2}) && near(c->segments[0].end, {10, 2}));
        const auto r = paths::offsetOpen(chain({ContourSegment::line({0, 0}, {10, 0})}), false, 2);
        QVERIFY(near(r->segments[0].start, {0, -2}) && near(r->segments[0].end, {10, -2}));
    }

    // An L turning left: on its right the corner is convex (an arc of radius
    // d about it), on its left concave (the parallels trimmed).
    void openOffsetOfAnL()
    {
        const Contour l = chain({ContourSegment::line({0, 0}, {10, 0}), ContourSegment::line({10, 0}, {10, 10})});
        const auto right = paths::offsetOpen(l, false, 2);
        QVERIFY(right);
        QCOMPARE(right->segments.size(), std::size_t{3});
        QVERIFY(near(right->segments[0].end, {10, -2}));
        QCOMPARE(right->segments[1].kind, ContourSegment::Kind::ArcCCW);
        QVERIFY(near(right->segments[1].centre, {10, 0}) && near(right->segments[1].end, {12, 0}));
        QVERIFY(near(right->segments[2].start, {12, 0}) && near(right->segments[2].end, {12, 10}));
        const auto left = paths::offsetOpen(l, true, 2);
        QVERIFY(left);
        QCOMPARE(left->segments.size(), std::size_t{2});
        QVERIFY(near(left->segments[0].start, {0, 2}) && near(left->segments[0].end, {8, 2}));
        QVERIFY(near(left->segments[1].start, {8, 2}) && near(left->segments[1].end, {8, 10}));
    }

    // An arc gains radius on its outside and loses it on its inside; an arc
    // curving round the tool tighter than d is left out and its neighbours
    // meet; a piece the trimming reverses is left out.
    void openOffsetOfArcs()
    {
        const Contour arc = chain({ContourSegment::arc({10, 0}, {0, 10}, {0, 0}, true)});
        const auto in = paths::offsetOpen(arc, true, 2), out = paths::offsetOpen(arc, false, 2);
        QVERIFY(in && out);
        QVERIFY(near(in->segments[0].start, {8, 0}) && near(in->segments[0].end, {0, 8}));
        QVERIFY(near(out->segments[0].start, {12, 0}) && near(out->segments[0].end, {0, 12}));
        QCOMPARE(out->segments[0].kind, ContourSegment::Kind::ArcCCW);

        const Contour fillet = chain({ContourSegment::line({0, 0}, {10, 0}), ContourSegment::arc({10, 0}, {12, 2}, {10, 2}, true),
                                      ContourSegment::line({12, 2}, {12, 10})});
        const auto gone = paths::offsetOpen(fillet, true, 3);
        QVERIFY(gone);
        QCOMPARE(gone->segments.size(), std::size_t{2});
        QVERIFY(near(gone->segments[0].end, {9, 3}) && near(gone->segments[1].end, {9, 10}));

        // A 1 mm step up and on: its riser's parallel is reversed; the
        // rounding about the step's top corner meets the first parallel.
        const Contour step = chain({ContourSegment::line({0, 0}, {10, 0}), ContourSegment::line({10, 0}, {10, 1}),
                                    ContourSegment::line({10, 1}, {20, 1})});
        const auto s = paths::offsetOpen(step, true, 3);
        QVERIFY2(s, s ? "" : s.error().c_str());
        QCOMPARE(s->segments.size(), std::size_t{3});
        QVERIFY(near(s->segments[0].end, {10 - std::sqrt(5.0), 3}));
        QCOMPARE(s->segments[1].kind, ContourSegment::Kind::ArcCW);
        QVERIFY(near(s->segments[1].centre, {10, 1}) && near(s->segments[1].end, {10, 4}));
        QVERIFY(near(s->segments[2].end, {20, 4}));
    }

    // side::Sides looks at the edges of the point's horizontal band only:
    // every point off the contour must still be on the side the contour's
    // own direction says (left of the nearest segment's tangent when the
    // tool is on the left), for a closed contour and an open one (continued
    // past its ends), both ways round.
    void toolSideOfEveryPoint()
    {
        using S = ContourSegment;
        const Contour boss = [] {
            Contour c = chain({S::line({0, 0}, {40, 0}), S::arc({40, 0}, {40, 20}, {40, 10}, true),
                               S::line({40, 20}, {25, 20}), S::arc({25, 20}, {15, 20}, {20, 20}, false),
                               S::line({15, 20}, {0, 20}), S::line({0, 20}, {0, 0})});
            c.closed = true;
            return c;
        }();
        const Contour open = chain({S::line({-10, 5}, {10, 5}), S::arc({10, 5}, {20, 15}, {10, 15}, true),
                                    S::line({20, 15}, {20, 30})});
        std::uint32_t seed = 12345;
        const auto uniform = [&](double a, double b) {
            seed = seed * 1664525u + 1013904223u;
            return a + (b - a) * (seed >> 8) / double(1u << 24);
        };
        for (const Contour* c : {&boss, &open})
            for (const bool left : {true, false}) {
                const side::Sides sides(*c, left);
                int checked = 0;
                for (int n = 0; n < 20000; ++n) {
                    const Point2 p{uniform(-30, 70), uniform(-30, 50)};
                    // The nearest segment and point; points nearest a vertex
                    // (or an open end) have no one tangent: skipped.
                    double best = std::numeric_limits<double>::infinity();
                    const S* seg = nullptr;
                    Point2 q{};
                    for (const S& sg : c->segments)
                        if (const Point2 at = sg.nearest(p); distance(p, at) < best) best = distance(p, at), seg = &sg, q = at;
                    if (best < 1e-3 || distance(q, seg->start) < 1e-6 || distance(q, seg->end) < 1e-6) continue;
                    Point2 t = seg->end - seg->start;
                    if (seg->isArc()) {
                        const Point2 r = q - seg->centre;
                        t = seg->kind == S::Kind::ArcCCW ? Point2{-r.y, r.x} : Point2{r.y, -r.x};
                    }
                    const bool onLeft = cross(t, p - q) > 0;
                    QVERIFY2(sides.onToolSide(p) == (onLeft == left),
                             qPrintable(QString("(%1, %2), tool on the %3").arg(p.x).arg(p.y).arg(left ? "left" : "right")));
                    ++checked;
                }
                QVERIFY(checked > 10000);
            }
    }

    void roughingPassesFromWToAlpha2()
    {
        const auto o = roughingOffsets(14, 0.3, 9);
        QCOMPARE(o.size(), std::size_t{2});
        QVERIFY(std::abs(o[0] - 7.15) < 1e-12 && std::abs(o[1] - 0.3) < 1e-12);
        QCOMPARE(roughingOffsets(5, 0.3, 9).size(), std::size_t{1});
    }

    void decomposition()
    {
        PlanOptions stepsOnly;
        stepsOnly.withToolPaths = false;
        const Plan open = planJob(sampleJob("side-open-contour.taiwa"), TechnologyTable::builtIn(), defaultToolLibrary(), stepsOnly);
        QVERIFY2(open.ok(), messages(open.diagnostics).c_str());
        QCOMPARE(open.steps.size(), std::size_t{2});
        const Step& rough = open.steps[0];
        const Step& finish = open.steps[1];
        QCOMPARE(rough.kind, StepKind::SideMilling);
        QCOMPARE(rough.machiningType, MachiningType::SideMilling);
        QCOMPARE(finish.machiningType, MachiningType::SideFinishing);
        QCOMPARE(rough.tool->toolId, 30);  // Ø20: its radius 10 fits the ROUND 10 on the tool's side
        QCOMPARE(finish.tool->toolId, 30);
        QCOMPARE(rough.payload.as<SidePasses>().offsets.size(), std::size_t{2});
        QVERIFY(std::abs(rough.payload.as<SidePasses>().offsets[0] - 7.15) < 1e-9 && std::abs(rough.payload.as<SidePasses>().offsets[1] - 0.3) < 1e-9);
        QCOMPARE(finish.payload.as<SidePasses>().offsets, std::vector<double>{0.0});
        QVERIFY(rough.payload.as<SidePasses>().toolOnLeft);  // climb
        QVERIFY(near(rough.payload.as<SidePasses>().contour.start(), {-15, 72}));  // run as drawn: tool left of K1, climb
        QVERIFY(!millingOf(finish).multiIncision);
        QCOMPARE(millingOf(rough).cutDepth, 12.0);

        const Plan boss = planJob(sampleJob("side-boss.taiwa"), TechnologyTable::builtIn(), defaultToolLibrary(), stepsOnly);
        QVERIFY2(boss.ok(), messages(boss.diagnostics).c_str());
        QCOMPARE(boss.steps.size(), std::size_t{2});
        QVERIFY(!boss.steps[0].payload.as<SidePasses>().toolOnLeft);  // conventional: the tool on the right of its travel
        QVERIFY(signedArea(boss.steps[0].payload.as<SidePasses>().contour) > 0);  // round the boss counter-clockwise
        QCOMPARE(boss.steps[0].tool->toolId, 31);                // Ø25: nothing limits it outside the boss
        QVERIFY(millingOf(boss.steps[1]).multiIncision);                    // F2
    }

    void refusals_data()
    {
        QTest::addColumn<QString>("change");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("message");
        QTest::newRow("unknown contour") << "contour=K9" << "contour"
                                         << "K9 is not a contour of the job's figure elements (its contours: K1)";
        QTest::newRow("no contour") << "contour=" << "contour"
                                    << "name the contour the side milling follows (a CONTOUR of the job's figure elements, open or closed)";
        QTest::newRow("side code") << "side=3" << "side"
                                   << "side 3 is not a code of side milling; use 1 (the tool on the left of the contour) or 2 (on its right)";
        QTest::newRow("direction code") << "direction=0" << "direction"
                                        << "direction 0 is not a code of side milling; use 1 (climb) or 2 (conventional)";
        QTest::newRow("cored U") << "U=7" << "U"
                                 << "U 7 is not a code of side milling; use 1 (roughing and finishing), 8 (finishing only) or 9 (roughing only)";
        QTest::newRow("two-stage F") << "F=3" << "F"
                                     << "F 3 is not a code of side milling; use 1 (finishing at full depth at once) or 2 (in several incisions)";
        QTest::newRow("width zero") << "width=0" << "width" << "the width W is 0 mm; it must be greater than zero";
        QTest::newRow("width within alpha2") << "width=0.2" << "width"
                                             << "the width W is 0.2 mm; roughing leaves α2 = 0.3 mm on the wall, so W must be larger than that";
        QTest::newRow("too deep") << "depth=30" << "depth" << "";
        QTest::newRow("sharp corner on the tool's side") << "figure:L2, ROUND, 10, L3=>L2, L3" << "contour"
                                                         << "K1 has a sharp inside corner at (62 mm, 66 mm): an end mill cannot cut it "
                                                            "and leaves its own radius there; round the corner (ROUND) in the contour";
        QTest::newRow("crossing itself") << "figure:P3 = POINT/135, 66=>P3 = POINT/-30, 66\nL9 = LINE/P3, ATANGL, 0" << "contour" << "";
        QTest::newRow("pin key") << "tools={\"roughing\": 30}" << "tools.roughing"
                                 << "\"roughing\" is not a step of module SIDE; its steps are side";
        QTest::newRow("pinned too big") << "tools={\"side\": 31}" << "tools.side" << "";
    }
    void refusals()
    {
        QFETCH(QString, change);
        QFETCH(QString, field);
        QFETCH(QString, message);
        Job job = sampleJob("side-open-contour.taiwa");
        const std::string c = change.toStdString();
        if (c.starts_with("figure:")) {
            const auto arrow = c.find("=>");
            const std::string from = c.substr(7, arrow - 7), to = c.substr(arrow + 2);
            const auto at = job.figure.find(from);
            QVERIFY(at != std::string::npos);
            job.figure.replace(at, from.size(), to);
        } else {
            auto j = nlohmann::json::parse(writeJob(job));
            const auto eq = c.find('=');
            const std::string key = c.substr(0, eq), value = c.substr(eq + 1);
            if (key == "contour") j["units"][0][key] = value;
            else j["units"][0][key] = nlohmann::json::parse(value);
            auto read = readJob(j.dump());
            QVERIFY(read.job);
            job = *read.job;
        }
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        std::string got;
        for (const auto& d : ds)
            if (d.field == field.toStdString() && got.empty()) got = d.message;
        QVERIFY2(!got.empty(), messages(ds).c_str());
        if (!message.isEmpty()) QCOMPARE(QString::fromStdString(got), message);
    }

    // The open contour crossing itself: that row only replaced a point; here
    // a contour that does cross.
    void contourCrossingItselfIsRefused()
    {
        Job job = sampleJob("side-open-contour.taiwa");
        job.figure += "\nP9 = POINT/0, 0\nP8 = POINT/10, 10\nP7 = POINT/10, 0\nP6 = POINT/0, 10\n"
                      "L7 = LINE/P9, P8\nL8 = LINE/P8, P7\nL9 = LINE/P7, P6\nK2 = CONTOUR/P9, L7, L8, L9, P6";
        auto j = nlohmann::json::parse(writeJob(job));
        j["units"][0]["contour"] = "K2";
        job = *readJob(j.dump()).job;
        const Diagnostics ds = checkJob(job, TechnologyTable::builtIn(), defaultToolLibrary());
        bool found = false;
        for (const auto& d : ds) found |= d.field == "contour" && d.message == "K2 crosses itself; check the order of its elements and the side chosen at each junction";
        QVERIFY2(found, messages(ds).c_str());
    }

    void jobFileRoundTripAndInch()
    {
        for (const char* name : {"side-open-contour.taiwa", "side-boss.taiwa"}) {
            const Job job = sampleJob(name);
            const std::string text = writeJob(job);
            const auto back = readJob(text);
            QVERIFY(back.job);
            QVERIFY(*back.job == job);
            QCOMPARE(writeJob(*back.job), text);
        }
        const Job mm = sampleJob("side-open-contour.taiwa");
        Job inch = withLengths(mm, LengthUnit::Inch, [](double v) { return v / 25.4; });
        const SideMill& u = inch.units[0].module.as<SideMill>();
        QVERIFY(std::abs(u.width - 14 / 25.4) < 1e-12 && std::abs(u.depth - 12 / 25.4) < 1e-12);
        QCOMPARE(u.side, 1);
    }

    // The oracle on the rs274 moves of both samples' linuxcnc tapes.
    // A semicircular R12 notch in a straight run, bands from 12 to 20 wide:
    // the largest end mill whose radius fits the notch (Ø20, R10; Ø25 does
    // not) mills it, and the product's verification finds nothing wrong.
    // Before: refused, "its flutes (6 mm) are shorter than the depth" (the
    // passes wider than the notch joined its two runs by a full circle).
    void notchIsMilledWithTheToolThatFitsIt_data()
    {
        QTest::addColumn<double>("width");
        QTest::newRow("W 12") << 12.0;
        QTest::newRow("W 14") << 14.0;
        QTest::newRow("W 20") << 20.0;
    }
    void notchIsMilledWithTheToolThatFitsIt()
    {
        QFETCH(double, width);
        const Plan plan = planJob(withFigure(notchFigure(12), width, 12), TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
        for (const Step& s : plan.steps) QCOMPARE(s.tool->toolId, 30);
        verify::Options o;
        o.resolution = 0.1;
        const verify::Report report = verify::verifyPlan(plan, o);
        QVERIFY2(!report.fatal(), report.findings.empty() ? "" : verify::describe(report.findings.front(), plan).c_str());
    }

    // A notch R3.87 in a run tilted 3° (the generator's seed 4 before it
    // was made smaller): its two runs' parallels, past the notch's radius,
    // lie on carriers 1e-6 apart (the figure's rounding) and their
    // rounding missed; every end mill was refused "cutting 7.4 mm into it
    // at the contour's start". Now bridged, proved, and verified clean.
    void notchInATiltedRun()
    {
        const std::string figure = "P1 = POINT/-15, 30.04537\nP2 = POINT/56.132217, 33.691382\n"
                                   "P3 = POINT/60, 33.889632\nP4 = POINT/63.867783, 34.087882\n"
                                   "P5 = POINT/135, 37.733894\nC1 = CIRCLE/CENTER, P3, RADIUS, 3.87286\n"
                                   "L1 = LINE/P1, P2\nL2 = LINE/P4, P5\n"
                                   "K1 = CONTOUR/P1, L1, XSMALL, CCLW, C1, XLARGE, L2, P5";
        const Plan plan = planJob(withFigure(figure, 7.3, 6.3), TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY2(plan.ok(), messages(plan.diagnostics).c_str());
        QCOMPARE(plan.steps.front().tool->toolId, 25);  // Ø6: R3 within the notch's 3.87; Ø8 is not
        verify::Options o;
        o.resolution = 0.1;
        const verify::Report report = verify::verifyPlan(plan, o);
        QVERIFY2(!report.fatal(), report.findings.empty() ? "" : verify::describe(report.findings.front(), plan).c_str());
    }

    // A notch no end mill fits: the arc is named, where it is, and by how
    // much the smallest end mill is too large. Before: on "cornerRadius", a
    // field SIDE does not have, naming no arc.
    void tooTightNotchNamesTheArc()
    {
        const Diagnostics ds = checkJob(withFigure(notchFigure(0.8), 14, 12), TechnologyTable::builtIn(), defaultToolLibrary());
        QCOMPARE(ds.size(), std::size_t{1});
        QCOMPARE(ds[0].field, std::string("contour"));
        QCOMPARE(ds[0].message, std::string("the arc of K1 at (60 mm, 59.2 mm) curves round the tool's side with radius "
                                            "0.8 mm: the smallest end mill, T21 (flat end mill Ø2 mm), is 0.2 mm too "
                                            "large for it (an arc of radius 1 mm or more would let it fit)"));
    }

    // An open contour whose end comes back 1.5 mm from its start's run:
    // every end mill fits its arcs, none passes there. Said on the contour,
    // where and how deep the smallest would cut. Before: "T21 ... is the
    // nearest, but  along K1" (the reason left empty).
    void channelNoEndMillPassesIsNamed()
    {
        const std::string figure = "P1 = POINT/-15, 20\nP2 = POINT/100, 40\nP3 = POINT/50, 21.5\n"
                                   "L1 = LINE/P1, ATANGL, 0\nC1 = CIRCLE/CENTER, P2, RADIUS, 20\n"
                                   "L2 = LINE/PARLEL, L1, YLARGE, 40\nL3 = LINE/P3, ATANGL, 90\n"
                                   "K1 = CONTOUR/P1, L1, CCLW, C1, L2, ROUND, 5, L3, P3";
        const Plan plan = planJob(withFigure(figure, 5, 5), TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(!plan.ok());
        QCOMPARE(plan.diagnostics.front().field, std::string("contour"));
        const std::string m = plan.diagnostics.front().message;
        QVERIFY2(m.starts_with("K1 leaves no room near (") &&
                     m.find("even the smallest end mill that fits its arcs, T21 (flat end mill Ø2 mm), would cut") != std::string::npos,
                 m.c_str());
    }

    void oracleOnTheTapes_data()
    {
        QTest::addColumn<QString>("sample");
        QTest::addColumn<int>("arcs");
        // Open: one rounding arc a pass (2 layers x 2 passes, 1 finishing).
        // Boss: 4 corners and 2 leads a loop (2 layers x 2 passes, 2 incisions).
        QTest::newRow("open") << "side-open-contour.taiwa" << 5;
        QTest::newRow("boss") << "side-boss.taiwa" << 36;
    }
    void oracleOnTheTapes()
    {
        QFETCH(QString, sample);
        QFETCH(int, arcs);
        const QString job = sourcePath("resources/samples/" + sample);
        QTemporaryDir out;
        const auto r = runTaiwa({"export", job, "--out", out.path(), "--dialect", "linuxcnc", "--no-pictures", "--resolution", "0.25"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const std::string nc = readFile(QDir(out.path()).filePath(QFileInfo(job).completeBaseName() + ".nc"));
        const Rs274Result run = runRs274(nc);
        QVERIFY2(run.ok, qPrintable(run.errors));
        const Plan plan = planJob(*readJobFile(job.toStdString()).job, TechnologyTable::builtIn(), defaultToolLibrary());
        QVERIFY(plan.ok());
        const ModuleInput& module = plan.mmJob.units[0].module;
        const SideMill& unit = module.as<SideMill>();
        const Contour& contour = *unit.path;
        const double T = unit.depth, W = unit.width, a2 = plan.technology.alpha2;

        int arcCount = 0;
        std::map<int, std::set<long>> levels;  // step -> cutting Z levels (µm)
        std::map<int, double> nearest;         // step -> closest approach of the tool's edge to the wall
        for (const auto& m : run.moves) {
            if (m.kind == CanonMove::Traverse) {
                QVERIFY2(m.end.z >= -1e-9, "a rapid below the stock top");
                continue;
            }
            if (m.kind == CanonMove::Arc) ++arcCount;
            const Step& s = plan.steps[static_cast<std::size_t>(m.step - 1)];
            const Tool& tool = *plan.tool(s.tool->toolId);
            std::vector<Point3> pts{m.start, m.end};
            if (m.kind == CanonMove::Arc) pts = sampleArc(m, 0.02);
            for (const Point3& p : pts) {
                const double g = *sideGouge(module, tool, p);
                QVERIFY2(g <= kTol, qPrintable(QString("gouge of %1 mm at X%2 Y%3 Z%4").arg(g).arg(p.x).arg(p.y).arg(p.z)));
                if (p.z < 0) {
                    const double edge = -(*sideWallDistance(module, p)) - tool.radius();
                    nearest[m.step] = std::min(nearest.count(m.step) ? nearest[m.step] : 1e9, edge);
                }
            }
            if (std::abs(m.start.z - m.end.z) < 1e-9 && m.end.z < 0) levels[m.step].insert(std::lround(-m.end.z * 1000));
        }
        QCOMPARE(arcCount, arcs);
        QCOMPARE(plan.steps.size(), std::size_t{2});
        for (std::size_t k = 0; k < plan.steps.size(); ++k) {
            const Step& s = plan.steps[k];
            const int n = static_cast<int>(k) + 1;
            const Tool& tool = *plan.tool(s.tool->toolId);
            const double R = tool.radius();
            // Layers and incisions of at most γ·D, equal, the last at T.
            const int count = millingOf(s).multiIncision ? static_cast<int>(std::ceil(T / (plan.technology.gamma * tool.diameter) - 1e-9)) : 1;
            std::set<long> want;
            for (int i = 1; i <= count; ++i) want.insert(std::lround(T * i / count * 1000));
            QCOMPARE(levels[n], want);
            const bool finishing = s.machiningType == MachiningType::SideFinishing;
            // Roughing leaves exactly α2; finishing reaches the wall.
            QVERIFY2(std::abs(nearest[n] - (finishing ? 0.0 : a2)) < kTol, qPrintable(QString("step %1 comes %2 from the wall").arg(n).arg(nearest[n])));
            if (!finishing) continue;
            // Every point of the wall touched by the finishing disc at each of
            // its depths: the centre's nearest pass exactly R away.
            for (const long level : want) {
                const auto pieces = piecesAt(run.moves, n, -static_cast<double>(level) / 1000.0);
                for (const ContourSegment& seg : contour.segments) {
                    const int samples = std::max(2, static_cast<int>(seg.length() / 0.25));
                    for (int i = 0; i <= samples; ++i) {
                        const Point2 q = seg.at(static_cast<double>(i) / samples);
                        const double d = nearestPiece(pieces, q);
                        QVERIFY2(std::abs(d - R) < kTol, qPrintable(QString("wall point (%1, %2) is %3 from the finishing pass at Z-%4")
                                                                        .arg(q.x).arg(q.y).arg(d).arg(static_cast<double>(level) / 1000.0)));
                    }
                }
            }
        }
        // The band W on the tool's side, inside the stock, swept at T.
        const Stock& st = plan.mmJob.stock;
        std::vector<std::pair<Point2, Point2>> bottom;
        for (int n = 1; n <= 2; ++n) {
            const auto p = piecesAt(run.moves, n, -T);
            bottom.insert(bottom.end(), p.begin(), p.end());
        }
        const double R = plan.tool(plan.steps[0].tool->toolId)->radius();
        int inBand = 0;
        for (double x = st.x + 0.25; x < st.x + st.width; x += 0.5)
            for (double y = st.y + 0.25; y < st.y + st.length; y += 0.5) {
                const double d = *sideWallDistance(module, {x, y, -T});
                if (d > 0 || d < -W) continue;
                ++inBand;
                QVERIFY2(nearestPiece(bottom, {x, y}) <= R + 1e-9, qPrintable(QString("(%1, %2) in the band not swept at T").arg(x).arg(y)));
            }
        QVERIFY(inBand > 1000);
    }
};

QTEST_APPLESS_MAIN(TestSideMilling)
#include "test_side_milling.moc"
