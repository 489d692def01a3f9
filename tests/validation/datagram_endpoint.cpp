#include "datagram_endpoint.hpp"

#include <ns3/inet-socket-address.h>
#include <ns3/packet.h>
#include <ns3/simulator.h>
#include <ns3/udp-socket-factory.h>

namespace swarmnet::validation {

namespace {
// ns-3's default IPv4 TTL; each IP forwarding decrements it.
constexpr std::uint32_t kDefaultTtl = 64;
}  // namespace

DatagramEndpoint::DatagramEndpoint(ns3::Ptr<ns3::Node> node, std::uint32_t node_id,
                                   ReplayWorld& world)
    : node_id_(node_id), world_(world) {
  socket_ = ns3::Socket::CreateSocket(node, ns3::UdpSocketFactory::GetTypeId());
  socket_->Bind(ns3::InetSocketAddress(ns3::Ipv4Address::GetAny(), world_.port));
  socket_->SetAllowBroadcast(true);
  socket_->SetIpRecvTtl(true);
  socket_->SetRecvCallback(ns3::MakeCallback(&DatagramEndpoint::receive, this));
}

void DatagramEndpoint::send(std::uint32_t index) {
  const TrafficMessage& message = world_.messages[index];
  std::vector<std::uint8_t> bytes;
  append_payload(bytes, index, message.payload_bytes);
  const ns3::Ipv4Address to = message.broadcast() ? ns3::Ipv4Address::GetBroadcast()
                                                  : world_.addresses.at(message.destination);
  world_.metrics.message_sent(index);
  const auto packet =
      ns3::Create<ns3::Packet>(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  socket_->SendTo(packet, 0, ns3::InetSocketAddress(to, world_.port));
}

void DatagramEndpoint::receive(ns3::Ptr<ns3::Socket> socket) {
  while (ns3::Ptr<ns3::Packet> packet = socket->Recv()) {
    std::uint8_t head[kMessageIndexBytes] = {};
    const std::uint32_t copied = packet->CopyData(head, sizeof head);
    const auto index = payload_index(head, copied, world_.messages.size());
    if (!index) continue;
    std::uint32_t hops = 1;
    ns3::SocketIpTtlTag ttl;
    if (packet->RemovePacketTag(ttl)) hops = kDefaultTtl + 1 - ttl.GetTtl();
    world_.metrics.message_received(*index, node_id_, ns3::Simulator::Now().GetNanoSeconds(), hops);
  }
}

}  // namespace swarmnet::validation
