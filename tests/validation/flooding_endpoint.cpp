#include "flooding_endpoint.hpp"

#include <ns3/inet-socket-address.h>
#include <ns3/nstime.h>
#include <ns3/packet.h>
#include <ns3/simulator.h>
#include <ns3/udp-socket-factory.h>

#include <algorithm>

namespace swarmnet::validation {

namespace {

void put_u32(std::vector<std::uint8_t>& out, std::size_t offset, std::uint32_t value) {
  for (std::size_t i = 0; i < 4; ++i) out[offset + i] = static_cast<std::uint8_t>(value >> (8 * i));
}

std::uint32_t get_u32(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    value |= static_cast<std::uint32_t>(bytes[offset + i]) << (8 * i);
  }
  return value;
}

}  // namespace

FloodingEndpoint::FloodingEndpoint(ns3::Ptr<ns3::Node> node, std::uint32_t node_id,
                                   ReplayWorld& world, const FloodingConfig& config,
                                   FloodingCounters& counters,
                                   ns3::Ptr<ns3::UniformRandomVariable> jitter)
    : node_id_(node_id),
      world_(world),
      config_(config),
      counters_(counters),
      jitter_(std::move(jitter)),
      seen_order_(std::max<std::size_t>(config.cache_size, 1)) {
  socket_ = ns3::Socket::CreateSocket(node, ns3::UdpSocketFactory::GetTypeId());
  socket_->Bind(ns3::InetSocketAddress(ns3::Ipv4Address::GetAny(), world_.port));
  socket_->SetAllowBroadcast(true);
  socket_->SetRecvCallback(ns3::MakeCallback(&FloodingEndpoint::receive, this));
}

bool FloodingEndpoint::remember(std::uint32_t originator, std::uint32_t sequence) {
  const std::uint64_t key = (static_cast<std::uint64_t>(originator) << 32U) | sequence;
  if (seen_.count(key) != 0) return false;
  if (seen_.size() == seen_order_.size()) seen_.erase(seen_order_[seen_next_]);
  seen_.insert(key);
  seen_order_[seen_next_] = key;
  seen_next_ = (seen_next_ + 1) % seen_order_.size();
  return true;
}

void FloodingEndpoint::send(std::uint32_t index) {
  const TrafficMessage& message = world_.messages[index];
  const std::uint32_t sequence = next_sequence_++;
  remember(node_id_, sequence);
  std::vector<std::uint8_t> bytes(kHeaderBytes, 0);
  put_u32(bytes, 0, node_id_);
  put_u32(bytes, 4, sequence);
  bytes[8] = static_cast<std::uint8_t>(config_.ttl);
  append_payload(bytes, index, message.payload_bytes);
  world_.metrics.message_sent(index);
  broadcast(bytes);
}

void FloodingEndpoint::broadcast(const std::vector<std::uint8_t>& bytes) {
  const auto packet =
      ns3::Create<ns3::Packet>(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  socket_->SendTo(packet, 0, ns3::InetSocketAddress(ns3::Ipv4Address::GetBroadcast(), world_.port));
}

void FloodingEndpoint::receive(ns3::Ptr<ns3::Socket> socket) {
  while (ns3::Ptr<ns3::Packet> packet = socket->Recv()) {
    std::vector<std::uint8_t> bytes(packet->GetSize());
    packet->CopyData(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
    if (bytes.size() < kHeaderBytes) continue;
    const auto index = payload_index(bytes.data() + kHeaderBytes, bytes.size() - kHeaderBytes,
                                     world_.messages.size());
    if (!index) continue;
    const std::uint32_t originator = get_u32(bytes, 0);
    const std::uint32_t sequence = get_u32(bytes, 4);
    const std::uint32_t ttl = bytes[8];
    if (!remember(originator, sequence)) {
      ++counters_.duplicates;
      continue;
    }
    const TrafficMessage& message = world_.messages[*index];
    const std::uint32_t hops = config_.ttl - ttl + 1;
    const std::int64_t now_ns = ns3::Simulator::Now().GetNanoSeconds();
    if (message.destination == node_id_) {
      world_.metrics.message_received(*index, node_id_, now_ns, hops);
      continue;
    }
    if (message.broadcast()) world_.metrics.message_received(*index, node_id_, now_ns, hops);
    if (ttl <= 1) {
      ++counters_.ttl_expired;
      continue;
    }
    bytes[8] = static_cast<std::uint8_t>(ttl - 1);
    const ns3::Time delay = ns3::Seconds(jitter_->GetValue(0.0, config_.jitter_max_s));
    ns3::Simulator::Schedule(delay, [this, relayed = std::move(bytes)]() {
      ++counters_.forwards;
      broadcast(relayed);
    });
  }
}

}  // namespace swarmnet::validation
