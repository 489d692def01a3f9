#include "protocol/step_channel.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "protocol/network_report_codec.hpp"

namespace swarmnet {

namespace {

// Positions travel in chunks so that no record approaches a ring's size at any swarm size.
constexpr std::uint32_t kPositionsPerRecord = 1024;
constexpr std::size_t kPositionBytes = 2 * sizeof(double);  // x, y

}  // namespace

const char* to_string(RecordType type) {
  switch (type) {
    case RecordType::step_begin:
      return "step_begin";
    case RecordType::positions:
      return "positions";
    case RecordType::message:
      return "message";
    case RecordType::step_end:
      return "step_end";
    case RecordType::delivery:
      return "delivery";
    case RecordType::step_done:
      return "step_done";
    case RecordType::finish:
      return "finish";
    case RecordType::report:
      return "report";
    case RecordType::failure:
      return "failure";
    case RecordType::neighbors:
      return "neighbors";
    case RecordType::send_report:
      return "send_report";
    case RecordType::route_query:
      return "route_query";
    case RecordType::route:
      return "route";
    case RecordType::hello:
      return "hello";
    case RecordType::welcome:
      return "welcome";
  }
  return "unknown";
}

StepChannel::StepChannel(Transport& transport, std::string peer)
    : transport_(transport), peer_(std::move(peer)) {}

template <typename... Fields>
ProtocolResult StepChannel::send_record(const char* what, bool last_of_batch,
                                        const Fields&... fields) {
  std::span<std::byte> space;
  IoStatus status = transport_.reserve((encoded_bytes(fields) + ...), space);
  if (status == IoStatus::ok) {
    RecordWriter writer(space);
    (writer.put(fields), ...);
    status = transport_.commit();
  }
  return sent(what, status, last_of_batch);
}

ProtocolResult StepChannel::send_positions(const StepBatch& batch, std::uint32_t first,
                                           std::uint32_t count) {
  const RecordType type = RecordType::positions;
  std::span<std::byte> space;
  IoStatus status =
      transport_.reserve(encoded_bytes(type) + encoded_bytes(first) + encoded_bytes(count) +
                             std::size_t{count} * kPositionBytes,
                         space);
  if (status == IoStatus::ok) {
    RecordWriter writer(space);
    writer.put(type).put(first).put(count);
    for (std::uint32_t i = 0; i < count; ++i) {
      const Vec2& p = batch.positions[first + i];
      writer.put(p.x()).put(p.y());
    }
    status = transport_.commit();
  }
  return sent("positions", status, false);
}

// id, last_heard, rssi, smoothed rssi, sinr, frames, unicasts, first-attempt acks.
constexpr std::size_t kNeighborBytes = 4 + 8 + 8 + 8 + 8 + 4 + 4 + 4;

ProtocolResult StepChannel::send_neighbors(RobotId robot, std::span<const RadioNeighbor> table) {
  const RecordType type = RecordType::neighbors;
  const auto count = static_cast<std::uint32_t>(table.size());
  std::span<std::byte> space;
  IoStatus status = transport_.reserve(encoded_bytes(type) + encoded_bytes(robot) +
                                           encoded_bytes(count) + table.size() * kNeighborBytes,
                                       space);
  if (status == IoStatus::ok) {
    RecordWriter writer(space);
    writer.put(type).put(robot).put(count);
    for (const RadioNeighbor& n : table) {
      writer.put(n.id).put(n.last_heard.count()).put(n.rssi_dbm).put(n.rssi_smoothed_dbm);
      writer.put(n.sinr_db).put(n.frames).put(n.unicasts).put(n.first_attempt_acks);
    }
    status = transport_.commit();
  }
  return sent("neighbors", status, false);
}

ProtocolResult StepChannel::receive_neighbors(RecordReader& reader, StepResult& result,
                                              std::int64_t& last_robot) {
  std::uint32_t robot = 0;
  std::uint32_t count = 0;
  if (limits_.max_neighbors == 0) return over_limit("sent a neighbour table nobody asked for");
  if (!reader.get(robot) || !reader.get(count) ||
      reader.remaining() != std::size_t{count} * kNeighborBytes) {
    return malformed(RecordType::neighbors);
  }
  if (robot >= limits_.robots || static_cast<std::int64_t>(robot) <= last_robot || count == 0 ||
      count > limits_.max_neighbors) {
    return over_limit("sent a neighbour table of " + std::to_string(count) + " entries for robot " +
                      std::to_string(robot) + " (tables come once per robot, in order, with 1 to " +
                      std::to_string(limits_.max_neighbors) + " entries)");
  }
  last_robot = robot;
  result.neighbor_counts[robot] = count;
  std::int64_t last_id = -1;
  for (std::uint32_t i = 0; i < count; ++i) {
    RadioNeighbor n;
    std::int64_t heard = 0;
    (void)reader.get(n.id);  // the length check above guarantees every field
    (void)reader.get(heard);
    (void)reader.get(n.rssi_dbm);
    (void)reader.get(n.rssi_smoothed_dbm);
    (void)reader.get(n.sinr_db);
    (void)reader.get(n.frames);
    (void)reader.get(n.unicasts);
    (void)reader.get(n.first_attempt_acks);
    if (n.id >= limits_.robots || static_cast<std::int64_t>(n.id) <= last_id || n.id == robot) {
      return over_limit("sent a neighbour table for robot " + std::to_string(robot) +
                        " naming node " + std::to_string(n.id) +
                        " (entries name other robots, ascending)");
    }
    if (n.first_attempt_acks > n.unicasts) {
      return over_limit(
          "sent a neighbour table for robot " + std::to_string(robot) + " where node " +
          std::to_string(n.id) + " has " + std::to_string(n.first_attempt_acks) +
          " first-attempt acknowledgements of " + std::to_string(n.unicasts) + " unicasts");
    }
    last_id = n.id;
    n.last_heard = SimTime{heard};
    result.neighbors.push_back(n);
  }
  return {};
}

ProtocolResult StepChannel::send_send_report(const AddressedSendReport& addressed) {
  const SendReport& r = addressed.report;
  return send_record("send_report", false, RecordType::send_report, r.message_id, addressed.source,
                     addressed.port, r.outcome, r.reason, r.at.count(), r.next_hop, r.attempts);
}

ProtocolResult StepChannel::receive_send_report(RecordReader& reader, StepResult& result) {
  AddressedSendReport addressed;
  SendReport& r = addressed.report;
  std::int64_t at = 0;
  if (!reader.get(r.message_id) || !reader.get(addressed.source) || !reader.get(addressed.port) ||
      !reader.get(r.outcome) || !reader.get(r.reason) || !reader.get(at) ||
      !reader.get(r.next_hop) || !reader.get(r.attempts) || !reader.at_end()) {
    return malformed(RecordType::send_report);
  }
  const auto owed = reports_owed_.find(r.message_id);
  if (owed == reports_owed_.end() || owed->second.source != addressed.source ||
      owed->second.port != addressed.port) {
    return over_limit("sent a report on message " + std::to_string(r.message_id) + " from robot " +
                      std::to_string(addressed.source) + " port " + std::to_string(addressed.port) +
                      ", which asked for none there or was reported already");
  }
  if (r.outcome > SendOutcome::dropped || r.reason > DropReason::arp_unresolved) {
    return malformed(RecordType::send_report);
  }
  reports_owed_.erase(owed);
  r.at = SimTime{at};
  result.send_reports.push_back(addressed);
  return {};
}

namespace {

// The run of `items` from `first` that belongs to the same robot.
template <typename T, typename RobotOf>
std::size_t same_robot_run(std::span<const T> items, std::size_t first, RobotOf robot_of) {
  std::size_t last = first;
  while (last < items.size() && robot_of(items[last]) == robot_of(items[first])) ++last;
  return last - first;
}

constexpr std::size_t kRouteQueryBytes = 4;                   // destination
constexpr std::size_t kRouteAnswerBytes = 4 + 1 + 4 + 4 + 8;  // destination, status, next hop,
                                                              // hops, as_of

}  // namespace

ProtocolResult StepChannel::send_route_queries(std::span<const RouteQuery> queries) {
  const RecordType type = RecordType::route_query;
  const RobotId robot = queries.front().robot;
  const auto count = static_cast<std::uint32_t>(queries.size());
  std::span<std::byte> space;
  IoStatus status = transport_.reserve(encoded_bytes(type) + encoded_bytes(robot) +
                                           encoded_bytes(count) + queries.size() * kRouteQueryBytes,
                                       space);
  if (status == IoStatus::ok) {
    RecordWriter writer(space);
    writer.put(type).put(robot).put(count);
    for (const RouteQuery& q : queries) writer.put(q.destination);
    status = transport_.commit();
  }
  return sent("route_query", status, false);
}

ProtocolResult StepChannel::receive_route_queries(RecordReader& reader, StepBatch& batch) {
  RobotId robot = 0;
  std::uint32_t count = 0;
  if (!reader.get(robot) || !reader.get(count) ||
      reader.remaining() != std::size_t{count} * kRouteQueryBytes) {
    return malformed(RecordType::route_query);
  }
  const bool after_last = batch.route_queries.empty() || batch.route_queries.back().robot < robot;
  if (robot >= limits_.robots || !after_last || count == 0 || count > kMaxRouteQueriesPerRobot) {
    return over_limit("sent route queries of robot " + std::to_string(robot) + " in step " +
                      std::to_string(batch.step) + " (" + std::to_string(count) +
                      " of them; queries come once per robot, in order, 1 to " +
                      std::to_string(kMaxRouteQueriesPerRobot) + " each)");
  }
  std::int64_t last = -1;
  for (std::uint32_t i = 0; i < count; ++i) {
    RobotId destination = 0;
    (void)reader.get(destination);  // the length check above guarantees it
    if (destination >= limits_.robots || destination == robot ||
        static_cast<std::int64_t>(destination) <= last) {
      return over_limit("sent a route query of robot " + std::to_string(robot) + " about " +
                        std::to_string(destination) +
                        " (destinations are other robots, ascending)");
    }
    last = destination;
    batch.route_queries.push_back(RouteQuery{robot, destination});
  }
  return {};
}

ProtocolResult StepChannel::send_routes(std::span<const RouteAnswer> answers) {
  const RecordType type = RecordType::route;
  const RobotId robot = answers.front().query.robot;
  const auto count = static_cast<std::uint32_t>(answers.size());
  std::span<std::byte> space;
  IoStatus status =
      transport_.reserve(encoded_bytes(type) + encoded_bytes(robot) + encoded_bytes(count) +
                             answers.size() * kRouteAnswerBytes,
                         space);
  if (status == IoStatus::ok) {
    RecordWriter writer(space);
    writer.put(type).put(robot).put(count);
    for (const RouteAnswer& a : answers) {
      writer.put(a.query.destination).put(a.route.status).put(a.route.next_hop);
      writer.put(a.route.hops).put(a.route.as_of.count());
    }
    status = transport_.commit();
  }
  return sent("route", status, false);
}

ProtocolResult StepChannel::receive_routes(RecordReader& reader, StepResult& result) {
  RobotId robot = 0;
  std::uint32_t count = 0;
  if (!reader.get(robot) || !reader.get(count) ||
      reader.remaining() != std::size_t{count} * kRouteAnswerBytes ||
      count > kMaxRouteQueriesPerRobot) {
    return malformed(RecordType::route);
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    RouteAnswer a;
    a.query.robot = robot;
    std::int64_t as_of = 0;
    (void)reader.get(a.query.destination);  // the length check above guarantees every field
    (void)reader.get(a.route.status);
    (void)reader.get(a.route.next_hop);
    (void)reader.get(a.route.hops);
    (void)reader.get(as_of);
    a.route.as_of = SimTime{as_of};
    if (!is_possible_answer(a.route, limits_.robots)) {
      return over_limit("sent a route answer for robot " + std::to_string(robot) + " about " +
                        std::to_string(a.query.destination) + " with status " +
                        std::to_string(static_cast<unsigned>(a.route.status)) + ", next hop " +
                        std::to_string(a.route.next_hop) + ", " + std::to_string(a.route.hops) +
                        " hops");
    }
    result.routes.push_back(a);
  }
  return {};
}

ProtocolResult StepChannel::check_routes_owed(const StepResult& result) {
  static const std::vector<RouteQuery> kNone;
  const bool owed = !routes_owed_.empty() && routes_owed_.front().first == result.step;
  const std::vector<RouteQuery>& queries = owed ? routes_owed_.front().second : kNone;
  bool match = queries.size() == result.routes.size();
  for (std::size_t i = 0; match && i < queries.size(); ++i) {
    match = queries[i] == result.routes[i].query;
  }
  if (!match) {
    return over_limit("answered " + std::to_string(result.routes.size()) +
                      " route queries in step " + std::to_string(result.step) + ", which asked " +
                      std::to_string(queries.size()) + " (each once, in order)");
  }
  if (owed) routes_owed_.pop_front();
  return {};
}

ProtocolResult StepChannel::sent(const char* what, IoStatus status, bool last_of_batch) {
  if (status == IoStatus::ok && last_of_batch) status = transport_.flush();
  if (status == IoStatus::ok) return {};
  return {status, "cannot send " + std::string(what) + " to " + peer_ + ": " + to_string(status)};
}

ProtocolResult StepChannel::receive(RecordType& type, RecordReader*& reader) {
  const IoStatus status = transport_.receive_view(in_);
  if (status != IoStatus::ok) {
    std::string how = to_string(status);
    if (status == IoStatus::closed) how = "it closed the channel before finishing";
    if (status == IoStatus::peer_dead) how = "it is no longer running";
    if (status == IoStatus::timeout) how = "no answer within the step timeout; it hangs";
    return {status, "lost " + peer_ + ": " + how};
  }
  reader_.emplace(in_);
  std::uint32_t raw = 0;
  if (!reader_->get(raw) || raw < 1 || raw > static_cast<std::uint32_t>(RecordType::route)) {
    return {IoStatus::corrupt,
            "malformed record from " + peer_ + ": unknown record type " + std::to_string(raw)};
  }
  type = static_cast<RecordType>(raw);
  reader = &*reader_;
  if (type == RecordType::failure) {
    std::span<const std::byte> text;
    if (!reader->get_view(text, kMaxTextBytes)) return malformed(type);
    peer_failed_ = true;
    return {IoStatus::closed, peer_ + " failed: " + as_text(text)};
  }
  return {};
}

ProtocolResult StepChannel::malformed(RecordType type) const {
  return {IoStatus::corrupt, "malformed " + std::string(to_string(type)) + " record from " + peer_ +
                                 " (" + std::to_string(in_.size()) + " bytes)"};
}

ProtocolResult StepChannel::unexpected(RecordType got, const char* expected) const {
  return {IoStatus::corrupt, "protocol error: " + peer_ + " sent a " + to_string(got) +
                                 " record where " + expected + " was expected"};
}

ProtocolResult StepChannel::send_hello(const Hello& hello) {
  return send_record("hello", true, RecordType::hello, hello.protocol_version,
                     as_bytes(hello.scenario_yaml), as_bytes(hello.run_dir));
}

ProtocolResult StepChannel::receive_hello(Hello& hello) {
  RecordType type{};
  RecordReader* reader = nullptr;
  if (auto r = receive(type, reader); !r.ok()) return r;
  if (type != RecordType::hello) return unexpected(type, "hello");
  if (!reader->get(hello.protocol_version)) return malformed(type);
  if (hello.protocol_version != kStepProtocolVersion) {
    return {IoStatus::corrupt,
            "protocol version mismatch: " + peer_ + " speaks step protocol version " +
                std::to_string(hello.protocol_version) + ", this one speaks version " +
                std::to_string(kStepProtocolVersion)};
  }
  std::span<const std::byte> yaml;
  std::span<const std::byte> dir;
  if (!reader->get_view(yaml, kMaxTextBytes) || !reader->get_view(dir, kMaxTextBytes) ||
      !reader->at_end()) {
    return malformed(type);
  }
  hello.scenario_yaml = as_text(yaml);
  hello.run_dir = as_text(dir);
  return {};
}

ProtocolResult StepChannel::send_welcome(const Welcome& welcome) {
  if (welcome.robots == 0 || welcome.robots > kMaxRobots || welcome.step_ns <= 0) {
    return {IoStatus::corrupt, "cannot welcome " + peer_ + " to " + std::to_string(welcome.robots) +
                                   " robots with a step of " + std::to_string(welcome.step_ns) +
                                   " ns; 1 to " + std::to_string(kMaxRobots) +
                                   " robots and a positive step are allowed"};
  }
  fix_limits(welcome);
  return send_record("welcome", true, RecordType::welcome, kStepProtocolVersion, welcome.seed,
                     welcome.robots, welcome.step_ns, welcome.max_neighbors);
}

ProtocolResult StepChannel::receive_welcome(const Welcome& expected) {
  RecordType type{};
  RecordReader* reader = nullptr;
  if (auto r = receive(type, reader); !r.ok()) return r;
  if (type != RecordType::welcome) return unexpected(type, "welcome");
  std::uint32_t version = 0;
  Welcome echo;
  if (!reader->get(version)) return malformed(type);
  if (version != kStepProtocolVersion) {
    return {IoStatus::corrupt, "protocol version mismatch: " + peer_ +
                                   " speaks step protocol version " + std::to_string(version) +
                                   ", this one speaks version " +
                                   std::to_string(kStepProtocolVersion)};
  }
  if (!reader->get(echo.seed) || !reader->get(echo.robots) || !reader->get(echo.step_ns) ||
      !reader->get(echo.max_neighbors) || !reader->at_end()) {
    return malformed(type);
  }
  if (echo.seed != expected.seed || echo.robots != expected.robots ||
      echo.step_ns != expected.step_ns || echo.max_neighbors != expected.max_neighbors) {
    return {IoStatus::corrupt,
            "handshake mismatch: " + peer_ + " would simulate " + std::to_string(echo.robots) +
                " robots, seed " + std::to_string(echo.seed) + ", step " +
                std::to_string(echo.step_ns) + " ns; asked for " + std::to_string(expected.robots) +
                ", " + std::to_string(expected.seed) + ", " + std::to_string(expected.step_ns) +
                " ns" +
                (echo.max_neighbors != expected.max_neighbors
                     ? "; neighbour tables of " + std::to_string(echo.max_neighbors) +
                           " entries where " + std::to_string(expected.max_neighbors) +
                           " were asked for"
                     : "")};
  }
  fix_limits(expected);
  return {};
}

void StepChannel::fix_limits(const Welcome& welcome) {
  limits_.robots = welcome.robots;
  limits_.max_messages_per_step = std::uint64_t{welcome.robots} * kMaxMessagesPerRobotStep;
  limits_.step_ns = welcome.step_ns;
  limits_.max_neighbors = std::min(welcome.max_neighbors, kMaxNeighborsPerRobot);
  deliveries_owed_ = 0;
  reports_owed_.clear();
  next_step_ = 0;
}

ProtocolResult StepChannel::over_limit(const std::string& what) const {
  return {IoStatus::corrupt, "protocol error: " + peer_ + " " + what};
}

ProtocolResult StepChannel::send_batch(const StepBatch& batch) {
  const auto robots = static_cast<std::uint32_t>(batch.positions.size());
  if (auto r =
          send_record("step_begin", false, RecordType::step_begin, batch.step, batch.start.count(),
                      robots, static_cast<std::uint32_t>(batch.messages.size()));
      !r.ok()) {
    return r;
  }
  for (std::uint32_t first = 0; first < robots; first += kPositionsPerRecord) {
    const std::uint32_t count = std::min(kPositionsPerRecord, robots - first);
    if (auto r = send_positions(batch, first, count); !r.ok()) return r;
  }
  for (const AppMessage& message : batch.messages) {
    deliveries_owed_ += message.destination == kBroadcast ? limits_.robots : 1U;
    if (message.report) reports_owed_[message.message_id] = {message.source, message.port};
    if (auto r = send_record("message", false, RecordType::message, message.message_id,
                             message.source, message.destination, message.port, message.hop_limit,
                             static_cast<std::uint8_t>(message.report),
                             std::span<const std::byte>(message.payload));
        !r.ok()) {
      return r;
    }
  }
  const std::span<const RouteQuery> queries(batch.route_queries);
  for (std::size_t first = 0; first < queries.size();) {
    const std::size_t count =
        same_robot_run(queries, first, [](const RouteQuery& q) { return q.robot; });
    if (auto r = send_route_queries(queries.subspan(first, count)); !r.ok()) return r;
    first += count;
  }
  if (!queries.empty()) routes_owed_.emplace_back(batch.step, batch.route_queries);
  return send_record("step_end", true, RecordType::step_end, batch.step);
}

ProtocolResult StepChannel::receive_batch(StepBatch& batch, bool& finished) {
  finished = false;
  RecordType type{};
  RecordReader* reader = nullptr;
  if (auto r = receive(type, reader); !r.ok()) return r;
  if (type == RecordType::finish) {
    finished = true;
    return reader->at_end() ? ProtocolResult{} : malformed(type);
  }
  if (type != RecordType::step_begin) return unexpected(type, "step_begin or finish");
  std::int64_t start_ns = 0;
  std::uint32_t robots = 0;
  std::uint32_t messages = 0;
  if (!reader->get(batch.step) || !reader->get(start_ns) || !reader->get(robots) ||
      !reader->get(messages) || !reader->at_end()) {
    return malformed(type);
  }
  if (limits_.robots == 0) return over_limit("sent a step before the handshake");
  if (robots != limits_.robots) {
    return over_limit("announced " + std::to_string(robots) + " robots in step_begin; the " +
                      "handshake fixed " + std::to_string(limits_.robots));
  }
  if (messages > limits_.max_messages_per_step) {
    return over_limit("announced " + std::to_string(messages) +
                      " messages in step_begin; at most " +
                      std::to_string(limits_.max_messages_per_step) + " (" +
                      std::to_string(kMaxMessagesPerRobotStep) + " per robot) may come in a step");
  }
  if (batch.step != next_step_) {
    return over_limit("sent step " + std::to_string(batch.step) + " where step " +
                      std::to_string(next_step_) + " was due");
  }
  // step x step_ns, computed only where it cannot overflow (a step number past that is refused).
  const bool start_representable =
      limits_.step_ns > 0 &&
      batch.step <=
          static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max() / limits_.step_ns);
  if (!start_representable || start_ns != static_cast<std::int64_t>(batch.step) * limits_.step_ns) {
    return over_limit("said step " + std::to_string(batch.step) + " starts at " +
                      std::to_string(start_ns) + " ns; the handshake's step of " +
                      std::to_string(limits_.step_ns) + " ns puts it at step x step");
  }
  ++next_step_;
  batch.start = SimTime{start_ns};
  batch.positions.resize(robots);
  std::uint32_t filled = 0;
  while (filled < robots) {
    if (auto r = receive(type, reader); !r.ok()) return r;
    if (type != RecordType::positions) return unexpected(type, "positions");
    std::uint32_t first = 0;
    std::uint32_t count = 0;
    if (!reader->get(first) || !reader->get(count) || first != filled || count > robots - first ||
        reader->remaining() != std::size_t{count} * kPositionBytes) {
      return malformed(type);
    }
    for (std::uint32_t i = 0; i < count; ++i) {
      double x = 0.0;
      double y = 0.0;
      (void)reader->get(x);  // the length check above guarantees both
      (void)reader->get(y);
      // A NaN or infinite position would index no grid cell of the channel.
      if (!std::isfinite(x) || !std::isfinite(y)) {
        return over_limit("sent a position that is not a finite number for robot " +
                          std::to_string(first + i) + " in step " + std::to_string(batch.step));
      }
      batch.positions[first + i] = Vec2(x, y);
    }
    filled += count;
  }
  batch.messages.resize(messages);
  std::uint64_t payload_bytes = 0;
  for (AppMessage& message : batch.messages) {
    if (auto r = receive(type, reader); !r.ok()) return r;
    if (type != RecordType::message) return unexpected(type, "message");
    std::uint8_t report = 0;
    if (!reader->get(message.message_id) || !reader->get(message.source) ||
        !reader->get(message.destination) || !reader->get(message.port) ||
        !reader->get(message.hop_limit) || !reader->get(report) || report > 1 ||
        !reader->get_bytes(message.payload, kMaxPayloadBytes) || !reader->at_end()) {
      return malformed(type);
    }
    message.report = report == 1;
    payload_bytes += message.payload.size();
    if (payload_bytes > step_payload_limit_) {
      batch.messages.clear();  // give the memory back before the failure is reported
      batch.messages.shrink_to_fit();
      return over_limit("sent more than " + std::to_string(step_payload_limit_ >> 20U) +
                        " MiB of payload in step " + std::to_string(batch.step) +
                        ", the most the network half's memory budget allows in one step");
    }
  }
  batch.route_queries.clear();
  for (;;) {
    if (auto r = receive(type, reader); !r.ok()) return r;
    if (type != RecordType::route_query) break;
    if (auto r = receive_route_queries(*reader, batch); !r.ok()) return r;
  }
  if (type != RecordType::step_end) return unexpected(type, "route_query or step_end");
  std::uint64_t step = 0;
  if (!reader->get(step) || !reader->at_end()) return malformed(type);
  if (step != batch.step) {
    return {IoStatus::corrupt, "protocol error: " + peer_ + " ended step " + std::to_string(step) +
                                   " inside step " + std::to_string(batch.step)};
  }
  return {};
}

ProtocolResult StepChannel::send_result(const StepResult& result) {
  for (const Delivery& delivery : result.deliveries) {
    if (auto r = send_record("delivery", false, RecordType::delivery, delivery.message_id,
                             delivery.source, delivery.destination, delivery.receiver,
                             delivery.sent_at.count(), delivery.delivered_at.count(), delivery.hops,
                             delivery.port, std::span<const std::byte>(delivery.payload));
        !r.ok()) {
      return r;
    }
  }
  if (!result.neighbor_counts.empty()) {
    std::size_t first = 0;
    for (RobotId robot = 0; robot < result.neighbor_counts.size(); ++robot) {
      const std::uint32_t count = result.neighbor_counts[robot];
      if (count == 0) continue;
      const std::span<const RadioNeighbor> table(result.neighbors.data() + first, count);
      first += count;
      if (auto r = send_neighbors(robot, table); !r.ok()) return r;
    }
  }
  for (const AddressedSendReport& report : result.send_reports) {
    if (auto r = send_send_report(report); !r.ok()) return r;
  }
  const std::span<const RouteAnswer> answers(result.routes);
  for (std::size_t first = 0; first < answers.size();) {
    const std::size_t count =
        same_robot_run(answers, first, [](const RouteAnswer& a) { return a.query.robot; });
    if (auto r = send_routes(answers.subspan(first, count)); !r.ok()) return r;
    first += count;
  }
  return send_record("step_done", true, RecordType::step_done, result.step, result.events,
                     static_cast<std::uint32_t>(result.deliveries.size()));
}

ProtocolResult StepChannel::receive_result(StepResult& result) {
  // Deliveries are decoded into the elements of earlier steps, reusing their payload buffers:
  // no allocation per delivery once the largest step has been seen.
  std::size_t count_so_far = 0;
  std::int64_t last_table = -1;  // the robot whose neighbour table came last
  result.neighbors.clear();
  result.send_reports.clear();
  result.routes.clear();
  result.neighbor_counts.assign(limits_.max_neighbors == 0 ? 0 : limits_.robots, 0);
  for (;;) {
    RecordType type{};
    RecordReader* reader = nullptr;
    if (auto r = receive(type, reader); !r.ok()) return r;
    if (type == RecordType::delivery) {
      if (deliveries_owed_ == 0) {
        return over_limit("sent more deliveries than the messages it was given can produce");
      }
      --deliveries_owed_;
      if (count_so_far == result.deliveries.size()) result.deliveries.emplace_back();
      Delivery& d = result.deliveries[count_so_far++];
      std::int64_t sent = 0;
      std::int64_t delivered = 0;
      if (!reader->get(d.message_id) || !reader->get(d.source) || !reader->get(d.destination) ||
          !reader->get(d.receiver) || !reader->get(sent) || !reader->get(delivered) ||
          !reader->get(d.hops) || !reader->get(d.port) ||
          !reader->get_bytes(d.payload, kMaxPayloadBytes) || !reader->at_end()) {
        return malformed(type);
      }
      d.sent_at = SimTime{sent};
      d.delivered_at = SimTime{delivered};
      continue;
    }
    if (type == RecordType::neighbors) {
      if (auto r = receive_neighbors(*reader, result, last_table); !r.ok()) return r;
      continue;
    }
    if (type == RecordType::send_report) {
      if (auto r = receive_send_report(*reader, result); !r.ok()) return r;
      continue;
    }
    if (type == RecordType::route) {
      if (auto r = receive_routes(*reader, result); !r.ok()) return r;
      continue;
    }
    if (type != RecordType::step_done) {
      return unexpected(type, "delivery, neighbors, send_report, route or step_done");
    }
    result.deliveries.resize(count_so_far);
    std::uint32_t count = 0;
    if (!reader->get(result.step) || !reader->get(result.events) || !reader->get(count) ||
        !reader->at_end()) {
      return malformed(type);
    }
    if (count != result.deliveries.size()) {
      return {IoStatus::corrupt, "protocol error: " + peer_ + " announced " +
                                     std::to_string(count) + " deliveries but sent " +
                                     std::to_string(result.deliveries.size())};
    }
    return check_routes_owed(result);
  }
}

ProtocolResult StepChannel::send_finish() {
  return send_record("finish", true, RecordType::finish);
}

ProtocolResult StepChannel::send_report(const NetworkReport& report) {
  std::vector<std::byte> record;
  encode_report(report, record);
  std::span<std::byte> space;
  IoStatus status = transport_.reserve(record.size(), space);
  if (status == IoStatus::ok) {
    std::memcpy(space.data(), record.data(), record.size());
    status = transport_.commit();
  }
  return sent("report", status, true);
}

ProtocolResult StepChannel::receive_report(NetworkReport& report) {
  RecordType type{};
  RecordReader* reader = nullptr;
  if (auto r = receive(type, reader); !r.ok()) return r;
  if (type != RecordType::report) return unexpected(type, "report");
  if (!decode_report(*reader, report)) return malformed(type);
  return {};
}

std::string StepChannel::drain_for_failure() {
  // Bounded: a peer that stopped left at most a few steps of records behind.
  constexpr int kMaxRecords = 1 << 24;
  for (int i = 0; i < kMaxRecords && !peer_failed_; ++i) {
    RecordType type{};
    RecordReader* reader = nullptr;
    const ProtocolResult r = receive(type, reader);
    if (!r.ok()) return peer_failed_ ? r.error : "";
  }
  return "";
}

void StepChannel::send_failure(const std::string& message) {
  // Encoded aside rather than in place: try_send must not wait for room, and a reservation
  // would.
  const std::span<const std::byte> text = as_bytes(message);
  std::vector<std::byte> record(encoded_bytes(RecordType::failure) + encoded_bytes(text));
  RecordWriter(record).put(RecordType::failure).put(text);
  (void)transport_.try_send(record);
}

}  // namespace swarmnet
