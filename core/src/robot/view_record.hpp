// What controllers and world plugins asked the viewer to show (RobotContext::show_state,
// WorldContext::show_object and hide_object), kept as changes with their time and written as
// view_states.csv:
//
//   time_ns,entity,id,kind,state,x_m,y_m,radius_m
//
// entity "robot": robot `id` is in `state` from time_ns on (kind, x_m, y_m, radius_m empty);
// entity "object": object `id` of `kind` is in `state`, a disc of radius_m at (x_m, y_m);
// entity "hidden": object `id` is no longer drawn. Rows are in the order of the calls; a call
// that repeats what is shown adds none. Numbers are written in their shortest exact form.
#pragma once

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

class ViewRecord {
 public:
  explicit ViewRecord(std::size_t robots = 0) : robot_states_(robots) {}

  void robot_state(SimTime at, std::uint32_t robot, std::string_view label);
  void object(SimTime at, std::uint32_t id, std::string_view kind, std::string_view state,
              const Vec2& position, double radius_m);
  void hide(SimTime at, std::uint32_t id);

  [[nodiscard]] bool empty() const { return rows_.empty(); }
  [[nodiscard]] std::size_t rows() const { return rows_.size(); }
  void write_csv(std::ostream& out) const;

 private:
  enum class Entity : std::uint8_t { robot, object, hidden };
  struct Shown {
    std::string kind;
    std::string state;
    Vec2 position = Vec2::Zero();
    double radius_m = 0.0;
  };
  struct Row {
    SimTime at{};
    Entity entity = Entity::robot;
    std::uint32_t id = 0;
    Shown shown;
  };

  std::vector<std::string> robot_states_;
  std::map<std::uint32_t, Shown> objects_;
  std::vector<Row> rows_;
};

// `label` with commas, quotes and line breaks replaced by '_', so that it is one CSV field.
std::string csv_safe_label(std::string_view label);

}  // namespace swarmnet
