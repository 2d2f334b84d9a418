// The milling verifier cutting one step into a band of the height field
// (milling_verifier.h): every piece of the step's path swept level by level,
// straight or along its arc, and each cell it lowers checked on the way for
// a gouge, a rapid into stock, and the shank or the holder in stock. A run
// of pieces that only goes down and can find nothing is cut last piece
// first (see StepCut::backwards).
#include "verify/milling_verifier.h"

#include "model/translate_noop.h"
#include "sim/cutter_profile.h"
#include "sim/path_samples.h"
#include "sim/sweep.h"

namespace taiwa::verify::milling {

namespace {

// One horizontal sweep of the tool tip at height z, as forward cutting
// makes it of a piece: a straight part a -> b (a point where a == b), or
// the part of an arc of `radius` about `centre` from angle a0 over `sweep`.
struct Sweep {
    Point2 a{}, b{};
    double z = 0.0;
    bool arc = false;
    Point2 centre{};
    double radius = 0.0, a0 = 0.0, sweep = 0.0;
};

// The sweeps of a piece: a straight piece split into levels no more than
// zStep apart (sim::forEachLevel), an arc exactly and a helix in parts,
// each at its higher end, then its end point at its own height.
void sweepsOf(const sim::SweptPiece& piece, double zStep, std::vector<Sweep>& out)
{
    if (!piece.arc) {
        sim::forEachLevel(piece.from, piece.to, zStep, [&](Point2 a, Point2 b, double z) { out.push_back({a, b, z}); });
        return;
    }
    const Point2 c = piece.centre;
    const double radius = std::hypot(piece.from.x - c.x, piece.from.y - c.y);
    const double a0 = std::atan2(piece.from.y - c.y, piece.from.x - c.x);
    const double dz = piece.to.z - piece.from.z;
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(dz) / zStep)));
    for (int part = 0; part < n; ++part) {
        const double t0 = static_cast<double>(part) / n, t1 = static_cast<double>(part + 1) / n;
        Sweep s;
        s.z = std::max(piece.from.z + t0 * dz, piece.from.z + t1 * dz);
        s.arc = true;
        s.centre = c;
        s.radius = radius;
        s.a0 = a0 + t0 * piece.sweep;
        s.sweep = (t1 - t0) * piece.sweep;
        out.push_back(s);
    }
    const Point2 end{piece.to.x, piece.to.y};
    if (dz != 0.0) out.push_back({end, end, piece.to.z});
}

}  // namespace

// Cuts one step into one band's rows.
class StepCut {
public:
    StepCut(Verifier& v, int k, int row0, int row1, Collector& out)
        : v_(v), k_(k), row0_(row0), row1_(row1), out_(out), d_(v.steps_[static_cast<std::size_t>(k)]),
          cutter_(*d_.cutter), reach_(cutter_.reach()), h_(v.field_.data()), bottom_(v.field_.bottom())
    {
    }

    // The sum of the heights the step took off.
    double run()
    {
        const std::vector<sim::SweptPiece>& pieces = d_.pieces;
        std::vector<Sweep>& sweeps = sweeps_;
        for (std::size_t p = 0; p < pieces.size();) {
            if (overBudget()) break;
            const sim::SweptPiece& piece = pieces[p];
            if (std::min(piece.from.z, piece.to.z) >= 0.0) {
                ++p;
                continue;
            }
            // The run of pieces from p that may be cut backwards: when it
            // goes down, it is (unless it gouges: then in order after all).
            std::size_t q = p;
            bool down = false;
            for (; q < pieces.size() && mayGoBackwards(pieces[q]); ++q) down |= pieces[q].to.z < pieces[q].from.z;
            if (down) {
                sweeps.clear();
                for (std::size_t r = p; r < q; ++r) sweepsOf(pieces[r], v_.zStep_, sweeps);
                if (backwards(sweeps)) {
                    p = q;
                    continue;
                }
            }
            for (const std::size_t end = std::max(q, p + 1); p < end && !overBudget(); ++p) {
                const sim::SweptPiece& next = pieces[p];
                sweeps.clear();
                sweepsOf(next, v_.zStep_, sweeps);
                if (next.arc) chain_.broken();
                for (const Sweep& s : sweeps) forward(s, next);
            }
        }
        Verifier::visits_ += visits_;
        return removed_;
    }

private:
    // Adds this band's visits to the job's count; past the bound, every band stops.
    bool overBudget()
    {
        if (v_.maxVisits_ > 0.0 && visits_ > counted_) {
            const auto sum = v_.allVisits_.fetch_add(visits_ - counted_, std::memory_order_relaxed) + (visits_ - counted_);
            counted_ = visits_;
            if (static_cast<double>(sum) > v_.maxVisits_) v_.over_.store(true, std::memory_order_relaxed);
        }
        return v_.over();
    }

    // The cells near one sweep, from `from` to `to` when straight, at the
    // sweep's height; `skip`: the radius about `from` already cut at it.
    void cut(const Sweep& s, Point2 from, Point2 to, double skip, int move, bool rapid)
    {
        const double z = s.z;
        if (z >= 0.0) return;
        const bool shankLow = z + d_.flute < -kTouch;
        const bool holderLow = z + d_.holderZ < -kTouch;
        const double radius = holderLow ? std::max(reach_, d_.holderR) : reach_;
        const double reach2 = reach_ * reach_;
        // No cell at or below the tip's height changes, nor touches the
        // shank or holder (both above the tip): its tile is skipped, and
        // within a tile above the tip, only the runs of cells above it
        // are handed on (reading a height costs less than measuring the
        // cell's distance from the path).
        //
        // Nor does a cell at or below the cutting surface's lowest over its
        // row: a row dy from the sweep (from its Y extent; an arc's whole
        // circle's) meets the cutter no lower than heightSquared(dy²) above
        // the tip. On a ball or a corner radius that keeps most of a short
        // move's disc from being visited again; never above the shank's or
        // the holder's bottom while either is low, whose touch is looked for
        // in every cell above it.
        const float tipFloor = static_cast<float>(std::max(z, bottom_));
        const double yLo = s.arc ? s.centre.y - s.radius : std::min(from.y, to.y);
        const double yHi = s.arc ? s.centre.y + s.radius : std::max(from.y, to.y);
        double ceiling = 1e300;  // the most a row's floor may be
        if (shankLow) ceiling = z + d_.flute;
        if (holderLow) ceiling = std::min(ceiling, z + d_.holderZ);
        const auto rowFloor = [&](int j) {
            const double y = v_.field_.centre(0, j).y, dy = std::max({0.0, yLo - y, y - yHi});
            if (dy >= reach_) return tipFloor;
            return std::max(tipFloor, static_cast<float>(std::min(z + cutter_.heightSquared(dy * dy), ceiling)));
        };
        const auto runs = [&](int j, int first, int last, const auto& cells) {
            const float* row = h_ + v_.field_.indexOf(0, j);
            const float floor = rowFloor(j);
            int start = -1;  // the first cell of the run still to visit
            for (int lo = first; lo <= last;) {
                const int t = lo / kTile, hi = std::min(last, (t + 1) * kTile - 1);
                if (v_.tileTop(j, t) > floor) {
                    for (int i = lo; i <= hi; ++i) {
                        if (row[i] > floor) {
                            if (start < 0) start = i;
                        } else if (start >= 0) {
                            cells(start, i - 1);
                            start = -1;
                        }
                    }
                } else if (start >= 0) {
                    cells(start, lo - 1);
                    start = -1;
                }
                lo = hi + 1;
            }
            if (start >= 0) cells(start, last);
        };
        const sim::HeightField& field = v_.field_;
        const auto visit = [&](int i, int j, double r2) {
            if (gouged_) return;  // (a backwards run stopped)
            const std::size_t c = field.indexOf(i, j);
            ++visits_;
            const double before = h_[c];
            const auto where = [&](double zz) {
                const Point2 p = field.centre(i, j);
                return Point3{p.x, p.y, zz};
            };
            if (holderLow && before > z + d_.holderZ + kTouch)
                out_.add(FindingKind::Collision, k_, move, TAIWA_TRANSLATE_NOOP("taiwa::msg", "holder"), where(before), before - (z + d_.holderZ));
            if (r2 > reach2) return;
            if (shankLow && before > z + d_.flute + kTouch && before <= z + d_.holderZ + kTouch)
                out_.add(FindingKind::Collision, k_, move, TAIWA_TRANSLATE_NOOP("taiwa::msg", "shank"), where(before), before - (z + d_.flute));
            const double after = std::max(z + cutter_.heightSquared(r2), bottom_);
            const float lowered = static_cast<float>(after);  // the grid's heights are floats
            if (lowered >= h_[c]) return;
            if (backwards_) {
                if (lowered < v_.limit_[c]) {
                    gouged_ = true;
                    return;
                }
                undo_.push_back({static_cast<std::uint32_t>(c), h_[c]});
            }
            if (rapid && before - after > kTouch)
                out_.add(FindingKind::RapidIntoStock, k_, move, "", where(after), before - after);
            h_[c] = lowered;
            v_.tileStale_[v_.tileOf(i, j)] = 1;
            removed_ += before - h_[c];
            if (h_[c] < v_.limit_[c]) {
                const double area = before >= v_.limit_[c] ? v_.cellArea() : 0.0;  // each cell counted once
                out_.add(FindingKind::Gouge, k_, move, "", where(after), v_.limit_[c] + kGougeTolerance - after, area);
            }
        };
        if (s.arc)
            sim::forEachCellNearArc(field, s.centre, s.radius, s.a0, s.sweep, radius, row0_, row1_, visit, runs);
        else
            sim::forEachCellNear(field, from, to, radius, row0_, row1_, visit, skip, runs);
    }

    // A sweep cut in the path's order. A straight one that starts where the
    // last ended, at the same height and without the holder low, skips the
    // cells within the cutter's flat bottom of its start: they are at that
    // height already (or lower), and a contour's short chords would
    // otherwise each visit a whole disc of cells.
    void forward(const Sweep& s, const sim::SweptPiece& piece)
    {
        if (s.arc) {
            cut(s, {}, {}, 0.0, piece.move, piece.rapid);
            return;
        }
        const bool holderLow = s.z + d_.holderZ < -kTouch;
        const double skip = holderLow ? 0.0 : chain_.skip(s.a, s.z, cutter_.flatRadius());
        cut(s, s.a, s.b, skip, piece.move, piece.rapid);
        if (s.z < 0.0 && !holderLow) chain_.ended(s.b, s.z);
        else chain_.broken();
    }

    // Whether a piece may be cut out of the path's order: it cuts (no
    // rapid), it does not go up, and neither the shank nor the holder
    // reaches the stock. Cells are only ever lowered, to the least of what
    // every sweep leaves, so the order of such pieces changes no height,
    // only the work; what it would change is which move a gouge is laid to
    // (backwards() gives up on one).
    // (Never with Options::inPathOrder.)
    bool mayGoBackwards(const sim::SweptPiece& piece) const
    {
        return !v_.inPathOrder_ && !piece.rapid && piece.to.z <= piece.from.z && piece.to.z < 0.0 && piece.to.z + d_.flute >= -kTouch;
    }

    // A run of pieces going down cut last sweep first, each straight sweep
    // from its end: the lowest is cut first, and the higher sweeps before
    // it then find most of their cells at or below their tip already (a
    // ramp into a layer costs little more than the layer). Straight sweeps
    // are chained backwards as forward. Afterwards the path's chain is
    // where forward cutting would have left it. A cell that would go below
    // its gouge limit stops it: every cell it lowered is put back, and
    // false says the run is still to cut, in order.
    bool backwards(const std::vector<Sweep>& sweeps)
    {
        sim::SweepChain back;
        const double flat = cutter_.flatRadius(), removedBefore = removed_;
        undo_.clear();
        backwards_ = true;
        gouged_ = false;
        for (auto it = sweeps.rbegin(); it != sweeps.rend() && !gouged_ && !overBudget(); ++it) {
            const Sweep& s = *it;
            if (s.arc) {
                back.broken();
                cut(s, {}, {}, 0.0, -1, false);
                continue;
            }
            cut(s, s.b, s.a, back.skip(s.b, s.z, flat), -1, false);
            if (s.z < 0.0) back.ended(s.a, s.z);
            else back.broken();
        }
        backwards_ = false;
        if (gouged_) {
            for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) h_[it->cell] = it->before;
            removed_ = removedBefore;
            gouged_ = false;
            return false;
        }
        const Sweep& last = sweeps.back();
        if (!last.arc && last.z < 0.0) chain_.ended(last.b, last.z);
        else chain_.broken();
        return true;
    }

    Verifier& v_;
    const int k_, row0_, row1_;
    Collector& out_;
    const StepData& d_;
    const sim::CutterProfile& cutter_;
    const double reach_;
    float* h_;
    const double bottom_;
    std::uint64_t visits_ = 0;
    std::uint64_t counted_ = 0;  // of visits_, added to the job's count
    double removed_ = 0.0;
    sim::SweepChain chain_;  // where the last straight sweep ended, and its height
    bool backwards_ = false;  // cutting a run backwards: a gouge stops it
    bool gouged_ = false;
    // The cells a backwards run lowered and their heights before, in a
    // buffer each thread keeps from step to step (its pages are faulted in
    // once, not at every run).
    struct Lowered {
        std::uint32_t cell;
        float before;
    };
    static thread_local std::vector<Lowered> undo_;
    static thread_local std::vector<Sweep> sweeps_;  // a run's sweeps, kept the same way
    friend void releaseCutBuffers();
};

thread_local std::vector<StepCut::Lowered> StepCut::undo_;
thread_local std::vector<Sweep> StepCut::sweeps_;

void releaseCutBuffers()
{
    std::vector<StepCut::Lowered>().swap(StepCut::undo_);
    std::vector<Sweep>().swap(StepCut::sweeps_);
}

// Cuts step k into the band's rows; the sum of the heights it took off.
double Verifier::cutStep(int k, int row0, int row1, Collector& out) { return StepCut(*this, k, row0, row1, out).run(); }

}  // namespace taiwa::verify::milling
