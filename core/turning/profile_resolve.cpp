// From the profile table to exact edges (profile_resolve.h).
#include "turning/profile_resolve.h"
#include "model/translate_noop.h"

#include "check/messages.h"
#include "model/turned_geometry.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <set>

namespace taiwa::turning {

namespace {

constexpr double kMinElement = 1e-6;  // mm: shorter is no element

struct Raw {
    Segment s;
    std::size_t row;
    std::optional<Segment> corner;  // made at the row's end
    double consumedAtStart = 0.0;   // taken by the previous row's corner
};

class Resolver {
public:
    Resolver(const TurnedProfile& p, LengthUnit shown) : p_(p), shown_(shown) {}

    Resolution run()
    {
        res_.profile.side = p_.side;
        checkStart();
        std::set<int> ids;
        for (std::size_t i = 0; i < p_.rows.size(); ++i)
            if (!ids.insert(p_.rows[i].id).second || p_.rows[i].id <= 0)
                problem(rowField(i, "id"),
                        fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                         "row {} has the edge id {}, which is not a positive number "
                                                         "of its own; every row needs one"),
                                    i + 1, p_.rows[i].id));
        if (p_.rows.empty()) problem("rows", "the profile has no rows: enter at least one element");
        buildElements();
        cutCorners();
        for (const Raw& r : raw_) {
            const ProfileRow& row = p_.rows[r.row];
            if (length(r.s) > kMinElement) res_.profile.edges.push_back({edgeId(row.id), r.s, row.attributes, static_cast<int>(r.row), false});
            if (r.corner) res_.profile.edges.push_back({cornerEdgeId(row.id), *r.corner, {}, static_cast<int>(r.row), true});
        }
        if (res_.problems.empty()) checkOneChain();
        return std::move(res_);
    }

private:
    std::string len(double mm) const { return msg::quote({mm, shown_}); }
    std::string dia(double mm) const { return "Ø" + len(mm); }
    void problem(std::string field, std::string message) { res_.problems.push_back({std::move(field), std::move(message)}); }

    void checkStart()
    {
        if (!std::isfinite(p_.startX) || !std::isfinite(p_.startZ))
            problem("start", "the start point is not a number");
        else if (p_.startX < 0.0)
            problem("start.x",
                    fmt::format(
                        TAIWA_TRANSLATE_NOOP("taiwa::msg", "the start diameter is {}; a diameter cannot be below zero"),
                        len(p_.startX)));
    }

    void buildElements()
    {
        ZR prev{p_.startZ, p_.startX / 2.0};
        for (std::size_t i = 0; i < p_.rows.size(); ++i) {
            const ProfileRow& row = p_.rows[i];
            if (!std::isfinite(row.x) || !std::isfinite(row.z)) {
                problem(
                    rowField(i, "x"),
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "row {}: the end point is not a number"), i + 1));
                continue;
            }
            if (row.x < 0.0) {
                problem(
                    rowField(i, "x"),
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                     "row {}: the end diameter is {}; a diameter cannot be below zero"),
                                i + 1, len(row.x)));
                continue;
            }
            const ZR end{row.z, row.x / 2.0};
            if (dist(prev, end) < kMinElement) {
                problem(
                    rowField(i, "z"),
                    fmt::format(TAIWA_TRANSLATE_NOOP(
                                    "taiwa::msg", "row {} ends where it starts (X{} Z{}): an element needs a length"),
                                i + 1, len(row.x), len(row.z)));
                continue;
            }
            std::optional<Segment> s = row.kind == ElementKind::Line ? lineSegment(prev, end) : arc(i, prev, end);
            prev = end;
            if (s) raw_.push_back({*s, i, std::nullopt, 0.0});
        }
    }

    std::optional<Segment> arc(std::size_t i, ZR a, ZR b)
    {
        const ProfileRow& row = p_.rows[i];
        const bool ccw = row.kind == ElementKind::ArcCCW;
        ZR centre;
        if (row.centreX && row.centreZ) {
            centre = {*row.centreZ, *row.centreX / 2.0};
            const double ra = dist(centre, a), rb = dist(centre, b);
            if (std::abs(ra - rb) > 1e-3) {
                problem(rowField(i, "centre"),
                        fmt::format(TAIWA_TRANSLATE_NOOP(
                                        "taiwa::msg",
                                        "row {}: the centre is {} from the start and {} from the end point; an arc's "
                                        "centre is equally far from both"),
                                    i + 1, len(ra), len(rb)));
                return std::nullopt;
            }
            if (row.radius && std::abs(*row.radius - ra) > 1e-3) {
                problem(rowField(i, "radius"),
                        fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                         "row {}: the radius {} does not match the centre, which is {} "
                                                         "from the start"),
                                    i + 1, len(*row.radius), len(ra)));
                return std::nullopt;
            }
        } else if (row.radius) {
            const double r = *row.radius, chord = dist(a, b);
            if (!(r > 0.0)) {
                problem(rowField(i, "radius"),
                        fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "row {}: an arc's radius must be above zero"),
                                    i + 1));
                return std::nullopt;
            }
            if (chord > 2.0 * r + 1e-9) {
                problem(
                    rowField(i, "radius"),
                    fmt::format(TAIWA_TRANSLATE_NOOP(
                                    "taiwa::msg",
                                    "row {}: a radius of {} cannot reach the end point, which is {} from the start; "
                                    "the radius must be at least {}"),
                                i + 1, len(r), len(chord), len(chord / 2.0)));
                return std::nullopt;
            }
            // The arc of less than half a turn: its centre lies left of the
            // chord for a counter-clockwise arc, right of it for a clockwise one.
            const double h = std::sqrt(std::max(0.0, r * r - chord * chord / 4.0));
            centre = 0.5 * (a + b) + (ccw ? h : -h) * leftNormal(unit(b - a));
        } else {
            problem(rowField(i, "radius"),
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "row {}: an arc needs its radius or its centre"),
                                i + 1));
            return std::nullopt;
        }
        Segment s = arcSegment(a, b, centre, ccw);
        // The arc's lowest point, when the arc passes it, must not be below the axis.
        const ZR bottom{centre.z, centre.r - s.radius};
        if (bottom.r < -1e-9 && contains(s, bottom, 1e-9)) {
            problem(
                rowField(i, "radius"),
                fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "row {}: the arc dips below the axis (to Ø{}); a turned "
                                                               "profile stays at or above it"),
                            i + 1, len(2.0 * bottom.r)));
            return std::nullopt;
        }
        return s;
    }

    void cutCorners()
    {
        for (std::size_t k = 0; k < raw_.size(); ++k) {
            const ProfileRow& row = p_.rows[raw_[k].row];
            if (row.corner == CornerKind::None) continue;
            const std::string field = rowField(raw_[k].row, "cornerSize");
            const char* what = row.corner == CornerKind::Chamfer ? "chamfer" : "rounding";
            if (k + 1 >= raw_.size() || raw_[k + 1].row != raw_[k].row + 1) {
                problem(rowField(raw_[k].row, "corner"),
                        fmt::format(
                            TAIWA_TRANSLATE_NOOP("taiwa::msg", "row {}: a {} needs a next row to meet; there is none"),
                            raw_[k].row + 1, what));
                continue;
            }
            Segment& s1 = raw_[k].s;
            Segment& s2 = raw_[k + 1].s;
            if (s1.arc || s2.arc) {
                problem(rowField(raw_[k].row, "corner"),
                        fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                         "row {}: a {} is made between two lines; row {} is an arc"),
                                    raw_[k].row + 1, what, s1.arc ? raw_[k].row + 1 : raw_[k + 1].row + 1));
                continue;
            }
            if (!(row.cornerSize > 0.0)) {
                problem(field, fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "row {}: the {} size must be above zero"),
                                           raw_[k].row + 1, what));
                continue;
            }
            const ZR d1 = unit(s1.b - s1.a), d2 = unit(s2.b - s2.a);
            const double turn = turnDegrees(d1, d2);
            if (std::abs(turn) < 1e-3 || std::abs(turn) > 180.0 - 1e-3) {
                problem(
                    rowField(raw_[k].row, "corner"),
                    fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                     "row {}: rows {} and {} are in line; there is no corner for a {}"),
                                raw_[k].row + 1, raw_[k].row + 1, raw_[k + 1].row + 1, what));
                continue;
            }
            const double t = row.corner == CornerKind::Chamfer
                                 ? row.cornerSize
                                 : row.cornerSize * std::tan(std::abs(turn) * std::numbers::pi / 360.0);
            const double room1 = length(s1) - raw_[k].consumedAtStart, room2 = length(s2);
            if (t > room1 + 1e-9 || t > room2 + 1e-9) {
                problem(field,
                        fmt::format(TAIWA_TRANSLATE_NOOP(
                                        "taiwa::msg",
                                        "row {}: a {} of {} takes {} of both lines; row {} has {} and row {} has {}"),
                                    raw_[k].row + 1, what, len(row.cornerSize), len(t), raw_[k].row + 1, len(room1),
                                    raw_[k + 1].row + 1, len(room2)));
                continue;
            }
            const ZR v = s1.b, t1 = v - t * d1, t2 = v + t * d2;
            s1.b = t1;
            s2.a = t2;
            raw_[k + 1].consumedAtStart = t;
            if (row.corner == CornerKind::Chamfer) {
                raw_[k].corner = lineSegment(t1, t2);
            } else {
                const bool ccw = turn > 0.0;
                raw_[k].corner = arcSegment(t1, t2, t1 + (ccw ? row.cornerSize : -row.cornerSize) * leftNormal(d1), ccw);
            }
        }
    }

    // The edges and the closing lines make one simple loop: no edge crosses
    // another, nor the line back to the axis (or out to the stock).
    void checkOneChain()
    {
        const auto& edges = res_.profile.edges;
        if (edges.empty()) return;
        double rMax = 0.0;
        for (const auto& e : edges) rMax = std::max({rMax, e.geometry.a.r, e.geometry.b.r});
        const auto rowOf = [&](const Edge& e) { return static_cast<std::size_t>(e.row); };
        for (std::size_t i = 0; i < edges.size(); ++i)
            for (std::size_t j = i + 1; j < edges.size(); ++j) {
                for (ZR x : crossings(edges[i].geometry, edges[j].geometry)) {
                    const bool shared = j == i + 1 && dist(x, edges[i].geometry.b) < 1e-6;
                    if (shared) continue;
                    problem(rowField(rowOf(edges[j]), "x"),
                            fmt::format(TAIWA_TRANSLATE_NOOP(
                                            "taiwa::msg",
                                            "the profile is not one chain: {} (row {}) meets {} (row {}) at X{} Z{}"),
                                        edges[j].id, rowOf(edges[j]) + 1, edges[i].id, rowOf(edges[i]) + 1,
                                        len(2.0 * x.r), len(x.z)));
                    return;
                }
            }
        const ZR start = edges.front().geometry.a, end = edges.back().geometry.b;
        for (const Segment& c : closure(res_.profile, rMax + 1.0))
            for (const auto& e : edges)
                for (ZR x : crossings(c, e.geometry)) {
                    if (dist(x, start) < 1e-6 || dist(x, end) < 1e-6) continue;
                    problem(
                        rowField(rowOf(e), "x"),
                        fmt::format(TAIWA_TRANSLATE_NOOP(
                                        "taiwa::msg",
                                        "the profile is not one chain around the part: {} (row {}) reaches the line "
                                        "closing it {} at X{} Z{}"),
                                    e.id, rowOf(e) + 1,
                                    p_.side == ProfileSide::Outer ? "along the axis" : "outside the bore",
                                    len(2.0 * x.r), len(x.z)));
                    return;
                }
    }

    const TurnedProfile& p_;
    LengthUnit shown_;
    std::vector<Raw> raw_;
    Resolution res_;
};

}  // namespace

std::string rowField(std::size_t row, const char* key) { return fmt::format("rows[{}].{}", row + 1, key); }
std::string allowanceField(std::size_t row, const char* key) { return fmt::format("allowances[{}].{}", row + 1, key); }

Resolution resolveProfile(const TurnedProfile& p, LengthUnit shown) { return Resolver(p, shown).run(); }

std::vector<Segment> closure(const ResolvedProfile& p, double outerRadius)
{
    std::vector<Segment> out;
    if (p.edges.empty()) return out;
    const ZR s = p.edges.front().geometry.a, e = p.edges.back().geometry.b;
    const double r = p.side == ProfileSide::Outer ? 0.0 : outerRadius;
    const ZR pts[] = {e, {e.z, r}, {s.z, r}, s};
    for (int i = 0; i < 3; ++i)
        if (dist(pts[i], pts[i + 1]) > kPointTol) out.push_back(lineSegment(pts[i], pts[i + 1]));
    return out;
}

}  // namespace taiwa::turning
