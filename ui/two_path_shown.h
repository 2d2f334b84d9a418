// What the station shows of a job on a two-path lathe
// (docs/two-path-lathe.md "In the station"): the balanced roughing and its
// timeline exactly as the sheet has them (export/two_path_sheet.h), both
// paths' programs posted in the dialect on view as the export writes them,
// each program's lines naming the step and move of the job's plan they were
// posted from (the roughing's moves as the single path's, which the 3-D
// view draws), which tools stand on each path's turret, and where each
// path's tool is at each roughing move (the 3-D view draws both turrets'
// tools there).
#pragma once

#include "export/two_path_sheet.h"
#include "post/post.h"

#include <QColor>
#include <QString>

#include <optional>
#include <string>
#include <vector>

namespace taiwa::ui {

struct TwoPathShown {
    BalancedRoughing balanced;
    std::vector<std::string> pathNames;   // the machine's ("upper turret")
    std::vector<PostedProgram> programs;  // STEM.p1, STEM.p2; empty: `error` says why
    QString error;                        // the balancing's or the post's refusal (none and no programs: no roughing step)
    std::vector<std::vector<int>> tools;  // each path's tool numbers, in the order its program calls them
    // The (path, CB number) of the roughing's single-path move, or nothing.
    std::optional<std::pair<std::size_t, int>> blockOfMove(int step, int move) const;
    // The single-path move before which a block's wait and dwell stand (its first feed), -1: no such block.
    int cutMoveOf(int block) const;
    std::vector<int> blockStart;          // by CB number: its first move among the single path's
    // When the cut balances: each path's tool at each move of the roughing
    // step (verify/two_path_timeline.h toolPlaces), and the side of the axis
    // each path's turret stands on (+1 path 1's, -1 the other: X mirrored).
    ToolPlaces places;
    std::vector<int> sides;
};

// A path's name from the machine file ("upper turret") in the station's
// language when the catalogue knows it (context "taiwa::PathNames": the
// shipped machines' names); a shop's own name as its file has it.
QString localPathName(const std::string& name);
// The colour path `path`'s tool is drawn in, in the 3-D view and beside the
// path's name (viz/palette.h: kTool, kTool2, kTool3).
QColor turretColour(std::size_t path);

// Nothing for a job on a machine of one path.
std::optional<TwoPathShown> twoPathShown(const Plan& plan, const std::string& dialect, const std::string& stem);

}  // namespace taiwa::ui
