// A uniform grid over points in a rectangle, for neighbourhood queries in O(neighbours).
//
// Used by the physics engine (collisions, proximity), the channel (receivers of a frame) and,
// through GridCells, robot placement.
// Rebuild it from all positions when they change; queries visit candidate indices in ascending
// order within each cell and cells in row-major order, so results are deterministic.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "swarmnet/vector.hpp"

namespace swarmnet {

// The cells of a uniform grid over a rectangle, in row-major order: which cell a point falls in
// (points outside the rectangle are clamped to the border cells) and which cells lie near a
// point. SpatialGrid stores points in them rebuilt all at once; a grid that adds points one at a
// time (robot placement) stores its own lists in the same cells.
class GridCells {
 public:
  GridCells() = default;
  // `cell_m` should be about the query radius. A tiny cell over a huge area is coarsened (the
  // cell size doubled until there are at most 2^24 cells).
  GridCells(const Rect& bounds, double cell_m) : bounds_(bounds), cell_m_(std::max(cell_m, 1e-9)) {
    columns_ = cells_along(bounds.width_m());
    rows_ = cells_along(bounds.height_m());
    while (columns_ * rows_ > (std::int64_t{1} << 24)) {
      cell_m_ *= 2.0;
      columns_ = (columns_ + 1) / 2;
      rows_ = (rows_ + 1) / 2;
    }
  }

  [[nodiscard]] std::size_t count() const { return static_cast<std::size_t>(columns_ * rows_); }
  [[nodiscard]] double cell_m() const { return cell_m_; }
  [[nodiscard]] std::uint32_t cell_of(const Vec2& p) const {
    return static_cast<std::uint32_t>(row_of(p.y()) * columns_ + column_of(p.x()));
  }

  // Calls visit(cell) for every cell that intersects the square of half-side `radius_m` around
  // `center`, in row-major order.
  template <typename Visit>
  void for_each_cell_near(const Vec2& center, double radius_m, Visit&& visit) const {
    const std::int64_t c0 = column_of(center.x() - radius_m);
    const std::int64_t c1 = column_of(center.x() + radius_m);
    const std::int64_t r0 = row_of(center.y() - radius_m);
    const std::int64_t r1 = row_of(center.y() + radius_m);
    for (std::int64_t r = r0; r <= r1; ++r) {
      for (std::int64_t c = c0; c <= c1; ++c) visit(static_cast<std::size_t>(r * columns_ + c));
    }
  }

 private:
  [[nodiscard]] std::int64_t cells_along(double length_m) const {
    return std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(length_m / cell_m_)));
  }
  // A NaN coordinate (which clamp would pass through, and a cast would turn into any index)
  // falls in the first cell, as anything below the rectangle does.
  [[nodiscard]] std::int64_t column_of(double x) const {
    const double c = std::floor((x - bounds_.x_min_m) / cell_m_);
    if (!(c > 0.0)) return 0;
    return static_cast<std::int64_t>(std::min(c, static_cast<double>(columns_ - 1)));
  }
  [[nodiscard]] std::int64_t row_of(double y) const {
    const double r = std::floor((y - bounds_.y_min_m) / cell_m_);
    if (!(r > 0.0)) return 0;
    return static_cast<std::int64_t>(std::min(r, static_cast<double>(rows_ - 1)));
  }

  Rect bounds_;
  double cell_m_ = 1.0;
  std::int64_t columns_ = 1;
  std::int64_t rows_ = 1;
};

class SpatialGrid {
 public:
  // `bounds` is the area points normally lie in (points outside are clamped to the border
  // cells); `cell_m` should be about the query radius.
  void reset(const Rect& bounds, double cell_m) {
    cells_ = GridCells(bounds, cell_m);
    cell_start_.assign(cells_.count() + 1, 0);
  }

  // Counting sort of point indices by cell: O(n), no allocation once capacities are reached.
  void build(std::span<const Vec2> points) {
    std::fill(cell_start_.begin(), cell_start_.end(), 0U);
    cell_of_.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      cell_of_[i] = cells_.cell_of(points[i]);
      ++cell_start_[cell_of_[i] + 1];
    }
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    entries_.resize(points.size());
    fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) {
      entries_[fill_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
    }
  }

  // Calls visit(index) for every point whose cell intersects the square of half-side `radius_m`
  // around `center` (a superset of the points within radius_m; the caller checks distance).
  template <typename Visit>
  void for_each_candidate(const Vec2& center, double radius_m, Visit&& visit) const {
    cells_.for_each_cell_near(center, radius_m, [&](std::size_t cell) {
      for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) visit(entries_[k]);
    });
  }

  [[nodiscard]] double cell_m() const { return cells_.cell_m(); }

 private:
  GridCells cells_;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> cell_of_;
  std::vector<std::uint32_t> entries_;
  std::vector<std::uint32_t> fill_;
};

}  // namespace swarmnet
