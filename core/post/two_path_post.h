// The programs of a balanced cut (model/two_path.h, docs/two-path-lathe.md
// "The programs"): one whole lathe program per path, `STEM.p1.nc` and
// `STEM.p2.nc`, each with its header and its own O-number (the job's, then
// the next), the path's blocks written by the lathe post as explicit passes
// in the path's coordinates, and before each block's cut its wait and its
// dwell. FANUC (two-path control): `M101` … the same number on both paths,
// `G04 X<seconds>`. LinuxCNC (no two-path control: two machine instances
// wired to each other through digital I/O): at the k-th meeting each
// program sets its output 0 to k's parity (`M64 P0` on odd meetings, `M65
// P0` on even) and waits for the other's, wired to its input 0, to say the
// same (`M66 P0 L3 Q…` high, `L4` low); a time-out stops the program
// (`M2` after a `#5399` check). Then `G4 P<seconds>`.
#pragma once

#include "machine/lathe_kinds.h"
#include "model/two_path.h"
#include "post/post.h"

#include <utility>
#include <vector>

namespace taiwa {

// `steps`: the job's turning steps in machining order; `roughing`: the
// index of the one the cut was balanced from. Path 1's program is the whole
// job with that step's passes replaced by path 1's blocks; every other
// path's program is its blocks alone (with `meetAtEnds`, balanced_roughing.h,
// they wait for path 1 to come to the roughing and path 1 waits for them
// after it). `options` as for postProcess (fileStem: the job's STEM, the
// programs say STEM.p1 and STEM.p2). Throws as
// postProcess does, and Refusal for a dialect that is neither FANUC's
// family nor LinuxCNC's.
std::vector<PostedProgram> postBalancedCut(const BalancedCut& cut, const std::vector<Step>& steps, std::size_t roughing,
                                           const MultiPath& layout, const std::vector<Tool>& library,
                                           const PostOptions& options);

// What one path's program of a balanced cut is posted from, before its
// waits go in: the steps the lathe post writes (path 1: the job's, the
// roughing's passes replaced by the path's blocks; another path: its blocks
// alone as one step), which of them is the balanced one, the options (the
// path's program number, name, stem and change point), and where each
// block's cut and the tail start among that step's moves. The read-back
// holds each path's program against the same steps (verify/tape_readback.h).
struct BalancedPathJob {
    std::vector<Step> steps;
    std::size_t step = 0;
    PostOptions options;
    std::vector<std::pair<std::size_t, const BalancedBlock*>> cuts;
    std::size_t tailFrom = 0;
};
BalancedPathJob balancedPathJob(const BalancedCut& cut, const std::vector<Step>& steps, std::size_t roughing,
                                const MultiPath& layout, const PostOptions& options, std::size_t path);

// How long a LinuxCNC program waits for its partner before it gives up [s].
constexpr double kLinuxcncWaitTimeout = 60.0;

}  // namespace taiwa
