// The milling verifier cutting one step into a band of the height field
// (milling_verifier.h): every piece of the step's path swept level by level,
// straight or along its arc, and each cell it lowers checked on the way for
// a gouge, a rapid into stock, and the shank or the holder in stock.
#include "verify/milling_verifier.h"

#include "model/translate_noop.h"
#include "sim/cutter_profile.h"
#include "sim/path_samples.h"
#include "sim/sweep.h"

namespace taiwa::verify::milling {

// Cuts step k into the band's rows; the sum of the heights it took off.
double Verifier::cutStep(int k, int row0, int row1, Collector& out)
{
    double removed = 0.0;
    const StepData& d = steps_[static_cast<std::size_t>(k)];
    const sim::CutterProfile& cutter = *d.cutter;
    const double reach = cutter.reach(), reach2 = reach * reach;
    float* h = field_.data();
    const double bottom = field_.bottom();
    std::uint64_t visits = 0;
    sim::SweepChain chain;  // where the last straight sweep ended, and its height
    std::uint64_t counted = 0;  // of `visits`, added to the job's count
    for (const sim::SweptPiece& piece : d.pieces) {
        if (maxVisits_ > 0.0 && visits > counted) {  // the bound of the work, over every band
            const auto sum = allVisits_.fetch_add(visits - counted, std::memory_order_relaxed) + (visits - counted);
            counted = visits;
            if (static_cast<double>(sum) > maxVisits_) over_.store(true, std::memory_order_relaxed);
        }
        if (over()) break;
        if (std::min(piece.from.z, piece.to.z) >= 0.0) continue;
        // The cells near one horizontal sweep at tip height z: a
        // straight piece from a to b, or the part [t0, t1] of the arc.
        const auto level = [&](double z, const auto& cellsWithin) {
            if (z >= 0.0) return;
            const bool shankLow = z + d.flute < -kTouch;
            const bool holderLow = z + d.holderZ < -kTouch;
            const double radius = holderLow ? std::max(reach, d.holderR) : reach;
            // No cell at or below the tip's height changes, nor touches
            // the shank or holder (both above the tip): skip its tile.
            const float floor = static_cast<float>(std::max(z, bottom));
            const auto runs = [&](int j, int from, int to, const auto& cells) {
                int start = -1;  // the first cell of the run still to visit
                for (int lo = from; lo <= to;) {
                    const int t = lo / kTile, hi = std::min(to, (t + 1) * kTile - 1);
                    if (tileTop(j, t) > floor) {
                        if (start < 0) start = lo;
                    } else if (start >= 0) {
                        cells(start, lo - 1);
                        start = -1;
                    }
                    lo = hi + 1;
                }
                if (start >= 0) cells(start, to);
            };
            cellsWithin(radius, runs, [&](int i, int j, double r2) {
                const std::size_t c = field_.indexOf(i, j);
                ++visits;
                const double before = h[c];
                const auto where = [&](double zz) {
                    const Point2 p = field_.centre(i, j);
                    return Point3{p.x, p.y, zz};
                };
                if (holderLow && before > z + d.holderZ + kTouch)
                    out.add(FindingKind::Collision, k, piece.move, TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder"), where(before), before - (z + d.holderZ));
                if (r2 > reach2) return;
                if (shankLow && before > z + d.flute + kTouch && before <= z + d.holderZ + kTouch)
                    out.add(FindingKind::Collision, k, piece.move, TAIWA_TRANSLATE_NOOP("taiwa::msg", "shank"), where(before), before - (z + d.flute));
                const double after = std::max(z + cutter.heightSquared(r2), bottom);
                const float lowered = static_cast<float>(after);  // the grid's heights are floats
                if (lowered >= h[c]) return;
                if (piece.rapid && before - after > kTouch)
                    out.add(FindingKind::RapidIntoStock, k, piece.move, "", where(after), before - after);
                h[c] = lowered;
                tileStale_[tileOf(i, j)] = 1;
                removed += before - h[c];
                if (h[c] < limit_[c]) {
                    const double area = before >= limit_[c] ? cellArea() : 0.0;  // each cell counted once
                    out.add(FindingKind::Gouge, k, piece.move, "", where(after), limit_[c] + kGougeTolerance - after, area);
                }
            });
        };
        // A straight sweep; when the last one ended where it starts, at
        // the same height and without the holder low, the cells within
        // the cutter's flat bottom of its start are at that height
        // already (or lower) and are not visited again: a contour's
        // short chords would otherwise each visit a whole disc of cells.
        const auto line = [&](Point2 a, Point2 b, double z) {
            const bool holderLow = z + d.holderZ < -kTouch;
            const double skip = holderLow ? 0.0 : chain.skip(a, z, cutter.flatRadius());
            level(z, [&](double radius, const auto& runs, const auto& visit) {
                sim::forEachCellNear(field_, a, b, radius, row0, row1, visit, skip, runs);
            });
            if (z < 0.0 && !holderLow) chain.ended(b, z);
            else chain.broken();
        };
        if (!piece.arc) {
            sim::forEachLevel(piece.from, piece.to, zStep_, line);
            continue;
        }
        chain.broken();
        // An arc exactly; a helix in parts at most zStep apart in Z, each
        // at its higher end, then its end point at its own height.
        const Point2 c = piece.centre;
        const double radius = std::hypot(piece.from.x - c.x, piece.from.y - c.y);
        const double a0 = std::atan2(piece.from.y - c.y, piece.from.x - c.x);
        const double dz = piece.to.z - piece.from.z;
        const int n = std::max(1, static_cast<int>(std::ceil(std::abs(dz) / zStep_)));
        for (int part = 0; part < n; ++part) {
            const double t0 = static_cast<double>(part) / n, t1 = static_cast<double>(part + 1) / n;
            const double z = std::max(piece.from.z + t0 * dz, piece.from.z + t1 * dz);
            level(z, [&](double reachOf, const auto& runs, const auto& visit) {
                sim::forEachCellNearArc(field_, c, radius, a0 + t0 * piece.sweep, (t1 - t0) * piece.sweep, reachOf, row0,
                                        row1, visit, runs);
            });
        }
        if (dz != 0.0) line({piece.to.x, piece.to.y}, {piece.to.x, piece.to.y}, piece.to.z);
    }
    visits_ += visits;
    return removed;
}

}  // namespace taiwa::verify::milling
