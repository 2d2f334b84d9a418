// The shape of a cutter as data: the height of its cutting surface above the
// tool tip as a function of the distance from the axis (OpenCAMLib style),
// for the material-removal simulation and the tool glyph of the 3-D view.
#pragma once

#include "model/tool.h"

#include <cmath>
#include <vector>

namespace taiwa::sim {

class CutterProfile {
public:
    explicit CutterProfile(const Tool& tool);

    // Largest distance from the axis at which the tool cuts [mm].
    double reach() const { return reach_; }
    // Height above the tip of the cutting surface at distance r from the
    // axis (0 <= r <= reach()): 0 on a flat bottom, growing on a corner
    // radius, a ball, a drill point or a taper flank.
    double height(double r) const { return r <= flatUpTo_ ? 0.0 : curvedHeight(r); }
    // The same from the square of the distance (no root on the flat bottom).
    double heightSquared(double r2) const { return r2 <= flatUpTo2_ ? 0.0 : curvedHeight(std::sqrt(r2)); }
    // The radius of the flat bottom, where height() is 0 (none: -1).
    double flatRadius() const { return flatUpTo_; }
    // Length of the cutting part above the tip (flute length, or 3 x D when
    // the library does not say).
    double cuttingLength() const { return length_; }
    // The outline (r, h) from the tip up the cutting part, for drawing the
    // tool as a solid of revolution: starts on the axis at the tip.
    std::vector<std::pair<double, double>> outline(int samplesPerCurve = 8) const;

private:
    double curvedHeight(double r) const;
    enum class Shape { Flat, Drill, Taper };
    Shape shape_ = Shape::Flat;
    double radius_ = 0.0;        // tip radius (flat, ball, taper) or drill radius
    double cornerRadius_ = 0.0;  // flat / ball / taper tip rounding
    double pointSlope_ = 0.0;    // drill: height per mm of radius
    double flankSlope_ = 0.0;    // taper: radius per mm of height (tan of the taper angle)
    double length_ = 0.0;
    double reach_ = 0.0;
    double flatUpTo_ = -1.0;     // the flat bottom's radius (none: -1)
    double flatUpTo2_ = -1.0;    // its square (none: -1)
};

}  // namespace taiwa::sim
