// The winding number of a point about a closed polygon (its last point
// joined back to the first): how many times the polygon turns around it,
// counter-clockwise positive; not 0 when the point lies inside. Shared by
// the contour's inside test (model/contour.cpp) and the region offset's
// sorting of islands into their outer loops (paths/region_offset.cpp).
#pragma once

#include "model/geometry.h"

#include <cstddef>
#include <vector>

namespace taiwa {

inline int windingNumber(const std::vector<Point2>& polygon, Point2 p)
{
    int winding = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Point2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        const double side = cross(b - a, p - a);
        if (a.y <= p.y) {
            if (b.y > p.y && side > 0.0) ++winding;
        } else if (b.y <= p.y && side < 0.0) {
            --winding;
        }
    }
    return winding;
}

}  // namespace taiwa
