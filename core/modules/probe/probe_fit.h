// The fits of work-centre probing (spec: "Work centre as machining origin"):
// the touch points of a round or rectangular workpiece, measured as the
// stylus ball's centre at each touch, relative to the first touch (the
// measuring origin), become the workpiece's centre, its size and (for a
// rectangle touched twice on one side) its rotation, with each point's
// residual. Refusals name the point (1-based, as the operator entered it).
#pragma once

#include "model/geometry.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace taiwa::probe {

// The side of a rectangle a touch is on, in the part's own axes.
enum class Side { None = 0, XMinus = 1, XPlus = 2, YMinus = 3, YPlus = 4 };

struct Touch {
    Point2 at;               // ball centre at the touch, relative to the first touch
    Side side = Side::None;  // rectangles only
};

// Where the ball was: outside the part (boss, block: the surface is the
// ball radius nearer the centre) or inside it (bore, pocket: farther).
struct FitSettings {
    double ballRadius = 0.0;
    bool inside = false;
    double tolerance = 0.01;  // largest residual accepted [mm]
};

struct FitProblem {
    int point = 0;  // 1-based; 0 when no single point is to blame
    std::string message;
};

struct CircleFit {
    Point2 centre;                   // relative to the first touch
    double radius = 0.0;             // of the workpiece's surface (ball accounted for)
    std::vector<double> residuals;   // per touch: distance off the fitted circle [mm], outward positive
};

struct RectangleFit {
    Point2 centre;                   // relative to the first touch
    double width = 0.0, length = 0.0;  // along the part's own X and Y (ball accounted for)
    double rotation = 0.0;           // of the part's X axis from the machine's [deg], counter-clockwise
    bool rotationMeasured = false;   // a side was touched twice
    std::vector<double> residuals;   // per touch: distance off its side [mm], outward positive
};

// Three touches give the circumcentre; more, the least-squares circle of
// their distances (geometric fit, Gauss-Newton from the algebraic one).
std::variant<CircleFit, FitProblem> fitCircle(const std::vector<Touch>& touches, const FitSettings& s);

// One touch on each side at least; a side touched twice or more gives the
// rotation (all sides fitted with that direction, the directions of every
// side touched twice pooled).
std::variant<RectangleFit, FitProblem> fitRectangle(const std::vector<Touch>& touches, const FitSettings& s);

// "-X" / "+X" / "-Y" / "+Y".
const char* toString(Side s);

}  // namespace taiwa::probe
