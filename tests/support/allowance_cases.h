// Helpers of the grinding-allowance tests (test_grinding_allowance.cpp,
// test_relief_grooves.cpp): profile rows and allowance rows as a test types
// them, the stepped shaft most cases use, the deformation of a profile, and
// the deformed chain compared edge by edge (id, origin, ends, arc centre) to
// 1 nm. Header only.
#pragma once

#include "model/turned_geometry.h"
#include "turning/allowance.h"
#include "turning/profile_resolve.h"

#include <QtTest>

#include <optional>
#include <string>
#include <vector>

namespace taiwa::test {

using namespace taiwa::turning;

inline constexpr double kTol = 1e-6;  // mm: well inside 1 µm

inline ProfileRow line(int id, double x, double z, CornerKind corner = CornerKind::None, double size = 0.0)
{
    ProfileRow r;
    r.id = id;
    r.x = x;
    r.z = z;
    r.corner = corner;
    r.cornerSize = size;
    return r;
}

// The stepped shaft most cases use: front face E1 up to Ø40 at Z0, the Ø40
// cylinder E2 to Z-50, the shoulder E3 up to Ø60, the Ø60 cylinder E4 to Z-80.
inline TurnedProfile steppedShaft()
{
    TurnedProfile p;
    p.rows = {line(1, 40, 0), line(2, 40, -50), line(3, 60, -50), line(4, 60, -80)};
    return p;
}

inline AllowanceRow row(const std::string& edge, double a)
{
    AllowanceRow r;
    r.edge = edge;
    r.allowance = a;
    return r;
}

struct Expect {
    std::string id;
    Origin origin;
    ZR a, b;
    std::optional<ZR> centre = std::nullopt;  // arcs
};

inline Deformation deform(const TurnedProfile& p, const AllowanceOptions& o = {})
{
    const Resolution r = resolveProfile(p);
    for (const auto& pr : r.problems) qWarning("%s: %s", pr.field.c_str(), pr.message.c_str());
    return applyAllowances(r.profile, p.allowances, o);
}

inline QString describe(const DeformedProfile& d)
{
    QString s;
    for (const auto& e : d.edges)
        s += QString("  %1 %2 (%3, %4) -> (%5, %6)\n")
                 .arg(QString::fromStdString(e.id), toKey(e.origin))
                 .arg(e.geometry.a.z)
                 .arg(e.geometry.a.r)
                 .arg(e.geometry.b.z)
                 .arg(e.geometry.b.r);
    return s;
}

inline void expectChain(const Deformation& d, const std::vector<Expect>& want)
{
    for (const auto& p : d.problems) qWarning("%s: %s", p.field.c_str(), p.message.c_str());
    QVERIFY(d.ok());
    const auto& got = d.profile.edges;
    QVERIFY2(got.size() == want.size(), qPrintable("got\n" + describe(d.profile)));
    for (std::size_t i = 0; i < want.size(); ++i) {
        const auto& g = got[i];
        const auto& w = want[i];
        const QString where = QString("edge %1 of\n%2").arg(i).arg(describe(d.profile));
        QVERIFY2(g.id == w.id, qPrintable("id " + QString::fromStdString(g.id) + " at " + where));
        QVERIFY2(g.origin == w.origin, qPrintable("origin at " + where));
        QVERIFY2(dist(g.geometry.a, w.a) < kTol && dist(g.geometry.b, w.b) < kTol, qPrintable("ends at " + where));
        QCOMPARE(g.geometry.arc, w.centre.has_value());
        if (w.centre) QVERIFY2(dist(g.geometry.centre, *w.centre) < kTol, qPrintable("centre at " + where));
    }
}

inline const FieldProblem* problemOn(const std::vector<FieldProblem>& ps, const std::string& field)
{
    for (const auto& p : ps)
        if (p.field == field) return &p;
    return nullptr;
}

}  // namespace taiwa::test
