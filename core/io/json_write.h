// Writing values into a job document the canonical way (job-format.md): whole
// numbers without ".0", points as [x, y], tool pins as an object. Shared by
// the job writer and every module's writer.
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

inline ordered pins(const ToolPins& tools)
{
    ordered out = ordered::object();
    for (const auto& [step, id] : tools) out[step] = id;
    return out;
}

}  // namespace taiwa::io
