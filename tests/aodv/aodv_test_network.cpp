#include "aodv_test_network.hpp"

#include <algorithm>
#include <sstream>

#include "swarmnet/random.hpp"
#include "swarmnet/routing.hpp"

namespace swarmnet::aodv::test {

namespace {
constexpr double kBitrateBps = 6.0e6;
constexpr std::uint32_t kMacHeaderBytes = 28;
constexpr SimTime kFeedbackDelay = std::chrono::milliseconds(2);  // retries before giving up
}  // namespace

ParamSet aodv_params(const std::map<std::string, ParamValue>& overrides) {
  ParamSet params;
  for (const ParamSpec& spec : parameter_schema()) params.set(spec.name, spec.default_value);
  for (const auto& [name, value] : overrides) params.set(name, value);
  return params;
}

struct TestNetwork::TestNode final : RoutingContext {
  TestNode(TestNetwork& network, NodeId id) : network(network), id(id) {}
  [[nodiscard]] NodeId node() const override { return id; }
  [[nodiscard]] std::size_t node_count() const override { return network.size(); }
  [[nodiscard]] SimTime now() const override { return network.now(); }
  [[nodiscard]] Vec2 position() const override { return network.positions_[id]; }
  TimerId schedule(SimTime delay, std::function<void()> callback) override {
    return network.scheduler_.schedule_in(delay, std::move(callback));
  }
  void cancel(TimerId timer) override { network.scheduler_.cancel(timer); }
  void count(std::string_view counter, std::uint64_t amount) override {
    counters[std::string(counter)] += amount;
  }
  Packet make_control_packet(NodeId destination) override {
    Packet p;
    p.uid = network.next_uid_++;
    p.source = id;
    p.destination = destination;
    p.sent_at = now();
    return p;
  }
  void send_to_mac(Packet packet, NodeId next_hop) override {
    network.transmit(id, std::move(packet), next_hop);
  }
  void deliver(const Packet& packet) override { network.deliver(id, packet); }
  void drop(const Packet& packet, DropReason reason) override {
    network.drops_.push_back({id, packet.message_id, packet.is_control(), reason});
  }
  void trace_forward(const Packet& /*packet*/) override { ++counters["test_forwards"]; }
  [[nodiscard]] bool link_address_known(NodeId /*neighbor*/) const override { return true; }

  TestNetwork& network;
  NodeId id;
  std::map<std::string, std::uint64_t> counters;
  std::unique_ptr<Aodv> aodv;
};

TestNetwork::TestNetwork(std::vector<Vec2> positions, const ParamSet& params, bool mac_feedback,
                         std::uint64_t seed, double range_m)
    : positions_(std::move(positions)),
      mac_feedback_(mac_feedback),
      range_m_(range_m),
      busy_until_(positions_.size(), kTimeZero) {
  for (NodeId id = 0; id < positions_.size(); ++id) {
    auto node = std::make_unique<TestNode>(*this, id);
    PluginArgs args;
    args.params = params;
    args.seed = derive_seed(seed, {hash_name("aodv"), id});
    args.instance = id;
    args.instance_count = static_cast<std::uint32_t>(positions_.size());
    node->aodv = std::make_unique<Aodv>(args);
    nodes_.push_back(std::move(node));
  }
  for (auto& node : nodes_) node->aodv->attach(*node);
}

TestNetwork::~TestNetwork() { scheduler_.clear(); }

Aodv& TestNetwork::aodv(NodeId node) { return *nodes_[node]->aodv; }

bool TestNetwork::in_range(NodeId a, NodeId b) const {
  if (a == b || blocked_.contains({a, b})) return false;
  return (positions_[a] - positions_[b]).norm() <= range_m_;
}

void TestNetwork::send(NodeId source, NodeId destination, std::uint64_t message_id) {
  Packet p;
  p.uid = next_uid_++;
  p.source = source;
  p.destination = destination;
  p.message_id = message_id;
  p.sent_at = now();
  p.payload = std::make_shared<const Payload>(100);
  nodes_[source]->aodv->send(std::move(p));
}

void TestNetwork::inject(NodeId node, const Message& message, NodeId from) {
  Packet p = nodes_[from]->make_control_packet(node);
  encode(message, p.header);
  p.hops = 1;
  nodes_[node]->aodv->receive(std::move(p), from);
}

void TestNetwork::transmit(NodeId sender, Packet packet, NodeId next_hop) {
  const double bits = 8.0 * static_cast<double>(kMacHeaderBytes + packet.size_bytes());
  const SimTime start = std::max(now(), busy_until_[sender]);
  const SimTime end = start + from_seconds(bits / kBitrateBps);
  busy_until_[sender] = end;
  scheduler_.schedule_at(end, [this, sender, next_hop, packet = std::move(packet)]() mutable {
    ++packet.hops;
    if (next_hop == kBroadcast) {
      for (NodeId r = 0; r < size(); ++r) {
        if (!in_range(sender, r)) continue;
        if (packet.is_control()) receptions_.push_back({r, sender, now(), packet.header});
        nodes_[r]->aodv->receive(packet, sender);
      }
      return;
    }
    if (in_range(sender, next_hop)) {
      if (packet.is_control()) receptions_.push_back({next_hop, sender, now(), packet.header});
      nodes_[next_hop]->aodv->receive(std::move(packet), sender);
    } else if (mac_feedback_) {
      --packet.hops;
      scheduler_.schedule_in(kFeedbackDelay, [this, sender, next_hop, packet] {
        nodes_[sender]->aodv->link_failed(packet, next_hop);
      });
    }
  });
}

void TestNetwork::deliver(NodeId node, const Packet& packet) {
  deliveries_.push_back(
      {node, packet.source, packet.message_id, packet.hops, packet.sent_at, now()});
}

std::uint64_t TestNetwork::count(NodeId node, const std::string& counter) const {
  const auto& counters = nodes_[node]->counters;
  const auto it = counters.find(counter);
  return it == counters.end() ? 0 : it->second;
}

std::uint64_t TestNetwork::count(const std::string& counter) const {
  std::uint64_t total = 0;
  for (NodeId n = 0; n < size(); ++n) total += count(n, counter);
  return total;
}

const RouteEntry* TestNetwork::valid_route(NodeId node, NodeId destination) const {
  const RouteEntry* route = nodes_[node]->aodv->routing_table().entry(destination);
  if (route == nullptr || !route->is_valid() || route->expires < now()) return nullptr;
  return route;
}

std::string TestNetwork::find_loop() const {
  for (NodeId destination = 0; destination < size(); ++destination) {
    for (NodeId start = 0; start < size(); ++start) {
      std::vector<NodeId> path{start};
      NodeId at = start;
      while (at != destination) {
        const RouteEntry* route = valid_route(at, destination);
        if (route == nullptr) break;
        at = route->next_hop;
        if (std::find(path.begin(), path.end(), at) != path.end()) {
          std::ostringstream out;
          out << "loop towards " << destination << " at t=" << to_seconds(now()) << " s:";
          for (const NodeId n : path) {
            const RouteEntry* r = valid_route(n, destination);
            out << ' ' << n << "(next " << r->next_hop << ", hops " << r->hop_count << ", seq "
                << r->seq << (r->valid_seq ? "" : "?") << ", until " << to_seconds(r->expires)
                << ")";
          }
          out << ' ' << at;
          return out.str();
        }
        path.push_back(at);
      }
    }
  }
  return "";
}

}  // namespace swarmnet::aodv::test
