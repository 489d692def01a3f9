// What of a scenario the ns-3 engine can run, and as what: each plugin with an ns-3 counterpart
// and, for each of its parameters, the ns-3 attribute it sets, or the one value that describes
// what ns-3 does. The scenario check refuses any other plugin, a parameter with neither set to
// other than its default, and a fixed behaviour's parameter set to another value; the mapping
// (ns3_settings.cpp) reads the same tables, so the two cannot disagree.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace swarmnet {

// How a parameter's value becomes the attribute's text.
enum class Ns3Conversion : std::uint8_t {
  number,       // as is (%.17g)
  integer,      // as a whole number
  boolean,      // true / false
  seconds,      // an ns-3 Time in seconds ("0.5s")
  db_to_ratio,  // dB to a linear ratio (friis' SystemLoss)
  packets,      // a QueueSize in packets ("100p")
  special,      // mapped by code in ns3_settings.cpp (rates, antenna heights, AODV's times
                // whose 0 means "derived from the others", which ns-3 does not derive)
};

// Which ns-3 object an attribute is set on.
enum class Ns3Target : std::uint8_t {
  plugin_object,  // the counterpart's own object (a loss model, AODV's RoutingProtocol)
  phy,            // YansWifiPhy
  rate_manager,   // the WifiRemoteStationManager
  txop,           // the ad hoc MAC's Txop
  mac_queue,      // the Txop's WifiMacQueue
  application,    // the module's own application (flooding)
};

struct Ns3ParamAttribute {
  std::string_view param;
  std::string_view attribute;  // empty for `special` and `application`
  Ns3Conversion conversion;
  Ns3Target target = Ns3Target::plugin_object;
};

struct Ns3Counterpart {
  std::string_view plugin;
  std::string_view type_id;  // the ns-3 object it becomes (empty: an application of the module)
  std::span<const Ns3ParamAttribute> params;
};

namespace ns3_tables {
using enum Ns3Conversion;
inline constexpr std::array<Ns3ParamAttribute, 3> kLogDistance{{
    {"exponent", "Exponent", number},
    {"reference_distance_m", "ReferenceDistance", number},
    {"reference_loss_db", "ReferenceLoss", number},
}};
inline constexpr std::array<Ns3ParamAttribute, 3> kFriis{{
    {"frequency_hz", "Frequency", number},
    {"system_loss_db", "SystemLoss", db_to_ratio},
    {"min_loss_db", "MinLoss", number},
}};
inline constexpr std::array<Ns3ParamAttribute, 4> kTwoRayGround{{
    {"frequency_hz", "Frequency", number},
    {"system_loss_db", "SystemLoss", db_to_ratio},
    {"tx_height_m", "HeightAboveZ", special},  // ns-3 has one height for both ends
    {"rx_height_m", "HeightAboveZ", special},
}};
inline constexpr std::array<Ns3ParamAttribute, 1> kRange{{
    {"max_range_m", "MaxRange", number},
}};
inline constexpr std::array<Ns3ParamAttribute, 5> kNakagami{{
    {"distance1_m", "Distance1", number},
    {"distance2_m", "Distance2", number},
    {"m0", "m0", number},
    {"m1", "m1", number},
    {"m2", "m2", number},
}};
inline constexpr std::array<Ns3ParamAttribute, 11> kDcf80211{{
    {"data_rate_bps", "DataMode", special, Ns3Target::rate_manager},
    {"control_rate_bps", "ControlMode", special, Ns3Target::rate_manager},
    {"slot_s", "Slot", seconds, Ns3Target::phy},
    {"sifs_s", "Sifs", seconds, Ns3Target::phy},
    {"cw_min", "MinCw", integer, Ns3Target::txop},
    {"cw_max", "MaxCw", integer, Ns3Target::txop},
    {"short_retry_limit", "MaxSsrc", integer, Ns3Target::rate_manager},
    {"long_retry_limit", "MaxSlrc", integer, Ns3Target::rate_manager},
    {"rts_threshold_bytes", "RtsCtsThreshold", integer, Ns3Target::rate_manager},
    {"queue_limit", "MaxSize", packets, Ns3Target::mac_queue},
    {"queue_max_delay_s", "MaxDelay", seconds, Ns3Target::mac_queue},
}};
inline constexpr std::array<Ns3ParamAttribute, 25> kAodv{{
    {"hello_interval_s", "HelloInterval", seconds},
    {"allowed_hello_loss", "AllowedHelloLoss", integer},
    {"active_route_timeout_s", "ActiveRouteTimeout", seconds},
    {"net_diameter", "NetDiameter", integer},
    {"node_traversal_time_s", "NodeTraversalTime", seconds},
    {"net_traversal_time_s", "NetTraversalTime", special},
    {"path_discovery_time_s", "PathDiscoveryTime", special},
    {"next_hop_wait_s", "NextHopWait", special},
    {"my_route_timeout_s", "MyRouteTimeout", special},
    {"blacklist_timeout_s", "BlackListTimeout", special},
    {"delete_period_s", "DeletePeriod", special},
    {"rreq_retries", "RreqRetries", integer},
    {"rreq_rate_limit", "RreqRateLimit", integer},
    {"rerr_rate_limit", "RerrRateLimit", integer},
    {"ttl_start", "TtlStart", integer},
    {"ttl_increment", "TtlIncrement", integer},
    {"ttl_threshold", "TtlThreshold", integer},
    {"timeout_buffer", "TimeoutBuffer", integer},
    {"max_queue_len", "MaxQueueLen", integer},
    {"max_queue_time_s", "MaxQueueTime", seconds},
    {"destination_only", "DestinationOnly", boolean},
    {"gratuitous_reply", "GratuitousReply", boolean},
    {"enable_hello", "EnableHello", boolean},
    {"enable_broadcast", "EnableBroadcast", boolean},
    {"link_layer_feedback", "", special},  // with network.arp (ns3_settings.cpp)
}};
inline constexpr std::array<Ns3ParamAttribute, 3> kFlooding{{
    {"ttl", "", special, Ns3Target::application},
    {"jitter_max_s", "", special, Ns3Target::application},
    {"cache_size", "", special, Ns3Target::application},
}};
}  // namespace ns3_tables

inline constexpr std::array<Ns3Counterpart, 5> kNs3Propagation{{
    {"log_distance", "ns3::LogDistancePropagationLossModel", ns3_tables::kLogDistance},
    {"friis", "ns3::FriisPropagationLossModel", ns3_tables::kFriis},
    {"two_ray_ground", "ns3::TwoRayGroundPropagationLossModel", ns3_tables::kTwoRayGround},
    {"range", "ns3::RangePropagationLossModel", ns3_tables::kRange},
    {"nakagami", "ns3::NakagamiPropagationLossModel", ns3_tables::kNakagami},
}};

// The MAC: its parameters land on the rate manager, the PHY, the Txop and the queue.
inline constexpr std::array<Ns3Counterpart, 1> kNs3Mac{{
    {"dcf80211", "ns3::AdhocWifiMac", ns3_tables::kDcf80211},
}};

inline constexpr std::array<Ns3Counterpart, 3> kNs3Routing{{
    {"direct", "", {}},
    {"flooding", "", ns3_tables::kFlooding},
    {"aodv", "ns3::aodv::RoutingProtocol", ns3_tables::kAodv},
}};

// A parameter ns-3 has no attribute for, but one fixed behaviour that a value of it describes:
// with the ns-3 engine the parameter must have that value (booleans as 0 and 1), and any other
// is refused, even the plugin's default, which would otherwise be silently not what ran.
struct Ns3FixedBehaviour {
  std::string_view plugin;
  std::string_view param;
  double value;
  std::string_view behaviour;  // what ns-3 does, for the refusal
};

inline constexpr std::array<Ns3FixedBehaviour, 23> kNs3FixedBehaviour{{
    {"aodv", "increment_seqno_on_break", 0,
     "ns-3.37's AODV does not increment a broken route's destination sequence number"},
    {"aodv", "rreq_invalidates_sender_seqno", 1,
     "ns-3.37's AODV leaves the route to a RREQ's sender without a valid sequence number"},
    {"aodv", "rrep_over_invalid_reverse_route", 1,
     "ns-3.37's AODV forwards a RREP over an invalid route to its originator too"},
    {"aodv", "rrep_ip_ttl", 1,
     "ns-3.37's AODV sends a RREP with an IP TTL of the replier's hop count to the originator"},
    {"aodv", "rerr_to_valid_precursors", 1,
     "ns-3.37's AODV sends a RERR only to precursors with a valid route, after a jitter"},
    {"aodv", "queue_released_by_rrep_only", 1,
     "ns-3.37's AODV sends buffered packets only on a RREP or when the discovery timer fires"},
    {"aodv", "rreq_overwrites_reverse_route", 1,
     "ns-3.37's AODV makes a RREQ's sender the next hop to its originator whatever the route's "
     "freshness"},
    {"aodv", "neighbor_route_forgets_seqno", 1,
     "ns-3.37's AODV gives a neighbour's route that an AODV message makes one hop sequence "
     "number 0, marked unknown"},
    {"aodv", "reply_seqno_plus_one_only", 1,
     "ns-3.37's AODV destination increments its sequence number only when asked for exactly one "
     "more"},
    {"aodv", "control_via_route_to_neighbor", 1,
     "ns-3.37's AODV sends a unicast message to a neighbour as an IP datagram along the route to "
     "it"},
    {"aodv", "ip_input_refreshes_routes", 1,
     "ns-3.37's IP refreshes the route to an AODV message's sender before AODV reads it"},
    {"aodv", "rerr_covers_routes_in_any_state", 1,
     "ns-3.37's AODV reports a broken link's and a RERR's routes in any state, invalid ones "
     "included"},
    {"aodv", "rrep_replaces_route", 1,
     "ns-3.37's AODV puts a new entry, without precursors, in the place of a route a RREP "
     "updates"},
    {"aodv", "rate_limited_requests_stack", 1,
     "ns-3.37's AODV schedules every RREQ its rate limit refuses on its own, for when the window "
     "turns"},
    {"aodv", "rrep_ends_search_only", 1,
     "ns-3.37's AODV ends a discovery on a RREP only if the route was in search, and sends the "
     "buffer over the route whatever its state"},
    {"aodv", "lookups_age_all_routes", 1,
     "ns-3.37's AODV ages every route of its table at every route lookup"},
    {"aodv", "enable_local_repair", 0, "ns-3.37's AODV has no local repair"},
    {"aodv", "rrep_ack_required", 0,
     "ns-3.37's AODV requests a RREP-ACK only when an intermediate node answers"},
    {"aodv", "data_ttl", 64, "ns-3's IPv4 sends data with a TTL of 64"},
    {"aodv", "broadcast_jitter_max_s", 0.01, "ns-3.37's AODV delays its broadcasts by up to 10 ms"},
    {"aodv", "hello_start_jitter_max_s", 0.1,
     "ns-3.37's AODV starts its HELLOs within the first 100 ms"},
    {"aodv", "local_add_ttl", 2, "ns-3.37's AODV has no local repair to add TTL to"},
    {"dcf80211", "header_bytes", 36,
     "ns-3 sends real headers: MAC 24 + FCS 4 + LLC/SNAP 8 = 36 bytes"},
}};

inline const Ns3FixedBehaviour* find_ns3_fixed_behaviour(std::string_view plugin,
                                                         std::string_view param) {
  for (const auto& entry : kNs3FixedBehaviour) {
    if (entry.plugin == plugin && entry.param == param) return &entry;
  }
  return nullptr;
}

// The counterpart of plugin `name` in `table`, or null.
inline const Ns3Counterpart* find_ns3_counterpart(std::span<const Ns3Counterpart> table,
                                                  std::string_view name) {
  for (const auto& entry : table) {
    if (entry.plugin == name) return &entry;
  }
  return nullptr;
}

inline const Ns3ParamAttribute* find_ns3_attribute(const Ns3Counterpart& counterpart,
                                                   std::string_view param) {
  for (const auto& row : counterpart.params) {
    if (row.param == param) return &row;
  }
  return nullptr;
}

}  // namespace swarmnet
