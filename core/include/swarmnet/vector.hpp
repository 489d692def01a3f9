// Geometry types (Eigen) used across the SDK.
#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace swarmnet {

using Vec2 = Eigen::Vector2d;

// Axis-aligned rectangle, in metres, arena coordinates.
struct Rect {
  double x_min_m = 0.0;
  double y_min_m = 0.0;
  double x_max_m = 0.0;
  double y_max_m = 0.0;

  bool operator==(const Rect&) const = default;

  [[nodiscard]] double width_m() const { return x_max_m - x_min_m; }
  [[nodiscard]] double height_m() const { return y_max_m - y_min_m; }
  [[nodiscard]] bool contains(const Vec2& p) const {
    return p.x() >= x_min_m && p.x() <= x_max_m && p.y() >= y_min_m && p.y() <= y_max_m;
  }
  // Grows the rectangle just enough to contain `p`.
  void include(const Vec2& p) {
    x_min_m = std::min(x_min_m, p.x());
    y_min_m = std::min(y_min_m, p.y());
    x_max_m = std::max(x_max_m, p.x());
    y_max_m = std::max(y_max_m, p.y());
  }
};

}  // namespace swarmnet
