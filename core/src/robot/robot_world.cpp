#include "robot/robot_world.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include "robot/robot_placement.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet {

namespace {

// Points the contexts' send() at `messages` while controllers run, and nowhere afterwards, even
// when a controller throws.
class OutboxScope {
 public:
  OutboxScope(RobotWorldState& state, std::vector<AppMessage>& messages) : state_(state) {
    state_.outbox = &messages;
  }
  OutboxScope(const OutboxScope&) = delete;
  OutboxScope& operator=(const OutboxScope&) = delete;
  ~OutboxScope() { state_.outbox = nullptr; }

 private:
  RobotWorldState& state_;
};

}  // namespace

RobotWorld::RobotWorld(const RobotSettings& settings, PluginLoader& loader) {
  const RobotsConfig& robots = settings.robots;
  if (!(settings.step_s > 0.0)) {
    throw std::invalid_argument("step_s must be positive, not " + std::to_string(settings.step_s));
  }
  state_.step_s = settings.step_s;
  state_.arena = settings.arena;
  step_length_ = from_seconds(settings.step_s);

  RobotBody prototype;
  prototype.radius_m = robots.radius_m;
  prototype.axle_m = robots.axle_m;
  prototype.max_speed_mps = robots.max_speed_mps;
  state_.bodies = place_robots(settings.arena, robots.placement, robots.count, prototype,
                               derive_seed(settings.seed, {hash_name("placement")}));

  const std::size_t count = state_.bodies.size();
  state_.rays_per_robot = robots.proximity.rays;
  state_.proximity_range_m = robots.proximity.range_m;
  state_.proximity.assign(count * state_.rays_per_robot, robots.proximity.range_m);
  for (std::size_t c = 0; c < robots.controllers.size(); ++c) {
    entry_ports_.push_back(robots.port_of(c));
    state_.ports.push_back(robots.port_of(c));
  }
  std::sort(state_.ports.begin(), state_.ports.end());
  state_.ports.erase(std::unique(state_.ports.begin(), state_.ports.end()), state_.ports.end());
  for (const std::uint16_t port : entry_ports_) entry_port_indices_.push_back(port_index(port));
  state_.inboxes.resize(count * std::max<std::size_t>(state_.ports.size(), 1));
  state_.neighbors_enabled = settings.neighbor_tables;
  state_.neighbor_first.assign(count + 1, 0);
  state_.route_asks.assign(count, {});
  state_.metrics = RobotMetrics(count);
  state_.series = MetricSeries(settings.open_series);
  if (robots.range_and_bearing.enabled) {
    range_and_bearing_.emplace(robots.range_and_bearing, count, settings.seed);
    state_.range_and_bearing = &*range_and_bearing_;
  }

  PluginArgs physics_args;
  physics_args.params = settings.physics.params;
  physics_args.seed = derive_seed(settings.seed, {hash_name("physics")});
  physics_args.shared_seed = physics_args.seed;
  physics_ = loader.create<Physics>(settings.physics.name, physics_args);
  physics_->setup(settings.arena, state_.bodies);
  state_.switched_off.assign(count, 0);
  worlds_.emplace(state_, settings.worlds, settings.seed, loader);
  state_.worlds = &*worlds_;

  controllers_per_robot_ = robots.controllers.size();
  controllers_.reserve(count * controllers_per_robot_);
  contexts_.reserve(count);
  for (std::size_t r = 0; r < count; ++r) {
    contexts_.emplace_back(state_, static_cast<RobotId>(r));
    for (std::size_t c = 0; c < controllers_per_robot_; ++c) {
      const PluginChoice& choice = robots.controllers[c];
      PluginArgs args;
      args.params = choice.params;
      args.seed = derive_seed(settings.seed, {hash_name("controller"), c, r});
      args.shared_seed = derive_seed(settings.seed, {hash_name("controller"), c});
      args.instance = static_cast<std::uint32_t>(r);
      args.instance_count = static_cast<std::uint32_t>(count);
      controllers_.push_back(loader.create<Controller>(choice.name, args));
    }
  }

  sense();
  state_.now = kTimeZero;
  worlds_->setup();
  const OutboxScope outbox(state_, sent_in_init_);
  for (std::size_t r = 0; r < count; ++r) {
    for (std::size_t c = 0; c < controllers_per_robot_; ++c) {
      enter(c);
      controllers_[r * controllers_per_robot_ + c]->init(contexts_[r]);
    }
  }
}

std::span<const double> RobotWorld::proximity(RobotId robot) const {
  return {state_.proximity.data() + static_cast<std::size_t>(robot) * state_.rays_per_robot,
          state_.rays_per_robot};
}

std::span<const RangeAndBearingReading> RobotWorld::range_and_bearing(RobotId robot) const {
  if (!range_and_bearing_) return {};
  return range_and_bearing_->readings(robot);
}

std::size_t RobotWorld::port_index(std::uint16_t port) const {
  return static_cast<std::size_t>(std::lower_bound(state_.ports.begin(), state_.ports.end(), port) -
                                  state_.ports.begin());
}

void RobotWorld::enter(std::size_t entry) {
  state_.current_port = entry_ports_[entry];
  state_.current_port_index = entry_port_indices_[entry];
}

void RobotWorld::fill_inboxes(std::span<const Delivery> deliveries) {
  for (Inbox& inbox : state_.inboxes) inbox.size = 0;
  const std::size_t ports = state_.ports.size();
  for (const Delivery& delivery : deliveries) {
    if (delivery.receiver >= state_.bodies.size() || ports == 0) continue;
    // A port no controller entry has (only a faulty peer sends one) reaches no inbox.
    const std::size_t k = port_index(delivery.port);
    if (k == ports || state_.ports[k] != delivery.port) continue;
    Inbox& inbox = state_.inboxes[delivery.receiver * ports + k];
    if (inbox.size == inbox.slots.size()) inbox.slots.emplace_back();
    ReceivedMessage& message = inbox.slots[inbox.size++];
    message.message_id = delivery.message_id;
    message.source = delivery.source;
    message.destination = delivery.destination;
    message.sent_at = delivery.sent_at;
    message.delivered_at = delivery.delivered_at;
    message.hops = delivery.hops;
    // assign() reuses the slot's buffer: no allocation unless this payload is the largest yet.
    message.payload.assign(delivery.payload.begin(), delivery.payload.end());
  }
}

void RobotWorld::sense() {
  const std::size_t rays = state_.rays_per_robot;
  if (rays == 0) return;
  for (std::size_t r = 0; r < state_.bodies.size(); ++r) {
    physics_->sense_proximity(state_.bodies, r, state_.proximity_range_m,
                              std::span<double>(state_.proximity.data() + r * rays, rays));
  }
}

void RobotWorld::sense_range_and_bearing() {
  if (!range_and_bearing_) return;
  range_and_bearing_->sense(state_.arena, state_.bodies, physics_->object_poses(),
                            state_.switched_off, step_index_);
}

void RobotWorld::set_neighbor_tables(std::span<const std::uint32_t> counts,
                                     std::span<const RadioNeighbor> entries) {
  if (!state_.neighbors_enabled) return;
  const std::size_t robots = state_.bodies.size();
  std::size_t total = 0;
  for (std::size_t r = 0; r < robots; ++r) {
    state_.neighbor_first[r] = total;
    if (r < counts.size()) total += counts[r];
  }
  state_.neighbor_first[robots] = std::min(total, entries.size());
  state_.neighbors.assign(entries.begin(), entries.begin() + static_cast<std::ptrdiff_t>(
                                                                 state_.neighbor_first[robots]));
}

void RobotWorld::set_send_reports(std::span<const AddressedSendReport> reports) {
  state_.send_report_slots.clear();
  state_.send_reports.clear();
  if (reports.empty()) return;
  const std::size_t ports = state_.ports.size();
  std::vector<std::pair<std::size_t, const SendReport*>> addressed;
  addressed.reserve(reports.size());
  for (const AddressedSendReport& r : reports) {
    const std::size_t k = port_index(r.port);
    if (r.source >= state_.bodies.size() || k == ports || state_.ports[k] != r.port) continue;
    addressed.emplace_back(r.source * ports + k, &r.report);
  }
  // Stable: a slot's reports keep the order their outcomes happened in.
  std::stable_sort(addressed.begin(), addressed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [slot, report] : addressed) {
    state_.send_report_slots.push_back(slot);
    state_.send_reports.push_back(*report);
  }
}

void RobotWorld::set_routes(std::span<const RouteAnswer> routes) {
  state_.routes.clear();
  for (const RouteAnswer& answer : routes) {
    if (answer.query.robot < state_.bodies.size()) state_.routes.push_back(answer);
  }
}

void RobotWorld::take_route_queries(std::vector<RouteQuery>& queries) {
  queries.clear();
  for (RobotId r = 0; r < state_.route_asks.size(); ++r) {
    std::vector<RobotId>& asks = state_.route_asks[r];
    std::sort(asks.begin(), asks.end());
    for (const RobotId destination : asks) queries.push_back(RouteQuery{r, destination});
    asks.clear();
  }
}

void RobotWorld::step(std::span<const Delivery> deliveries, std::vector<AppMessage>& sent) {
  fill_inboxes(deliveries);
  if (!sent_in_init_.empty()) {
    sent.insert(sent.end(), std::make_move_iterator(sent_in_init_.begin()),
                std::make_move_iterator(sent_in_init_.end()));
    sent_in_init_.clear();
  }
  state_.now = now();
  // Switch-offs asked for during the previous step take effect now (swarmnet/world.hpp).
  std::replace(state_.switched_off.begin(), state_.switched_off.end(), kSwitchOffPending,
               std::uint8_t{1});
  sense_range_and_bearing();
  worlds_->pre_step();
  {
    const OutboxScope outbox(state_, sent);
    for (std::size_t r = 0; r < contexts_.size(); ++r) {
      if (state_.switched_off[r] == 1) {
        state_.bodies[r].left_mps = 0.0;
        state_.bodies[r].right_mps = 0.0;
        continue;
      }
      for (std::size_t c = 0; c < controllers_per_robot_; ++c) {
        enter(c);
        controllers_[r * controllers_per_robot_ + c]->control_step(contexts_[r]);
      }
    }
  }
  physics_->step(state_.step_s, state_.bodies);
  sense();
  ++step_index_;
  state_.now = now();
  worlds_->post_step();
}

}  // namespace swarmnet
