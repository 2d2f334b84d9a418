// The milling verifier's checks of material left (milling_verifier.h):
// after a roughing layer, a floor finish, a face-milling layer or a pilot
// hole, and after each unit's last finishing step.
#include "verify/milling_verifier.h"

#include <numbers>

namespace taiwa::verify::milling {

// A roughing layer, a floor finish or a face-milling layer clears its
// unit's cross-section at its depth, less the walls' allowance (and its
// tool's corner radius);
// a pilot hole reaches its depth at its centre.
void Verifier::restAfterStep(int k, int row0, int row1, Collector& out)
{
    const Step& s = plan_.steps[static_cast<std::size_t>(k)];
    const MillingGeometry& g = millingOf(s);
    const StepData& d = steps_[static_cast<std::size_t>(k)];
    const float* h = field_.data();
    const double tolerance = kGougeTolerance + zStep_;
    if (s.machiningType == MachiningType::PilotHole) {
        const Stock& st = field_.stock();
        const int i = static_cast<int>(std::floor((g.position.x - st.x) / res_));
        const int j = static_cast<int>(std::floor((g.position.y - st.y) / res_));
        if (i < 0 || j < row0 || i >= field_.columns() || j > row1) return;
        const double allowed = -g.cutDepth + tolerance + d.cutter->height(distance(field_.centre(i, j), g.position));
        if (h[field_.indexOf(i, j)] > allowed)
            out.add(FindingKind::RestMaterial, k, -1, "", {g.position.x, g.position.y, h[field_.indexOf(i, j)]},
                    h[field_.indexOf(i, j)] - allowed + tolerance, cellArea());
        return;
    }
    const MachiningType m = s.machiningType;
    if (m != MachiningType::Roughing && m != MachiningType::FloorFinishing && m != MachiningType::FaceMilling &&
        m != MachiningType::FaceFinishing)
        return;
    if (s.unit < 0 || s.unit >= static_cast<int>(units_.size()) || !units_[s.unit].cavity) return;
    const Cavity& cav = *units_[s.unit].cavity;
    const double slack = -(g.wallAllowance / std::cos(cav.wallAngle * std::numbers::pi / 180.0) + res_ + d.cornerRadius);
    forCells(cav, 0.0, row0, row1, [&](int i, int j, Point2 p) {
        const double z = h[field_.indexOf(i, j)];
        if (z <= -g.cutDepth + tolerance) return;
        if (cav.depthAt(p, slack) < g.cutDepth - 1e-9) return;
        out.add(FindingKind::RestMaterial, k, -1, "", {p.x, p.y, z}, z + g.cutDepth, cellArea());
    });
}

// After the last step, a unit whose walls (or inclined faces) are
// finished is cut down to its whole cavity, less what its finishing
// steps leave. (A unit roughed only keeps its stairs: its layers are
// checked one by one.)
void Verifier::restAtEnd(int row0, int row1, Collector& out)
{
    const float* h = field_.data();
    for (const UnitData& ud : units_) {
        if (!ud.cavity || ud.lastFinish < 0) continue;
        const Cavity& cav = *ud.cavity;
        const int lastStep = ud.lastFinish;
        const double slack =
            -(ud.wallAllowance / std::cos(cav.wallAngle * std::numbers::pi / 180.0) + res_ + ud.cornerRadius);
        const double tolerance = kGougeTolerance + zStep_ + cav.surfaceTolerance;
        forCells(cav, 0.0, row0, row1, [&](int i, int j, Point2 p) {
            const double z = h[field_.indexOf(i, j)];
            const double depth = cav.depthAt(p, slack);
            if (depth <= 0.0) return;
            const double excess = z - (-depth + ud.floorAllowance);
            if (excess > tolerance) out.add(FindingKind::RestMaterial, lastStep, -1, "", {p.x, p.y, z}, excess, cellArea());
        });
    }
}

}  // namespace taiwa::verify::milling
