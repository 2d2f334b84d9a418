// Random valid turned profiles and the check that the deformed profile
// never lies inside the part (turned_generator.h).
#include "support/turned_generator.h"

#include "model/turned_geometry.h"
#include "turning/profile_resolve.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace taiwa::test {

using namespace turning;

namespace {

// splitmix64: the same numbers on every machine and library. The seed is
// mixed first, so that neighbouring seeds do not start one number apart in
// the same stream.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : s_(seed ^ 0x632BE59BD9B4E019ull) { s_ = next(); }
    std::uint64_t next()
    {
        std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform(double a, double b) { return a + (b - a) * static_cast<double>(next() >> 11) * 0x1.0p-53; }
    int between(int a, int b) { return a + static_cast<int>(next() % static_cast<std::uint64_t>(b - a + 1)); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

private:
    std::uint64_t s_;
};

// As an operator types them: to 0.01 mm.
double typed(double v) { return std::round(v * 100.0) / 100.0; }

ProfileRow element(int id, ElementKind kind, double r, double z)
{
    ProfileRow row;
    row.id = id;
    row.kind = kind;
    row.x = typed(2.0 * r);
    row.z = typed(z);
    return row;
}

// One chain toward the chuck (Z never rising), so that it cannot cross itself.
// `lathe`: with the shapes planning trips on added (generateLathePart); off,
// the draws are the same as before they existed.
TurnedProfile drawProfile(Rng& g, bool lathe = false, std::vector<std::string>* shapes = nullptr)
{
    TurnedProfile p;
    const bool inner = g.chance(0.3);
    p.side = inner ? ProfileSide::Inner : ProfileSide::Outer;
    const double rMin = inner ? 4.0 : 3.0, rMax = inner ? 25.0 : 28.0;
    double r = typed(inner ? g.uniform(10.0, 25.0) : g.uniform(6.0, 20.0)), z = 0.0;
    int id = 1;
    bool lastFace = !inner;
    if (inner) {
        p.startX = 2.0 * r;  // the bore's mouth in the front face
    } else {
        p.rows.push_back(element(id++, ElementKind::Line, r, 0.0));  // the front face from the axis
    }
    const auto within = [&](double dr) { return std::clamp(r + dr, rMin, rMax) - r; };
    const int n = g.between(2, 8);
    for (int k = 0; k < n; ++k) {
        const double pick = g.uniform(0.0, 1.0);
        double dr = 0.0, dz = 0.0;
        ElementKind kind = ElementKind::Line;
        std::optional<double> radius;
        bool face = false;
        if (lathe && k + 1 < n && g.chance(0.1)) {
            // An acute ridge: a taper rising 45-75° then one falling 30-60°
            // (the roughing insert's rapids out of the valley behind it).
            const double deg = std::numbers::pi / 180.0;
            const double up = g.uniform(45.0, 75.0) * deg, down = g.uniform(30.0, 60.0) * deg;
            const double h = std::min(typed(g.uniform(1.5, 6.0)), (inner ? r - rMin : rMax - r) - 0.5);
            if (h >= 1.0) {
                const double rise = inner ? -h : h;
                const double dz1 = std::max(0.05, typed(h / std::tan(up))), dz2 = std::max(0.05, typed(h / std::tan(down)));
                r += rise;
                z -= dz1;
                p.rows.push_back(element(id++, ElementKind::Line, r, z));
                r -= rise;
                z -= dz2;
                p.rows.push_back(element(id++, ElementKind::Line, r, z));
                if (shapes) shapes->push_back("ridge");
                lastFace = false;
                ++k;
                continue;
            }
        }
        if (pick < 0.25) {  // a cylinder
            dz = typed(g.uniform(2.0, 20.0));
        } else if (pick < 0.4) {  // a taper
            dz = typed(g.uniform(2.0, 15.0));
            dr = typed(within(g.uniform(-0.7, 0.7) * dz));
        } else if (pick < 0.6 && !lastFace) {  // a shoulder, up or down
            dr = typed(within(g.uniform(1.0, 8.0) * (g.chance(0.6) ? 1.0 : -1.0)));
            face = std::abs(dr) >= 0.5;
            if (!face) {  // no room to rise or fall: a cylinder
                dz = typed(g.uniform(2.0, 10.0));
                dr = 0.0;
            }
        } else {  // an arc, convex or concave
            dz = typed(g.uniform(2.0, 12.0));
            dr = typed(within(g.uniform(-0.6, 0.6) * dz));
            kind = g.chance(0.5) ? ElementKind::ArcCW : ElementKind::ArcCCW;
            radius = typed(std::hypot(dz, dr) * g.uniform(0.55, 2.5));
        }
        r += dr;
        z -= dz;
        ProfileRow row = element(id++, kind, r, z);
        row.radius = radius;
        p.rows.push_back(row);
        lastFace = face;
    }
    // Chamfers and roundings between lines.
    for (std::size_t i = 0; i + 1 < p.rows.size(); ++i)
        if (p.rows[i].kind == ElementKind::Line && p.rows[i + 1].kind == ElementKind::Line && g.chance(0.25)) {
            p.rows[i].corner = g.chance(0.5) ? CornerKind::Chamfer : CornerKind::Rounding;
            p.rows[i].cornerSize = typed(g.uniform(0.2, 1.5));
        }
    if (!lathe) return p;
    // A rounding at the front corner (the face into the first element), and
    // roundings at concave corners between lines: fillets smaller and larger
    // than the library's nose radii (0.4 and 0.8 mm).
    if (!inner && p.rows.size() > 1 && p.rows[1].kind == ElementKind::Line && g.chance(0.35)) {
        p.rows[0].corner = CornerKind::Rounding;
        p.rows[0].cornerSize = typed(g.uniform(0.2, 2.0));
        if (shapes) shapes->push_back("front rounding");
    }
    ZR at{0.0, inner ? p.startX / 2.0 : 0.0};
    for (std::size_t i = 0; i + 1 < p.rows.size(); ++i) {
        const ZR a = at, b{p.rows[i].z, p.rows[i].x / 2.0}, c{p.rows[i + 1].z, p.rows[i + 1].x / 2.0};
        at = b;
        if (p.rows[i].kind != ElementKind::Line || p.rows[i + 1].kind != ElementKind::Line || dist(a, b) < 1e-9 || dist(b, c) < 1e-9)
            continue;
        const double turn = cross(b - a, c - b);
        if (!(inner ? turn > 1e-9 : turn < -1e-9) || !g.chance(0.5)) continue;
        p.rows[i].corner = CornerKind::Rounding;
        p.rows[i].cornerSize = typed(g.chance(0.5) ? g.uniform(0.1, 0.8) : g.uniform(0.8, 3.0));
        if (shapes) shapes->push_back(p.rows[i].cornerSize < 0.4 ? "fillet under 0.4" : p.rows[i].cornerSize < 0.8 ? "fillet under 0.8" : "fillet");
    }
    return p;
}

// The edges at a concave corner of the part (more likely to get grooves).
std::vector<std::size_t> atConcaveCorners(const ResolvedProfile& rp)
{
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i + 1 < rp.edges.size(); ++i) {
        const double turn = cross(tangentAtEnd(rp.edges[i].geometry), tangentAtStart(rp.edges[i + 1].geometry));
        if (rp.side == ProfileSide::Outer ? turn < -1e-9 : turn > 1e-9) {
            out.push_back(i);
            out.push_back(i + 1);
        }
    }
    return out;
}

std::vector<AllowanceRow> drawAllowances(Rng& g, const ResolvedProfile& rp)
{
    const std::vector<std::size_t> concave = atConcaveCorners(rp);
    const int count = g.between(1, std::min<int>(4, static_cast<int>(rp.edges.size())));
    std::vector<std::size_t> picked;
    std::vector<AllowanceRow> rows;
    for (int tries = 0; static_cast<int>(picked.size()) < count && tries < 50; ++tries) {
        const std::size_t i = !concave.empty() && g.chance(0.6)
                                  ? concave[static_cast<std::size_t>(g.between(0, static_cast<int>(concave.size()) - 1))]
                                  : static_cast<std::size_t>(g.between(0, static_cast<int>(rp.edges.size()) - 1));
        if (std::find(picked.begin(), picked.end(), i) != picked.end()) continue;
        picked.push_back(i);
        AllowanceRow a;
        a.edge = rp.edges[i].id;
        a.allowance = typed(g.uniform(0.05, 0.5));
        if (g.chance(0.25)) a.adjustment = typed(g.uniform(0.0, 1.0));
        const double kind = g.uniform(0.0, 1.0);
        a.groove = kind < 0.4    ? GrooveKind::Auto
                   : kind < 0.5  ? GrooveKind::None
                   : kind < 0.65 ? GrooveKind::Lateral
                   : kind < 0.8  ? GrooveKind::Longitudinal
                                 : GrooveKind::Ring;
        if (g.chance(0.75)) a.grooveWidth = typed(g.uniform(0.3, 3.0));
        if (g.chance(0.3)) a.grooveDepth = typed(g.uniform(0.05, 0.8));
        rows.push_back(a);
    }
    return rows;
}

// An arc split where its tangent runs along Z, so that R changes one way along each piece.
std::vector<Segment> monotonePieces(const Segment& s)
{
    if (!s.arc) return {s};
    std::vector<std::pair<double, ZR>> cuts;
    for (ZR x : {ZR{s.centre.z, s.centre.r + s.radius}, ZR{s.centre.z, s.centre.r - s.radius}}) {
        const double t = parameterOf(s, x);
        if (t > 1e-9 && t < length(s) - 1e-9) cuts.push_back({t, x});
    }
    std::sort(cuts.begin(), cuts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Segment> out;
    ZR from = s.a;
    for (const auto& c : cuts) {
        out.push_back(piece(s, from, c.second));
        from = c.second;
    }
    out.push_back(piece(s, from, s.b));
    return out;
}

// Crossing number along +Z at the point's radius, on the exact lines and arcs.
bool insidePart(const std::vector<Segment>& loop, ZR p)
{
    bool in = false;
    for (const Segment& s : loop)
        for (const Segment& m : monotonePieces(s)) {
            if ((m.a.r > p.r) == (m.b.r > p.r)) continue;
            double z = 0.0;
            if (!m.arc) {
                z = m.a.z + (p.r - m.a.r) * (m.b.z - m.a.z) / (m.b.r - m.a.r);
            } else {
                const double dr = p.r - m.centre.r;
                const double h = std::sqrt(std::max(0.0, m.radius * m.radius - dr * dr));
                z = m.centre.z + (midpoint(m).z >= m.centre.z ? h : -h);
            }
            if (z > p.z) in = !in;
        }
    return in;
}

double distanceTo(const Segment& s, ZR p)
{
    if (!s.arc) {
        const ZR d = s.b - s.a;
        const double l2 = dot(d, d);
        const double t = l2 > 0.0 ? std::clamp(dot(p - s.a, d) / l2, 0.0, 1.0) : 0.0;
        return dist(p, s.a + t * d);
    }
    const ZR d = p - s.centre;
    const double n = norm(d);
    if (n > 1e-12 && contains(s, s.centre + (s.radius / n) * d, 1e-9)) return std::abs(n - s.radius);
    return std::min(dist(p, s.a), dist(p, s.b));
}

}  // namespace

GeneratedProfile generateTurnedProfile(std::uint64_t seed)
{
    Rng g(seed);
    GeneratedProfile out;
    out.seed = seed;
    for (out.attempts = 1; out.attempts <= 100; ++out.attempts) {
        TurnedProfile p = drawProfile(g);
        const Resolution r = resolveProfile(p);
        if (!r.ok() || r.profile.edges.size() < 2) continue;
        p.allowances = drawAllowances(g, r.profile);
        out.profile = std::move(p);
        out.options.noseRadius = g.chance(0.5) ? 0.4 : 0.8;
        out.options.toolName = "T102";
        return out;
    }
    return out;  // no rows: nothing resolved in 100 draws
}

GeneratedProfile generateLathePart(std::uint64_t seed)
{
    Rng g(seed ^ 0x5EEDF00D1A7E0000ull);
    GeneratedProfile out;
    out.seed = seed;
    for (out.attempts = 1; out.attempts <= 100; ++out.attempts) {
        std::vector<std::string> shapes;
        TurnedProfile p = drawProfile(g, true, &shapes);
        const Resolution r = resolveProfile(p);
        if (!r.ok() || r.profile.edges.size() < 2) continue;
        if (g.chance(0.6)) p.allowances = drawAllowances(g, r.profile);
        out.profile = std::move(p);
        out.shapes = std::move(shapes);
        out.options.noseRadius = 0.4;
        out.options.toolName = "T102";
        return out;
    }
    return out;
}

Intrusion deepestIntoPart(const ResolvedProfile& part, const DeformedProfile& deformed)
{
    std::vector<Segment> loop;
    double rMax = 0.0;
    for (const auto& e : part.edges) {
        loop.push_back(e.geometry);
        rMax = std::max({rMax, e.geometry.a.r, e.geometry.b.r, e.geometry.arc ? e.geometry.centre.r + e.geometry.radius : 0.0});
    }
    for (const auto& e : deformed.edges) rMax = std::max({rMax, e.geometry.a.r, e.geometry.b.r});
    for (const Segment& c : closure(part, rMax + 2.0)) loop.push_back(c);
    Intrusion worst;
    for (const auto& e : deformed.edges) {
        const Segment& s = e.geometry;
        const double len = length(s);
        // Every piece between crossings with the part gets its middle looked
        // at, besides points every 0.05 mm.
        std::vector<double> ts{0.0, len};
        for (const Segment& q : loop)
            for (ZR x : crossings(s, q)) ts.push_back(std::clamp(parameterOf(s, x), 0.0, len));
        const int n = std::clamp(static_cast<int>(len / 0.05), 8, 200);
        for (int i = 1; i < n; ++i) ts.push_back(len * i / n);
        std::sort(ts.begin(), ts.end());
        const std::size_t ends = ts.size();
        for (std::size_t i = 0; i + 1 < ends; ++i) ts.push_back(0.5 * (ts[i] + ts[i + 1]));
        for (double t : ts) {
            const ZR p = pointAt(s, t);
            if (!insidePart(loop, p)) continue;
            double d = 1e300;
            for (const Segment& q : loop) d = std::min(d, distanceTo(q, p));
            if (d > worst.depth) worst = {d, p, e.id};
        }
    }
    return worst;
}

SeedResult runSeed(std::uint64_t seed)
{
    SeedResult out;
    out.seed = seed;
    const GeneratedProfile g = generateTurnedProfile(seed);
    out.inner = g.profile.side == ProfileSide::Inner;
    const Resolution r = resolveProfile(g.profile);
    if (!r.ok() || g.profile.rows.empty()) {
        out.refusedOn = "rows";
        out.refusal = r.problems.empty() ? "nothing resolved" : r.problems.front().message;
        return out;
    }
    const Deformation d = applyAllowances(r.profile, g.profile.allowances, g.options);
    if (!d.ok()) {
        const std::string& field = d.problems.front().field;
        const auto dot = field.rfind('.');
        out.refusedOn = dot == std::string::npos ? field : field.substr(dot + 1);
        out.refusal = d.problems.front().message;
        return out;
    }
    out.accepted = true;
    const auto allowanceOf = [&](const std::string& edge) {
        for (const AllowanceRow& a : g.profile.allowances)
            if (a.edge == edge) return fmt::format(" {} {}", edge, a.allowance);
        return std::string();
    };
    for (const AllowanceOutcome& row : d.profile.rows)
        for (const EndOutcome* e : {&row.start, &row.end})
            if (e->groove) {
                out.grooves.push_back(*e->groove);
                if (std::abs(e->angle - 270.0) > 1e-6) ++out.nonSquareGrooves;
                out.groovesMade += fmt::format("{}{} {} {}x{} at {:.1f}° ({}{})", out.groovesMade.empty() ? "" : ", ",
                                               row.edge, toKey(e->groove->kind), e->groove->width, e->groove->depth,
                                               e->angle, allowanceOf(row.edge), allowanceOf(e->neighbour));
            }
    out.intrusion = deepestIntoPart(r.profile, d.profile);
    return out;
}

void GeneratorTally::add(const SeedResult& r)
{
    ++profiles;
    if (r.inner) ++inner;
    if (!r.accepted) {
        ++refusedOn[r.refusedOn];
        if (r.refusedOn == "allowances" && !refusalExample.count(r.refusedOn))
            refusalExample[r.refusedOn] = fmt::format("seed {}: {}", r.seed, r.refusal);
        return;
    }
    ++accepted;
    for (const GrooveMade& g : r.grooves) ++groovesByKind[toKey(g.kind)];
    nonSquareGrooves += r.nonSquareGrooves;
    if (r.intrusion.depth > tolerance) failing.push_back(r);
}

std::string GeneratorTally::summary() const
{
    std::string refused, grooves, worst;
    for (const auto& [k, n] : refusedOn)
        refused += fmt::format("{}{} {}{}", refused.empty() ? "" : ", ", n, k,
                               refusalExample.count(k) ? " (" + refusalExample.at(k) + ")" : "");
    for (const auto& [k, n] : groovesByKind) grooves += fmt::format("{}{} {}", grooves.empty() ? "" : ", ", n, k);
    for (std::size_t i = 0; i < failing.size() && i < shown; ++i)
        worst += fmt::format("\n  seed {}: {} goes {:.6f} mm into the part at Z{:.4f} X{:.4f}; grooves: {}",
                             failing[i].seed, failing[i].intrusion.edge, failing[i].intrusion.depth,
                             failing[i].intrusion.where.z, 2.0 * failing[i].intrusion.where.r,
                             failing[i].groovesMade.empty() ? "none" : failing[i].groovesMade);
    return fmt::format("{} profiles ({} inner), {} allowance tables accepted, refused on: {}; grooves made: {} ({} at "
                       "corners that are not square); {} deformed profiles inside the part by more than {} mm{}",
                       profiles, inner, accepted, refused.empty() ? "none" : refused, grooves.empty() ? "none" : grooves,
                       nonSquareGrooves, failing.size(), tolerance, worst);
}

}  // namespace taiwa::test
