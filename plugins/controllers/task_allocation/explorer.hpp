// explorer: probabilistic exploration with a memory of explored areas, standing in for the
// search strategy the paper cites ([24], not given in it).
//
// The arena is cut into a grid of equal cells, as many per side as explore_cell_m needs
// (ceil(width / explore_cell_m) columns, likewise rows), so that every cell and its centre lie
// inside the arena and no cell is larger than explore_cell_m. A cell whose centre lies inside an
// obstacle can never be visited and counts as explored for good. A cell becomes explored once
// the robot has been within explore_cell_m / 2 of its centre. The robot's target is an
// unexplored cell's centre, drawn with weight exp(-distance / explore_scale_m) (near cells
// first, far ones still possible); a new one is drawn once the target is explored. When every
// cell is explored, the memory is cleared (obstacle cells excepted) and exploration starts over.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet::task_allocation {

class Explorer {
 public:
  Explorer() = default;
  Explorer(const Arena& arena, double cell_m, double scale_m);

  // Marks every cell whose centre lies within cell_m / 2 of `position`.
  void observe(const Vec2& position);
  // The current target, drawn anew when there is none or it has been explored.
  [[nodiscard]] Vec2 target(const Vec2& position, RandomStream& random);
  // Forgets the target (a new one is drawn at the next target()); the explored cells stay.
  void drop_target() { target_.reset(); }

  [[nodiscard]] std::size_t cell_count() const { return cells_.size(); }
  [[nodiscard]] std::size_t explored_count() const;
  [[nodiscard]] bool explored(std::size_t cell) const { return cells_[cell].explored; }
  [[nodiscard]] Vec2 centre(std::size_t cell) const { return cells_[cell].centre; }
  [[nodiscard]] std::optional<std::size_t> target_cell() const { return target_; }

  bool operator==(const Explorer&) const = default;

 private:
  struct Cell {
    Vec2 centre = Vec2::Zero();
    bool explored = false;
    bool blocked = false;  // centre inside an obstacle
    bool operator==(const Cell&) const = default;
  };
  void forget();

  double reach_m_ = 0.0;
  double scale_m_ = 1.0;
  std::vector<Cell> cells_;
  std::optional<std::size_t> target_;
};

}  // namespace swarmnet::task_allocation
