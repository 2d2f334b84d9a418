// The stock as a height field (Z-map): a regular grid of square cells over
// the stock's rectangle, each holding the Z of the material's top surface
// at its centre. Fresh stock is at Z = 0; nothing goes below the stock's
// bottom (a cell at the bottom is cut through).
#pragma once

#include "model/job.h"
#include "model/toolpath.h"

#include <cstddef>
#include <vector>

namespace taiwa::sim {

class HeightField {
public:
    // Cells of `cellSize` mm covering the stock (the last row and column
    // may reach a little past its edge).
    HeightField(const Stock& stock, double cellSize);
    HeightField() = default;

    // The cell size for a stock: `finest` mm unless that makes more than
    // `maxCells` cells, then the size that makes exactly that many.
    static double cellSizeFor(const Stock& stock, std::size_t maxCells = 1'000'000, double finest = 0.25);

    int columns() const { return nx_; }  // along X
    int rows() const { return ny_; }     // along Y
    double cellSize() const { return cell_; }
    const Stock& stock() const { return stock_; }
    double bottom() const { return -stock_.height; }

    Point2 centre(int i, int j) const { return {stock_.x + (i + 0.5) * cell_, stock_.y + (j + 0.5) * cell_}; }
    double at(int i, int j) const { return z_[index(i, j)]; }
    // True when (x, y) lies on the grid.
    bool contains(double x, double y) const;
    // Height of the cell containing (x, y), clamped to the grid's edge.
    double atPoint(double x, double y) const;

    // Lowers the cell to z (never raises it, never below the bottom).
    void lower(int i, int j, double z)
    {
        float& h = z_[index(i, j)];
        const float v = static_cast<float>(z < bottom() ? bottom() : z);
        if (v < h) h = v;
    }

    // Keeps the lower of the two heights in every cell: the material that
    // both leave. The fields must have the same grid.
    void meet(const HeightField& other);

    const std::vector<float>& heights() const { return z_; }  // row-major, row j = Y
    // The cells to lower in place (the verification checks each cell as it
    // lowers it); whoever writes through it keeps "never raised".
    float* data() { return z_.data(); }
    std::size_t indexOf(int i, int j) const { return index(i, j); }
    friend bool operator==(const HeightField&, const HeightField&) = default;

private:
    std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx_ + i; }
    Stock stock_;
    double cell_ = 1.0;
    int nx_ = 0, ny_ = 0;
    std::vector<float> z_;
};

}  // namespace taiwa::sim
