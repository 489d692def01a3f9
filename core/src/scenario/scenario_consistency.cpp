#include "scenario/scenario_consistency.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <vector>

#include "plugin/plugin_catalog.hpp"
#include "scenario/free_area.hpp"
#include "swarmnet/arena.hpp"

namespace swarmnet {

namespace {

std::optional<double> real_at(const YAML::Node& tree, const KeyPath& path) {
  const auto node = checked_node_at(tree, path);
  if (!node || !node->IsScalar()) return std::nullopt;
  return node->as<double>();
}

std::optional<Rect> rect_of(const YAML::Node& node) {
  for (const char* key : {"x_min_m", "y_min_m", "x_max_m", "y_max_m"}) {
    if (!node[key]) return std::nullopt;
  }
  return Rect{node["x_min_m"].as<double>(), node["y_min_m"].as<double>(),
              node["x_max_m"].as<double>(), node["y_max_m"].as<double>()};
}

YAML::Node rect_node(const Rect& rect) {
  YAML::Node node(YAML::NodeType::Map);
  node["x_min_m"] = format_real(rect.x_min_m);
  node["y_min_m"] = format_real(rect.y_min_m);
  node["x_max_m"] = format_real(rect.x_max_m);
  node["y_max_m"] = format_real(rect.y_max_m);
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

// Numbers in messages, without the noise of binary fractions (11 * 0.1 = 1.1000000000000001).
std::string approx(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", value);
  return buffer;
}

// Areas, to a precision that reads well.
std::string area(double value_m2) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value_m2);
  return std::string(buffer) + " m^2";
}

std::string describe(const Rect& rect) {
  return "[" + approx(rect.x_min_m) + ", " + approx(rect.x_max_m) + "] x [" + approx(rect.y_min_m) +
         ", " + approx(rect.y_max_m) + "]";
}

// Refuses an empty rectangle or one reaching outside the arena; true when it is usable.
bool check_rect(const Rect& rect, double width_m, double height_m, const KeyPath& path,
                const YAML::Mark& mark, const std::string& what, ProblemList& problems) {
  if (!(rect.x_min_m < rect.x_max_m) || !(rect.y_min_m < rect.y_max_m)) {
    problems.add(path, mark, describe(rect) + " is empty",
                 "x_min_m < x_max_m and y_min_m < y_max_m");
    return false;
  }
  if (rect.x_min_m < 0.0 || rect.y_min_m < 0.0 || rect.x_max_m > width_m ||
      rect.y_max_m > height_m) {
    problems.add(path, mark,
                 describe(rect) + " reaches outside the arena [0, " + approx(width_m) + "] x [0, " +
                     approx(height_m) + "]",
                 what + " inside the arena");
    return false;
  }
  return true;
}

void check_steps(const YAML::Node& tree, const ScenarioChecker& checker, ProblemList& problems) {
  const KeyPath duration_path({"duration_s"});
  const auto duration = real_at(tree, duration_path);
  const auto step = real_at(tree, KeyPath({"step_s"}));
  if (!duration || !step) return;
  const YAML::Mark mark = checker.mark_of(duration_path);
  const double steps = std::round(*duration / *step);
  const std::string expected = "a positive multiple of step_s";
  if (steps < 1.0) {
    problems.add(duration_path, mark,
                 approx(*duration) + " s is shorter than one step of " + approx(*step) + " s",
                 expected);
  } else if (steps > kMaxSteps) {
    problems.add(duration_path, mark,
                 approx(*duration) + " s is " + approx(steps) + " steps of " + approx(*step) + " s",
                 "at most " + approx(kMaxSteps) + " steps");
  } else if (std::fabs(*duration - steps * *step) > 1e-9 * *duration) {
    const double below = std::floor(*duration / *step) * *step;
    const double above = below + *step;
    problems.add(
        duration_path, mark,
        approx(*duration) + " s is not a whole number of steps of " + approx(*step) + " s",
        expected + ", such as " + (below > 0.0 ? approx(below) + " or " : "") + approx(above));
  }
}

// Movable objects: a box with both sides, a cylinder with a radius, lying inside the arena.
void check_objects(const YAML::Node& tree, const ScenarioChecker& checker, double width_m,
                   double height_m, ProblemList& problems) {
  const KeyPath objects_path({"arena", "objects"});
  const auto objects_node = checked_node_at(tree, objects_path);
  if (!objects_node) return;
  for (std::size_t i = 0; i < objects_node->size(); ++i) {
    const YAML::Node node = (*objects_node)[i];
    const KeyPath path = objects_path / i;
    const YAML::Mark mark = checker.mark_of(path);
    if (!node["shape"] || !node["x_m"] || !node["y_m"]) continue;  // already reported
    ArenaObject object;
    object.position = Vec2(node["x_m"].as<double>(), node["y_m"].as<double>());
    object.heading_rad = node["heading_rad"].as<double>();
    if (node["shape"].as<std::string>() == "box") {
      object.size_x_m = node["size_x_m"].as<double>();
      object.size_y_m = node["size_y_m"].as<double>();
      if (!(object.size_x_m > 0.0) || !(object.size_y_m > 0.0)) {
        problems.add(path, mark,
                     "a box of " + approx(object.size_x_m) + " x " + approx(object.size_y_m) +
                         " m has no area",
                     "a box with size_x_m > 0 and size_y_m > 0");
        continue;
      }
    } else {
      object.shape = ArenaObject::Shape::cylinder;
      object.radius_m = node["radius_m"].as<double>();
      if (!(object.radius_m > 0.0)) {
        problems.add(path, mark, "a cylinder of radius " + approx(object.radius_m) + " m",
                     "a cylinder with radius_m > 0");
        continue;
      }
    }
    const Rect bounds = object.bounds();
    if (bounds.x_min_m < 0.0 || bounds.y_min_m < 0.0 || bounds.x_max_m > width_m ||
        bounds.y_max_m > height_m) {
      problems.add(path, mark,
                   "the object covers " + describe(bounds) + ", reaching outside the arena [0, " +
                       approx(width_m) + "] x [0, " + approx(height_m) + "]",
                   "an object inside the arena");
    }
  }
}

}  // namespace

void check_consistency(YAML::Node& tree, const ScenarioChecker& checker, ProblemList& problems) {
  check_steps(tree, checker, problems);

  const auto width = real_at(tree, KeyPath({"arena", "width_m"}));
  const auto height = real_at(tree, KeyPath({"arena", "height_m"}));
  if (!width || !height) return;

  // Obstacles inside the arena.
  const KeyPath obstacles_path({"arena", "obstacles"});
  const auto obstacles_node = checked_node_at(tree, obstacles_path);
  std::vector<Rect> obstacles;
  bool obstacles_valid = obstacles_node.has_value();
  if (obstacles_node) {
    for (std::size_t i = 0; i < obstacles_node->size(); ++i) {
      const auto rect = rect_of((*obstacles_node)[i]);
      if (!rect) continue;
      const KeyPath path = obstacles_path / i;
      if (check_rect(*rect, *width, *height, path, checker.mark_of(path), "an obstacle",
                     problems)) {
        obstacles.push_back(*rect);
      } else {
        obstacles_valid = false;
      }
    }
  }

  check_objects(tree, checker, *width, *height, problems);

  // The placement region: inside the arena, or the whole arena when not given.
  const KeyPath placement_path({"robots", "placement"});
  auto placement = checked_node_at(tree, placement_path);
  if (!placement) return;
  const KeyPath region_path = placement_path / "region";
  std::optional<Rect> region;
  if (const auto region_node = checked_node_at(tree, region_path)) {
    region = rect_of(*region_node);
    if (region && !check_rect(*region, *width, *height, region_path, checker.mark_of(region_path),
                              "a region", problems)) {
      region.reset();
    }
  } else if (!checker.mark_of(region_path).is_null()) {
    return;  // given, but invalid: already reported
  } else {
    region = Rect{0.0, 0.0, *width, *height};
    (*placement)["region"] = rect_node(*region);
  }
  if (!region || !obstacles_valid) return;

  // Do the robots fit?
  const KeyPath count_path({"robots", "count"});
  const KeyPath radius_path({"robots", "radius_m"});
  const auto count = real_at(tree, count_path);
  const auto radius = real_at(tree, radius_path);
  if (!count || !radius) return;
  if (2.0 * *radius > region->width_m() || 2.0 * *radius > region->height_m()) {
    problems.add(radius_path, checker.mark_of(radius_path),
                 "a robot of radius " + approx(*radius) +
                     " m does not fit in the placement region " + describe(*region),
                 "a radius below half the region's smaller side");
    return;
  }
  const double free_m2 = free_area(*region, obstacles);
  const double disc_m2 = std::numbers::pi * *radius * *radius;
  const double robots_m2 = *count * disc_m2;
  if (robots_m2 > 0.5 * free_m2) {
    const double most = std::floor(0.5 * free_m2 / disc_m2);
    problems.add(count_path, checker.mark_of(count_path),
                 approx(*count) + " robots of radius " + approx(*radius) + " m cover " +
                     area(robots_m2) + ", more than half of the " + area(free_m2) +
                     " free area of the placement region",
                 "at most " + approx(most) +
                     " robots of this size (or a smaller radius_m, or a larger region)");
  }
}

}  // namespace swarmnet
