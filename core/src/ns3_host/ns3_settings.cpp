#include "ns3_host/ns3_settings.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "ns3_host/ns3_counterparts.hpp"
#include "ns3_host/ns3_wifi_modes.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

namespace {

using ns3engine::Attribute;

std::string number_text(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// Whole nanoseconds: the network half's own resolution, and text ns-3's Time parses exactly.
std::string time_text(double seconds) { return std::to_string(std::llround(seconds * 1e9)) + "ns"; }

double as_real(const ParamValue& value) {
  if (const auto* real = std::get_if<double>(&value)) return *real;
  if (const auto* integer = std::get_if<std::int64_t>(&value)) return static_cast<double>(*integer);
  if (const auto* flag = std::get_if<bool>(&value)) return *flag ? 1.0 : 0.0;
  throw std::invalid_argument("a text parameter where a number was expected");
}

std::string attribute_text(const ParamValue& value, Ns3Conversion conversion) {
  const double number = as_real(value);
  switch (conversion) {
    case Ns3Conversion::number:
      return number_text(number);
    case Ns3Conversion::integer:
      return std::to_string(std::llround(number));
    case Ns3Conversion::boolean:
      return number != 0.0 ? "true" : "false";
    case Ns3Conversion::seconds:
      return time_text(number);
    case Ns3Conversion::db_to_ratio:
      return number_text(std::pow(10.0, number / 10.0));
    case Ns3Conversion::packets:
      return std::to_string(std::llround(number)) + "p";
    case Ns3Conversion::special:
      break;
  }
  throw std::logic_error("attribute_text: a special parameter");
}

const Ns3Counterpart& counterpart_of(std::span<const Ns3Counterpart> table,
                                     const PluginChoice& choice, const char* kind) {
  const Ns3Counterpart* counterpart = find_ns3_counterpart(table, choice.name);
  if (counterpart == nullptr) {
    throw std::invalid_argument(std::string("the ") + kind + " plugin '" + choice.name +
                                "' has no ns-3 counterpart");
  }
  for (const auto& [param, value] : choice.params.values()) {
    const Ns3FixedBehaviour* fixed = find_ns3_fixed_behaviour(choice.name, param);
    if (fixed != nullptr && as_real(value) != fixed->value) {
      throw std::invalid_argument("'" + choice.name + "' parameter " + param + ": " +
                                  std::string(fixed->behaviour));
    }
  }
  return *counterpart;
}

// The slot, SIFS and contention window of dcf80211 are 802.11a's by default; with another
// standard ns-3 keeps that standard's own (the check refuses them given).
bool applies(const Ns3ParamAttribute& row, const std::string& standard) {
  if (standard == "80211a") return true;
  return row.target != Ns3Target::txop && row.attribute != "Slot" && row.attribute != "Sifs";
}

ns3engine::ObjectSpec loss_model(const PluginChoice& choice) {
  const Ns3Counterpart& counterpart = counterpart_of(kNs3Propagation, choice, "propagation");
  ns3engine::ObjectSpec spec{std::string(counterpart.type_id), {}};
  for (const auto& row : counterpart.params) {
    if (row.conversion == Ns3Conversion::special) continue;
    spec.attributes.push_back(
        {std::string(row.attribute),
         attribute_text(choice.params.values().at(std::string(row.param)), row.conversion)});
  }
  if (counterpart.plugin == "two_ray_ground") {
    const double tx = choice.params.real("tx_height_m");
    if (tx != choice.params.real("rx_height_m")) {
      throw std::invalid_argument("two_ray_ground: ns-3 has one antenna height for both ends");
    }
    spec.attributes.push_back({"HeightAboveZ", number_text(tx)});
    // The plugin applies its loss down to lambda / (4 pi); ns-3 stops at MinDistance (0.5 m).
    const double wavelength = kSpeedOfLightMps / choice.params.real("frequency_hz");
    spec.attributes.push_back({"MinDistance", number_text(wavelength / (4.0 * std::numbers::pi))});
  }
  return spec;
}

const char* error_rate_model_type(const std::string& name) {
  if (name == "nist") return "ns3::NistErrorRateModel";
  if (name == "table") return "ns3::TableBasedErrorRateModel";
  if (name == "yans") return "ns3::YansErrorRateModel";
  throw std::invalid_argument("network.ns3.error_rate_model '" + name + "' is not known");
}

// ns-3's AODV has layer-2 feedback whenever it can map a MAC address to a neighbour: always with
// ARP, and with entries filled in before the run only when they are permanent.
ns3engine::Arp arp_mode(const NetworkSettings& settings) {
  const PluginChoice& routing = settings.network.routing;
  const bool feedback = routing.name == "aodv" && routing.params.boolean("link_layer_feedback");
  if (settings.network.arp) {
    if (routing.name == "aodv" && !feedback) {
      throw std::invalid_argument(
          "aodv link_layer_feedback: false needs network.arp: static (ns-3's AODV takes "
          "layer-2 feedback whenever ARP resolved the neighbour)");
    }
    return ns3engine::Arp::dynamic;
  }
  return feedback ? ns3engine::Arp::static_with_feedback : ns3engine::Arp::static_no_feedback;
}

const char* rate_manager_type(const std::string& name) {
  if (name == "constant") return "ns3::ConstantRateWifiManager";
  if (name == "arf") return "ns3::ArfWifiManager";
  if (name == "aarf") return "ns3::AarfWifiManager";
  if (name == "minstrel") return "ns3::MinstrelWifiManager";
  if (name == "minstrel_ht") return "ns3::MinstrelHtWifiManager";
  if (name == "ideal") return "ns3::IdealWifiManager";
  throw std::invalid_argument("network.ns3.rate_manager '" + name + "' is not known");
}

// The constant manager's mode: named outright, or the standard's mode of the MAC's rate.
std::string mode(const std::string& named, const std::string& standard, double bps,
                 const char* key) {
  if (!named.empty()) return named;
  if (auto derived = ns3_mode_for_rate(standard, bps)) return *derived;
  throw std::invalid_argument(std::string("network.ns3.") + key + ": 802." + standard.substr(3) +
                              " has no mode of " + number_text(bps) + " bit/s; name one");
}

void map_mac(const NetworkSettings& settings, ns3engine::Config& config) {
  const PluginChoice& mac = settings.network.mac;
  const Ns3Counterpart& counterpart = counterpart_of(kNs3Mac, mac, "MAC");
  const Ns3Options& options = settings.network.ns3;
  config.rate_manager.type_id = rate_manager_type(options.rate_manager);
  if (options.rate_manager == "constant") {
    const std::string data_mode =
        mode(options.data_mode, options.standard, mac.params.real("data_rate_bps"), "data_mode");
    config.rate_manager.attributes.push_back({"DataMode", data_mode});
    // Broadcasts at the data rate, as dcf80211 sends them (ns-3 would use the lowest mode).
    config.rate_manager.attributes.push_back({"NonUnicastMode", data_mode});
    config.rate_manager.attributes.push_back(
        {"ControlMode", mode(options.control_mode, options.standard,
                             mac.params.real("control_rate_bps"), "control_mode")});
  }
  for (const auto& row : counterpart.params) {
    if (row.conversion == Ns3Conversion::special || !applies(row, options.standard)) continue;
    Attribute attribute{
        std::string(row.attribute),
        attribute_text(mac.params.values().at(std::string(row.param)), row.conversion)};
    switch (row.target) {
      case Ns3Target::phy:
        config.phy.push_back(std::move(attribute));
        break;
      case Ns3Target::rate_manager:
        config.rate_manager.attributes.push_back(std::move(attribute));
        break;
      case Ns3Target::txop:
        config.txop.push_back(std::move(attribute));
        break;
      case Ns3Target::mac_queue:
        config.mac_queue.push_back(std::move(attribute));
        break;
      case Ns3Target::plugin_object:
      case Ns3Target::application:
        throw std::logic_error("dcf80211 maps only onto the PHY, the manager, Txop and queue");
    }
  }
}

void map_phy(const PhyConfig& phy, ns3engine::Config& config) {
  if (phy.model != PhyModel::sinr) {
    throw std::invalid_argument(
        "network.phy.model: ns-3 receives by SINR; threshold has no "
        "ns-3 counterpart");
  }
  config.phy.push_back({"TxPowerStart", number_text(phy.tx_power_dbm)});
  config.phy.push_back({"TxPowerEnd", number_text(phy.tx_power_dbm)});
  config.phy.push_back({"TxPowerLevels", "1"});
  config.phy.push_back({"TxGain", number_text(phy.tx_gain_db)});
  config.phy.push_back({"RxGain", number_text(phy.rx_gain_db)});
  config.phy.push_back({"RxNoiseFigure", number_text(phy.noise_figure_db)});
  config.phy.push_back({"CcaEdThreshold", number_text(phy.energy_detection_dbm)});
  config.phy.push_back({"CcaSensitivity", number_text(phy.cca_threshold_dbm)});
  // ns-3 discards anything weaker than RxSensitivity (-101 dBm by default) before preamble
  // detection; SwarmNet's sinr PHY has no such floor above the preamble's own.
  config.phy.push_back({"RxSensitivity", number_text(std::min(phy.cca_threshold_dbm, -101.0))});
  if (phy.bandwidth_hz != 20e6) {
    config.phy.push_back(
        {"ChannelSettings",
         "{0, " + std::to_string(std::llround(phy.bandwidth_hz / 1e6)) + ", BAND_5GHZ, 0}"});
  }
  config.preamble_detection.push_back({"MinimumRssi", number_text(phy.cca_threshold_dbm)});
  config.preamble_detection.push_back({"Threshold", number_text(phy.preamble_snr_db)});
}

// AODV's times that the aodv plugin derives from the others when given as 0, derived the same
// way (RFC 3561 section 10) and in the same whole nanoseconds (aodv_parameters.cpp): ns-3 keeps
// fixed defaults for them whatever the others are.
std::vector<std::pair<std::string, SimTime>> aodv_derived_times(const ParamSet& params) {
  const auto given_or = [&](const char* name, SimTime derived) {
    const SimTime value = from_seconds(params.real(name));
    return value == kTimeZero ? derived : value;
  };
  const SimTime node_traversal = from_seconds(params.real("node_traversal_time_s"));
  const SimTime active_route = from_seconds(params.real("active_route_timeout_s"));
  const SimTime hello = from_seconds(params.real("hello_interval_s"));
  const SimTime net_traversal =
      given_or("net_traversal_time_s", 2 * node_traversal * params.integer("net_diameter"));
  const SimTime path_discovery = given_or("path_discovery_time_s", 2 * net_traversal);
  const std::int64_t retries = std::max<std::int64_t>(params.integer("rreq_retries"), 1);
  return {
      {"NetTraversalTime", net_traversal},
      {"PathDiscoveryTime", path_discovery},
      {"NextHopWait", given_or("next_hop_wait_s", node_traversal + from_seconds(0.01))},
      {"MyRouteTimeout",
       given_or("my_route_timeout_s", 2 * std::max(path_discovery, active_route))},
      {"BlackListTimeout", given_or("blacklist_timeout_s", net_traversal * retries)},
      {"DeletePeriod", given_or("delete_period_s", 5 * std::max(active_route, hello))},
  };
}

void map_routing(const NetworkSettings& settings, ns3engine::Config& config) {
  const PluginChoice& routing = settings.network.routing;
  const Ns3Counterpart& counterpart = counterpart_of(kNs3Routing, routing, "routing");
  const Ns3Options& options = settings.network.ns3;
  if (options.ip_routing != "none" && counterpart.plugin != "direct") {
    throw std::invalid_argument("network.ns3.ip_routing needs the `direct` routing plugin");
  }
  if (counterpart.plugin == "flooding") {
    config.routing = ns3engine::Routing::flooding;
    config.flooding.ttl = static_cast<std::uint32_t>(routing.params.integer("ttl"));
    config.flooding.jitter_max_s = routing.params.real("jitter_max_s");
    config.flooding.cache_size = static_cast<std::uint32_t>(routing.params.integer("cache_size"));
    return;
  }
  if (counterpart.plugin == "aodv") {
    config.routing = ns3engine::Routing::aodv;
    for (const auto& row : counterpart.params) {
      if (row.conversion == Ns3Conversion::special) continue;
      config.routing_attributes.push_back(
          {std::string(row.attribute),
           attribute_text(routing.params.values().at(std::string(row.param)), row.conversion)});
    }
    for (const auto& [attribute, time] : aodv_derived_times(routing.params)) {
      config.routing_attributes.push_back({attribute, std::to_string(time.count()) + "ns"});
    }
    return;
  }
  if (options.ip_routing == "olsr") {
    config.routing = ns3engine::Routing::olsr;
    config.routing_attributes = {{"HelloInterval", time_text(options.olsr_hello_interval_s)},
                                 {"TcInterval", time_text(options.olsr_tc_interval_s)}};
  } else if (options.ip_routing == "dsdv") {
    config.routing = ns3engine::Routing::dsdv;
    config.routing_attributes = {
        {"PeriodicUpdateInterval", time_text(options.dsdv_periodic_update_interval_s)},
        {"SettlingTime", time_text(options.dsdv_settling_time_s)}};
  } else {
    config.routing = ns3engine::Routing::direct;
  }
}

}  // namespace

ns3engine::Config ns3_config_for(const NetworkSettings& settings) {
  ns3engine::Config config;
  config.nodes = settings.nodes;
  config.run = settings.seed;
  config.standard = settings.network.ns3.standard;
  for (const auto& stage : settings.network.propagation) {
    config.loss_chain.push_back(loss_model(stage));
  }
  map_phy(settings.network.phy, config);
  config.error_rate_model.type_id = error_rate_model_type(settings.network.ns3.error_rate_model);
  config.arp = arp_mode(settings);
  map_mac(settings, config);
  map_routing(settings, config);
  return config;
}

}  // namespace swarmnet
