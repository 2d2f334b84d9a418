// The two lathes beyond the one-turret lathe, as parts of a machine
// definition (machine.h, docs/two-path-lathe.md): a two-path lathe, whose
// turrets stand on opposite sides of the work, each path with its program
// origin in the machine's frame and its axis directions, so that a point of
// path 1's program is converted into path 2's by the offset between the
// origins and the mirrored X; and a gang-tool lathe, whose tools stand side
// by side on one slide, each at its mounting offset from the slide's
// reference point, with the clearance the slide keeps from the part in Z
// before it moves in X. Read from the machine file's "paths" and "gangSlide"
// keys and checked there; the refusals name the key.
#pragma once

#include "model/result.h"
#include "model/turned.h"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace taiwa {

// One path (turret, channel) of a multi-path lathe.
struct LathePath {
    std::string name;          // "upper turret"
    turning::ZR origin{};      // the path's program zero in the machine's frame (z, radius) [mm]
    int zDirection = 1;        // +1 or -1: the path's +Z along the machine's +Z or against it
    int xDirection = 1;        // +1 or -1: the path's +X away from the axis on the machine's +X side or the other
    int turretStations = 0;
};

// The wait M-codes a multi-path control offers (M101…M199 on most FANUC
// two-path controls): the numbers a balanced cut may use, both ends included.
struct WaitCodeRange {
    int first = 0, last = 0;
    bool contains(int code) const { return code >= first && code <= last; }
};

struct MultiPath {
    std::vector<LathePath> paths;  // 2 or 3, path 1 first
    WaitCodeRange waitCodes;
    // `p` of path 1's program in path `to`'s program (0-based; 0: `p`).
    turning::ZR fromPath1(turning::ZR p, std::size_t to) const;
    // `p` of path `from`'s program in path 1's (the inverse of fromPath1).
    turning::ZR toPath1(turning::ZR p, std::size_t from) const;
};

// One place on a gang slide: the tool number that sits there and its
// tip's offset from the slide's reference point (z, radius) [mm].
struct GangPlace {
    int tool = 0;
    turning::ZR offset{};
};

struct GangSlide {
    std::vector<GangPlace> places;
    double clearance = 0.0;  // kept from the part's envelope in Z and X before X moves [mm]
    const GangPlace* place(int tool) const;
};

struct LatheLayout {
    std::optional<MultiPath> multiPath;  // a two-path lathe
    std::optional<GangSlide> gang;       // a gang-tool lathe
    std::size_t pathCount() const { return multiPath ? multiPath->paths.size() : 1; }
};

// Reads the "paths", "waitCodes" and "gangSlide" keys of a lathe's
// definition (none: an empty layout, the one-turret lathe). A problem is a
// Failure whose message starts with the dotted key ("paths[1].direction.x:
// must be 1 or -1"), for the machine reader to put file and line before.
Result<LatheLayout> readLatheLayout(const nlohmann::json& machine);

}  // namespace taiwa
