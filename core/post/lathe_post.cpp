// The lathe post-processor (lathe_post.h): the poster, which walks the
// steps and decides what the lathe is told (tool changes, spindle, coolant,
// each move or the control's cycle), through the lathe's sink chain: the
// stage a caller puts first (the gang change), the inch adapter when the
// tape is in inch, then the lathe writer, which says it in the dialect's
// family of words (lathe_writer.h) on the block tape.
#include "post/lathe_post.h"

#include "post/bound_tool.h"
#include "post/dialect.h"
#include "post/lathe_writer.h"
#include "post/tape_image.h"
#include "post/unit_adapter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>

namespace taiwa {

namespace {

std::string upper(std::string s)
{
    for (auto& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return s;
}

class LathePoster {
public:
    LathePoster(post::LatheSink& sink, const post::Dialect& dialect, const PostOptions& o, const std::vector<Tool>& library,
                const std::vector<Step>& steps)
        : sink_(sink), d_(dialect), o_(o), lib_(library), steps_(steps), stations_(latheStations(steps))
    {
    }

    void start()
    {
        post::LatheProgramInfo info{o_.programName, o_.programNumber, o_.machine, o_.material, o_.fileStem, o_.workOffset, {}};
        for (const auto& [station, id] : stations_) {
            const Tool& t = post::boundTool(lib_, id);
            info.stations.push_back({station, id, &t, t.cornerRadius, orientationOf(id)});
        }
        sink_.source({});
        sink_.programStart(info);
        // Roughing contours the control's cycle calls, defined before they
        // are called (LinuxCNC's subroutines; the other writers pass them by).
        for (std::size_t i = 0; i < steps_.size(); ++i)
            if (usesCycle(steps_[i])) {
                sink_.source({static_cast<int>(i), -1});
                sink_.contourSubroutine(subNumber(i), *turnOf(steps_[i])->path.cycle);
            }
    }

    void step(std::size_t index, const Step& s)
    {
        const TurnStep& ts = *turnOf(s);
        const int station = stationOf(s.tool->toolId);
        sink_.source({static_cast<int>(index), -1});
        const auto u = static_cast<std::size_t>(s.unit);
        const std::string name = u < o_.unitNames.size() && !o_.unitNames[u].empty() ? " \"" + o_.unitNames[u] + "\"" : "";
        sink_.comment(fmt::format("STEP {}: UNIT {}{} {} {} T{}", index + 1, s.unit + 1, name, s.module, upper(s.label()), s.tool->toolId));
        bool changed = false;
        if (station != station_) {
            stop();
            sink_.rapid(changePoint());
            sink_.toolChange(station);
            station_ = station;
            changed = true;
        }
        const TurnCutting& c = ts.cutting;
        sink_.spindle({c.constantSurfaceSpeed, c.surfaceSpeed, c.maxRpm, c.rpm});
        // Coolant with the first spindle start after a tool change.
        if (changed && o_.coolant && !coolant_) {
            sink_.coolant(true);
            coolant_ = true;
        }
        const TurnPath& p = ts.path;
        sink_.rapid(p.start);
        if (usesCycle(s)) {
            sink_.rapid(p.cycle->start);
            sink_.roughingCycle(subNumber(index), *p.cycle, c.feedPerRev);
            sink_.rapid(p.cycle->start);
            return;
        }
        if (ts.thread && d_.syntax != post::Syntax::Sinumerik) {
            sink_.threadingCycle(*ts.thread);
            return;
        }
        for (std::size_t m = 0; m < p.moves.size(); ++m) {
            sink_.source({static_cast<int>(index), static_cast<int>(m)});
            const TurnMove& mv = p.moves[m];
            const double f = mv.feed == FeedKind::Plunge ? c.plungeFeedPerRev : c.feedPerRev;
            auto comp = post::CompensationWord::None;
            if (p.comp != NoseCompensation::Off && static_cast<int>(m) == p.compFrom)
                comp = p.comp == NoseCompensation::Left ? post::CompensationWord::Left : post::CompensationWord::Right;
            if (p.comp != NoseCompensation::Off && static_cast<int>(m) == p.compTo) comp = post::CompensationWord::Cancel;
            switch (mv.kind) {
            case TurnMove::Rapid: sink_.rapid(mv.end, comp); break;
            case TurnMove::Feed:
                // A threading pass: synchronised with the spindle, its lead along Z.
                if (ts.thread) sink_.threadPass(mv.end, ts.thread->pitch);
                else sink_.feed(mv.end, f, comp);
                break;
            case TurnMove::ArcCW:
            case TurnMove::ArcCCW: sink_.arc(mv.kind == TurnMove::ArcCW, mv.end, mv.centre, f); break;
            }
        }
    }

    void end()
    {
        sink_.source({});
        stop();
        sink_.rapid(changePoint());
        sink_.programEnd();
    }

private:
    // The control's G71 where the step has one (Siemens' CYCLE95 is not
    // written: its tapes carry the passes).
    bool usesCycle(const Step& s) const
    {
        return o_.turningCycles && d_.syntax != post::Syntax::Sinumerik && turnOf(s) && turnOf(s)->path.cycle.has_value();
    }
    static int subNumber(std::size_t stepIndex) { return 100 + static_cast<int>(stepIndex) + 1; }
    turning::ZR changePoint() const { return {o_.latheChangeZ, o_.latheChangeX / 2.0}; }

    int stationOf(int id) const
    {
        for (const auto& [station, tool] : stations_)
            if (tool == id) return station;
        return 0;
    }
    int orientationOf(int id) const
    {
        for (const auto& s : steps_)
            if (s.tool && s.tool->toolId == id && turnOf(s)) return turnOf(s)->orientation;
        return 0;
    }

    void stop()
    {
        if (station_ == 0) return;
        if (coolant_) sink_.coolant(false);
        coolant_ = false;
        sink_.spindleStop();
    }

    post::LatheSink& sink_;
    const post::Dialect& d_;
    const PostOptions& o_;
    const std::vector<Tool>& lib_;
    const std::vector<Step>& steps_;
    std::vector<std::pair<int, int>> stations_;
    int station_ = 0;
    bool coolant_ = false;
};

}  // namespace

std::vector<std::pair<int, int>> latheStations(const std::vector<Step>& orderedSteps)
{
    std::vector<std::pair<int, int>> out;
    for (const auto& s : orderedSteps) {
        if (!s.tool) continue;
        if (std::none_of(out.begin(), out.end(), [&](const auto& p) { return p.second == s.tool->toolId; }))
            out.emplace_back(static_cast<int>(out.size()) + 1, s.tool->toolId);
    }
    return out;
}

PostedProgram postLathe(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library, const PostOptions& options)
{
    return postLathe(orderedSteps, library, options, {});
}

PostedProgram postLathe(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library, const PostOptions& options,
                        const LatheStage& stage)
{
    const post::Dialect* dialect = &post::dialectNamed(options.dialect);
    if (const auto can = post::canPost(*dialect, post::Task::LatheTape); !can) throw Refusal(can.error());
    // What planJob made and bound: a step without is the caller's bug.
    for (const auto& s : orderedSteps) {
        if (!turnOf(s) || !s.tool) throw std::logic_error("post-processor: step " + s.label() + " is not a turning step with a tool");
        (void)post::boundTool(library, s.tool->toolId);
    }
    // The chain: poster -> [stage] -> [mm to inch] -> lathe writer -> block tape.
    post::LatheWriter writer(*dialect, options.units);
    std::optional<post::LatheInchAdapter> inch;
    post::LatheSink& afterStage = options.units == LengthUnit::Inch ? static_cast<post::LatheSink&>(inch.emplace(writer)) : writer;
    const std::unique_ptr<post::LatheSink> first = stage ? stage(afterStage) : nullptr;
    post::LatheSink& sink = first ? *first : afterStage;
    LathePoster poster(sink, *dialect, options, library, orderedSteps);
    poster.start();
    for (std::size_t i = 0; i < orderedSteps.size(); ++i) poster.step(i, orderedSteps[i]);
    poster.end();
    PostedProgram p;
    p.nc = writer.takeText();
    p.lines = writer.takeSources();
    p.tapeImage = post::tapeImage(p.nc, options.programName, dialect->name, options.machine);
    return p;
}

}  // namespace taiwa
