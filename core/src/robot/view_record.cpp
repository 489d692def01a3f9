#include "robot/view_record.hpp"

#include "text/shortest_number.hpp"

namespace swarmnet {

std::string csv_safe_label(std::string_view label) {
  std::string safe(label);
  for (char& c : safe) {
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = '_';
  }
  return safe;
}

void ViewRecord::robot_state(SimTime at, std::uint32_t robot, std::string_view label) {
  if (robot >= robot_states_.size()) robot_states_.resize(robot + 1);
  std::string safe = csv_safe_label(label);
  if (robot_states_[robot] == safe) return;
  robot_states_[robot] = std::move(safe);
  Row row;
  row.at = at;
  row.entity = Entity::robot;
  row.id = robot;
  row.shown.state = robot_states_[robot];
  rows_.push_back(std::move(row));
}

void ViewRecord::object(SimTime at, std::uint32_t id, std::string_view kind, std::string_view state,
                        const Vec2& position, double radius_m) {
  Shown shown{csv_safe_label(kind), csv_safe_label(state), position, radius_m};
  const auto it = objects_.find(id);
  if (it != objects_.end() && it->second.kind == shown.kind && it->second.state == shown.state &&
      it->second.position == shown.position && it->second.radius_m == shown.radius_m) {
    return;
  }
  objects_[id] = shown;
  rows_.push_back(Row{at, Entity::object, id, std::move(shown)});
}

void ViewRecord::hide(SimTime at, std::uint32_t id) {
  if (objects_.erase(id) == 0) return;
  rows_.push_back(Row{at, Entity::hidden, id, {}});
}

void ViewRecord::write_csv(std::ostream& out) const {
  out << "time_ns,entity,id,kind,state,x_m,y_m,radius_m\n";
  for (const Row& row : rows_) {
    out << row.at.count() << ',';
    switch (row.entity) {
      case Entity::robot:
        out << "robot," << row.id << ",," << row.shown.state << ",,,\n";
        break;
      case Entity::object:
        out << "object," << row.id << ',' << row.shown.kind << ',' << row.shown.state << ',';
        write_shortest(out, row.shown.position.x());
        out << ',';
        write_shortest(out, row.shown.position.y());
        out << ',';
        write_shortest(out, row.shown.radius_m);
        out << '\n';
        break;
      case Entity::hidden:
        out << "hidden," << row.id << ",,,,,\n";
        break;
    }
  }
}

}  // namespace swarmnet
