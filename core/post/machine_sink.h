// The machine sink: what a post-processor tells a machine, one call per
// action (CAMotics' MachineInterface). The poster drives a chain of sinks
// (unit adapter, then the G-code writer); every length and feed a sink
// receives is in the chain's units at that point (mm in the core).
#pragma once

#include "model/toolpath.h"
#include "post/post.h"

#include <string>
#include <vector>

namespace taiwa::post {

struct ToolEntry {
    int number = 0;
    double diameter = 0.0;
    std::string name;
};

struct ProgramInfo {
    std::string name;
    std::string file;        // the tape's file name without extension (HEIDENHAIN's program name)
    int number = 1000;       // O-number where the dialect has one
    std::string material;
    std::vector<ToolEntry> tools;  // in order of first use
    std::string machine;           // the job's machine ("vmc"), named in the header
    // The stock block, its two corners (HEIDENHAIN's BLK FORM); none: unknown.
    bool hasStock = false;
    Point3 stockMin{}, stockMax{};
};

struct DrillCycle {
    Point3 bottom{};         // hole position and depth
    double retractZ = 0.0;   // R plane
    double peck = 0.0;       // 0: straight drilling (G81), else pecking (G83 Q)
    double feed = 0.0;       // tapping: pitch x S
    CycleKind cycle = CycleKind::Drill;  // drill, tap, ream or bore (model/toolpath.h)
    double pitch = 0.0;      // tapping: the thread's pitch, per revolution
};

enum class SpindleDirection { Off, Clockwise, CounterClockwise };

class MachineSink {
public:
    virtual ~MachineSink() = default;
    // Where the following output comes from.
    virtual void source(BlockSource where) = 0;
    virtual void programStart(const ProgramInfo& info) = 0;
    virtual void comment(const std::string& text) = 0;
    // Retract to the machine's safe height and load `tool`; its length
    // offset is applied with the first move down after it.
    virtual void toolChange(int tool) = 0;
    virtual void spindle(SpindleDirection direction, double rpm) = 0;
    virtual void coolant(bool on) = 0;
    virtual void rapid(const Point3& to) = 0;
    virtual void feed(const Point3& to, double feedRate) = 0;
    // Circular (or, with a change of Z, helical) move in the XY plane.
    virtual void arc(const Point3& to, Point2 centre, bool clockwise, double feedRate) = 0;
    virtual void drillCycle(const DrillCycle& cycle) = 0;
    virtual void dwell(double seconds) = 0;
    // Retract, end of program, trailer.
    virtual void programEnd() = 0;
};

}  // namespace taiwa::post
