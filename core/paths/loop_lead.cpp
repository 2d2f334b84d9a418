// Where a closed tool-centre loop is entered and the moves along a contour
// (paths/loop_lead.h).
#include "paths/loop_lead.h"

namespace taiwa::paths {

std::size_t longestPiece(const Contour& loop)
{
    std::size_t best = 0;
    double bestLength = -1.0;
    for (std::size_t i = 0; i < loop.segments.size(); ++i) {
        const ContourSegment& s = loop.segments[i];
        const double l = s.length() * (s.isArc() ? 0.5 : 1.0);  // lines first
        if (l > bestLength) bestLength = l, best = i;
    }
    return best;
}

Contour startedAtMiddle(const Contour& loop, std::size_t k)
{
    const ContourSegment& s = loop.segments[k];
    const Point2 middle = s.at(0.5);
    ContourSegment first = s, second = s;
    first.end = middle;
    second.start = middle;
    Contour out;
    out.closed = true;
    out.segments.push_back(second);
    for (std::size_t i = 1; i < loop.segments.size(); ++i)
        out.segments.push_back(loop.segments[(k + i) % loop.segments.size()]);
    out.segments.push_back(first);
    return out;
}

void appendPieces(PathBuilder& b, const Contour& contour, double z)
{
    for (const ContourSegment& s : contour.segments) {
        if (s.isArc()) b.arc(s.kind == ContourSegment::Kind::ArcCCW, Point3{s.end.x, s.end.y, z}, s.centre);
        else b.feed(Point3{s.end.x, s.end.y, z});
    }
}

}  // namespace taiwa::paths
