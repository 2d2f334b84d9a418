// The height-field grid of the stock simulation.
#include "sim/height_field.h"
#include "sim/large_array.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace taiwa::sim {

HeightField::HeightField(const Stock& stock, double cellSize)
    : stock_(stock), cell_(cellSize),
      nx_(std::max(1, static_cast<int>(std::ceil(stock.width / cellSize - 1e-9)))),
      ny_(std::max(1, static_cast<int>(std::ceil(stock.length / cellSize - 1e-9))))
{
    assignLarge(z_, static_cast<std::size_t>(nx_) * ny_, 0.0f);
}

double HeightField::cellSizeFor(const Stock& stock, std::size_t maxCells, double finest)
{
    const double area = std::max(stock.width, 1e-3) * std::max(stock.length, 1e-3);
    return std::max(finest, std::sqrt(area / static_cast<double>(std::max<std::size_t>(maxCells, 1))));
}

bool HeightField::contains(double x, double y) const
{
    const double u = (x - stock_.x) / cell_, v = (y - stock_.y) / cell_;
    return u >= 0 && v >= 0 && u < nx_ && v < ny_;
}

double HeightField::atPoint(double x, double y) const
{
    const int i = std::clamp(static_cast<int>(std::floor((x - stock_.x) / cell_)), 0, nx_ - 1);
    const int j = std::clamp(static_cast<int>(std::floor((y - stock_.y) / cell_)), 0, ny_ - 1);
    return at(i, j);
}

void HeightField::meet(const HeightField& other)
{
    if (other.nx_ != nx_ || other.ny_ != ny_) throw std::logic_error("HeightField::meet: different grids");
    for (std::size_t k = 0; k < z_.size(); ++k) z_[k] = std::min(z_[k], other.z_[k]);
}

}  // namespace taiwa::sim
