// The lathe's machine sink: what the lathe post-processor tells a lathe,
// one call per action, as MachineSink is for milling. The poster drives a
// chain of sinks (the inch adapter when the tape is in inch, then the lathe
// writer); every length, feed per revolution and surface speed a sink
// receives is in the chain's units at that point (mm, mm/rev and m/min in
// the core). Positions are turning::ZR, X as a radius: the writer writes
// it as a diameter.
#pragma once

#include "model/turn_path.h"
#include "post/post.h"

#include <string>
#include <vector>

namespace taiwa::post {

// A turret station of the program, as the header lists it.
struct LatheStation {
    int station = 0;
    int libraryId = 0;
    const Tool* tool = nullptr;  // null: not in the library ("?" in the header)
    double noseRadius = 0.0;
    int orientation = 0;
};

struct LatheProgramInfo {
    std::string name;
    int number = 1000;
    std::string machine;
    std::string material;
    std::string fileStem;   // the tool table beside the tape (LinuxCNC), when known
    std::string workOffset = "G54";
    std::vector<LatheStation> stations;  // in order of first use
};

// The spindle as a step runs it: constant surface speed under a limit, or a
// fixed speed.
struct LatheSpindle {
    bool constantSurfaceSpeed = true;
    double surfaceSpeed = 0.0;  // m/min in the core; ft/min after the inch adapter
    double maxRpm = 0.0;
    double rpm = 0.0;
};

// The nose-radius compensation word a move states: G41, G42, G40, or none.
enum class CompensationWord { None, Left, Right, Cancel };

// An axis of the lathe: Z along the spindle, X across it (a radius in the sink).
enum class LatheAxis { X, Z };

class LatheSink {
public:
    virtual ~LatheSink() = default;
    virtual void source(BlockSource where) = 0;
    // Framing, header, the tool list and the modes.
    virtual void programStart(const LatheProgramInfo& info) = 0;
    // A roughing contour the control's cycle will call by `number` (LinuxCNC's
    // o-subroutines, defined before use; other families ignore it).
    virtual void contourSubroutine(int number, const TurnCycle& cycle) = 0;
    virtual void comment(const std::string& text) = 0;
    virtual void toolChange(int station) = 0;
    // The spindle on (clockwise) at these speeds, written when its words change.
    virtual void spindle(const LatheSpindle& speeds) = 0;
    virtual void spindleStop() = 0;
    virtual void coolant(bool on) = 0;
    virtual void rapid(turning::ZR to, CompensationWord comp = CompensationWord::None) = 0;
    virtual void feed(turning::ZR to, double feedPerRev, CompensationWord comp = CompensationWord::None) = 0;
    // A rapid along one axis, the other staying where it is (also where the
    // chain does not know it: at the program's start), stated whole (G0 and
    // the one word): a gang slide's Z clear and X move (gang_post.h).
    virtual void rapidAlong(LatheAxis axis, double value) = 0;
    virtual void arc(bool clockwise, turning::ZR to, turning::ZR centre, double feedPerRev) = 0;
    // A threading pass synchronised with the spindle, `lead` along Z.
    virtual void threadPass(turning::ZR to, double lead) = 0;
    // The control's roughing cycle from the tool's place at the cycle's start.
    virtual void roughingCycle(int number, const TurnCycle& cycle, double feedPerRev) = 0;
    // The control's threading cycle from the drive point.
    virtual void threadingCycle(const TurnThread& thread) = 0;
    virtual void programEnd() = 0;
};

}  // namespace taiwa::post
