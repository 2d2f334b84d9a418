// The plans the rendering tests draw: a hand-built one whose pixels are
// known (stock 100 x 80 x 30, a pilot drill at (40, 40) and one pocket
// [20, 80] x [20, 60], depth 5, roughed with a D10 end mill) and the sample
// jobs planned with the default tool library. Header only, like images.h.
#pragma once

#include "job/job_file.h"
#include "pipeline/pipeline.h"
#include "support/support.h"
#include "tools/tool_library.h"

namespace taiwa::test {

inline constexpr int kW = 800, kH = 600;
inline constexpr int kRoughing = 1;     // step index of the pocket
inline constexpr int kSlotMove = 2;     // the feed (40,40) -> (60,40) through the pocket centre
inline constexpr int kRapidMove = 16;   // the rapid (75,40,5) -> (90,70,5)

inline Plan handPlan()
{
    Plan plan;
    plan.mmJob.stock = {0, 0, 100, 80, 30};
    Tool drill;
    drill.id = 2;
    drill.type = ToolType::Drill;
    drill.diameter = 12;
    drill.fluteLength = 40;
    Tool mill;
    mill.id = 1;
    mill.type = ToolType::FlatEndMill;
    mill.diameter = 10;
    mill.fluteLength = 25;
    plan.tools = {drill, mill};

    Step pilot;
    pilot.kind = StepKind::PilotHole;
    pilot.tool = ToolChoice{2, "pilot"};
    Move cycle{MoveKind::DrillCycle, {40, 40, -4}};
    cycle.retractZ = 1;
    pilot.path = ToolPath{{40, 40, 5}, {cycle}};

    // Pocket [20,80] x [20,60], depth 5, D10: a slot through the centre,
    // then two rings counter-clockwise, then away at safe height.
    Step rough;
    rough.kind = StepKind::Roughing;
    rough.tool = ToolChoice{1, "roughing"};
    ToolPath p{{40, 40, 5}, {}};
    p.moves.push_back({MoveKind::Rapid, {40, 40, 1}});
    p.moves.push_back({MoveKind::Feed, {40, 40, -5}, {}, FeedKind::Plunge});
    for (Point2 q : {Point2{60, 40}, {70, 40}, {70, 48}, {30, 48}, {30, 32}, {70, 32}, {70, 40}, {75, 40}, {75, 55}, {25, 55},
                     {25, 25}, {75, 25}})
        p.moves.push_back({MoveKind::Feed, {q.x, q.y, -5}});
    p.moves.push_back({MoveKind::Feed, {75, 40, -5}});
    p.moves.push_back({MoveKind::Rapid, {75, 40, 5}});
    p.moves.push_back({MoveKind::Rapid, {90, 70, 5}});
    rough.path = p;
    plan.steps = {pilot, rough};
    return plan;
}

// A sample job of resources/samples, planned; an empty plan if it cannot be read.
inline Plan samplePlan(const char* name)
{
    const auto read = readJobFile(test::sourcePath(QString("resources/samples/") + name).toStdString());
    return read.job ? planJob(*read.job, TechnologyTable::builtIn(), defaultToolLibrary()) : Plan{};
}

}  // namespace taiwa::test
