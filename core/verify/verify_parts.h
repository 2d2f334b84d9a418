// The milling verifier's parts (milling_verifier.h): what one step and one unit hand
// the bands, the collector of the worst cell per finding, and the check of
// the paths against the machine's travel. Internal to core/verify.
#pragma once

#include "model/cavity.h"
#include "model/plan.h"
#include "sim/cutter_profile.h"
#include "sim/path_samples.h"
#include "verify/verify.h"

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace taiwa::verify {

// What one step hands the bands.
struct StepData {
    bool cuts = false;
    std::vector<sim::SweptPiece> pieces;
    std::optional<sim::CutterProfile> cutter;
    double cornerRadius = 0.0;
    double flute = 0.0;      // the flutes' length above the tip: the shank above it
    double holderZ = 0.0;    // the stick-out: the holder's nose above it (0: no holder check)
    double holderR = 0.0;    // the nose's radius
};

// A unit's cavity and what its finishing steps (walls, inclined faces) are
// meant to leave of it: the least allowances of those steps, the largest
// corner radius of their tools (a corner the tool cannot reach), the last.
struct UnitData {
    std::optional<Cavity> cavity;
    double wallAllowance = std::numeric_limits<double>::infinity();
    double floorAllowance = std::numeric_limits<double>::infinity();
    double cornerRadius = 0.0;
    int lastFinish = -1;
};

// The worst cell per kind, step, move and part found by one band.
class Collector {
public:
    Finding& at(FindingKind kind, int step, int move, const char* part)
    {
        const Key key{static_cast<int>(kind), step, move, part};
        if (last_ && key == lastKey_) return *last_;
        auto [it, fresh] = worst_.try_emplace(key);
        if (fresh) {
            it->second.kind = kind;
            it->second.step = step;
            it->second.move = move;
            it->second.part = part;
        }
        lastKey_ = key;
        last_ = &it->second;
        return it->second;
    }
    void add(FindingKind kind, int step, int move, const char* part, Point3 where, double size, double area = 0.0)
    {
        Finding& f = at(kind, step, move, part);
        f.area += area;
        if (size > f.size) {
            f.size = size;
            f.position = where;
        }
    }
    void mergeInto(std::map<std::tuple<int, int, int, std::string>, Finding>& all) const
    {
        for (const auto& [key, f] : worst_) {
            auto [it, fresh] = all.try_emplace({std::get<0>(key), std::get<1>(key), std::get<2>(key), f.part}, f);
            if (fresh) continue;
            it->second.area += f.area;
            if (f.size > it->second.size) {
                it->second.size = f.size;
                it->second.position = f.position;
            }
        }
    }

private:
    using Key = std::tuple<int, int, int, const char*>;
    std::map<Key, Finding> worst_;
    Key lastKey_{};
    Finding* last_ = nullptr;
};

// The findings of the whole job, by (kind, step, move, part).
using FindingMap = std::map<std::tuple<int, int, int, std::string>, Finding>;

// The tip's extent over every path against the machine's travel: a
// TravelLimit finding per axis the paths span more of than it travels.
void addTravelFindings(const Plan& plan, const std::vector<StepData>& steps, FindingMap& all);

}  // namespace taiwa::verify
