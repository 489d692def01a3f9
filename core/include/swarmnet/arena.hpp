// The world robots move in: a walled rectangle [0, width] x [0, height] with rectangular obstacles
// and movable objects.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "swarmnet/vector.hpp"

namespace swarmnet {

// A movable object resting on the floor (scenario key arena.objects): a box or an upright
// cylinder that robots can push. Physics engines with dynamics (ode) move it; kinematic2d
// refuses a scenario that has objects.
// `point` in the frame of a body at `origin` turned by `heading_rad` (x along the heading): how a
// box is tested against a point or a ray, in its own frame where it is axis-aligned.
inline Vec2 in_frame(const Vec2& point, const Vec2& origin, double heading_rad) {
  const double c = std::cos(heading_rad);
  const double s = std::sin(heading_rad);
  const Vec2 offset = point - origin;
  return {c * offset.x() + s * offset.y(), -s * offset.x() + c * offset.y()};
}

struct ArenaObject {
  enum class Shape : std::uint8_t { box, cylinder };

  Shape shape = Shape::box;
  Vec2 position = Vec2::Zero();  // centre, m
  double heading_rad = 0.0;      // box: direction of its size_x_m side, from +x
  double size_x_m = 0.0;         // box: side along its heading
  double size_y_m = 0.0;         // box: side across it
  double radius_m = 0.0;         // cylinder
  double mass_kg = 1.0;

  // The axis-aligned rectangle that contains the object at its pose.
  [[nodiscard]] Rect bounds() const {
    double half_x = radius_m;
    double half_y = radius_m;
    if (shape == Shape::box) {
      const double c = std::abs(std::cos(heading_rad));
      const double s = std::abs(std::sin(heading_rad));
      half_x = 0.5 * (c * size_x_m + s * size_y_m);
      half_y = 0.5 * (s * size_x_m + c * size_y_m);
    }
    return {position.x() - half_x, position.y() - half_y, position.x() + half_x,
            position.y() + half_y};
  }
};

struct Arena {
  double width_m = 0.0;
  double height_m = 0.0;
  std::vector<Rect> obstacles;
  std::vector<ArenaObject> objects = {};  // initial poses, in scenario order
};

}  // namespace swarmnet
