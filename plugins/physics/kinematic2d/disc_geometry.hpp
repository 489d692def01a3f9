// Geometry of disc-shaped robots against each other, the arena walls and rectangular obstacles.
//
// The predicates below define "overlap" for the whole engine: touching is allowed, any
// penetration is not, compared exactly (no tolerance). The push-outs leave a gap of
// kSeparationSlopM beyond contact so that rounding in the push cannot leave the pair overlapping
// by the predicate.
#pragma once

#include <algorithm>
#include <cmath>

#include "swarmnet/arena.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet::kinematic2d {

// 1 nm: far below anything a robot can sense, far above the rounding of metre-scale coordinates.
inline constexpr double kSeparationSlopM = 1e-9;

inline Vec2 closest_point(const Rect& rect, const Vec2& p) {
  return {std::clamp(p.x(), rect.x_min_m, rect.x_max_m),
          std::clamp(p.y(), rect.y_min_m, rect.y_max_m)};
}

inline bool discs_overlap(const Vec2& a, double a_radius_m, const Vec2& b, double b_radius_m) {
  const double contact_m = a_radius_m + b_radius_m;
  return (b - a).squaredNorm() < contact_m * contact_m;
}

inline bool disc_outside_arena(const Arena& arena, const Vec2& p, double radius_m) {
  return p.x() < radius_m || p.x() > arena.width_m - radius_m || p.y() < radius_m ||
         p.y() > arena.height_m - radius_m;
}

inline bool disc_overlaps_rect(const Rect& rect, const Vec2& p, double radius_m) {
  return (p - closest_point(rect, p)).squaredNorm() < radius_m * radius_m;
}

inline bool disc_overlaps_obstacle(const Arena& arena, const Vec2& p, double radius_m) {
  return std::any_of(arena.obstacles.begin(), arena.obstacles.end(),
                     [&](const Rect& rect) { return disc_overlaps_rect(rect, p, radius_m); });
}

// Moves the centre so that the disc lies inside the walls (the same bounds disc_outside_arena
// tests, so the result passes it exactly). Returns whether it moved.
inline bool clamp_into_arena(const Arena& arena, Vec2& p, double radius_m) {
  const Vec2 before = p;
  p.x() = std::min(std::max(p.x(), radius_m), arena.width_m - radius_m);
  p.y() = std::min(std::max(p.y(), radius_m), arena.height_m - radius_m);
  return p != before;
}

// Moves the centre out of `rect` along the shortest way: away from the nearest point of the
// rectangle, or, when the centre is inside it, through the nearest side. Returns whether it moved.
inline bool push_out_of_rect(const Rect& rect, Vec2& p, double radius_m) {
  if (!disc_overlaps_rect(rect, p, radius_m)) return false;
  const Vec2 nearest = closest_point(rect, p);
  const Vec2 away = p - nearest;
  const double distance_m = away.norm();
  if (distance_m > 0.0) {
    p = nearest + away * ((radius_m + kSeparationSlopM) / distance_m);
    return true;
  }
  // Centre inside the rectangle: leave through the side with the least penetration (ties in
  // the order left, right, bottom, top, so the choice is deterministic).
  const double to_left = p.x() - rect.x_min_m;
  const double to_right = rect.x_max_m - p.x();
  const double to_bottom = p.y() - rect.y_min_m;
  const double to_top = rect.y_max_m - p.y();
  const double least = std::min({to_left, to_right, to_bottom, to_top});
  const double clearance_m = radius_m + kSeparationSlopM;
  if (least == to_left) {
    p.x() = rect.x_min_m - clearance_m;
  } else if (least == to_right) {
    p.x() = rect.x_max_m + clearance_m;
  } else if (least == to_bottom) {
    p.y() = rect.y_min_m - clearance_m;
  } else {
    p.y() = rect.y_max_m + clearance_m;
  }
  return true;
}

}  // namespace swarmnet::kinematic2d
