// Network settings of the study's radio for the ns-3 engine's tests, built by hand as the
// scenario loader would fill them (every parameter of each plugin, at its declared default):
// log-distance loss with a 120 m range, the sinr PHY, dcf80211 at 6 Mbit/s, and AODV.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "network/network_settings.hpp"

namespace swarmnet::test {

inline PluginChoice plugin(std::string name, PluginKind kind, ParamSet params = {}) {
  return PluginChoice{std::move(name), kind, std::move(params), {}};
}

// dcf80211's parameters at their defaults (plugins/radio/dcf80211).
inline ParamSet dcf80211_params() {
  return ParamSet({{"data_rate_bps", 6e6},
                   {"control_rate_bps", 6e6},
                   {"slot_s", 9e-6},
                   {"sifs_s", 16e-6},
                   {"cw_min", std::int64_t{15}},
                   {"cw_max", std::int64_t{1023}},
                   {"short_retry_limit", std::int64_t{7}},
                   {"long_retry_limit", std::int64_t{4}},
                   {"rts_threshold_bytes", std::int64_t{65535}},
                   {"queue_limit", std::int64_t{500}},
                   {"queue_max_delay_s", 0.5},
                   {"header_bytes", std::int64_t{36}}});
}

// aodv's parameters that the ns-3 engine maps, at their defaults (plugins/routing/aodv).
inline ParamSet aodv_params() {
  return ParamSet({{"hello_interval_s", 1.0},
                   {"allowed_hello_loss", std::int64_t{2}},
                   {"active_route_timeout_s", 3.0},
                   {"net_diameter", std::int64_t{35}},
                   {"node_traversal_time_s", 0.04},
                   {"net_traversal_time_s", 0.0},
                   {"path_discovery_time_s", 0.0},
                   {"next_hop_wait_s", 0.0},
                   {"my_route_timeout_s", 0.0},
                   {"blacklist_timeout_s", 0.0},
                   {"delete_period_s", 0.0},
                   {"rreq_retries", std::int64_t{2}},
                   {"rreq_rate_limit", std::int64_t{10}},
                   {"rerr_rate_limit", std::int64_t{10}},
                   {"ttl_start", std::int64_t{1}},
                   {"ttl_increment", std::int64_t{2}},
                   {"ttl_threshold", std::int64_t{7}},
                   {"timeout_buffer", std::int64_t{2}},
                   {"max_queue_len", std::int64_t{64}},
                   {"max_queue_time_s", 30.0},
                   {"destination_only", false},
                   {"gratuitous_reply", true},
                   {"enable_hello", true},
                   {"enable_broadcast", true},
                   {"link_layer_feedback", true}});
}

// `nodes` nodes on the study's radio with `routing`, for the ns-3 engine.
inline NetworkSettings study_settings(std::uint32_t nodes, std::uint64_t seed,
                                      PluginChoice routing) {
  NetworkSettings s;
  s.seed = seed;
  s.nodes = nodes;
  s.step_s = 0.1;
  s.network.propagation = {plugin(
      "log_distance", PluginKind::propagation,
      ParamSet(
          {{"exponent", 3.0}, {"reference_distance_m", 1.0}, {"reference_loss_db", 46.6777}}))};
  s.network.phy.model = PhyModel::sinr;
  s.network.phy.tx_power_dbm = 27.0531;  // -82 dBm at 120 m
  s.network.mac = plugin("dcf80211", PluginKind::mac, dcf80211_params());
  s.network.routing = std::move(routing);
  s.network.engine = NetworkEngineKind::ns3;
  return s;
}

}  // namespace swarmnet::test
