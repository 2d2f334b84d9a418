// A unit's live figure for the station's form, as plain values: marked
// points with labels, closed outlines, a centre and lines of text. A module
// that has one (probing: the touches as entered, the fitted circle or
// rectangle, each touch's residual, the centre and the offset to set) makes
// it through its door (ModuleKind::sketch); ui::SketchView draws it.
// Coordinates in mm, in the unit's own frame (y up); texts already in the
// job's unit.
#pragma once

#include "model/geometry.h"

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

struct Sketch {
    struct Mark {
        Point2 at;
        std::string label;     // "P2 +0.003"
        bool flagged = false;  // the point a problem names
    };
    std::vector<Mark> marks;
    std::vector<std::vector<Point2>> outlines;  // closed
    std::optional<Point2> centre;
    std::vector<std::string> lines;  // below the figure
    bool problem = false;            // the lines say what is wrong
};

}  // namespace taiwa
