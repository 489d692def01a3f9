#include "robot/robot_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "swarmnet/random.hpp"
#include "swarmnet/spatial_grid.hpp"

namespace swarmnet {

namespace {

// Placed centres, added one at a time, in a linked list per cell of a uniform grid over the
// sampling rectangle (`next_`). Cells are at least one robot diameter wide, so a candidate can only
// touch robots in its own and the 8 surrounding cells; in a sparse region they grow to about 4
// cells per robot so that the grid stays O(count) in size.
class PlacementGrid {
 public:
  PlacementGrid(const Rect& bounds, double radius_m, std::uint32_t count) {
    const double area_m2 = std::max(bounds.width_m() * bounds.height_m(), 0.0);
    cells_ = GridCells(bounds,
                       std::max(2.0 * radius_m, std::sqrt(area_m2 / (4.0 * std::max(count, 1U)))));
    head_.assign(cells_.count(), kEnd);
    next_.reserve(count);
    centres_.reserve(count);
  }

  [[nodiscard]] bool touches_any(const Vec2& p, double contact_m) const {
    bool touches = false;
    cells_.for_each_cell_near(p, contact_m, [&](std::size_t cell) {
      for (std::uint32_t i = head_[cell]; i != kEnd && !touches; i = next_[i]) {
        touches = (centres_[i] - p).squaredNorm() < contact_m * contact_m;
      }
    });
    return touches;
  }

  void insert(const Vec2& p) {
    const std::uint32_t cell = cells_.cell_of(p);
    next_.push_back(head_[cell]);
    head_[cell] = static_cast<std::uint32_t>(centres_.size());
    centres_.push_back(p);
  }

 private:
  static constexpr std::uint32_t kEnd = 0xFFFFFFFFU;

  GridCells cells_;
  std::vector<std::uint32_t> head_;
  std::vector<std::uint32_t> next_;
  std::vector<Vec2> centres_;
};

// The same predicates as the physics engine: touching is allowed, penetration is not.
bool outside_arena(const Arena& arena, const Vec2& p, double radius_m) {
  return p.x() < radius_m || p.x() > arena.width_m - radius_m || p.y() < radius_m ||
         p.y() > arena.height_m - radius_m;
}

bool overlaps_obstacle(const Arena& arena, const Vec2& p, double radius_m) {
  return std::any_of(arena.obstacles.begin(), arena.obstacles.end(), [&](const Rect& rect) {
    const Vec2 nearest(std::clamp(p.x(), rect.x_min_m, rect.x_max_m),
                       std::clamp(p.y(), rect.y_min_m, rect.y_max_m));
    return (p - nearest).squaredNorm() < radius_m * radius_m;
  });
}

// A disc overlaps a movable object: a cylinder's disc, or a box turned by its heading (the disc's
// centre taken into the box's frame, then the nearest point of the box).
bool overlaps_object(const ArenaObject& object, const Vec2& p, double radius_m) {
  if (object.shape == ArenaObject::Shape::cylinder) {
    const double contact_m = object.radius_m + radius_m;
    return (p - object.position).squaredNorm() < contact_m * contact_m;
  }
  const Vec2 local = in_frame(p, object.position, object.heading_rad);
  const Vec2 nearest(std::clamp(local.x(), -0.5 * object.size_x_m, 0.5 * object.size_x_m),
                     std::clamp(local.y(), -0.5 * object.size_y_m, 0.5 * object.size_y_m));
  return (local - nearest).squaredNorm() < radius_m * radius_m;
}

bool overlaps_any_object(const Arena& arena, const Vec2& p, double radius_m) {
  return std::any_of(arena.objects.begin(), arena.objects.end(), [&](const ArenaObject& object) {
    return overlaps_object(object, p, radius_m);
  });
}

std::string describe(const Rect& rect) {
  std::ostringstream text;
  text << "[" << rect.x_min_m << ", " << rect.x_max_m << "] x [" << rect.y_min_m << ", "
       << rect.y_max_m << "] m";
  return text.str();
}

}  // namespace

std::vector<RobotBody> place_robots(const Arena& arena, const Rect& region, std::uint32_t count,
                                    const RobotBody& prototype, std::uint64_t seed) {
  std::vector<RobotBody> bodies;
  if (count == 0) return bodies;
  const double radius_m = prototype.radius_m;
  // Centres are drawn where the disc can be inside the walls: the region shrunk to the arena
  // minus a radius. This is exact rejection of wall contacts, without wasting draws on them.
  const Rect sample{std::max(region.x_min_m, radius_m), std::max(region.y_min_m, radius_m),
                    std::min(region.x_max_m, arena.width_m - radius_m),
                    std::min(region.y_max_m, arena.height_m - radius_m)};
  if (!(sample.x_min_m <= sample.x_max_m && sample.y_min_m <= sample.y_max_m)) {
    throw std::runtime_error(
        "cannot place any robot: no point of the placement region " + describe(region) +
        " is at least a robot radius (" + std::to_string(radius_m) + " m) inside the arena [0, " +
        std::to_string(arena.width_m) + "] x [0, " + std::to_string(arena.height_m) + "] m");
  }

  RandomStream random(seed);
  PlacementGrid grid(sample, radius_m, count);
  bodies.reserve(count);
  for (std::uint32_t placed = 0; placed < count; ++placed) {
    bool done = false;
    for (std::uint32_t attempt = 0; attempt < kPlacementAttemptsPerRobot && !done; ++attempt) {
      // Three draws per attempt, whatever the outcome: the stream position depends only on the
      // attempt count.
      const Vec2 centre(random.uniform(sample.x_min_m, sample.x_max_m),
                        random.uniform(sample.y_min_m, sample.y_max_m));
      const double heading_rad = random.uniform(-std::numbers::pi, std::numbers::pi);
      if (outside_arena(arena, centre, radius_m) || overlaps_obstacle(arena, centre, radius_m) ||
          overlaps_any_object(arena, centre, radius_m) ||
          grid.touches_any(centre, 2.0 * radius_m)) {
        continue;
      }
      RobotBody body = prototype;
      body.position = centre;
      body.heading_rad = heading_rad;
      bodies.push_back(body);
      grid.insert(centre);
      done = true;
    }
    if (!done) {
      std::ostringstream text;
      text << "could place only " << placed << " of " << count << " robots (radius " << radius_m
           << " m) in the placement region " << describe(region) << ": robot " << placed
           << " found no free spot in " << kPlacementAttemptsPerRobot
           << " random attempts (robots may not overlap each other, the walls, obstacles or "
              "objects). "
           << "Use a larger robots.placement region or arena, or fewer robots.";
      throw std::runtime_error(text.str());
    }
  }
  return bodies;
}

}  // namespace swarmnet
