// The exact nearest approach of two contour segments (lines and arcs): the
// proof that a side-milling chain keeps its distance from the contour
// (contour_offset.h chainClearance) asks it of every pair that can come
// near, instead of probing points along the chain. Internal to core/paths/.
//
// The nearest pair of points of two segments is either a crossing (gap 0),
// an end of one against the other, or a pair inside both: for a line and an
// arc on the arc's radius square to the line, for two arcs on the line of
// their centres. Each such point of the first segment is a seed; the seed's
// nearest point of the first segment, and that point's nearest point of the
// second, make a pair of points truly on both. The least of these pairs is
// the exact gap, since it includes the nearest pair and no pair is nearer.
#pragma once

#include "model/contour.h"

namespace taiwa::paths {

struct SegmentGap {
    double gap = 0.0;  // the least distance between the two segments
    Point2 onA{};      // where on the first segment it is reached
    Point2 onB{};      // and on the second
};
SegmentGap segmentGap(const ContourSegment& a, const ContourSegment& b);

// The least distance between the two segments' bounding boxes (arcs exact):
// no point of the two comes nearer. 0 when the boxes overlap.
double boxGap(const Box2& a, const Box2& b);
Box2 segmentBox(const ContourSegment& s);

}  // namespace taiwa::paths
