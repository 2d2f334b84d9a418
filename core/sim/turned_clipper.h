// The (z, r) half-plane on the core's Clipper grid (model/clipper_scale.h):
// points and polygons of the turning simulations (turned_stock.cpp,
// core/verify). Include it from core .cpp files only: Clipper is private to
// taiwa_core.
#pragma once

#include "model/clipper_scale.h"
#include "model/turned.h"

#include <vector>

namespace taiwa::sim {

inline ClipperLib::IntPoint clipperPoint(turning::ZR p)
{
    return toClipper(Point2{p.z, p.r});
}

inline turning::ZR zrOf(const ClipperLib::IntPoint& q)
{
    const Point2 p = fromClipper(q);
    return {p.x, p.y};
}

// A polygon, counter-clockwise.
inline ClipperLib::Path clipperPolygon(const std::vector<turning::ZR>& pts)
{
    ClipperLib::Path p;
    p.reserve(pts.size());
    for (const turning::ZR q : pts) p.push_back(clipperPoint(q));
    if (!ClipperLib::Orientation(p)) ClipperLib::ReversePath(p);
    return p;
}

}  // namespace taiwa::sim
