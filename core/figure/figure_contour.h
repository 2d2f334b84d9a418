// Evaluated figure contours (`K1 = CONTOUR/...`, figure_text.h): the exact
// line/arc chain (model/contour.h) a contour statement gives, its corners
// (ROUND, CHAMF) with where their values are written, so that a corner
// revision UI can list them and change one value in the text
// (reviseCorner) leaving every other byte as it was. The evaluation itself is
// evaluate() in figure_eval.h; the rules are in docs/figure-elements.md.
#pragma once

#include "figure/figure_text.h"
#include "model/contour.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::figure {

// A ROUND or CHAMF on a contour corner, in the order written.
struct ContourCorner {
    enum class Kind { Round, Chamfer };
    Kind kind = Kind::Round;
    double value = 0;        // the radius (ROUND) or the distance cut off each element (CHAMF)
    int segment = 0;         // the fillet arc's or chamfer line's index in EvaluatedContour::contour.segments
    int line = 0;            // where the value is written (1-based, bytes), for editing
    int column = 0;
    std::string between[2];  // the elements before and after the corner, in tool-motion order
};

// One evaluated contour. Lines are run in the chain's direction whatever
// their own, circles as arcs in the direction written (CLW/CCLW).
struct EvaluatedContour {
    std::string name;
    taiwa::Contour contour;
    std::vector<ContourCorner> corners;
    // Per segment of `contour`: the element it lies on, or "" for a corner's
    // fillet or chamfer (found through corners[i].segment).
    std::vector<std::string> elements;
    // The corner whose fillet or chamfer is segment `segment`, or nullptr.
    const ContourCorner* cornerAt(int segment) const;
};

// `text` with the value of corner `cornerIndex` (0-based, in the order the
// corners are written) of contour `contour` replaced by `newValue` in its
// canonical form (formatNumber); every other byte unchanged. nullopt when the
// text is refused, there is no such contour or corner, or the value is not
// greater than 0 or beyond kMaxNumber.
std::optional<std::string> reviseCorner(std::string_view text, const std::string& contour, int cornerIndex,
                                        double newValue);

}  // namespace taiwa::figure
