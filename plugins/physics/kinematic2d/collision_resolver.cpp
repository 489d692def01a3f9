#include "collision_resolver.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "disc_geometry.hpp"

namespace swarmnet::kinematic2d {

namespace {

std::string describe(std::size_t robot, const RobotBody& body) {
  return "robot " + std::to_string(robot) + " at (" + std::to_string(body.position.x()) + ", " +
         std::to_string(body.position.y()) + ") m with radius " + std::to_string(body.radius_m) +
         " m";
}

}  // namespace

void CollisionResolver::setup(const Arena& arena, std::span<const RobotBody> bodies,
                              int iterations) {
  arena_ = arena;
  iterations_ = std::max(iterations, 0);
  max_radius_m_ = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RobotBody& body = bodies[i];
    if (!(body.radius_m > 0.0) || !(body.axle_m > 0.0)) {
      throw std::invalid_argument("kinematic2d: " + describe(i, body) + " and axle " +
                                  std::to_string(body.axle_m) +
                                  " m: radius and axle must be positive");
    }
    max_radius_m_ = std::max(max_radius_m_, body.radius_m);
  }
  // Cells are at least one robot diameter wide, so a collision query visits at most 3 x 3
  // cells. In a sparse swarm they grow to keep about 4 cells per robot: rebuilding the grid
  // costs O(cells), which must stay O(N) (a 500 m arena in 0.17 m cells would be 8.6 million).
  const double area_m2 = arena.width_m * arena.height_m;
  const double robots = static_cast<double>(std::max<std::size_t>(bodies.size(), 1));
  const double cell_m = std::max(2.0 * max_radius_m_, std::sqrt(area_m2 / (4.0 * robots)));
  grid_.reset(Rect{0.0, 0.0, arena.width_m, arena.height_m}, cell_m);

  points_.resize(bodies.size());
  previous_.resize(bodies.size());
  reverted_.assign(bodies.size(), 0);
  worklist_.reserve(bodies.size());
  candidates_.reserve(64);  // neighbours of one robot: a handful even in a jam
  rebuild_grid(bodies);

  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RobotBody& body = bodies[i];
    if (disc_outside_arena(arena_, body.position, body.radius_m)) {
      throw std::invalid_argument("kinematic2d: " + describe(i, body) +
                                  " is not inside the arena [0, " + std::to_string(arena.width_m) +
                                  "] x [0, " + std::to_string(arena.height_m) + "] m");
    }
    if (disc_overlaps_obstacle(arena_, body.position, body.radius_m)) {
      throw std::invalid_argument("kinematic2d: " + describe(i, body) + " overlaps an obstacle");
    }
    grid_.for_each_candidate(body.position, body.radius_m + max_radius_m_, [&](std::uint32_t j) {
      if (j > i &&
          discs_overlap(body.position, body.radius_m, bodies[j].position, bodies[j].radius_m)) {
        throw std::invalid_argument("kinematic2d: " + describe(i, body) + " overlaps " +
                                    describe(j, bodies[j]));
      }
    });
  }
}

void CollisionResolver::remember(std::span<const RobotBody> bodies) {
  previous_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) previous_[i] = bodies[i].position;
}

void CollisionResolver::rebuild_grid(std::span<const RobotBody> bodies) {
  points_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) points_[i] = bodies[i].position;
  grid_.build(points_);
}

void CollisionResolver::resolve(std::span<RobotBody> bodies) {
  for (int iteration = 0; iteration < iterations_; ++iteration) {
    const bool separated = separate_robots(bodies);
    const bool pushed = push_into_free_space(bodies);
    if (!separated && !pushed) break;
  }
  enforce_invariants(bodies);
}

bool CollisionResolver::separate_robots(std::span<RobotBody> bodies) {
  rebuild_grid(bodies);
  bool moved = false;
  for (std::uint32_t i = 0; i < bodies.size(); ++i) {
    RobotBody& a = bodies[i];
    // Pairs (i, j) with j > i, in ascending j: the order a sequential sweep would use, whatever
    // the grid's cell size.
    candidates_.clear();
    grid_.for_each_candidate(a.position, a.radius_m + max_radius_m_, [&](std::uint32_t j) {
      if (j > i) candidates_.push_back(j);
    });
    std::sort(candidates_.begin(), candidates_.end());
    for (const std::uint32_t j : candidates_) {
      RobotBody& b = bodies[j];
      if (!discs_overlap(a.position, a.radius_m, b.position, b.radius_m)) continue;
      const Vec2 between = b.position - a.position;
      const double distance_m = between.norm();
      // Coincident centres have no direction between them; separate them along +x.
      const Vec2 normal = distance_m > 0.0 ? Vec2(between / distance_m) : Vec2(1.0, 0.0);
      const double push_m = 0.5 * (a.radius_m + b.radius_m - distance_m) + kSeparationSlopM;
      a.position -= push_m * normal;
      b.position += push_m * normal;
      moved = true;
    }
  }
  return moved;
}

bool CollisionResolver::push_into_free_space(std::span<RobotBody> bodies) const {
  bool moved = false;
  for (RobotBody& body : bodies) {
    for (const Rect& obstacle : arena_.obstacles) {
      moved = push_out_of_rect(obstacle, body.position, body.radius_m) || moved;
    }
    moved = clamp_into_arena(arena_, body.position, body.radius_m) || moved;
  }
  return moved;
}

bool CollisionResolver::violates_boundaries(const RobotBody& body) const {
  return disc_outside_arena(arena_, body.position, body.radius_m) ||
         disc_overlaps_obstacle(arena_, body.position, body.radius_m);
}

void CollisionResolver::revert(std::span<RobotBody> bodies, std::uint32_t robot) {
  // Only the position goes back: a disc's heading cannot make it overlap anything, and keeping
  // the new heading lets a jammed robot still turn in place towards a way out.
  bodies[robot].position = previous_[robot];
  reverted_[robot] = 1;
  worklist_.push_back(robot);
  ++reverted_count_;
}

// The guarantee. Pre-step positions were free of overlaps (setup() checked the initial state and
// every step ends in a valid state), so any set of robots returned to them is valid among itself
// and against walls and obstacles. A robot is returned when it still violates a constraint after
// the iterations, and then, transitively, any robot that stayed at its new position but overlaps
// a returned one. What remains is valid: pairs that stayed were checked below, pairs that
// returned are pre-step pairs, and mixed pairs are checked by the propagation. Each robot is
// returned at most once, so this is O(N + grid cells) too.
void CollisionResolver::enforce_invariants(std::span<RobotBody> bodies) {
  rebuild_grid(bodies);
  reverted_.assign(bodies.size(), 0);
  worklist_.clear();
  reverted_count_ = 0;
  // Marks first, against the positions the grid was built from, then reverts.
  for (std::uint32_t i = 0; i < bodies.size(); ++i) {
    const RobotBody& a = bodies[i];
    if (violates_boundaries(a)) reverted_[i] = 1;
    grid_.for_each_candidate(a.position, a.radius_m + max_radius_m_, [&](std::uint32_t j) {
      if (j > i && discs_overlap(a.position, a.radius_m, bodies[j].position, bodies[j].radius_m)) {
        reverted_[i] = 1;
        reverted_[j] = 1;
      }
    });
  }
  for (std::uint32_t i = 0; i < bodies.size(); ++i) {
    if (reverted_[i] != 0) revert(bodies, i);
  }
  // Grid positions of robots that stayed are still current; a returned robot is looked up at
  // its pre-step position.
  for (std::size_t next = 0; next < worklist_.size(); ++next) {
    const std::uint32_t i = worklist_[next];
    const RobotBody& a = bodies[i];
    grid_.for_each_candidate(a.position, a.radius_m + max_radius_m_, [&](std::uint32_t j) {
      if (reverted_[j] == 0 &&
          discs_overlap(a.position, a.radius_m, bodies[j].position, bodies[j].radius_m)) {
        revert(bodies, j);
      }
    });
  }
  if (reverted_count_ > 0) rebuild_grid(bodies);
}

}  // namespace swarmnet::kinematic2d
