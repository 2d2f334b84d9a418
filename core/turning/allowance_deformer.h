// The grinding allowance's deformer (allowance.cpp runs it): the profile's
// edges mapped to the allowance rows, each row's allowance shape
// (allowance_shapes.cpp) and relief grooves (allowance_grooves.cpp), the
// shapes less the grooves united with the part, and the deformed chain read
// back with each piece's origin. Internal to core/turning.
#pragma once

#include "turning/allowance.h"
#include "model/translate_noop.h"

#include "check/messages.h"
#include "occt/profile_boolean.h"
#include "model/turned_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace taiwa::turning::deform {

// A curve of the deformed profile may lie on, in the order of preference when
// a piece lies on more than one.
struct Source {
    Segment s;
    Origin origin = Origin::Original;
    std::string from;
    std::string id;
    int row = -1;
    EdgeAttributes attributes;
    bool closure = false;
};

// Arc length from the start of `s` to p, negative for points before its start.
inline double signedParameter(const Segment& s, ZR p)
{
    const double t = parameterOf(s, p);
    if (!s.arc) return t;
    const double full = 2.0 * std::numbers::pi * s.radius, len = length(s);
    return t > len + 0.5 * (full - len) ? t - full : t;
}

inline bool sameCurve(const Segment& x, const Segment& y)
{
    if (x.arc != y.arc) return false;
    if (x.arc) return x.ccw == y.ccw && dist(x.centre, y.centre) < 1e-6 && std::abs(x.radius - y.radius) < 1e-6;
    const ZR d = unit(x.b - x.a);
    return std::abs(cross(d, unit(y.b - y.a))) < 1e-9 && dot(d, y.b - y.a) > 0.0 && std::abs(cross(d, y.a - x.a)) < 1e-7;
}

// One end of a picked edge, worked out.
struct End {
    EndOutcome outcome;
    ZR foot;        // where the allowance shape starts on the picked edge
    ZR onMoved;     // where it meets the moved edge
    Segment side;   // from foot to onMoved
    std::optional<ZR> grooveCorner;  // a concave corner of 90°-180° (air side)
    int neighbour = -1;
};

class Deformer {
public:
    Deformer(const ResolvedProfile& p, const std::vector<AllowanceRow>& rows, const AllowanceOptions& o)
        : p_(p), rows_(rows), o_(o)
    {
    }

    Deformation run();

private:
    std::string len(double mm) const { return msg::quote({mm, o_.shown}); }
    void problem(std::size_t row, const char* key, std::string message)
    {
        out_.problems.push_back({allowanceField(row, key), std::move(message)});
    }

    Loop edgesLoop() const;

    void mapRows();

    // Outward (into the stock) normal of an edge at p.
    ZR outward(const Segment& s, ZR p) const { return static_cast<double>(-side_) * leftNormal(tangentAt(s, p)); }
    // The part's angle at a vertex, from the direction arriving to the one leaving.
    double partAngle(ZR in, ZR out) const { return 180.0 - static_cast<double>(side_) * turnDegrees(in, out); }
    std::optional<Segment> moved(int edge, double a) const { return offset(p_.edges[edge].geometry, a, -side_); }

    End endOf(std::size_t k, int i, bool atStart, const Segment& pm);

    // The allowance shape of row k, its sources and its grooves.
    void shapeOf(std::size_t k);

    void groove(std::size_t k, int i, bool atStart, const End& end, EndOutcome& oc, const Segment& movedEdge);

    // The deformed chain from the boundary of the union, each piece named by
    // the curve it lies on.
    void readBack();

    void keepProfileUnchanged();

    const ResolvedProfile& p_;
    const std::vector<AllowanceRow>& rows_;
    const AllowanceOptions& o_;
    Deformation out_;
    std::vector<int> edgeRow_, rowEdge_;
    int side_ = 1;  // +1: the part lies left of the direction of travel
    double closureRadius_ = 0.0;
    Loop part_;
    std::vector<Loop> shapes_, cuts_;
    std::vector<Source> sources_, grooveSources_;
};

}  // namespace taiwa::turning::deform
