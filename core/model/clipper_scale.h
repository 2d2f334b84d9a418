// The one integer grid on which the core hands polygons to Clipper
// (polyclipping works on integers): 1e4 units per mm, 0.1 µm, fine enough
// for 1 µm proofs and coarse enough that coordinates of a few metres stay in
// Clipper's fast 30-bit range. Used by the coverage proof of tool paths and
// the interference check of input processing; the only core/model header
// that sees Clipper (include it from .cpp files only: Clipper is private to
// taiwa_core).
#pragma once

#include "model/geometry.h"

#include <polyclipping/clipper.hpp>

#include <cmath>
#include <vector>

namespace taiwa {

constexpr double kClipperScale = 1e4;  // Clipper integer units per mm

inline ClipperLib::IntPoint toClipper(Point2 p)
{
    return {static_cast<ClipperLib::cInt>(std::llround(p.x * kClipperScale)),
            static_cast<ClipperLib::cInt>(std::llround(p.y * kClipperScale))};
}

inline ClipperLib::Path toClipper(const std::vector<Point2>& points)
{
    ClipperLib::Path path;
    path.reserve(points.size());
    for (const auto& p : points) path.push_back(toClipper(p));
    return path;
}

inline Point2 fromClipper(const ClipperLib::IntPoint& p)
{
    return {static_cast<double>(p.X) / kClipperScale, static_cast<double>(p.Y) / kClipperScale};
}

// The area of a Clipper polygon in mm², whatever its orientation.
inline double clipperAreaMm2(const ClipperLib::Path& p)
{
    return std::abs(ClipperLib::Area(p)) / (kClipperScale * kClipperScale);
}

}  // namespace taiwa
