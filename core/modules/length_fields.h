// The lengths of a module input through one conversion (model/module.h's
// LengthMap, mm <-> inch), for the input structs' convertLengths and the
// regions of named_region.h: convertEach(f, a, b, ...) converts each length
// it is given whatever holds it — a number, an optional one (when present),
// a point, a contour segment, a contour, a region, or a range of any of
// these — so that a struct names its lengths and nothing else.
#pragma once

#include "model/contour.h"
#include "model/geometry.h"
#include "model/module.h"
#include "model/toolpath.h"

#include <optional>
#include <ranges>

namespace taiwa {

inline void convertLength(const LengthMap& f, double& v) { v = f(v); }
inline void convertLength(const LengthMap& f, Point2& p) { p = {f(p.x), f(p.y)}; }
inline void convertLength(const LengthMap& f, Point3& p) { p = {f(p.x), f(p.y), f(p.z)}; }
template <class T>
void convertLength(const LengthMap& f, std::optional<T>& v);
template <std::ranges::range R>
void convertLength(const LengthMap& f, R& range);
inline void convertLength(const LengthMap& f, ContourSegment& s)
{
    convertLength(f, s.start);
    convertLength(f, s.end);
    convertLength(f, s.centre);
}
inline void convertLength(const LengthMap& f, Contour& c) { convertLength(f, c.segments); }
inline void convertLength(const LengthMap& f, Region& r)
{
    convertLength(f, r.outer);
    convertLength(f, r.islands);
}

template <class T>
void convertLength(const LengthMap& f, std::optional<T>& v)
{
    if (v) convertLength(f, *v);
}

template <std::ranges::range R>
void convertLength(const LengthMap& f, R& range)
{
    for (auto& v : range) convertLength(f, v);
}

template <class... Lengths>
void convertEach(const LengthMap& f, Lengths&... lengths)
{
    (convertLength(f, lengths), ...);
}

}  // namespace taiwa
