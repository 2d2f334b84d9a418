// Module SURFACE's plans against an oracle the program does not use
// (docs/surfaces.md, "The verifier's cavity and the edges"): every move of
// both steps (rapids, plunges and cuts, sampled at their ends and middles)
// keeps the ball's centre off the exact finishing surface, OpenCASCADE's
// bilinear patches between the rulings (GeomAPI_ProjectPointOnSurf on each
// patch's parameter range, the patches' straight edges by hand): finishing at least r − 1 µm
// away, roughing at least r + allowance − 1 µm; and the verifying simulation
// (`taiwa verify`'s verifyPlan) finds nothing fatal. On the sample
// tests/data/surface-ruled.taiwa and on seeded random ruled surfaces between
// random curve pairs within the module's limits. Before the fix the sample
// verified with 372 gouges (2.68 mm deep, the ball hanging over curve 1's
// edge) and 29 rapids into stock. Negative control: the finishing lowered by
// 5 µm is caught by the oracle.
#include "modules/surface/surface.h"
#include "occt/surface_curves.h"
#include "support/support.h"
#include "support/surface_oracle.h"

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "tools/tool_library.h"
#include "verify/verify.h"

#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <nlohmann/json.hpp>

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

using namespace taiwa;
using namespace taiwa::test;
using json = nlohmann::json;

namespace {

json sample() { return json::parse(readFile(dataPath("surface-ruled.taiwa"))); }

Plan planOf(const json& j)
{
    const JobReadResult r = readJob(j.dump());
    if (!r.job) qFatal("%s", r.diagnostics.empty() ? "unreadable" : r.diagnostics.front().message.c_str());
    return planJob(*r.job, TechnologyTable::builtIn(), defaultToolLibrary());
}

double segmentDistance(const gp_Pnt& p, const Point3& a, const Point3& b, gp_Pnt& foot)
{
    const double ex = b.x - a.x, ey = b.y - a.y, ez = b.z - a.z;
    const double l2 = ex * ex + ey * ey + ez * ez;
    double t = l2 > 0 ? ((p.X() - a.x) * ex + (p.Y() - a.y) * ey + (p.Z() - a.z) * ez) / l2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    foot = gp_Pnt(a.x + t * ex, a.y + t * ey, a.z + t * ez);
    return p.Distance(foot);
}

// The exact finishing surface: one bilinear patch between each two
// neighbouring rulings, as OpenCASCADE's Bézier surfaces of degree 1 × 1.
class ExactSurface {
public:
    explicit ExactSurface(const surface::RuledSurface& s) : s_(s)
    {
        // One B-spline of degree 1 × 1 through the rulings' ends (u along
        // the curves, knot i at ruling i; v along the rulings), projected on
        // one patch [i, i + 1] × [0, 1] at a time, where it is smooth.
        const int n = static_cast<int>(s.first.size());
        TColgp_Array2OfPnt poles(1, n, 1, 2);
        TColStd_Array1OfReal uk(1, n), vk(1, 2);
        TColStd_Array1OfInteger um(1, n), vm(1, 2);
        for (int i = 0; i < n; ++i) {
            const Point3 a = s.first[static_cast<std::size_t>(i)], b = s.second[static_cast<std::size_t>(i)];
            poles(i + 1, 1) = gp_Pnt(a.x, a.y, a.z);
            poles(i + 1, 2) = gp_Pnt(b.x, b.y, b.z);
            uk(i + 1) = i;
            um(i + 1) = i == 0 || i == n - 1 ? 2 : 1;
        }
        vk(1) = 0, vk(2) = 1, vm(1) = 2, vm(2) = 2;
        surface_ = new Geom_BSplineSurface(poles, uk, vk, um, vm, 1, 1);
        for (int i = 0; i + 1 < n; ++i) {
            const std::size_t k = static_cast<std::size_t>(i);
            auto proj = std::make_unique<GeomAPI_ProjectPointOnSurf>();
            proj->Init(surface_, i, i + 1.0, 0.0, 1.0);
            Patch p{std::move(proj), {s.first[k], s.first[k + 1], s.second[k + 1], s.second[k]}, 1e300, 1e300, -1e300, -1e300};
            for (const Point3& c : p.corners)
                p.x0 = std::min(p.x0, c.x), p.y0 = std::min(p.y0, c.y), p.x1 = std::max(p.x1, c.x), p.y1 = std::max(p.y1, c.y);
            patches_.push_back(std::move(p));
        }
    }
    // The signed distance of q from the surface (negative when q is below
    // its nearest point), looking at patches within `reach` in XY; +1e9 when
    // none is.
    double signedDistance(const Point3& q, double reach)
    {
        const gp_Pnt p(q.x, q.y, q.z);
        double best = 1e9;
        gp_Pnt bestFoot;
        for (Patch& pa : patches_) {
            if (q.x < pa.x0 - reach || q.x > pa.x1 + reach || q.y < pa.y0 - reach || q.y > pa.y1 + reach) continue;
            pa.proj->Perform(p);
            if (pa.proj->NbPoints() > 0 && pa.proj->LowerDistance() < best) {
                best = pa.proj->LowerDistance();
                bestFoot = pa.proj->NearestPoint();
            }
            for (int e = 0; e < 4; ++e) {
                gp_Pnt foot;
                const double d = segmentDistance(p, pa.corners[e], pa.corners[(e + 1) % 4], foot);
                if (d < best) best = d, bestFoot = foot;
            }
        }
        if (best >= 1e9) return best;
        return q.z >= bestFoot.Z() ? best : -best;
    }

private:
    struct Patch {
        std::unique_ptr<GeomAPI_ProjectPointOnSurf> proj;
        Point3 corners[4];
        double x0, y0, x1, y1;
    };
    surface::RuledSurface s_;
    Handle(Geom_BSplineSurface) surface_;
    std::vector<Patch> patches_;
};

struct Clearance {
    double nearest = 1e9;  // the smallest signed distance less the ball's radius [mm]
    int samples = 0;
    Point3 where{};  // the ball's nose there
    int move = -1;
};

// Every move of the step sampled at its middle and end: the ball's centre's
// signed distance from the exact surface, less its radius.
Clearance clearanceOf(const Step& step, double r, ExactSurface& exact, double lower = 0.0)
{
    Clearance c;
    Point3 at = step.path->start;
    for (std::size_t k = 0; k < step.path->moves.size(); ++k) {
        const Move& m = step.path->moves[k];
        Point3 end = m.end;
        if (m.kind == MoveKind::Feed) end.z -= lower;
        for (double t : {0.5, 1.0}) {
            const Point3 q{at.x + t * (end.x - at.x), at.y + t * (end.y - at.y), at.z + t * (end.z - at.z) + r};
            const double d = exact.signedDistance(q, r + 0.5);
            if (d >= 1e8) continue;
            ++c.samples;
            if (d - r < c.nearest) c.nearest = d - r, c.where = {q.x, q.y, q.z - r}, c.move = static_cast<int>(k);
        }
        at = end;
    }
    return c;
}

struct Outcome {
    Clearance roughing, finishing;
    int fatal = 0;
    std::string first;
};

Outcome judge(const json& j, double resolution)
{
    Outcome o;
    const Plan p = planOf(j);
    if (!p.ok() || p.steps.size() != 2) qFatal("the surface job does not plan");
    const JobReadResult r = readJob(j.dump());
    const SurfaceUnit& u = r.job->units[0].module.as<SurfaceUnit>();
    const int m = u.m ? *u.m : 0;
    ExactSurface exact(finishingSurface(u, m));
    const Tool& tool = *p.tool(p.steps[0].tool->toolId);
    o.roughing = clearanceOf(p.steps[0], tool.radius(), exact);
    o.finishing = clearanceOf(p.steps[1], tool.radius(), exact);
    verify::Options vo;
    vo.resolution = resolution;
    for (const verify::Finding& f : verify::verifyPlan(p, vo).findings)
        if (f.fatal()) {
            if (o.fatal++ == 0) o.first = std::string(verify::toKey(f.kind)) + " " + std::to_string(f.size);
        }
    qInfo("D%g, roughing: %d samples, nearest %+.4f mm off the surface less r (allowance %g); finishing: %d "
          "samples, nearest %+.4f mm (move %d, X%.3f Y%.3f Z%.4f); %d fatal findings %s",
          tool.diameter, o.roughing.samples, o.roughing.nearest, u.allowance, o.finishing.samples,
          o.finishing.nearest, o.finishing.move, o.finishing.where.x, o.finishing.where.y, o.finishing.where.z, o.fatal,
          o.first.c_str());
    return o;
}

json randomPoint(std::mt19937& g, double x, double y0, double y1)
{
    std::uniform_real_distribution<double> y(y0, y1), z(-14.0, -4.0);
    return json::array({x, y(g), z(g)});
}

}  // namespace

class TestSurfacePlanOracle : public QObject {
    Q_OBJECT

private slots:
    void theSampleKeepsOffTheSurfaceAndVerifiesClean()
    {
        const json j = sample();
        const Outcome o = judge(j, verify::kDefaultResolution);
        QVERIFY(o.finishing.samples > 20000 && o.roughing.samples > 10000);
        QVERIFY2(o.finishing.nearest >= -0.001, qPrintable(QString::number(o.finishing.nearest)));
        QVERIFY(o.finishing.nearest <= 0.01);  // the ball touches it somewhere
        QVERIFY2(o.roughing.nearest >= 0.3 - 0.001, qPrintable(QString::number(o.roughing.nearest)));
        QVERIFY2(o.fatal == 0, o.first.c_str());
    }

    void theOracleCatchesAFinishingFiveMicronsTooDeep()
    {
        const json j = sample();
        const Plan p = planOf(j);
        QVERIFY(p.ok());
        const JobReadResult r = readJob(j.dump());
        const SurfaceUnit& u = r.job->units[0].module.as<SurfaceUnit>();
        ExactSurface exact(finishingSurface(u, *u.m));
        const double rr = p.tool(p.steps[1].tool->toolId)->radius();
        const Clearance lowered = clearanceOf(p.steps[1], rr, exact, 0.005);
        qInfo("lowered 5 µm: nearest %+.4f mm", lowered.nearest);
        QVERIFY(lowered.nearest < -0.003);
    }

    // Random curve pairs, one seed a row: curve 1 of 2 to 4 points near the
    // front, curve 2 of 2 or 3 near the back, Z −14 to −4, N 2 to 6, M N + 2
    // to 30, allowance 0.2 to 0.5; a job the module refuses (a bend tighter
    // than any ball) is drawn again.
    void randomRuledSurfacesKeepOffAndVerifyClean_data()
    {
        QTest::addColumn<int>("seed");
        for (int seed : {1, 2, 3}) QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed;
    }
    void randomRuledSurfacesKeepOffAndVerifyClean()
    {
        QFETCH(int, seed);
        std::mt19937 g(static_cast<unsigned>(seed));
        for (int tries = 0; tries < 20; ++tries) {
            json j = sample();
            json& u = j["units"][0];
            const int n1 = std::uniform_int_distribution<int>(2, 4)(g), n2 = std::uniform_int_distribution<int>(2, 3)(g);
            json c1 = json::array(), c2 = json::array();
            for (int i = 0; i < n1; ++i) c1.push_back(randomPoint(g, 5.0 + 110.0 * i / (n1 - 1), 5, 22));
            for (int i = 0; i < n2; ++i) c2.push_back(randomPoint(g, 5.0 + 110.0 * i / (n2 - 1), 58, 75));
            u["curve1"] = {{"points", c1}};
            u["curve2"] = {{"points", c2}};
            const int n = std::uniform_int_distribution<int>(2, 6)(g);
            u["n"] = n;
            u["m"] = std::uniform_int_distribution<int>(n + 2, 30)(g);
            u["allowance"] = std::round(std::uniform_real_distribution<double>(0.2, 0.5)(g) * 100) / 100;
            u["scallop"] = 0.15;
            if (!planOf(j).ok()) continue;
            qInfo("curve 1 %s, curve 2 %s, N %d, M %d", c1.dump().c_str(), c2.dump().c_str(), n, u["m"].get<int>());
            const Outcome o = judge(j, 0.2);
            QVERIFY2(o.finishing.nearest >= -0.001, qPrintable(QString::number(o.finishing.nearest)));
            QVERIFY2(o.roughing.nearest >= u["allowance"].get<double>() - 0.001,
                     qPrintable(QString::number(o.roughing.nearest)));
            QVERIFY2(o.fatal == 0, o.first.c_str());
            return;
        }
        QFAIL("twenty random jobs refused");
    }
};

QTEST_GUILESS_MAIN(TestSurfacePlanOracle)
#include "test_surface_plan_oracle.moc"
