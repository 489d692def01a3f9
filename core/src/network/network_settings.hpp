// What the network half is set up with (DESIGN.md section 1): typed settings, no YAML. The
// scenario loader fills them from a validated scenario (Scenario::network_settings); tests and
// benchmarks build them by hand.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "plugin/plugin_choice.hpp"
#include "swarmnet/arena.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

enum class PhyModel : std::uint8_t { threshold, sinr };

// What the MAC is told after a frame's PLCP header (L-SIG) fails (sinr model;
// network.phy.header_failure_cca): `sensed` keeps carrier sense on the signals; `ns3` tells it
// what ns-3.37 does (network/sinr_reception.hpp, "After a header failure").
enum class HeaderFailureCca : std::uint8_t { sensed, ns3 };

// The radio of every node (network/phy.hpp describes both reception models). Defaults of the
// sinr model's keys are ns-3.37's YansWifiPhy defaults for 802.11a.
struct PhyConfig {
  double tx_power_dbm = 16.0206;
  double rx_sensitivity_dbm = -96.0;  // threshold model: frames weaker than this are not received
  PhyModel model = PhyModel::threshold;
  double tx_gain_db = 0.0;
  double rx_gain_db = 0.0;
  double bandwidth_hz = 20.0e6;
  double noise_figure_db = 7.0;
  double energy_detection_dbm = -62.0;   // CCA-ED: total energy that makes the medium busy
  double cca_threshold_dbm = -82.0;      // weakest frame whose preamble is detected (and sensed)
  double preamble_snr_db = 4.0;          // SINR a preamble needs to be detected
  double interference_floor_db = -10.0;  // signals below noise floor + this are ignored
  // Signals below cca_threshold + this are quiet (not carrier-sensed); the default makes none.
  double sensing_floor_db = -100.0;
  HeaderFailureCca header_failure_cca = HeaderFailureCca::sensed;
};

// Which simulator is the network half (DESIGN.md section 3): SwarmNet's own, or ns-3.37 in a
// module of its own (core/src/ns3_engine/, docs/ns3-engine.md).
enum class NetworkEngineKind : std::uint8_t { native, ns3 };

inline const char* to_string(NetworkEngineKind engine) {
  return engine == NetworkEngineKind::native ? "native" : "ns3";
}

// Options of the ns-3 engine that SwarmNet's own has no counterpart for (`network.ns3:`).
struct Ns3Options {
  std::string standard = "80211a";        // 80211a, 80211b, 80211g, 80211n, 80211ac
  std::string rate_manager = "constant";  // constant, arf, aarf, minstrel, minstrel_ht, ideal
  std::string data_mode;     // constant: WifiMode of data frames; empty: from the MAC's rate
  std::string control_mode;  // constant: WifiMode of control frames; empty: from the MAC's rate
  std::string ip_routing = "none";        // under the `direct` plugin: none (one hop), olsr, dsdv
  std::string error_rate_model = "nist";  // nist (SwarmNet's sinr model), table, yans
  double olsr_hello_interval_s = 2.0;
  double olsr_tc_interval_s = 5.0;
  double dsdv_periodic_update_interval_s = 15.0;
  double dsdv_settling_time_s = 5.0;
};

// ns-3.37's defaults (ArpCache's attributes and ArpL3Protocol's RequestJitter).
struct ArpTimings {
  SimTime alive_timeout = from_seconds(120.0);     // an alive entry needs refreshing after this
  SimTime dead_timeout = from_seconds(100.0);      // a dead entry is retried after this
  SimTime wait_reply_timeout = from_seconds(1.0);  // period of the cache's wait-reply timer
  std::uint32_t max_retries = 3;                   // requests re-sent before an entry dies
  std::size_t pending_queue_size = 3;              // packets held per entry awaiting a reply
  // A request waits a uniform draw in [0, request_jitter_max_ms) milliseconds, truncated to a
  // whole millisecond (ns-3 converts the draw with MilliSeconds(uint64_t)).
  double request_jitter_max_ms = 10.0;
};

struct ChannelConfig {
  bool cutoff = true;  // visit only nodes that can possibly hear a frame (DESIGN.md section 7)
  // network.channel.far_signals: lazy (true) hands far signals (network/far_signals.hpp) to a
  // receiver only when they can matter to it; events (false) hands every signal over as events.
  // Both give the same results to the bit; lazy is faster.
  bool lazy_far_signals = true;
};

// network.neighbors: per-robot tables of the nodes each radio decoded frames from
// (swarmnet/radio_neighbor.hpp). Off, the network half keeps none and sends none (cost zero).
struct NeighborSensing {
  bool enabled = false;
  double window_s = 1.0;             // a node not heard for this long leaves the table
  std::uint32_t max_per_robot = 32;  // the most recently heard are kept
  double rssi_smoothing = 0.25;      // weight of a new frame in the smoothed RSSI (0, 1]
};

// The layers of every node, as the scenario's `network:` section chose them.
struct NetworkConfig {
  std::vector<PluginChoice> propagation;  // applied in order
  PhyConfig phy;
  ChannelConfig channel;
  PluginChoice mac;
  PluginChoice routing;
  // network.arp: ns3 runs ARP with these timings (network/arp.hpp); static (nullopt) fills every
  // neighbour's address before the run and sends no ARP frame.
  std::optional<ArpTimings> arp = ArpTimings{};
  NeighborSensing neighbors;
  NetworkEngineKind engine = NetworkEngineKind::native;
  Ns3Options ns3;
  // network.seed: the network half's own streams (MAC, PHY draws, ARP, routing, fading); absent,
  // the master seed. The traffic's injection instants stay on the master seed.
  std::optional<std::uint64_t> seed;
};

struct NetworkSettings {
  std::uint64_t seed = 1;  // the network half's streams are derived from it (swarmnet/random.hpp)
  // The master seed: it places each message's injection in its step (injection_offset), which
  // is part of the traffic (traffic.csv), not of the network, so network.seed leaves it alone.
  std::uint64_t traffic_seed = 1;
  double step_s = 0.1;      // the step window; at least 1 ns
  std::uint32_t nodes = 0;  // one per robot
  Arena arena;              // the channel's grid covers its rectangle
  NetworkConfig network;
};

}  // namespace swarmnet
