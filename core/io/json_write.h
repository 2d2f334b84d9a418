// Writing values into a job document the canonical way (job-format.md): whole
// numbers without ".0", points as [x, y], tool pins as an object. Shared by
// the job writer and every module's writer; and lengths of the step list
// (STEM.steps.json) in its unit, written by the export and the modules' doors.
#pragma once

#include "model/geometry.h"
#include "model/job.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>

namespace taiwa::io {

using ordered = nlohmann::ordered_json;

// A whole number is written as one ("20", not "20.0"); up to 2^53 every whole
// double is exact as an integer.
inline ordered number(double v)
{
    constexpr double kExactInteger = 9007199254740992.0;  // 2^53
    if (std::isfinite(v) && v == std::floor(v) && std::fabs(v) <= kExactInteger) return static_cast<std::int64_t>(v);
    return v;
}

inline ordered point(Point2 p) { return ordered::array({number(p.x), number(p.y)}); }

// A length of the step list: `mm` in the file's unit, rounded to 1 nm (no
// 15.299999999999997); a point of them as [x, y].
inline double stepLength(double mm, LengthUnit u) { return std::round(fromMm(mm, u) * 1e6) / 1e6; }
inline ordered stepPoint(Point2 p, LengthUnit u) { return ordered::array({stepLength(p.x, u), stepLength(p.y, u)}); }

inline ordered pins(const ToolPins& tools)
{
    ordered out = ordered::object();
    for (const auto& [step, id] : tools) out[step] = id;
    return out;
}

}  // namespace taiwa::io
