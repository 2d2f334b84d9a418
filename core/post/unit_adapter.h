// The unit adapter of the sink chain: the core works in mm; for an inch tape
// this sink divides every length and feed by 25.4 and passes the call on
// (CAMotics' MachineUnitAdapter). Speeds, times and numbers pass unchanged.
#pragma once

#include "post/machine_sink.h"

namespace taiwa::post {

class InchAdapter final : public MachineSink {
public:
    explicit InchAdapter(MachineSink& next) : next_(next) {}

    void source(BlockSource where) override { next_.source(where); }
    void programStart(const ProgramInfo& info) override;
    void comment(const std::string& text) override { next_.comment(text); }
    void toolChange(int tool) override { next_.toolChange(tool); }
    void spindle(SpindleDirection direction, double rpm) override { next_.spindle(direction, rpm); }
    void coolant(bool on) override { next_.coolant(on); }
    void rapid(const Point3& to) override { next_.rapid(inch(to)); }
    void feed(const Point3& to, double feedRate) override { next_.feed(inch(to), inch(feedRate)); }
    void arc(const Point3& to, Point2 centre, bool clockwise, double feedRate) override;
    void drillCycle(const DrillCycle& cycle) override;
    void dwell(double seconds) override { next_.dwell(seconds); }
    void programEnd() override { next_.programEnd(); }

private:
    static double inch(double mm);
    static Point3 inch(const Point3& mm) { return {inch(mm.x), inch(mm.y), inch(mm.z)}; }

    MachineSink& next_;
};

}  // namespace taiwa::post
