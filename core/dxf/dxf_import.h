// DXF import: the lines, arcs, circles, polylines (bulges exact), splines and
// ellipses (approximated by lines within a tolerance) of a 2D drawing, on the
// layers the operator selects, chained into the exact line/arc contours of
// model/contour.h. Gaps, branches and everything not read are reported, never
// silently dropped; a damaged or hostile file gives a message, not a crash.
// See docs/dxf-import.md.
#pragma once

#include "model/contour.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::dxf {

// How the drawing's lengths become mm.
enum class Units {
    FromFile,     // $INSUNITS; unitless or absent: mm (with a warning)
    Millimetres,  // the operator says mm, whatever the file says
    Inches,       // the operator says inches (×25.4)
};

struct DxfOptions {
    // The layers to import, matched without regard to case; empty: all.
    std::vector<std::string> layers;
    // Ends at most this far apart [mm] are joined; the operator's setting.
    double gapTolerance = 0.01;
    // Ends farther apart than the tolerance but within this distance [mm],
    // or within 10× the tolerance if that is more, are reported as gaps.
    double gapReportDistance = 1.0;
    // The largest distance [mm] of the lines replacing a SPLINE or an
    // ELLIPSE from the true curve.
    double splineTolerance = 0.01;
    Units units = Units::FromFile;
};

// Where a piece of a contour came from: "LINE", layer "OUTLINE", the line of
// the DXF file its entity starts on.
struct EntityRef {
    std::string type;
    std::string layer;
    int line = 0;
    // "LINE on layer OUTLINE (DXF line 57)"
    std::string text() const;
    friend bool operator==(const EntityRef&, const EntityRef&) = default;
};

// A contour and, for each of its segments, the entity it came from.
struct DxfContour {
    Contour contour;
    std::vector<EntityRef> sources;
};

// A layer of the drawing: from the LAYER table or named by an entity.
struct LayerInfo {
    std::string name;
    int entities = 0;  // model-space entities of every type on it
    bool selected = false;
};

// Two contour ends that come close but not within the gap tolerance.
struct DxfGap {
    Point2 at{};     // the end of `a`
    Point2 other{};  // the end of `b`
    double size = 0.0;
    EntityRef a, b;
    std::string message;
};

// Three or more ends meeting within the gap tolerance: the chaining had to
// choose, and some ends stay open.
struct DxfBranch {
    Point2 at{};
    int ends = 0;
    std::vector<EntityRef> entities;
    std::string message;
};

struct DxfReadResult {
    // Set when nothing could be imported; everything else is then empty
    // except, where known, `layers` and `warnings`.
    std::optional<std::string> error;
    bool ok() const { return !error.has_value(); }

    std::vector<DxfContour> contours;  // closed and open, in the file's order
    std::vector<LayerInfo> layers;     // sorted by name
    std::vector<DxfGap> gaps;          // largest first
    std::vector<DxfBranch> branches;
    int smallGapsClosed = 0;        // joins over more than 1e-9 mm and within the tolerance
    double largestGapClosed = 0.0;  // mm
    Point2 largestGapClosedAt{};
    double unitScale = 1.0;  // mm per drawing unit
    std::string units;       // "mm", "inch", … as read
    // Entities skipped or not read and why, units assumed, counts corrected.
    std::vector<std::string> warnings;

    int closedCount() const;
    int openCount() const;
};

// Reads a DXF file (ASCII; binary DXF is refused with a message).
DxfReadResult readDxf(const std::filesystem::path& path, const DxfOptions& options = {});
// The same from the file's bytes.
DxfReadResult readDxfBytes(std::string_view bytes, const DxfOptions& options = {});

}  // namespace taiwa::dxf
