// Collision resolution for disc robots after a kinematic move.
//
// Iterative projection: each iteration pushes every overlapping pair of robots apart (half each,
// along the line between centres), then pushes every robot out of obstacles and back inside the
// walls. Pairs come from a uniform grid, so an iteration costs O(N + grid cells), never O(N^2).
// A bounded number of iterations cannot untangle every jam, so a final pass enforces the
// invariant exactly: robots still in violation return to their pre-step position (see
// enforce_invariants()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "swarmnet/arena.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/spatial_grid.hpp"

namespace swarmnet::kinematic2d {

class CollisionResolver {
 public:
  // Sizes the grid for `bodies` in `arena`. Throws std::invalid_argument when a body has a
  // non-positive radius or axle, or the bodies already overlap, leave the arena or touch the
  // inside of an obstacle: the guarantee of resolve() rests on the initial state being valid.
  void setup(const Arena& arena, std::span<const RobotBody> bodies, int iterations);

  // Call before moving the bodies: remembers every position as the fallback pose.
  void remember(std::span<const RobotBody> bodies);

  // Resolves collisions of the moved bodies. Afterwards no two bodies overlap, none is outside the
  // arena and none overlaps an obstacle, and grid() indexes the final positions.
  void resolve(std::span<RobotBody> bodies);

  [[nodiscard]] const SpatialGrid& grid() const { return grid_; }
  [[nodiscard]] double max_radius_m() const { return max_radius_m_; }
  // How many bodies the last resolve() returned to their pre-step position.
  [[nodiscard]] std::size_t reverted_count() const { return reverted_count_; }

 private:
  void rebuild_grid(std::span<const RobotBody> bodies);
  bool separate_robots(std::span<RobotBody> bodies);
  bool push_into_free_space(std::span<RobotBody> bodies) const;
  [[nodiscard]] bool violates_boundaries(const RobotBody& body) const;
  void enforce_invariants(std::span<RobotBody> bodies);
  void revert(std::span<RobotBody> bodies, std::uint32_t robot);

  Arena arena_;
  int iterations_ = 4;
  double max_radius_m_ = 0.0;
  SpatialGrid grid_;
  // Buffers reused across steps: no allocation once they reach the robot count.
  std::vector<Vec2> points_;
  std::vector<Vec2> previous_;
  std::vector<std::uint32_t> candidates_;
  std::vector<std::uint8_t> reverted_;
  std::vector<std::uint32_t> worklist_;
  std::size_t reverted_count_ = 0;
};

}  // namespace swarmnet::kinematic2d
