// A small appender for tool paths: keeps the current tool position so that
// every generator writes moves as "go there" without repeating bookkeeping,
// drops zero-length moves and turns degenerate arcs into lines.
#pragma once

#include "model/toolpath.h"

#include <cmath>

namespace taiwa::paths {

// The shortest arc a path holds, in radius and in length [mm]: below it a
// controller has nothing to draw, and written to 3 decimals the ends and the
// centre coincide (a slot's collapsed ring once came out as
// "G3 X92 Y30 I0 J0", a zero-radius full circle LinuxCNC refuses).
inline constexpr double kMinArc = 1e-3;

class PathBuilder {
public:
    explicit PathBuilder(Point3 start) { path_.start = start; at_ = start; }

    const Point3& at() const { return at_; }
    void rapid(Point3 to) { add({MoveKind::Rapid, to}); }
    void feed(Point3 to, FeedKind kind = FeedKind::Cut)
    {
        Move m{MoveKind::Feed, to};
        m.feed = kind;
        add(m);
    }
    // An arc whose radius or length is below kMinArc is its chord, a line
    // to its end (nothing when it ends where it starts). The chord of a
    // convex contour's corner lies inside the arc, within its radius of it.
    void arc(bool ccw, Point3 to, Point2 centre, FeedKind kind = FeedKind::Cut)
    {
        Move m{ccw ? MoveKind::ArcCCW : MoveKind::ArcCW, to, centre};
        m.feed = kind;
        const double r = std::hypot(at_.x - centre.x, at_.y - centre.y);
        if (r < kMinArc || std::abs(arcSweep(at_, m)) * r < kMinArc) {
            m.kind = MoveKind::Feed;
            m.centre = {};
        }
        add(m);
    }
    void add(const Move& m)
    {
        if (m.kind != MoveKind::DrillCycle && m.end == at_) return;  // no zero-length moves
        path_.moves.push_back(m);
        if (m.kind != MoveKind::DrillCycle) at_ = m.end;
    }
    ToolPath take() { return std::move(path_); }

private:
    ToolPath path_;
    Point3 at_;
};

}  // namespace taiwa::paths
