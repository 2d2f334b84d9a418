// The verification's colour map (deviation.h): every verification cell
// judged against the finished part as the verification judges gouges and
// material left, in bands of rows on every core, then gathered onto a grid
// small enough to draw.
#include "verify/deviation.h"

#include "modules/registry.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <thread>

namespace taiwa::verify {

namespace {

constexpr double kTolerance = 0.001;  // as the verification's gouge tolerance [mm]

// The worse of two deviations: any gouge before material left.
float worse(float a, float b)
{
    if (a < 0.0f || b < 0.0f) return std::min(a, b);
    return std::max(a, b);
}

// The band of a cell's deviation (already 0 within the tolerances).
DeviationBand bandOf(double amount)
{
    if (amount < 0.0) return DeviationBand::Gouge;
    if (amount == 0.0) return DeviationBand::AtSize;
    if (amount <= kThinRest) return DeviationBand::RestThin;
    if (amount <= kMediumRest) return DeviationBand::RestMedium;
    return DeviationBand::RestThick;
}

}  // namespace

DeviationMap deviationMap(const Plan& plan, const Report& report, std::size_t maxCells)
{
    DeviationMap map;
    const sim::HeightField& fine = report.stock;
    const int nx = fine.columns(), ny = fine.rows();
    if (nx <= 0 || ny <= 0 || fine.heights().empty()) return map;
    const double res = fine.cellSize();
    // Material left is judged as at the end of the verification: beyond the
    // tolerance, the Z step of its sweeps and the cavity's own tolerance.
    const double zStep = std::min(0.02, res / 5.0);

    std::vector<Cavity> cavities;
    for (const auto& u : plan.mmJob.units)
        if (!u.module.empty())
            if (auto c = moduleKind(u.module).cavity(u.module, plan.technology)) cavities.push_back(std::move(*c));

    const double cells = static_cast<double>(nx) * ny;
    map.factor = std::max(1, static_cast<int>(std::ceil(std::sqrt(cells / static_cast<double>(std::max<std::size_t>(maxCells, 1))))));
    map.stock = sim::HeightField(fine.stock(), res * map.factor);
    const int mx = map.stock.columns(), my = map.stock.rows();
    const std::size_t mapCells = static_cast<std::size_t>(mx) * my;
    map.amount.assign(mapCells, 0.0f);
    std::vector<char> touched(mapCells, 0);

    // Each thread takes whole rows of map cells, so no two write one cell.
    const auto work = [&](int mj0, int mj1) {
        for (int j = mj0 * map.factor; j < std::min(ny, mj1 * map.factor); ++j) {
            const int mj = std::min(j / map.factor, my - 1);
            for (int i = 0; i < nx; ++i) {
                const Point2 p = fine.centre(i, j);
                const double h = fine.at(i, j);
                double low = 0.0, high = 0.0, surface = 0.0;  // the part: deepest and shallowest within one cell
                bool inUnit = false;
                for (const Cavity& c : cavities) {
                    if (p.x < c.min.x - res || p.x > c.max.x + res || p.y < c.min.y - res || p.y > c.max.y + res) continue;
                    const double deep = c.depthAt(p, res);
                    if (deep <= 0.0) continue;
                    inUnit = true;
                    low = std::min(low, -deep);
                    high = std::min(high, -c.depthAt(p, -res));
                    surface = std::max(surface, c.surfaceTolerance);
                }
                float amount = 0.0f;
                if (h < low - kTolerance) amount = static_cast<float>(h - low);
                else if (h > high + kTolerance + zStep + surface) amount = static_cast<float>(h - high);
                const std::size_t m = map.stock.indexOf(std::min(i / map.factor, mx - 1), mj);
                map.amount[m] = worse(map.amount[m], amount);
                if (inUnit || h < -kTolerance) touched[m] = 1;
                map.stock.lower(std::min(i / map.factor, mx - 1), mj, h);
            }
        }
    };
    const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    std::vector<std::future<void>> running;
    for (int t = 1; t < threads; ++t) running.push_back(std::async(std::launch::async, work, my * t / threads, my * (t + 1) / threads));
    work(0, my / threads);
    for (auto& f : running) f.get();

    map.band.resize(mapCells);
    for (std::size_t m = 0; m < mapCells; ++m)
        map.band[m] = touched[m] ? bandOf(map.amount[m]) : DeviationBand::Untouched;
    return map;
}

}  // namespace taiwa::verify
