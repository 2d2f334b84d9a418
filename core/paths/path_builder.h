// A small appender for tool paths: keeps the current tool position so that
// every generator writes moves as "go there" without repeating bookkeeping.
#pragma once

#include "model/toolpath.h"

namespace taiwa::paths {

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
    void arc(bool ccw, Point3 to, Point2 centre, FeedKind kind = FeedKind::Cut)
    {
        Move m{ccw ? MoveKind::ArcCCW : MoveKind::ArcCW, to, centre};
        m.feed = kind;
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
