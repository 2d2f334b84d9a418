// The gang-tool lathe's tape (gang_post.h): the lathe post's program
// through one more link of its sink chain, the gang change, placed between
// the poster and the writer: it holds back the rapid to the change point,
// writes the Z clear in the old tool's offset and the T word at the tool
// change, and the X move (Z where the slide is, in the new tool's offset)
// before the first motion after it. Every block it writes goes through the
// writer and the block tape (N words, the line limit) like the poster's.
#include "post/gang_post.h"

#include "post/dialect.h"
#include "post/lathe_post.h"
#include "post/lathe_sink.h"
#include "model/turn_path.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

namespace taiwa {

namespace {

using post::CompensationWord;
using post::LatheAxis;

// The gang change as a link of the lathe's sink chain, in mm. The slide
// stands at a tool's tip less its mounting offset; a change moves it along
// Z out of the part (every tool beyond the part's front by the clearance,
// and by the offsets' spread in Z besides, for a control that applies the
// new offset at the T word), then along X to the first motion's X, then
// the poster's approach, which now moves Z alone.
class GangChangeAdapter final : public post::LatheSink {
public:
    GangChangeAdapter(post::LatheSink& next, const GangSlide& slide, const PartEnvelope& part, double changeX)
        : next_(next), slide_(slide), changeX_(changeX)
    {
        double lowest = 0.0, highest = 0.0;
        for (std::size_t k = 0; k < slide.places.size(); ++k) {
            lowest = k ? std::min(lowest, slide.places[k].offset.z) : slide.places[k].offset.z;
            highest = k ? std::max(highest, slide.places[k].offset.z) : slide.places[k].offset.z;
        }
        // Up to the next whole millimetre beyond it (not on the boundary itself).
        clearSlide_ = std::ceil(part.zFront + slide.clearance + (highest - lowest) - lowest + 1e-3);
    }

    void source(BlockSource where) override
    {
        flush();
        later([this, where] { next_.source(where); });
    }
    void programStart(const post::LatheProgramInfo& info) override
    {
        for (const auto& s : info.stations) {
            const GangPlace* p = slide_.place(s.libraryId);
            if (!p) throw std::logic_error(fmt::format("gang post: no tool on the slide for station {}", s.station));
            places_[s.station] = p;
        }
        next_.programStart(info);
    }
    void contourSubroutine(int number, const TurnCycle& cycle) override
    {
        flush();
        next_.contourSubroutine(number, cycle);
    }
    void comment(const std::string& text) override
    {
        flush();
        later([this, text] { next_.comment(text); });
    }
    void spindle(const post::LatheSpindle& speeds) override
    {
        flush();
        later([this, speeds] { next_.spindle(speeds); });
    }
    void spindleStop() override
    {
        flush();
        later([this] { next_.spindleStop(); });
    }
    void coolant(bool on) override
    {
        flush();
        later([this, on] { next_.coolant(on); });
    }

    // A rapid is held back until the next call says whether it was the
    // change point's (replaced by the Z clear) or a motion of the program.
    void rapid(turning::ZR to, CompensationWord comp) override
    {
        flush();
        arrive(to.r);
        held_ = {to, comp};
        beforeHeld_ = tip_;
        tip_ = to;
    }
    void feed(turning::ZR to, double feedPerRev, CompensationWord comp) override
    {
        flush();
        arrive(to.r);
        next_.feed(to, feedPerRev, comp);
        tip_ = to;
    }
    void rapidAlong(LatheAxis axis, double value) override
    {
        flush();
        next_.rapidAlong(axis, value);
        if (tip_) (axis == LatheAxis::X ? tip_->r : tip_->z) = value;
    }
    void arc(bool clockwise, turning::ZR to, turning::ZR centre, double feedPerRev) override
    {
        flush();
        arrive(to.r);
        next_.arc(clockwise, to, centre, feedPerRev);
        tip_ = to;
    }
    void threadPass(turning::ZR to, double lead) override
    {
        flush();
        arrive(to.r);
        next_.threadPass(to, lead);
        tip_ = to;
    }
    // The controls' cycles end where they started (the poster's rapid to
    // the cycle's start follows the roughing cycle).
    void roughingCycle(int number, const TurnCycle& cycle, double feedPerRev) override
    {
        flush();
        arrive(cycle.start.r);
        next_.roughingCycle(number, cycle, feedPerRev);
    }
    void threadingCycle(const TurnThread& thread) override
    {
        flush();
        arrive(thread.crestR + thread.clearance);
        next_.threadingCycle(thread);
    }

    void toolChange(int station) override
    {
        clearZ();
        const auto at = places_.find(station);
        if (at == places_.end()) throw std::logic_error(fmt::format("gang post: no tool on the slide for station {}", station));
        next_.toolChange(station);
        active_ = at->second;
        // The X move waits for the first motion's X; what comes before it
        // (the spindle, the coolant) is said after it, as the slide is then clear.
        xPending_ = true;
    }
    void programEnd() override
    {
        clearZ();
        next_.rapidAlong(LatheAxis::X, changeX_ / 2.0);
        next_.programEnd();
    }

private:
    struct Held {
        turning::ZR to;
        CompensationWord comp;
    };

    // Said now, or after the X move when one is pending.
    void later(std::function<void()> call)
    {
        if (xPending_) deferred_.push_back(std::move(call));
        else call();
    }
    // The held rapid was a motion of the program: written.
    void flush()
    {
        if (!held_) return;
        const Held h = *held_;
        held_.reset();
        next_.rapid(h.to, h.comp);
    }
    // The first motion after a change: the slide along X to its X, Z where
    // the slide is, then what waited for it.
    void arrive(double r)
    {
        if (!xPending_) return;
        xPending_ = false;
        const turning::ZR at{slideZ_ + active_->offset.z, r};
        next_.rapid(at);
        tip_ = at;
        for (auto& call : deferred_) call();
        deferred_.clear();
    }
    // In place of the change point's rapid (or after the last motion, when
    // there was none): Z out in the old offset from where the tip stood, or
    // stays where it is when already further.
    void clearZ()
    {
        if (xPending_) {  // a change with no motion after it: what waited is said
            xPending_ = false;
            for (auto& call : deferred_) call();
            deferred_.clear();
        }
        const std::optional<turning::ZR> from = held_ ? beforeHeld_ : tip_;
        held_.reset();
        slideZ_ = from ? std::max(from->z - active_->offset.z, clearSlide_) : clearSlide_;
        next_.rapidAlong(LatheAxis::Z, slideZ_ + active_->offset.z);
        tip_ = from ? std::optional<turning::ZR>({slideZ_ + active_->offset.z, from->r}) : std::nullopt;
    }

    post::LatheSink& next_;
    const GangSlide& slide_;
    double changeX_;  // the change point's X, a diameter [mm]
    double clearSlide_ = 0.0;
    std::map<int, const GangPlace*> places_;  // by turret station
    const GangPlace none_{};                  // at the program's start no tool offset is in force: the slide's reference
    const GangPlace* active_ = &none_;
    double slideZ_ = 0.0;
    std::optional<turning::ZR> tip_, beforeHeld_;  // the programmed position (X as a radius), and before the held rapid
    std::optional<Held> held_;
    bool xPending_ = false;
    std::vector<std::function<void()>> deferred_;
};

}  // namespace

PartEnvelope pathsEnvelope(const std::vector<Step>& steps)
{
    PartEnvelope e{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), 0.0};
    const auto take = [&](turning::ZR p) {
        e.zFront = std::max(e.zFront, p.z);
        e.zBack = std::min(e.zBack, p.z);
        e.radius = std::max(e.radius, std::abs(p.r));
    };
    for (const Step& s : steps)
        if (turnOf(s)) {
            take(turnOf(s)->path.start);
            for (const auto& m : turnOf(s)->path.moves) take(m.end);
        }
    if (e.zFront < e.zBack) e = {};
    return e;
}

PostedProgram postGangTool(const std::vector<Step>& steps, const std::vector<Tool>& library, const GangSlide& slide,
                           const PartEnvelope& part, const PostOptions& options)
{
    for (const Step& s : steps)
        if (s.tool && !slide.place(s.tool->toolId))
            throw Refusal(
                fmt::format("tools.T{0}: tool {0} has no mounting offset on the gang slide (gangSlide.tools)", s.tool->toolId));
    return postLathe(steps, library, options, [&](post::LatheSink& next) {
        return std::make_unique<GangChangeAdapter>(next, slide, part, options.latheChangeX);
    });
}

}  // namespace taiwa
