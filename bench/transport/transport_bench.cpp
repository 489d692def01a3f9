// Transport micro-benchmarks across two real processes, side by side in one run: the
// shared-memory ring, a Unix-domain socket and TCP loopback, each behind the same Transport
// interface that runs use.
//
//   Throughput/<transport>/<payload bytes>  one-way records made visible once per batch of 256
//                                           (how runs send: one flush per step), acknowledged
//   PerMessage/<transport>/<payload bytes>  the same, each record made visible on its own (one
//                                           system call per message for sockets)
//   RoundTrip/<transport>                   one 64-byte record there and back
//   StepExchange/<transport>/<robots>       one full step of the step protocol: the batch
//                                           (positions and the study's traffic) there, the
//                                           deliveries back
//   StepCodec/<robots>                      the same with both ends in this thread over an
//                                           in-process ring: the CPU that encoding and
//                                           decoding cost, without moving bytes between cores
//
// Every benchmark forks a peer process that serves it; the parent measures. Both ends of every
// transport wait by the same policy as in a run (spin, yield, then sleep).
#include <benchmark/benchmark.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "inproc_channel.hpp"
#include "protocol/step_channel.hpp"
#include "ring_transport.hpp"
#include "shm_segment.hpp"
#include "socket_transport.hpp"

namespace swarmnet {
namespace {

enum class Kind { ring, uds, tcp };
const char* name_of(Kind kind) {
  switch (kind) {
    case Kind::ring:
      return "ring";
    case Kind::uds:
      return "uds";
    case Kind::tcp:
      return "tcp";
  }
  return "?";
}

// What the peer does with what it receives.
enum class Service : std::uint8_t { sink, echo, step };

constexpr std::byte kAckRequest{0xA5};
constexpr std::uint64_t kRingBytes = std::uint64_t{1} << 22U;
constexpr SimTime kStep{100'000'000};  // the welcome's step: 0.1 s

WaitPolicy bench_policy() {
  WaitPolicy policy;
  policy.timeout = std::chrono::seconds(30);
  // The defaults of a run: the benchmark measures what runs get.
  return policy;
}

StepBatch make_batch(std::uint32_t robots) {
  // The study's traffic: 20% of robots send 5 messages/s; at 0.1 s steps that is 0.1 message
  // per robot per step, of 512 bytes.
  StepBatch batch;
  batch.step = 0;  // steps follow from 0, each kStep after the last (the channel checks)
  batch.start = SimTime{0};
  for (std::uint32_t i = 0; i < robots; ++i) batch.positions.emplace_back(i * 0.5, i * 0.25);
  for (std::uint32_t i = 0; i < std::max<std::uint32_t>(1, robots / 10); ++i) {
    batch.messages.push_back({i, i, (i + 7) % robots, 0, Payload(512, std::byte{1})});
  }
  return batch;
}

StepResult make_result(const StepBatch& batch) {
  StepResult result;
  result.step = batch.step;
  for (const AppMessage& m : batch.messages) {
    result.deliveries.push_back({m.message_id, m.source, m.destination, m.destination, batch.start,
                                 batch.start + SimTime{2'000'000}, 2, m.port, m.payload});
  }
  return result;
}

void serve(Transport& transport, Service service) {
  std::vector<std::byte> record;
  if (service == Service::step) {
    StepChannel channel(transport, "the benchmark");
    // The benchmark's hello carries the swarm size as its text, in place of a scenario.
    Hello hello;
    if (!channel.receive_hello(hello).ok()) return;
    const Welcome welcome{1, static_cast<std::uint32_t>(std::stoul(hello.scenario_yaml)),
                          kStep.count()};
    if (!channel.send_welcome(welcome).ok()) return;
    StepBatch batch;
    StepResult result;
    bool finished = false;
    while (channel.receive_batch(batch, finished).ok() && !finished) {
      // Every step's batch carries the same messages, so the deliveries are made once: building
      // them (an allocation and a copy per payload) is the network half's work, not the
      // transport's, and a run's network half reuses its result's buffers.
      if (result.deliveries.empty()) result = make_result(batch);
      result.step = batch.step;
      if (!channel.send_result(result).ok()) break;
    }
    return;
  }
  while (transport.receive(record) == IoStatus::ok) {
    if (service == Service::echo ||
        (!record.empty() && record[0] == kAckRequest && record.size() == 1)) {
      if (transport.send(record) != IoStatus::ok || transport.flush() != IoStatus::ok) return;
    }
  }
}

// A forked peer process and the parent's end of the transport to it.
class Peer {
 public:
  Peer(Kind kind, Service service) {
    std::string socket_path;
    int listener = -1;
    std::uint16_t port = 0;
    if (kind == Kind::ring) {
      segment_ = ShmSegment::create(kRingBytes);
    } else if (kind == Kind::uds) {
      socket_path = "/tmp/swarmnet-bench-" + std::to_string(::getpid()) + ".sock";
      std::filesystem::remove(socket_path);
      listener = listen_unix(socket_path);
    } else {
      listener = listen_tcp("127.0.0.1", 0, &port);
    }
    pid_ = ::fork();
    if (pid_ == 0) {
      std::unique_ptr<Transport> mine;
      if (kind == Kind::ring) {
        auto attached = ShmSegment::attach(segment_->name());
        mine = std::make_unique<RingTransport>(
            attached->network_to_robot(), attached->robot_to_network(), bench_policy(), "ring");
        serve(*mine, service);
      } else {
        ::close(listener);
        const int fd =
            kind == Kind::uds ? connect_unix(socket_path) : connect_tcp("127.0.0.1", port);
        mine = std::make_unique<SocketTransport>(fd, bench_policy(), name_of(kind));
        serve(*mine, service);
      }
      mine->close();
      _exit(0);
    }
    if (kind == Kind::ring) {
      transport_ = std::make_unique<RingTransport>(
          segment_->robot_to_network(), segment_->network_to_robot(), bench_policy(), "ring");
    } else {
      const int fd = accept_one(listener, bench_policy(), "benchmark peer");
      if (!socket_path.empty()) std::filesystem::remove(socket_path);
      transport_ = std::make_unique<SocketTransport>(fd, bench_policy(), name_of(kind));
    }
  }
  ~Peer() {
    transport_->close();
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  Peer(const Peer&) = delete;
  Peer& operator=(const Peer&) = delete;
  Transport& transport() { return *transport_; }

 private:
  std::unique_ptr<ShmSegment> segment_;
  std::unique_ptr<Transport> transport_;
  pid_t pid_ = -1;
};

constexpr int kBatch = 256;

void Throughput(benchmark::State& state, Kind kind, bool flush_each) {
  const auto payload = static_cast<std::size_t>(state.range(0));
  Peer peer(kind, Service::sink);
  Transport& t = peer.transport();
  std::vector<std::byte> record(payload, std::byte{0x42});
  const std::vector<std::byte> ack{kAckRequest};
  std::vector<std::byte> reply;
  bool failed = false;
  for (auto _ : state) {
    for (int i = 0; i < kBatch && !failed; ++i) {
      failed = t.send(record) != IoStatus::ok || (flush_each && t.flush() != IoStatus::ok);
    }
    if (failed) {
      state.SkipWithError("send failed");
      break;
    }
    // The batch counts once the peer has read all of it: ask it to acknowledge.
    if (t.send(ack) != IoStatus::ok || t.flush() != IoStatus::ok ||
        t.receive(reply) != IoStatus::ok) {
      state.SkipWithError("acknowledgement failed");
      break;
    }
  }
  state.SetItemsProcessed(state.iterations() * kBatch);
  state.SetBytesProcessed(state.iterations() * kBatch * static_cast<std::int64_t>(payload));
}

void RoundTrip(benchmark::State& state, Kind kind) {
  Peer peer(kind, Service::echo);
  Transport& t = peer.transport();
  std::vector<std::byte> record(64, std::byte{0x17});
  std::vector<std::byte> reply;
  for (auto _ : state) {
    if (t.send(record) != IoStatus::ok || t.flush() != IoStatus::ok ||
        t.receive(reply) != IoStatus::ok) {
      state.SkipWithError("round trip failed");
      break;
    }
  }
}

void StepExchange(benchmark::State& state, Kind kind) {
  const auto robots = static_cast<std::uint32_t>(state.range(0));
  Peer peer(kind, Service::step);
  StepChannel channel(peer.transport(), "the benchmark peer");
  Hello hello;
  hello.scenario_yaml = std::to_string(robots);
  if (!channel.send_hello(hello).ok() ||
      !channel.receive_welcome(Welcome{1, robots, kStep.count()}).ok()) {
    state.SkipWithError("handshake failed");
    return;
  }
  StepBatch batch = make_batch(robots);
  StepResult result;
  for (auto _ : state) {
    if (!channel.send_batch(batch).ok() || !channel.receive_result(result).ok()) {
      state.SkipWithError("step exchange failed");
      break;
    }
    ++batch.step;
    batch.start += kStep;
  }
  (void)channel.send_finish();
  state.counters["messages_per_step"] = static_cast<double>(batch.messages.size());
}

void StepCodec(benchmark::State& state) {
  const auto robots = static_cast<std::uint32_t>(state.range(0));
  InprocChannel link(kRingBytes, bench_policy());
  StepChannel robot(link.robot_end(), "the network end");
  StepChannel network(link.network_end(), "the robot end");
  robot.fix_limits(Welcome{1, robots, kStep.count()});
  network.fix_limits(Welcome{1, robots, kStep.count()});
  StepBatch batch = make_batch(robots);
  StepResult result = make_result(batch);
  StepBatch received_batch;
  StepResult received_result;
  bool finished = false;
  for (auto _ : state) {
    if (!robot.send_batch(batch).ok() || !network.receive_batch(received_batch, finished).ok() ||
        !network.send_result(result).ok() || !robot.receive_result(received_result).ok()) {
      state.SkipWithError("step codec failed");
      break;
    }
    result.step = ++batch.step;
    batch.start += kStep;
  }
}

void register_all() {
  for (bool flush_each : {false, true}) {
    for (Kind kind : {Kind::ring, Kind::uds, Kind::tcp}) {
      const std::string name =
          std::string(flush_each ? "PerMessage/" : "Throughput/") + name_of(kind);
      auto* b = benchmark::RegisterBenchmark(name.c_str(), Throughput, kind, flush_each);
      for (std::int64_t bytes : {16, 64, 256, 1024, 4096, 16384, 65536}) b->Arg(bytes);
      b->UseRealTime()->MinTime(0.2);
    }
  }
  for (Kind kind : {Kind::ring, Kind::uds, Kind::tcp}) {
    benchmark::RegisterBenchmark((std::string("RoundTrip/") + name_of(kind)).c_str(), RoundTrip,
                                 kind)
        ->UseRealTime()
        ->MinTime(0.2);
  }
  for (Kind kind : {Kind::ring, Kind::uds, Kind::tcp}) {
    auto* b = benchmark::RegisterBenchmark((std::string("StepExchange/") + name_of(kind)).c_str(),
                                           StepExchange, kind);
    for (std::int64_t robots : {25, 100, 400, 2000}) b->Arg(robots);
    b->UseRealTime()->MinTime(0.2);
  }
  auto* codec = benchmark::RegisterBenchmark("StepCodec/ring", StepCodec);
  for (std::int64_t robots : {25, 100, 400, 2000}) codec->Arg(robots);
  codec->UseRealTime()->MinTime(0.2);
}

}  // namespace
}  // namespace swarmnet

int main(int argc, char** argv) {
  ::signal(SIGPIPE, SIG_IGN);
  swarmnet::register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
