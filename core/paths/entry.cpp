// Entry of a pocket-clearing tool into a layer: pilot hole, helix, linear
// ramp or plunge.
#include "paths/entry.h"

#include "paths/contour.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace taiwa::paths {

namespace {

Point3 at(Point2 p, double z) { return {p.x, p.y, z}; }

void helix(PathBuilder& b, const Entry& e, double z, double tanRamp, bool ccw)
{
    const double perHalfTurn = std::numbers::pi * e.radius * tanRamp;
    const Point2 a{e.point.x + e.radius, e.point.y}, o{e.point.x - e.radius, e.point.y};
    b.feed(at(a, b.at().z), FeedKind::Ramp);
    bool atA = true;
    while (b.at().z > z + 1e-12) {
        b.arc(ccw, at(atA ? o : a, std::max(z, b.at().z - perHalfTurn)), e.point, FeedKind::Ramp);
        atA = !atA;
    }
    // A full turn at depth flattens the helix's floor; its bore (radius
    // e.radius + R, e.radius < R) has no core left.
    b.arc(ccw, at(atA ? o : a, z), e.point);
    b.arc(ccw, at(atA ? a : o, z), e.point);
    b.feed(at(e.point, z));
}

void linearRamp(PathBuilder& b, const Entry& e, double z, double tanRamp)
{
    const double leg = distance(e.point, e.other);
    const double drop = leg * tanRamp;
    Point2 target = e.other;
    while (true) {
        const Point2 from{b.at().x, b.at().y};
        if (b.at().z - drop <= z) {
            const double f = (b.at().z - z) / drop;
            b.feed(at(from + f * (target - from), z), FeedKind::Ramp);
            break;
        }
        b.feed(at(target, b.at().z - drop), FeedKind::Ramp);
        target = target == e.other ? e.point : e.other;
    }
    // At depth: cut the whole ramp line and come back to the entry point.
    b.feed(at(target, z));
    if (target == e.point) b.feed(at(e.other, z));
    b.feed(at(e.point, z));
}

}  // namespace

Entry chooseEntry(const Quad& outline, double R, double hole, Point2 holeAt)
{
    Entry e;
    if (hole >= 2 * R - 1e-9 && signedDistance(centreQuad(outline, R), holeAt) <= 1e-9) {
        e.kind = Entry::Kind::PilotHole;
        e.point = holeAt;
        return e;
    }
    // The region where the tool centre may go collapses at maxOffset - R
    // to a point or a segment: the middle of the largest inscribed circle.
    const double deepest = maxOffset(outline);
    const double room = std::max(0.0, deepest - R);
    const auto core = centreQuad(outline, std::max(R, deepest - 1e-4)).corners;
    e.point = centroid(core);
    e.radius = std::min(0.5 * R, 0.9 * room);
    if (e.radius >= 0.25 * R) {
        e.kind = Entry::Kind::Helix;
        return e;
    }
    // A slot: ramp along its centre line, between its two farthest points.
    std::size_t i0 = 0, i1 = 2;
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
            if (distance(core[i], core[j]) > distance(core[i0], core[i1])) i0 = i, i1 = j;
    if (distance(core[i0], core[i1]) >= R) {
        e.kind = Entry::Kind::LinearRamp;
        e.point = core[i0];
        e.other = core[i1];
        return e;
    }
    e.kind = Entry::Kind::Plunge;
    return e;
}

void appendEntry(PathBuilder& b, const Entry& e, double z, double rampAngle, bool ccw)
{
    b.feed(at(e.point, b.at().z));
    if (e.kind == Entry::Kind::Helix || e.kind == Entry::Kind::LinearRamp)
        if (!(rampAngle > 0.0 && rampAngle < 90.0)) throw std::logic_error("ramp angle must lie between 0 and 90 degrees");
    const double tanRamp = tanDeg(rampAngle);
    switch (e.kind) {
    case Entry::Kind::PilotHole:
    case Entry::Kind::Plunge: b.feed(at(e.point, z), FeedKind::Plunge); break;
    case Entry::Kind::Helix: helix(b, e, z, tanRamp, ccw); break;
    case Entry::Kind::LinearRamp: linearRamp(b, e, z, tanRamp); break;
    }
}

}  // namespace taiwa::paths
