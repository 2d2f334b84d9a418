// Cutter profiles of the tool types: flat and bull-nose end mills, ball end
// mills, drills (conical point), taper end mills (cone frustum).
#include "sim/cutter_profile.h"

#include "model/geometry.h"

#include <algorithm>
#include <cmath>

namespace taiwa::sim {

CutterProfile::CutterProfile(const Tool& tool)
{
    radius_ = std::max(tool.radius(), 1e-3);
    length_ = tool.fluteLength > 0 ? tool.fluteLength : 3.0 * tool.diameter;
    switch (tool.type) {
    case ToolType::Drill:
    case ToolType::CentreDrill:
        shape_ = Shape::Drill;
        pointSlope_ = 1.0 / tanDeg(std::clamp(tool.pointAngle, 1.0, 179.0) / 2.0);
        break;
    case ToolType::BallEndMill: cornerRadius_ = radius_; break;
    case ToolType::TaperEndMill:
        shape_ = Shape::Taper;
        flankSlope_ = tanDeg(std::clamp(tool.taperAngle, 0.0, 89.0));
        cornerRadius_ = std::min(tool.cornerRadius, radius_);
        break;
    default: cornerRadius_ = std::clamp(tool.cornerRadius, 0.0, radius_); break;
    }
    reach_ = shape_ == Shape::Taper ? radius_ + length_ * flankSlope_ : radius_;
    if (shape_ != Shape::Drill) {
        flatUpTo_ = radius_ - cornerRadius_;
        flatUpTo2_ = flatUpTo_ * flatUpTo_;
    }
}

double CutterProfile::curvedHeight(double r) const
{
    if (shape_ == Shape::Drill) return r * pointSlope_;
    if (shape_ == Shape::Taper && r > radius_) return flankSlope_ > 0 ? (r - radius_) / flankSlope_ : 0.0;
    const double flat = radius_ - cornerRadius_;
    if (r <= flat) return 0.0;
    const double u = std::min(r - flat, cornerRadius_);
    return cornerRadius_ - std::sqrt(cornerRadius_ * cornerRadius_ - u * u);
}

std::vector<std::pair<double, double>> CutterProfile::outline(int samplesPerCurve) const
{
    std::vector<std::pair<double, double>> pts{{0.0, 0.0}};
    if (shape_ == Shape::Drill) {
        pts.emplace_back(radius_, height(radius_));
    } else {
        const double flat = radius_ - cornerRadius_;
        if (flat > 0) pts.emplace_back(flat, 0.0);
        for (int i = 1; cornerRadius_ > 0 && i <= samplesPerCurve; ++i)
            pts.emplace_back(flat + cornerRadius_ * i / samplesPerCurve, height(flat + cornerRadius_ * i / samplesPerCurve));
    }
    pts.emplace_back(reach_, std::max(length_, pts.back().second));
    pts.emplace_back(0.0, std::max(length_, pts.back().second));
    return pts;
}

}  // namespace taiwa::sim
