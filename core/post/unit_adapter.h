// The unit adapters of the sink chains: the core works in mm; for an inch
// tape these sinks divide every length and feed by 25.4 and pass the call on
// (CAMotics' MachineUnitAdapter): InchAdapter for milling, LatheInchAdapter
// for the lathe, where the surface speed also becomes feet per minute.
// Spindle speeds, times and numbers pass unchanged.
#pragma once

#include "post/lathe_sink.h"
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

class LatheInchAdapter final : public LatheSink {
public:
    explicit LatheInchAdapter(LatheSink& next) : next_(next) {}

    void source(BlockSource where) override { next_.source(where); }
    void programStart(const LatheProgramInfo& info) override;
    void contourSubroutine(int number, const TurnCycle& cycle) override { next_.contourSubroutine(number, inch(cycle)); }
    void comment(const std::string& text) override { next_.comment(text); }
    void toolChange(int station) override { next_.toolChange(station); }
    void spindle(const LatheSpindle& speeds) override;
    void spindleStop() override { next_.spindleStop(); }
    void coolant(bool on) override { next_.coolant(on); }
    void rapid(turning::ZR to, CompensationWord comp) override { next_.rapid(inch(to), comp); }
    void feed(turning::ZR to, double feedPerRev, CompensationWord comp) override { next_.feed(inch(to), inch(feedPerRev), comp); }
    void rapidAlong(LatheAxis axis, double value) override { next_.rapidAlong(axis, inch(value)); }
    void arc(bool clockwise, turning::ZR to, turning::ZR centre, double feedPerRev) override
    {
        next_.arc(clockwise, inch(to), inch(centre), inch(feedPerRev));
    }
    void threadPass(turning::ZR to, double lead) override { next_.threadPass(inch(to), inch(lead)); }
    void roughingCycle(int number, const TurnCycle& cycle, double feedPerRev) override
    {
        next_.roughingCycle(number, inch(cycle), inch(feedPerRev));
    }
    void threadingCycle(const TurnThread& thread) override;
    void programEnd() override { next_.programEnd(); }

private:
    static double inch(double mm);
    static turning::ZR inch(turning::ZR mm) { return {inch(mm.z), inch(mm.r)}; }
    static TurnCycle inch(const TurnCycle& mm);

    LatheSink& next_;
};

}  // namespace taiwa::post
