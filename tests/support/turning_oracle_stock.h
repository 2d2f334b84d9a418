// The lathe tape oracle's bar (turning_oracle.cpp): the stock left after
// every move, cut by the tools' shapes, for material left and rapids into
// stock. Internal to tests/support.
#pragma once

#include "support/turning_oracle_shapes.h"

#include <map>

namespace taiwa::test::lathe_oracle {

// ---- the stock -------------------------------------------------------------

// The bar's half-section as columns along Z, each the interval of radii
// [lo, hi] still there (empty when hi <= lo). Outside tools take from the
// top of a column, inside tools and drills from its bottom: every tool
// shape here is one whole side of its cutting edge.
class Stock {
public:
    Stock(const BarStock& bar, double cell) : cell_(cell)
    {
        const double back = bar.face - bar.length;
        z0_ = back - 10.0;
        const auto n = static_cast<std::size_t>(std::ceil((bar.length + 20.0) / cell));
        lo_.assign(n, kInf);
        hi_.assign(n, -kInf);
        for (std::size_t i = 0; i < n; ++i) {
            const double z = centre(i);
            if (z >= back && z <= bar.face) {
                lo_[i] = bar.bore / 2.0;
                hi_[i] = bar.diameter / 2.0;
            }
        }
    }

    void cut(const Shape& s, P a, P b)
    {
        sweep(s, a, b, [&](std::size_t i, double v) {
            if (s.inner) lo_[i] = std::max(lo_[i], v);
            else hi_[i] = std::min(hi_[i], v);
        });
    }

    // The deepest overlap (in radius) of the shape swept from a to b with
    // what is left, and the Z where it is.
    double overlap(const Shape& s, P a, P b, double* atZ) const
    {
        double worst = -kInf;
        sweep(s, a, b, [&](std::size_t i, double v) {
            if (hi_[i] <= lo_[i]) return;
            const double o = s.inner ? std::min(v, hi_[i]) - lo_[i] : hi_[i] - std::max(v, lo_[i]);
            if (o > worst) {
                worst = o;
                if (atZ) *atZ = centre(i);
            }
        });
        return worst;
    }

private:
    double centre(std::size_t i) const { return z0_ + (static_cast<double>(i) + 0.5) * cell_; }

    // Calls f(column, value) for every column the shape's sweep from a to b
    // (reference points) reaches: outside tools, the lowest radius it takes
    // there (it takes everything above); inside ones the highest.
    template <class F>
    void sweep(const Shape& s, P a, P b, F&& f) const
    {
        double zMin = std::min(a.x, b.x), zMax = std::max(a.x, b.x);
        if (s.kind == Shape::Insert) {
            zMin -= s.nose;
            zMax += s.nose;
        } else if (s.kind == Shape::Blade) {
            zMin -= s.width;
        } else if (s.kind == Shape::Drill) {
            zMax = z0_ + cell_ * static_cast<double>(lo_.size());
        } else {
            return;
        }
        const double first = std::floor((zMin - z0_) / cell_ - 0.5), last = std::ceil((zMax - z0_) / cell_ - 0.5);
        const double count = static_cast<double>(lo_.size());
        for (double k = std::max(first, 0.0); k <= std::min(last, count - 1); k += 1.0) {
            const auto i = static_cast<std::size_t>(k);
            if (const auto v = value(s, a, b, centre(i))) f(i, *v);
        }
    }

    static std::optional<double> value(const Shape& s, P a, P b, double z)
    {
        const bool lower = !s.inner;
        const P d = b - a;
        std::optional<double> best;
        const auto take = [&](double v) { best = !best ? v : lower ? std::min(*best, v) : std::max(*best, v); };
        switch (s.kind) {
        case Shape::Insert: {
            // The capsule the nose sweeps: both end discs and the offset side.
            const double r = s.nose;
            for (const P c : {a, b}) {
                const double dz = z - c.x;
                if (std::abs(dz) <= r) {
                    const double h = std::sqrt(std::max(0.0, r * r - dz * dz));
                    take(lower ? c.y - h : c.y + h);
                }
            }
            const double l = length(d);
            if (l > 1e-12 && std::abs(d.x) > 1e-12) {
                P n{-d.y / l, d.x / l};
                if ((lower && n.y > 0) || (!lower && n.y < 0)) n = -1.0 * n;
                const double t = (z - a.x - r * n.x) / d.x;
                if (t >= 0 && t <= 1) take(a.y + t * d.y + r * n.y);
            }
            break;
        }
        case Shape::Blade: {
            // The rectangle covers [p.z - width, p.z]: the column while p.z is in [z, z + width].
            double t0 = 0, t1 = 1;
            if (std::abs(d.x) < 1e-12) {
                if (a.x < z - 1e-12 || a.x > z + s.width + 1e-12) return std::nullopt;
            } else {
                const double ta = (z - a.x) / d.x, tb = (z + s.width - a.x) / d.x;
                t0 = std::max(0.0, std::min(ta, tb));
                t1 = std::min(1.0, std::max(ta, tb));
                if (t0 > t1) return std::nullopt;
            }
            take(a.y + t0 * d.y);
            take(a.y + t1 * d.y);
            break;
        }
        case Shape::Drill: {
            const double zTip = std::min(a.x, b.x);
            if (z < zTip) return std::nullopt;
            take(std::max(a.y, b.y) + std::min(s.radius, (z - zTip) * s.tanHalf));
            break;
        }
        case Shape::None: break;
        }
        return best;
    }

    double z0_ = 0.0, cell_ = 0.02;
    std::vector<double> lo_, hi_;
};


}  // namespace taiwa::test::lathe_oracle
