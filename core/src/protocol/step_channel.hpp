// The step protocol (docs/transport.md) as records over a Transport.
//
// Robot half -> network half, per step: step_begin, positions (in chunks), one message record
// per application message, one route_query record per robot whose controllers called
// route_to() (ascending robot), step_end. At the end: finish.
// Network half -> robot half, per step: one delivery record per delivery, with
// network.neighbors one neighbors record per robot whose table is not empty (ascending robot),
// one send_report record per report (in the order the outcomes happened), one route record per
// robot that asked (the answers, in the queries' order), step_done. After
// finish: report (the network's metrics, a NetworkReport).
// Either side may send failure (a text) before it stops, so the other can say why.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/network_report.hpp"
#include "protocol/record_codec.hpp"
#include "protocol/step_data.hpp"
#include "ring_status.hpp"
#include "transport.hpp"

namespace swarmnet {

enum class RecordType : std::uint32_t {
  step_begin = 1,
  positions = 2,
  message = 3,
  step_end = 4,
  delivery = 5,
  step_done = 6,
  finish = 7,
  report = 8,
  failure = 9,
  hello = 10,
  welcome = 11,
  neighbors = 12,
  send_report = 13,
  route_query = 14,
  route = 15,  // the last: StepChannel::receive refuses any type beyond it
};

// What the handshake fixes, so that every count a peer announces later is checked before
// anything is allocated for it.
struct ProtocolLimits {
  std::uint32_t robots = 0;                 // positions per step, exactly
  std::uint64_t max_messages_per_step = 0;  // robots x kMaxMessagesPerRobotStep
  std::int64_t step_ns = 0;                 // step i starts at exactly i x step_ns
  std::uint32_t max_neighbors = 0;          // entries of one robot's neighbour table; 0: none sent
};

// The largest swarm a welcome may fix (the scenario's own limit on robots.count, which
// scenario_schema.cpp states again as the key's range).
inline constexpr std::uint32_t kMaxRobots = 100000;

// Version of the records above; both halves must speak the same one.
// 4: the report's arp counters. 5: neighbour tables (the welcome's max_neighbors). 6: send
// options in message records, send_report records. 7: neighbour entries' unicast exchanges,
// route_query and route records.
inline constexpr std::uint32_t kStepProtocolVersion = 7;

// The handshake (the study's Fig. 1). The robot half's hello carries exactly one description of
// what to simulate, the resolved scenario; the network half validates it and answers with a
// welcome saying what it will simulate, which the robot half checks against its own scenario.
struct Hello {
  std::uint32_t protocol_version = kStepProtocolVersion;
  std::string scenario_yaml;  // the resolved scenario: arena, radio and every plugin's parameters
  std::string run_dir;        // where a child network half writes (a remote one names its own)
};

struct Welcome {
  std::uint64_t seed = 0;
  std::uint32_t robots = 0;
  std::int64_t step_ns = 0;
  std::uint32_t max_neighbors = 0;  // network.neighbors.max_per_robot when enabled, else 0
};

const char* to_string(RecordType type);

// The outcome of one protocol operation: ok, or what went wrong in words naming the peer.
struct ProtocolResult {
  IoStatus io = IoStatus::ok;
  std::string error;  // empty when ok

  [[nodiscard]] bool ok() const { return error.empty(); }
};

class StepChannel {
 public:
  // `peer` names the other half in error messages ("the network half").
  StepChannel(Transport& transport, std::string peer);

  // Handshake. The network side answers a hello with welcome (what it will simulate, from the
  // scenario it validated), or with failure when it cannot: a protocol version mismatch names
  // both versions. Each side fixes the limits the welcome implies (send_welcome, and
  // receive_welcome once it matches `expected`); until then a batch or a result is refused.
  ProtocolResult send_hello(const Hello& hello);
  ProtocolResult receive_welcome(const Welcome& expected);
  ProtocolResult receive_hello(Hello& hello);
  ProtocolResult send_welcome(const Welcome& welcome);

  // The limits a welcome implies: exactly `robots` positions, at most
  // robots x kMaxMessagesPerRobotStep messages a step, and steps numbered 0, 1, 2, ... each
  // starting at its number times the welcome's step (a far start would have the network half
  // simulate toward it for hours). The handshake calls it; tests and
  // benchmarks that skip the handshake call it themselves.
  void fix_limits(const Welcome& welcome);
  [[nodiscard]] const ProtocolLimits& limits() const { return limits_; }
  // Network side: the payload bytes one step's messages may hold together (a server's memory
  // budget sets it; unbounded otherwise). A step beyond it is refused as it is read.
  void limit_step_payload(std::uint64_t bytes) { step_payload_limit_ = bytes; }

  // Robot side.
  ProtocolResult send_batch(const StepBatch& batch);
  ProtocolResult receive_result(StepResult& result);
  ProtocolResult send_finish();
  ProtocolResult receive_report(NetworkReport& report);

  // Network side: fills `batch`, or sets `finished` when the robot half sent finish.
  ProtocolResult receive_batch(StepBatch& batch, bool& finished);
  ProtocolResult send_result(const StepResult& result);
  ProtocolResult send_report(const NetworkReport& report);

  // Best effort: tells the peer why this side stops. Never waits.
  void send_failure(const std::string& message);

  // After this side lost the peer while sending (it saw only "closed"): reads what the peer
  // still left in the channel, up to a failure record, and returns the peer's reason ("" when
  // it left none). Call only once the peer has stopped, or it waits for it.
  std::string drain_for_failure();

  [[nodiscard]] Transport& transport() { return transport_; }
  // True once the peer has explained a failure with a failure record.
  [[nodiscard]] bool peer_failed() const { return peer_failed_; }

 private:
  // Encodes one record of `fields` straight into the transport's buffer and sends it; the last
  // record of a batch also flushes.
  template <typename... Fields>
  ProtocolResult send_record(const char* what, bool last_of_batch, const Fields&... fields);
  ProtocolResult send_positions(const StepBatch& batch, std::uint32_t first, std::uint32_t count);
  ProtocolResult send_neighbors(RobotId robot, std::span<const RadioNeighbor> table);
  ProtocolResult receive_neighbors(RecordReader& reader, StepResult& result,
                                   std::int64_t& last_robot);
  ProtocolResult send_send_report(const AddressedSendReport& addressed);
  ProtocolResult receive_send_report(RecordReader& reader, StepResult& result);
  // One robot's queries or answers: robot, count, then the entries.
  ProtocolResult send_route_queries(std::span<const RouteQuery> queries);
  ProtocolResult receive_route_queries(RecordReader& reader, StepBatch& batch);
  ProtocolResult send_routes(std::span<const RouteAnswer> answers);
  ProtocolResult receive_routes(RecordReader& reader, StepResult& result);
  // At a result's step_done: its route answers must be those of the step's queries.
  ProtocolResult check_routes_owed(const StepResult& result);
  ProtocolResult sent(const char* what, IoStatus status, bool last_of_batch);
  ProtocolResult receive(RecordType& type, RecordReader*& reader);
  ProtocolResult malformed(RecordType type) const;
  ProtocolResult unexpected(RecordType got, const char* expected) const;
  ProtocolResult over_limit(const std::string& what) const;

  Transport& transport_;
  std::string peer_;
  std::span<const std::byte> in_;  // the record being decoded, where it lies in the transport
  std::optional<RecordReader> reader_;
  bool peer_failed_ = false;
  ProtocolLimits limits_;
  // Deliveries the messages sent so far can still produce (one per unicast message, one per
  // robot per broadcast): a network half that sends more is refused before it is buffered.
  std::uint64_t deliveries_owed_ = 0;
  // Robot side: the messages sent with SendOptions::report and not reported yet, and from
  // where; a report for any other message is refused.
  struct Reported {
    RobotId source;
    std::uint16_t port;
  };
  std::map<std::uint64_t, Reported> reports_owed_;
  // Robot side: the route queries of each step sent and not answered yet (only steps that had
  // some), oldest first; a step's result must answer exactly its queries, in order.
  std::deque<std::pair<std::uint64_t, std::vector<RouteQuery>>> routes_owed_;
  std::uint64_t next_step_ = 0;  // the step number the next step_begin must carry
  std::uint64_t step_payload_limit_ = ~std::uint64_t{0};
};

}  // namespace swarmnet
