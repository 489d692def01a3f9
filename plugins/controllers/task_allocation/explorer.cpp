#include "explorer.hpp"

#include <algorithm>
#include <cmath>

namespace swarmnet::task_allocation {

Explorer::Explorer(const Arena& arena, double cell_m, double scale_m)
    : reach_m_(0.5 * cell_m), scale_m_(scale_m) {
  const auto columns =
      static_cast<std::size_t>(std::max(1.0, std::ceil(arena.width_m / cell_m - 1e-9)));
  const auto rows =
      static_cast<std::size_t>(std::max(1.0, std::ceil(arena.height_m / cell_m - 1e-9)));
  const double cell_width_m = arena.width_m / static_cast<double>(columns);
  const double cell_height_m = arena.height_m / static_cast<double>(rows);
  cells_.reserve(columns * rows);
  for (std::size_t row = 0; row < rows; ++row) {
    for (std::size_t column = 0; column < columns; ++column) {
      Cell cell;
      cell.centre = Vec2((static_cast<double>(column) + 0.5) * cell_width_m,
                         (static_cast<double>(row) + 0.5) * cell_height_m);
      cell.blocked = std::any_of(arena.obstacles.begin(), arena.obstacles.end(),
                                 [&](const Rect& r) { return r.contains(cell.centre); });
      cell.explored = cell.blocked;
      cells_.push_back(cell);
    }
  }
}

std::size_t Explorer::explored_count() const {
  return static_cast<std::size_t>(
      std::count_if(cells_.begin(), cells_.end(), [](const Cell& c) { return c.explored; }));
}

void Explorer::observe(const Vec2& position) {
  for (Cell& cell : cells_) {
    if ((cell.centre - position).norm() <= reach_m_) cell.explored = true;
  }
}

void Explorer::forget() {
  for (Cell& cell : cells_) cell.explored = cell.blocked;
}

Vec2 Explorer::target(const Vec2& position, RandomStream& random) {
  if (target_ && !cells_[*target_].explored) return cells_[*target_].centre;
  target_.reset();
  if (cells_.empty()) return position;
  if (explored_count() == cells_.size()) {
    forget();
    observe(position);
  }
  std::vector<double> weights(cells_.size(), 0.0);
  double total = 0.0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    if (cells_[i].explored) continue;
    weights[i] = std::exp(-(cells_[i].centre - position).norm() / scale_m_);
    total += weights[i];
  }
  if (total <= 0.0) {
    // Every cell was explored again at once (one cell), or the weights underflowed: the nearest
    // unexplored cell, or stay.
    double best_m = -1.0;
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      const double d = (cells_[i].centre - position).norm();
      if (!cells_[i].explored && (best_m < 0.0 || d < best_m)) {
        best_m = d;
        target_ = i;
      }
    }
    return target_ ? cells_[*target_].centre : position;
  }
  double draw = random.uniform(0.0, total);
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    if (weights[i] <= 0.0) continue;
    target_ = i;  // the last positive weight catches rounding at the top end
    if (draw < weights[i]) break;
    draw -= weights[i];
  }
  return cells_[*target_].centre;
}

}  // namespace swarmnet::task_allocation
