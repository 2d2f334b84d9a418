// The geometry of a SIDE unit: the direction the tool travels along its
// contour, the contour's concave radii and sharp corners on the tool's side,
// the two sides of an open contour (continued along its end tangents), and
// the finished shape the verification measures against.
#include "modules/side/side.h"

#include "check/messages.h"
#include "model/codes.h"
#include "model/translate_noop.h"
#include "paths/contour_offset.h"
#include "paths/narrowest.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace taiwa {

namespace side {

Travel travel(const SideMill& mm)
{
    // M3: climb milling keeps the tool on the left of its travel (G41).
    const bool climb = mm.direction != 2;
    const bool leftOfContour = mm.side != 2;
    Travel t;
    t.contour = leftOfContour == climb ? mm.path.value() : reversed(mm.path.value());
    t.toolOnLeft = climb;
    return t;
}

double smallestConcaveRadius(const Contour& c, bool toolOnLeft)
{
    const ContourSegment* arc = tightestConcaveArc(c, toolOnLeft);
    return arc ? arc->radius() : 1e300;
}

const ContourSegment* tightestConcaveArc(const Contour& c, bool toolOnLeft)
{
    const ContourSegment* tightest = nullptr;
    for (const ContourSegment& s : c.segments)
        if (s.isArc() && (s.kind == ContourSegment::Kind::ArcCCW) == toolOnLeft &&
            (!tightest || s.radius() < tightest->radius()))
            tightest = &s;
    return tightest;
}

std::string noRoomAt(const SideMill& mm, const Tool& tool, double allowance, LengthUnit shown)
{
    const Travel t = travel(mm);
    const auto len = [&](double v) { return msg::quote({v, shown}); };
    const double R = tool.radius() + allowance;  // the radius the place must have
    const ContourSegment* arc = tightestConcaveArc(t.contour, t.toolOnLeft);
    if (t.contour.closed && paths::toolInside(t.contour, t.toolOnLeft) && (!arc || mm.reach < arc->radius() - 1e-6)) {
        Region r;
        r.outer = t.contour;
        if (const auto n = paths::narrowestPlace(r); n && n->kind == paths::NarrowestPlace::Kind::Neck)
            return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                                    "{} narrows to {} between ({}, {}) and ({}, {}); the smallest end "
                                                    "mill, {}, needs {} there"),
                               mm.contour, len(n->width), len(n->a.x), len(n->a.y), len(n->b.x), len(n->b.y),
                               msg::toolName(tool), len(2.0 * R));
    }
    if (!arc) return {};
    const Point2 m = arc->at(0.5);
    return fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg",
                                            "the arc of {} at ({}, {}) curves round the tool's side with radius {}: "
                                            "the smallest end mill, {}, is {} too large for it (an arc of radius {} "
                                            "or more would let it fit)"),
                       mm.contour, len(m.x), len(m.y), len(arc->radius()), msg::toolName(tool),
                       len(R - arc->radius()), len(R));
}

std::optional<Point2> sharpConcaveCorner(const Contour& c, bool toolOnLeft)
{
    const std::size_t n = c.segments.size();
    const std::size_t joints = c.closed ? n : (n > 0 ? n - 1 : 0);
    for (std::size_t i = 0; i < joints; ++i) {
        const ContourSegment& a = c.segments[i];
        const ContourSegment& b = c.segments[(i + 1) % n];
        const Point2 d0 = a.endDirection(), d1 = b.startDirection();
        const double turn = cross(d0, d1) * (toolOnLeft ? 1.0 : -1.0);
        if (turn > 1e-9 || (dot(d0, d1) < 0.0 && std::abs(turn) <= 1e-9)) return a.end;
    }
    return std::nullopt;
}

double toolRoom(const SideMill& mm)
{
    const Travel t = travel(mm);
    double room = smallestConcaveRadius(t.contour, t.toolOnLeft);
    if (t.contour.closed && paths::toolInside(t.contour, t.toolOnLeft)) room = std::min(room, mm.reach);
    return room;
}

namespace {

// Where the ray from p along the unit direction d leaves the circle (m, r)
// that p lies in.
Point2 leave(Point2 p, Point2 d, Point2 m, double r)
{
    const Point2 f = p - m;
    const double b = dot(f, d), c = dot(f, f) - r * r;
    return p + (-b + std::sqrt(std::max(b * b - c, 0.0))) * d;
}

}  // namespace

Sides::Sides(const Contour& c, bool toolOnLeft) : contour_(c)
{
    polygon_ = flatten(c, 1e-4);
    if (c.closed) {
        inside_ = paths::toolInside(c, toolOnLeft);
        makeBands();
        return;
    }
    // The open contour continued along its end tangents to a circle well
    // round it, closed by that circle's arc on the tool's side (in 64
    // chords: it lies a kilometre off, where nothing is cut).
    const Box2 b = bounds(c);
    const Point2 m = 0.5 * (b.min + b.max);
    const double r = taiwa::distance(b.min, b.max) + 1000.0;
    const Point2 a = leave(c.start(), -1.0 * c.segments.front().startDirection(), m, r);
    const Point2 e = leave(c.end(), c.segments.back().endDirection(), m, r);
    polygon_.insert(polygon_.begin(), a);
    polygon_.push_back(e);
    const ContourSegment closing = ContourSegment::arc(e, a, m, toolOnLeft);
    for (int k = 1; k < 64; ++k) polygon_.push_back(closing.at(k / 64.0));
    inside_ = true;
    makeBands();
}

void Sides::makeBands()
{
    extent_ = {polygon_.front(), polygon_.front()};
    for (const Point2& q : polygon_)
        extent_.min = {std::min(extent_.min.x, q.x), std::min(extent_.min.y, q.y)},
        extent_.max = {std::max(extent_.max.x, q.x), std::max(extent_.max.y, q.y)};
    const Box2 own = bounds(contour_);
    const double y0 = own.min.y, y1 = own.max.y;
    const std::size_t n = std::clamp<std::size_t>(polygon_.size() / 2, 1, 4096);
    bandsY0_ = y0;
    bandHeight_ = std::max((y1 - y0) / static_cast<double>(n), 1e-9);
    bands_.assign(n, {});
    for (std::size_t i = 0, j = polygon_.size() - 1; i < polygon_.size(); j = i++) {
        const auto [lo, hi] = std::minmax(polygon_[i].y, polygon_[j].y);
        for (std::size_t k = band(lo), last = band(hi); k <= last; ++k) bands_[k].push_back(static_cast<std::uint32_t>(i));
    }
}

std::size_t Sides::band(double y) const
{
    const double k = std::floor((y - bandsY0_) / bandHeight_);
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(bands_.size() - 1)));
}

bool Sides::onToolSide(Point2 p) const
{
    // Crossing number of the polygon, over the edges whose y range meets
    // the point's band (an edge the test counts spans p.y, so it is there).
    // Below, above or right of the polygon no edge is counted.
    if (p.y < extent_.min.y || p.y >= extent_.max.y || p.x > extent_.max.x) return !inside_;
    bool in = false;
    for (const std::uint32_t e : bands_[band(p.y)]) {
        const Point2 u = polygon_[e], v = polygon_[e == 0 ? polygon_.size() - 1 : e - 1];
        if ((u.y > p.y) != (v.y > p.y) && p.x < (v.x - u.x) * (p.y - u.y) / (v.y - u.y) + u.x) in = !in;
    }
    return in == inside_;
}

double Sides::distance(Point2 p) const { return distanceTo(contour_, p); }

}  // namespace side

Cavity sideCavity(const SideMill& mm, const TechnologyData& tech)
{
    const side::Travel t = side::travel(mm);
    const auto sides = std::make_shared<side::Sides>(t.contour, t.toolOnLeft);
    Cavity c;
    const Box2 b = bounds(t.contour);
    // The tool's side may be cut anywhere (beyond W too: the passes reach
    // past it); the box holds what the widest end mill can reach.
    const bool inside = t.contour.closed && paths::toolInside(t.contour, t.toolOnLeft);
    const double grow = inside ? 0.0 : mm.width + 100.0;
    c.min = {b.min.x - grow, b.min.y - grow};
    c.max = {b.max.x + grow, b.max.y + grow};
    c.depth = mm.depth;
    // Deepest within s > 0: T on the tool's side grown by s. Shallowest
    // within |s|: T where the whole disc of radius |s| lies on the tool's
    // side within W of the contour (what the unit must remove).
    // The side first: it is a band's crossings, the distance a look at every
    // segment, and most of the box (all round a boss) is on the tool's side.
    c.depthAt = [sides, T = mm.depth, W = mm.width](Point2 p, double slack) {
        const bool tool = sides->onToolSide(p);
        if (slack >= 0.0) return tool || sides->distance(p) <= slack ? T : 0.0;
        if (!tool) return 0.0;
        const double d = sides->distance(p);
        return d >= -slack && d <= W + slack ? T : 0.0;
    };
    // Finishing only (U8): the wall was roughed elsewhere, the band from α2
    // to W is open before the unit's steps.
    if (mm.toolUse == 8)
        c.openAt = [sides, T = mm.depth, W = mm.width, a2 = tech.alpha2](Point2 p) {
            if (!sides->onToolSide(p)) return 0.0;
            const double d = sides->distance(p);
            return d >= a2 && d <= W ? T : 0.0;
        };
    return c;
}

}  // namespace taiwa
