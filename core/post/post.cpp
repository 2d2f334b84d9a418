// postProcess: builds the sink chain (unit adapter for inch, then the G-code
// writer of the dialect) and drives it through the ordered steps: program
// frame, a retract and tool change on every change of tool, spindle speed
// and feeds from the tool's cutting data (speedsFeeds), coolant, a comment
// naming every step, and each step's moves, each block mapped to its move.
#include "post/post.h"

#include "machine/machine.h"
#include "post/bound_tool.h"
#include "post/dialect.h"
#include "post/gang_post.h"
#include "post/gcode_writer.h"
#include "post/klartext_writer.h"
#include "post/lathe_post.h"
#include "post/tape_image.h"
#include "post/unit_adapter.h"
#include "tools/cutting.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <stdexcept>

namespace taiwa {

namespace {

using post::MachineSink;

std::string upper(std::string s)
{
    for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// A step's tool and its speeds and feeds, checked before anything is written.
struct Cutting {
    const Tool* tool = nullptr;
    SpeedsFeeds sf;
};

Cutting cuttingOf(const Step& s, const std::vector<Tool>& library, const std::string& material)
{
    // What planJob made and bound: a step without is the caller's bug.
    if (!s.tool || !s.path) throw std::logic_error("post-processor: step " + s.label() + " has no tool or no path");
    const Tool& tool = post::boundTool(library, s.tool->toolId);
    // Bound by planJob; a step made by hand gets them from the tool given.
    const auto sf = s.speeds ? s.speeds : stepSpeedsFeeds(s, tool, material);
    if (!sf) throw Refusal("post-processor: tool T" + std::to_string(tool.id) + " has no cutting data for " + material);
    return {&tool, *sf};
}

class Poster {
public:
    Poster(MachineSink& sink, const PostOptions& o) : sink_(sink), o_(o) {}

    void start(const std::vector<Cutting>& cutting)
    {
        post::ProgramInfo info{o_.programName, o_.fileStem, o_.programNumber, o_.material, {}, o_.machine, o_.hasStock, o_.stockMin, o_.stockMax};
        for (const auto& c : cutting)
            if (std::none_of(info.tools.begin(), info.tools.end(), [&](const auto& t) { return t.number == c.tool->id; }))
                info.tools.push_back({c.tool->id, c.tool->diameter, c.tool->name});
        sink_.source({});
        sink_.programStart(info);
    }

    void step(int index, const Step& s, const Cutting& c)
    {
        sink_.source({index, -1});
        // The unit by its number and the name the operator gave it (quoted:
        // a name may hold words like a step's).
        const auto u = static_cast<std::size_t>(s.unit);
        const std::string name = u < o_.unitNames.size() && !o_.unitNames[u].empty() ? " \"" + o_.unitNames[u] + "\"" : "";
        sink_.comment(fmt::format("STEP {}: UNIT {}{} {} {} T{}", index + 1, s.unit + 1, name, s.module, upper(s.label()), c.tool->id));
        const ToolPath& p = *s.path;
        const double approachZ = std::max(o_.safeZ, p.start.z);
        if (c.tool->id != tool_) {
            stopAndRetract();
            sink_.toolChange(c.tool->id);
            sink_.spindle(post::SpindleDirection::Clockwise, c.sf.rpm);
            rapid({p.start.x, p.start.y, approachZ});
            if (o_.coolant) sink_.coolant(true);
            tool_ = c.tool->id;
        } else {
            retract();
            rapid({p.start.x, p.start.y, approachZ});
        }
        rapid(p.start);
        for (std::size_t m = 0; m < p.moves.size(); ++m) {
            sink_.source({index, static_cast<int>(m)});
            move(p.moves[m], c.sf);
        }
    }

    void end()
    {
        sink_.source({});
        stopAndRetract();
        sink_.programEnd();
    }

private:
    void rapid(const Point3& to)
    {
        sink_.rapid(to);
        at_ = to;
        moved_ = true;
    }

    // Up to the safe height above the last position (no move when already there).
    void retract()
    {
        if (moved_ && at_.z < o_.safeZ) rapid({at_.x, at_.y, o_.safeZ});
    }

    void stopAndRetract()
    {
        if (tool_ == 0) return;
        retract();
        if (o_.coolant) sink_.coolant(false);
        sink_.spindle(post::SpindleDirection::Off, 0);
    }

    void move(const Move& m, const SpeedsFeeds& sf)
    {
        const double f = m.feed == FeedKind::Cut ? sf.feed : sf.plungeFeed;
        switch (m.kind) {
        case MoveKind::Rapid: sink_.rapid(m.end); break;
        case MoveKind::Feed: sink_.feed(m.end, f); break;
        case MoveKind::ArcCW: sink_.arc(m.end, m.centre, true, f); break;
        case MoveKind::ArcCCW: sink_.arc(m.end, m.centre, false, f); break;
        case MoveKind::DrillCycle:
            // Tapping feeds the pitch a revolution, whatever the tool's data say.
            sink_.drillCycle({m.end, m.retractZ, m.peck, m.cycle == CycleKind::Tap ? m.pitch * sf.rpm : sf.feed, m.cycle,
                              m.pitch});
            // G98: back at the initial level, or at R when that is higher.
            at_ = Point3{m.end.x, m.end.y, std::max(at_.z, m.retractZ)};
            return;
        }
        at_ = m.end;
    }

    MachineSink& sink_;
    const PostOptions& o_;
    int tool_ = 0;
    Point3 at_{};  // where the tool is, once it has moved
    bool moved_ = false;
};

}  // namespace

PostedProgram postProcess(const std::vector<Step>& orderedSteps, const std::vector<Tool>& library,
                          const PostOptions& options)
{
    if (std::any_of(orderedSteps.begin(), orderedSteps.end(), [](const Step& s) { return turnOf(s) != nullptr; })) {
        // A gang-tool lathe: its tool changes as the slide must make them (gang_post.h).
        if (const Machine* m = findMachine(options.machine); m && m->layout.gang)
            return postGangTool(orderedSteps, library, *m->layout.gang, pathsEnvelope(orderedSteps), options);
        return postLathe(orderedSteps, library, options);
    }
    const post::Dialect* dialect = &post::dialectNamed(options.dialect);
    std::vector<Cutting> cutting;
    cutting.reserve(orderedSteps.size());
    for (const auto& s : orderedSteps) cutting.push_back(cuttingOf(s, library, options.material));

    // The chain: poster -> [mm to inch] -> writer (G-code, or HEIDENHAIN's
    // Klartext where the job's offset G54..G59 is preset 1..6 of cycle 247).
    const std::string offset = post::workOffsetWords(*dialect, options.workOffset);
    std::optional<post::GCodeWriter> gcode;
    std::optional<post::KlartextWriter> klartext;
    MachineSink* writer = nullptr;
    if (dialect->syntax == post::Syntax::Klartext) {
        writer = &klartext.emplace(*dialect, options.units, std::stoi(offset.substr(1)) - 53);
    } else {
        std::size_t moves = 0;
        for (const auto& s : orderedSteps) moves += s.path ? s.path->moves.size() : 0;
        writer = &gcode.emplace(*dialect, options.units, offset);
        gcode->reserve(moves + 16 * orderedSteps.size() + 64);  // a block a move, plus each step's frame
    }
    std::optional<post::InchAdapter> inch;
    MachineSink& sink = options.units == LengthUnit::Inch ? static_cast<MachineSink&>(inch.emplace(*writer)) : *writer;

    Poster poster(sink, options);
    poster.start(cutting);
    for (std::size_t i = 0; i < orderedSteps.size(); ++i) poster.step(static_cast<int>(i), orderedSteps[i], cutting[i]);
    poster.end();

    PostedProgram p;
    p.nc = gcode ? gcode->takeText() : klartext->takeText();
    p.lines = gcode ? gcode->takeSources() : klartext->takeSources();
    p.tapeImage = post::tapeImage(p.nc, options.programName, dialect->name, options.machine);
    return p;
}

}  // namespace taiwa
