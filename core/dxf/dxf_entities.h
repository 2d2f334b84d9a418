// The entities dxflib decodes, in plain structs: the one file that includes
// dxflib (dxf_entities.cpp) turns the guarded ENTITIES text of dxf_scan.h
// into these, in drawing units and the entity's own coordinate system.
// Internal to core/dxf/.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace taiwa::dxf::detail {

using Vec3 = std::array<double, 3>;

struct RawVertex {
    double x = 0, y = 0, z = 0, bulge = 0;
};

struct RawEntity {
    enum class Type { Line, Arc, Circle, Ellipse, LwPolyline, Polyline, Spline };
    Type type = Type::Line;
    std::string layer;
    int line = 0;            // where it starts in the DXF file
    Vec3 extrusion{0, 0, 1};  // groups 210/220/230
    Vec3 a{}, b{};            // LINE ends; ARC/CIRCLE/ELLIPSE centre (a) and ELLIPSE major axis end (b)
    double radius = 0;        // ARC, CIRCLE; ELLIPSE: minor/major ratio
    double angle1 = 0, angle2 = 0;  // ARC: degrees; ELLIPSE: parameters [rad]
    int flags = 0;                  // polylines, SPLINE
    int degree = 0;                 // SPLINE
    std::vector<RawVertex> vertices;  // polylines; SPLINE control points (bulge = weight)
    std::vector<double> knots;        // SPLINE
    int fitPoints = 0;                // SPLINE
};

// The scan's kept entities (`count` of them: room is made at once).
std::vector<RawEntity> decodeEntities(const std::string& guardedText, std::size_t count);

}  // namespace taiwa::dxf::detail
