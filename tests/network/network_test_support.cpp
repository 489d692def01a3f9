#include "network_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "network/network_simulator.hpp"
#include "network/packet_trace.hpp"
#include "outputs/run_summary.hpp"
#include "plugin/default_plugin_choice.hpp"
#include "swarmnet/random.hpp"

namespace swarmnet::test {

PluginChoice choose(PluginLoader& loader, const std::string& name, PluginKind kind) {
  return default_plugin_choice(loader, name, kind);
}

void set_param(PluginChoice& choice, const std::string& name, ParamValue value) {
  ASSERT_TRUE(choice.params.contains(name)) << choice.name << " has no parameter " << name;
  ASSERT_EQ(choice.params.values().at(name).index(), value.index())
      << choice.name << "." << name << " has another type";
  choice.params.set(name, std::move(value));
}

NetworkSettings make_settings(PluginLoader& loader, std::uint32_t robots, const std::string& mac,
                              const std::string& routing) {
  NetworkSettings settings;
  settings.seed = 1;
  settings.step_s = 0.1;
  settings.arena.width_m = 1000.0;
  settings.arena.height_m = 1000.0;
  settings.nodes = robots;
  settings.network.propagation = {choose(loader, "disk", PluginKind::propagation)};
  settings.network.mac = choose(loader, mac, PluginKind::mac);
  settings.network.routing = choose(loader, routing, PluginKind::routing);
  return settings;
}

std::vector<Vec2> line_positions(std::uint32_t robots, double spacing_m) {
  std::vector<Vec2> positions;
  for (std::uint32_t i = 0; i < robots; ++i) positions.emplace_back(10.0 + spacing_m * i, 50.0);
  return positions;
}

AppMessage message(std::uint64_t id, RobotId source, RobotId destination,
                   std::size_t payload_bytes) {
  AppMessage m;
  m.message_id = id;
  m.source = source;
  m.destination = destination;
  m.payload.resize(payload_bytes);
  for (std::size_t i = 0; i < payload_bytes; ++i) m.payload[i] = static_cast<std::byte>(i + id);
  return m;
}

std::vector<StepBatch> fixed_batches(const NetworkSettings& settings,
                                     const std::vector<Vec2>& positions, std::uint64_t steps,
                                     std::vector<AppMessage> messages) {
  std::vector<StepBatch> batches(steps);
  const SimTime step = from_seconds(settings.step_s);
  for (std::uint64_t i = 0; i < steps; ++i) {
    batches[i].step = i;
    batches[i].start = step * static_cast<std::int64_t>(i);
    batches[i].positions = positions;
  }
  if (steps > 0) batches[0].messages = std::move(messages);
  return batches;
}

std::vector<StepBatch> random_batches(const NetworkSettings& settings, std::uint64_t traffic_seed,
                                      std::uint64_t steps, std::uint32_t messages_per_step,
                                      double broadcast_fraction, double move_m) {
  RandomStream random(traffic_seed);
  const std::uint32_t n = settings.nodes;
  const double w = settings.arena.width_m;
  const double h = settings.arena.height_m;
  std::vector<Vec2> positions;
  for (std::uint32_t i = 0; i < n; ++i) {
    positions.emplace_back(random.uniform(0.0, w), random.uniform(0.0, h));
  }
  const SimTime step = from_seconds(settings.step_s);
  std::vector<StepBatch> batches(steps);
  std::uint64_t next_id = 0;
  for (std::uint64_t s = 0; s < steps; ++s) {
    StepBatch& batch = batches[s];
    batch.step = s;
    batch.start = step * static_cast<std::int64_t>(s);
    for (Vec2& p : positions) {
      p.x() = std::clamp(p.x() + random.uniform(-move_m, move_m), 0.0, w);
      p.y() = std::clamp(p.y() + random.uniform(-move_m, move_m), 0.0, h);
    }
    batch.positions = positions;
    for (std::uint32_t k = 0; k < messages_per_step; ++k) {
      const auto source = static_cast<RobotId>(random.below(n));
      RobotId destination = kBroadcast;
      if (!random.bernoulli(broadcast_fraction)) {
        destination = static_cast<RobotId>((source + 1 + random.below(n - 1)) % n);
      }
      batch.messages.push_back(message(next_id++, source, destination, 16 + random.below(241)));
    }
  }
  return batches;
}

RunOutput run(const NetworkSettings& settings, PluginLoader& loader,
              const std::vector<StepBatch>& batches,
              std::vector<AddressedSendReport>* send_reports) {
  RunOutput output;
  std::ostringstream trace;
  {
    NetworkSimulator simulator(settings, loader, &trace);
    StepResult result;
    for (const StepBatch& batch : batches) {
      simulator.run_step(batch, result);
      EXPECT_EQ(result.step, batch.step);
      output.events_per_step.push_back(result.events);
      for (auto& delivery : result.deliveries) output.deliveries.push_back(std::move(delivery));
      if (send_reports != nullptr) {
        send_reports->insert(send_reports->end(), result.send_reports.begin(),
                             result.send_reports.end());
      }
    }
    simulator.finish();
    output.report = network_report_json(simulator.report());
  }
  output.trace = trace.str();
  return output;
}

std::vector<TraceLine> parse_trace(const std::string& text) {
  std::vector<TraceLine> lines;
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line + "\n", std::string(PacketTraceWriter::kHeader));
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::string field;
    std::istringstream cells(line);
    while (std::getline(cells, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    EXPECT_EQ(fields.size(), 10U) << "malformed trace line: " << line;
    if (fields.size() != 10U) continue;
    TraceLine t;
    t.time_ns = std::stoll(fields[0]);
    t.event = fields[1];
    t.node = std::stoll(fields[2]);
    t.uid = std::stoull(fields[3]);
    t.message_id = fields[4];
    t.source = std::stoll(fields[5]);
    t.destination = std::stoll(fields[6]);
    t.hops = static_cast<std::uint32_t>(std::stoul(fields[7]));
    t.bytes = static_cast<std::uint32_t>(std::stoul(fields[8]));
    t.detail = fields[9];
    lines.push_back(std::move(t));
  }
  return lines;
}

std::size_t count_events(const std::vector<TraceLine>& lines, const std::string& event,
                         std::int64_t node) {
  return static_cast<std::size_t>(
      std::count_if(lines.begin(), lines.end(),
                    [&](const TraceLine& t) { return t.event == event && t.node == node; }));
}

}  // namespace swarmnet::test
