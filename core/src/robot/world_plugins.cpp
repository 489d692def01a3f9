#include "robot/world_plugins.hpp"

#include <stdexcept>

#include "swarmnet/random.hpp"

namespace swarmnet {

namespace {

std::string offered_names(const std::map<std::string, std::size_t, std::less<>>& owners) {
  if (owners.empty()) return "none";
  std::string names;
  for (const auto& [name, world] : owners) names += (names.empty() ? "" : ", ") + name;
  return names;
}

}  // namespace

WorldPlugins::WorldPlugins(RobotWorldState& state, const std::vector<PluginChoice>& choices,
                           std::uint64_t seed, PluginLoader& loader)
    : state_(state) {
  for (std::size_t w = 0; w < choices.size(); ++w) {
    PluginArgs args;
    args.params = choices[w].params;
    args.seed = derive_seed(seed, {hash_name("world"), w});
    args.shared_seed = args.seed;
    args.instance_count = 1;
    names_.push_back(choices[w].name);
    worlds_.push_back(loader.create<World>(choices[w].name, args));
    const auto claim = [&](std::map<std::string, std::size_t, std::less<>>& owners,
                           const std::string& name, const char* what) {
      const auto [it, added] = owners.emplace(name, w);
      if (!added) {
        throw std::invalid_argument("world plugins " + names_[it->second] + " (world." +
                                    std::to_string(it->second) + ") and " + names_[w] + " (world." +
                                    std::to_string(w) + ") both offer the " + what + " '" + name +
                                    "'; a " + what + " needs one owner");
      }
    };
    for (const std::string& name : worlds_.back()->readings())
      claim(reading_owners_, name, "reading");
    for (const std::string& name : worlds_.back()->requests())
      claim(request_owners_, name, "request");
  }
}

template <typename Hook>
void WorldPlugins::call(std::size_t w, const char* hook, Hook&& action) {
  try {
    action(*worlds_[w]);
  } catch (const std::exception& error) {
    throw std::runtime_error("world " + names_[w] + " (world." + std::to_string(w) + "), " + hook +
                             " at " + std::to_string(to_seconds(state_.now)) +
                             " s: " + error.what());
  }
}

void WorldPlugins::setup() {
  for (std::size_t w = 0; w < worlds_.size(); ++w) {
    call(w, "setup", [&](World& world) { world.setup(*this); });
  }
}

void WorldPlugins::pre_step() {
  for (std::size_t w = 0; w < worlds_.size(); ++w) {
    call(w, "pre_step", [&](World& world) { world.pre_step(*this); });
  }
}

void WorldPlugins::post_step() {
  for (std::size_t w = 0; w < worlds_.size(); ++w) {
    call(w, "post_step", [&](World& world) { world.post_step(*this); });
    if (!done_by_ && worlds_[w]->task_done()) done_by_ = w;
  }
}

void WorldPlugins::end() {
  for (std::size_t w = 0; w < worlds_.size(); ++w) {
    call(w, "end", [&](World& world) { world.end(*this); });
  }
}

std::optional<std::string> WorldPlugins::done_by() const {
  if (!done_by_) return std::nullopt;
  return names_[*done_by_];
}

std::size_t WorldPlugins::owner(const std::map<std::string, std::size_t, std::less<>>& owners,
                                std::string_view name, std::string_view what, RobotId robot) const {
  const auto it = owners.find(name);
  if (it == owners.end()) {
    throw std::invalid_argument("robot " + std::to_string(robot) + ": no world plugin offers the " +
                                std::string(what) + " '" + std::string(name) +
                                "'; the scenario's worlds offer: " + offered_names(owners));
  }
  return it->second;
}

std::span<const double> WorldPlugins::read(RobotId robot, std::string_view name) {
  const std::size_t w = owner(reading_owners_, name, "reading", robot);
  scratch_.clear();
  try {
    worlds_[w]->read(*this, robot, name, scratch_);
  } catch (const std::exception& error) {
    throw std::runtime_error("world " + names_[w] + ": reading '" + std::string(name) +
                             "' for robot " + std::to_string(robot) + ": " + error.what());
  }
  return scratch_;
}

void WorldPlugins::request(RobotId robot, std::string_view name, std::span<const double> args) {
  const std::size_t w = owner(request_owners_, name, "request", robot);
  try {
    worlds_[w]->request(*this, robot, name, args);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("world " + names_[w] + ": request '" + std::string(name) +
                                "' from robot " + std::to_string(robot) + ": " + error.what());
  }
}

const RobotBody& WorldPlugins::body(RobotId robot) const {
  if (robot >= state_.bodies.size()) {
    throw std::out_of_range("a world plugin asked for robot " + std::to_string(robot) +
                            "; there are " + std::to_string(state_.bodies.size()));
  }
  return state_.bodies[robot];
}

bool WorldPlugins::switched_off(RobotId robot) const {
  (void)body(robot);
  return state_.switched_off[robot] != 0;
}

void WorldPlugins::switch_off(RobotId robot) {
  (void)body(robot);
  if (state_.switched_off[robot] == 0) state_.switched_off[robot] = kSwitchOffPending;
}

void WorldPlugins::record(std::string_view metric, double value) {
  record_metric(metrics_, metric, value);
}

void WorldPlugins::sample(std::string_view series, double value) {
  state_.series.sample(state_.now, std::nullopt, series, value);
}

void WorldPlugins::show_object(std::uint32_t id, std::string_view kind, std::string_view state,
                               Vec2 position, double radius_m) {
  state_.view.object(state_.now, id, kind, state, position, radius_m);
}

void WorldPlugins::hide_object(std::uint32_t id) { state_.view.hide(state_.now, id); }

}  // namespace swarmnet
