#include "ns3_engine/live_endpoints.hpp"

#include <ns3/inet-socket-address.h>
#include <ns3/nstime.h>
#include <ns3/packet.h>
#include <ns3/simulator.h>
#include <ns3/udp-socket-factory.h>

#include <algorithm>

#include "ns3_engine/message_tag.hpp"

namespace swarmnet::ns3engine {

namespace {

// ns-3's default IPv4 TTL; each IP forwarding decrements it.
constexpr std::uint32_t kDefaultTtl = 64;

ns3::Ptr<ns3::Packet> make_packet(const std::vector<std::uint8_t>& bytes, const MessageTag& tag) {
  const ns3::Ptr<ns3::Packet> packet =
      bytes.empty()
          ? ns3::Create<ns3::Packet>()
          : ns3::Create<ns3::Packet>(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  packet->AddPacketTag(tag);
  return packet;
}

ns3::Ptr<ns3::Socket> open_socket(const ns3::Ptr<ns3::Node>& node, std::uint16_t port) {
  ns3::Ptr<ns3::Socket> socket =
      ns3::Socket::CreateSocket(node, ns3::UdpSocketFactory::GetTypeId());
  socket->Bind(ns3::InetSocketAddress(ns3::Ipv4Address::GetAny(), port));
  socket->SetAllowBroadcast(true);
  return socket;
}

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

void EndpointWorld::arrive(const MessageTag& tag, std::uint32_t receiver,
                           std::uint32_t hops) const {
  if (arrivals == nullptr || receiver == tag.source()) return;
  arrivals->push_back({tag.message_id(), receiver, ns3::Simulator::Now().GetNanoSeconds(), hops});
}

DatagramEndpoint::DatagramEndpoint(const ns3::Ptr<ns3::Node>& node, std::uint32_t node_id,
                                   const EndpointWorld& world)
    : node_id_(node_id), world_(world), socket_(open_socket(node, world.port)) {
  socket_->SetIpRecvTtl(true);
  socket_->SetRecvCallback(ns3::MakeCallback(&DatagramEndpoint::receive, this));
}

void DatagramEndpoint::send(const Message& message) {
  const MessageTag tag(message.message_id, message.source, message.destination);
  const ns3::Ipv4Address to = message.destination == kBroadcastNode
                                  ? ns3::Ipv4Address::GetBroadcast()
                                  : world_.addresses[message.destination];
  if (socket_->SendTo(make_packet(message.payload, tag), 0,
                      ns3::InetSocketAddress(to, world_.port)) < 0 &&
      socket_->GetErrno() == ns3::Socket::ERROR_NOROUTETOHOST) {
    // The UDP socket asks the routing protocol itself and drops the datagram without an IP trace
    // when there is no route (OLSR, DSDV without buffering).
    ++world_.counts->no_route;
  }
}

void DatagramEndpoint::receive(ns3::Ptr<ns3::Socket> socket) {
  while (const ns3::Ptr<ns3::Packet> packet = socket->Recv()) {
    MessageTag tag;
    if (!find_message(packet, tag)) continue;
    // Every IP forwarding decrements the TTL, a broadcast's too (AODV and DSDV relay broadcasts).
    std::uint32_t hops = 1;
    ns3::SocketIpTtlTag ttl;
    if (packet->RemovePacketTag(ttl)) hops = kDefaultTtl + 1 - ttl.GetTtl();
    world_.arrive(tag, node_id_, hops);
  }
}

FloodingEndpoint::FloodingEndpoint(const ns3::Ptr<ns3::Node>& node, std::uint32_t node_id,
                                   const EndpointWorld& world, const FloodingParams& params,
                                   const ns3::Ptr<ns3::UniformRandomVariable>& jitter)
    : node_id_(node_id),
      world_(world),
      params_(params),
      jitter_(jitter),
      socket_(open_socket(node, world.port)),
      seen_order_(std::max<std::size_t>(params.cache_size, 1)) {
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

void FloodingEndpoint::send(const Message& message) {
  const std::uint32_t sequence = next_sequence_++;
  remember(node_id_, sequence);  // our own copies come back: not relayed
  std::vector<std::uint8_t> bytes(kHeaderBytes + message.payload.size(), 0);
  put_u32(bytes, 0, node_id_);
  put_u32(bytes, 4, sequence);
  bytes[8] = static_cast<std::uint8_t>(params_.ttl);
  std::copy(message.payload.begin(), message.payload.end(), bytes.begin() + kHeaderBytes);
  broadcast(bytes, MessageTag(message.message_id, message.source, message.destination));
}

void FloodingEndpoint::broadcast(const std::vector<std::uint8_t>& bytes, const MessageTag& tag) {
  socket_->SendTo(make_packet(bytes, tag), 0,
                  ns3::InetSocketAddress(ns3::Ipv4Address::GetBroadcast(), world_.port));
}

void FloodingEndpoint::receive(ns3::Ptr<ns3::Socket> socket) {
  while (const ns3::Ptr<ns3::Packet> packet = socket->Recv()) {
    MessageTag tag;
    if (!find_message(packet, tag) || packet->GetSize() < kHeaderBytes) continue;
    std::vector<std::uint8_t> bytes(packet->GetSize());
    packet->CopyData(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
    const std::uint32_t ttl = bytes[8];
    if (!remember(get_u32(bytes, 0), get_u32(bytes, 4))) {
      ++world_.counts->duplicates;
      continue;
    }
    const std::uint32_t hops = params_.ttl - ttl + 1;
    if (tag.destination() == node_id_) {
      world_.arrive(tag, node_id_, hops);
      continue;
    }
    if (tag.destination() == kBroadcastNode) world_.arrive(tag, node_id_, hops);
    if (ttl <= 1) {
      ++world_.counts->flooding_ttl_expired;
      ++world_.counts->ttl_expired;
      continue;
    }
    bytes[8] = static_cast<std::uint8_t>(ttl - 1);
    const ns3::Time delay = ns3::Seconds(jitter_->GetValue(0.0, params_.jitter_max_s));
    ns3::Simulator::Schedule(delay, [this, tag, relayed = std::move(bytes)]() {
      ++world_.counts->data_forwards;
      broadcast(relayed, tag);
    });
  }
}

}  // namespace swarmnet::ns3engine
