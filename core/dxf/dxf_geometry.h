// The decoded DXF entities as pieces of contour in mm: lines and arcs exact
// (polyline bulges become arcs with their centres), SPLINEs (NURBS) and
// ELLIPSEs replaced by lines within the spline tolerance, the mirrored
// object coordinate system of an extrusion (0, 0, -1) undone. Internal to
// core/dxf/.
#pragma once

#include "dxf/dxf_entities.h"
#include "dxf/dxf_import.h"
#include "dxf/dxf_notes.h"
#include "model/result.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa::dxf::detail {

// A run of connected segments from one entity.
struct Piece {
    std::vector<ContourSegment> segments;
    EntityRef source;
    bool closedByItself = false;  // a CIRCLE, a full ELLIPSE or ARC, a closed polyline
};

// Appends the pieces of `entities` scaled by `scale` [mm per drawing unit];
// an error when the drawing needs more than `segmentBudget` segments.
Result<void> buildPieces(const std::vector<RawEntity>& entities, double scale, double splineTolerance, std::size_t segmentBudget,
                         std::vector<Piece>& out, Notes& notes);

const char* typeName(RawEntity::Type t);

}  // namespace taiwa::dxf::detail
