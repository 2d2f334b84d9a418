// The gang-tool lathe's tool change (gang_change.h).
#include "machine/gang_change.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace taiwa {

bool anyToolInside(const GangSlide& slide, turning::ZR s, const PartEnvelope& part)
{
    const double c = slide.clearance;
    for (const auto& p : slide.places) {
        const double z = s.z + p.offset.z, r = s.r + p.offset.r;
        if (z < part.zFront + c && z > part.zBack - c && std::abs(r) < part.radius + c) return true;
    }
    return false;
}

Result<GangChange> gangToolChange(const GangSlide& slide, int from, turning::ZR at, int to, turning::ZR start,
                                  const PartEnvelope& part)
{
    const GangPlace* a = slide.place(from);
    const GangPlace* b = slide.place(to);
    for (const auto& [tool, place] : {std::pair{from, a}, std::pair{to, b}})
        if (!place)
            return Failure{"tools.T" + std::to_string(tool) + ": tool " + std::to_string(tool) +
                           " has no mounting offset on the gang slide (gangSlide.tools)"};
    double lowest = 1e300;
    for (const auto& p : slide.places) lowest = std::min(lowest, p.offset.z);
    GangChange c;
    const turning::ZR s0{at.z - a->offset.z, at.r - a->offset.r};
    // Every tip beyond the front by the clearance (and a hair, so that
    // "inside" does not hold on the boundary).
    const double clearZ = std::max(s0.z, part.zFront + slide.clearance + 1e-6 - lowest);
    const turning::ZR s1{clearZ, s0.r};
    const turning::ZR s2{clearZ, start.r - b->offset.r};
    const turning::ZR s3{start.z - b->offset.z, s2.r};
    c.slide = {s0, s1, s2, s3};
    return c;
}

}  // namespace taiwa
