#include "scenario/ns3_engine_check.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "network/network_settings.hpp"
#include "ns3_host/ns3_counterparts.hpp"
#include "ns3_host/ns3_wifi_modes.hpp"
#include "scenario/shown_value.hpp"

namespace swarmnet {

namespace {

// A key a check can point at, with the facts about it the checks need.
class KeyFacts {
 public:
  KeyFacts(const YAML::Node& tree, const ScenarioChecker& checker, ProblemList& problems,
           PluginLoader& loader)
      : tree_(tree), checker_(checker), problems_(problems), loader_(loader) {}

  // True when the file or a command-line option gave the value at `path`. A resolved scenario
  // (what a network half validates again) gives every value, so checks that must pass on it
  // compare values with their defaults instead (differs_from_default).
  [[nodiscard]] bool given(const KeyPath& path) const {
    return checker_.given(path) || problems_.overridden(path);
  }

  // True when plugin parameter `param` of the plugin at `plugin_path` differs from the plugin's
  // default.
  [[nodiscard]] bool differs_from_default(const KeyPath& plugin_path, const std::string& param) {
    const auto choice = checker_.plugins().find(plugin_path.text());
    if (choice == checker_.plugins().end() || !choice->second.params.contains(param)) return false;
    const auto library = loader_.find(choice->second.name);
    if (!library) return false;
    for (const auto& spec : library->info().params) {
      if (spec.name == param)
        return !(choice->second.params.values().at(param) == spec.default_value);
    }
    return false;
  }

  // True when the real value at `path` is present and differs from `fallback`.
  [[nodiscard]] bool real_differs(const KeyPath& path, double fallback) const {
    const YAML::Node node = at(path);
    if (!node.IsDefined() || !node.IsScalar()) return false;
    const std::string text = node.as<std::string>();
    if (text == "true" || text == "false") return (text == "true" ? 1.0 : 0.0) != fallback;
    return node.as<double>() != fallback;
  }
  // The checked value at `path`, or an undefined node when it is absent or was invalid.
  [[nodiscard]] YAML::Node at(const KeyPath& path) const {
    return checked_node_at(tree_, path).value_or(YAML::Node(YAML::NodeType::Undefined));
  }
  [[nodiscard]] std::string text(const KeyPath& path) const {
    const YAML::Node node = at(path);
    return node.IsDefined() && node.IsScalar() ? node.as<std::string>() : "";
  }
  void refuse(const KeyPath& path, const std::string& what, const std::string& expected) {
    problems_.add(path, checker_.mark_of(path), what, expected);
  }

 private:
  const YAML::Node& tree_;
  const ScenarioChecker& checker_;
  ProblemList& problems_;
  PluginLoader& loader_;
};

// `value` as the scenario would write it: a boolean when the scenario's value is one.
std::string format_fixed(double value, const std::string& written) {
  if (written == "true" || written == "false") return value != 0.0 ? "true" : "false";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

// "'aodv' parameter data_ttl", as refusals name a plugin's parameter.
std::string plugin_parameter(const std::string& plugin, const std::string& param) {
  std::string text = "'";
  text.append(plugin).append("' parameter ").append(param);
  return text;
}

std::string names_of(std::span<const Ns3Counterpart> table) {
  std::string names;
  for (const auto& entry : table) names += (names.empty() ? "" : ", ") + std::string(entry.plugin);
  return names;
}

// A plugin key: its plugin must have a counterpart, and every parameter given must map.
const Ns3Counterpart* check_plugin(KeyFacts& keys, const KeyPath& path,
                                   std::span<const Ns3Counterpart> table, const char* kind) {
  const std::string name = keys.text(path / "plugin");
  if (name.empty()) return nullptr;  // invalid: already reported
  const Ns3Counterpart* counterpart = find_ns3_counterpart(table, name);
  if (counterpart == nullptr) {
    keys.refuse(path / "plugin",
                "the " + std::string(kind) + " plugin '" + name +
                    "' has no ns-3 counterpart (network.engine: ns3)",
                "one of " + names_of(table) + " (docs/ns3-engine.md), or network.engine: native");
    return nullptr;
  }
  const YAML::Node params = keys.at(path / "params");
  if (!params.IsDefined() || !params.IsMap()) return counterpart;
  for (const auto& entry : params) {
    const std::string param = entry.first.as<std::string>();
    const KeyPath param_path = path / "params" / param;
    if (const Ns3FixedBehaviour* fixed = find_ns3_fixed_behaviour(name, param)) {
      if (keys.real_differs(param_path, fixed->value)) {
        // A default is the engine's choice to answer for, a value given is the user's.
        const bool given = keys.given(param_path);
        std::string what = plugin_parameter(name, param);
        what += " is ";
        what += keys.text(param_path);
        if (!given) what += " (its default)";
        what += ", but ";
        what += fixed->behaviour;
        keys.refuse(given ? param_path : KeyPath({"network", "engine"}), what,
                    param + ": " + format_fixed(fixed->value, keys.text(param_path)) + " in " +
                        path.text() + ".params with network.engine: ns3");
      }
      continue;
    }
    if (find_ns3_attribute(*counterpart, param) == nullptr &&
        keys.differs_from_default(path, param)) {
      keys.refuse(param_path, plugin_parameter(name, param).append(" has no ns-3 counterpart"),
                  "its default with network.engine: ns3 (docs/ns3-engine.md lists what maps)");
    }
  }
  return counterpart;
}

void check_propagation(KeyFacts& keys) {
  const KeyPath list({"network", "propagation"});
  const YAML::Node stages = keys.at(list);
  if (!stages.IsDefined() || !stages.IsSequence()) return;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const KeyPath stage = list / i;
    const Ns3Counterpart* counterpart = check_plugin(keys, stage, kNs3Propagation, "propagation");
    if (counterpart == nullptr || counterpart->plugin != "two_ray_ground") continue;
    const YAML::Node params = keys.at(stage / "params");
    if (params.IsDefined() && params["tx_height_m"] && params["rx_height_m"] &&
        params["tx_height_m"].as<double>() != params["rx_height_m"].as<double>()) {
      keys.refuse(
          stage / "params" / "rx_height_m",
          "ns-3's TwoRayGroundPropagationLossModel has one antenna height for both ends",
          "rx_height_m equal to tx_height_m (" + params["tx_height_m"].as<std::string>() + ")");
    }
  }
}

void check_phy(KeyFacts& keys) {
  const KeyPath phy({"network", "phy"});
  if (keys.text(phy / "model") != "sinr") {
    keys.refuse(keys.given(phy / "model") ? phy / "model" : KeyPath({"network", "engine"}),
                "ns-3's YansWifiPhy receives by SINR; the threshold model has no ns-3 "
                "counterpart",
                "network.phy.model: sinr with network.engine: ns3");
  }
  const PhyConfig defaults;
  for (const auto& [key, fallback] :
       {std::pair{"rx_sensitivity_dbm", defaults.rx_sensitivity_dbm},
        std::pair{"interference_floor_db", defaults.interference_floor_db},
        std::pair{"sensing_floor_db", defaults.sensing_floor_db}}) {
    if (keys.real_differs(phy / key, fallback)) {
      keys.refuse(phy / key, "has no ns-3 counterpart (it tunes SwarmNet's own PHY)",
                  "its default with network.engine: ns3");
    }
  }
  const YAML::Node bandwidth = keys.at(phy / "bandwidth_hz");
  if (bandwidth.IsDefined()) {
    const double hz = bandwidth.as<double>();
    if (hz != 20e6 && hz != 40e6 && hz != 80e6 && hz != 160e6) {
      keys.refuse(phy / "bandwidth_hz",
                  bandwidth.as<std::string>() + " Hz is no Wi-Fi channel width",
                  "20e6, 40e6, 80e6 or 160e6 with network.engine: ns3");
    }
  }
  if (keys.text(phy / "header_failure_cca") == "ns3") {
    keys.refuse(phy / "header_failure_cca",
                "has no ns-3 counterpart (it makes SwarmNet's own PHY do what ns-3.37 does)",
                "its default (sensed) with network.engine: ns3, where ns-3 does it anyway");
  }
  if (keys.text(KeyPath({"network", "channel", "cutoff"})) == "false") {
    keys.refuse(KeyPath({"network", "channel", "cutoff"}),
                "has no ns-3 counterpart (it tunes SwarmNet's own channel)",
                "its default (true) with network.engine: ns3");
  }
  if (keys.text(KeyPath({"network", "channel", "far_signals"})) == "events") {
    keys.refuse(KeyPath({"network", "channel", "far_signals"}),
                "has no ns-3 counterpart (it tunes SwarmNet's own channel)",
                "its default (lazy) with network.engine: ns3");
  }
  if (keys.text(KeyPath({"network", "neighbors", "enabled"})) == "true") {
    keys.refuse(KeyPath({"network", "neighbors", "enabled"}),
                "is not given by the ns-3 engine yet (neighbour tables come from SwarmNet's own "
                "PHY)",
                "false with network.engine: ns3, or network.engine: native");
  }
}

// The MAC's rates must be modes of the standard, unless a mode is named outright.
void check_rates(KeyFacts& keys) {
  const KeyPath ns3({"network", "ns3"});
  const std::string standard = keys.text(ns3 / "standard");
  if (keys.text(ns3 / "rate_manager") != "constant") {
    for (const char* key : {"data_mode", "control_mode"}) {
      if (!keys.text(ns3 / key).empty()) {
        keys.refuse(ns3 / key, "applies only to the constant rate manager",
                    "no value, or network.ns3.rate_manager: constant");
      }
    }
    return;
  }
  const KeyPath params({"network", "mac", "params"});
  for (const auto& [mode_key, rate_key] :
       {std::pair{"data_mode", "data_rate_bps"}, std::pair{"control_mode", "control_rate_bps"}}) {
    const std::string mode = keys.text(ns3 / mode_key);
    if (!mode.empty()) {
      if (!ns3_mode_known(standard, mode)) {
        keys.refuse(ns3 / mode_key,
                    "'" + shown_value(mode) + "' is no WifiMode of 802." + standard.substr(3),
                    "an ns-3 mode name of the standard (docs/ns3-engine.md)");
      }
      continue;
    }
    const YAML::Node rate = keys.at(params / rate_key);
    if (!rate.IsDefined()) continue;
    if (!ns3_mode_for_rate(standard, rate.as<double>())) {
      keys.refuse(keys.given(params / rate_key) ? params / rate_key : ns3 / "standard",
                  "802." + standard.substr(3) + " has no constant mode of " +
                      rate.as<std::string>() + " bit/s",
                  "a rate of the standard, or network.ns3." + std::string(mode_key) +
                      " naming a mode (needed for 802.11n and ac)");
    }
  }
}

// dcf80211's slot, SIFS and contention window are 802.11a's; another standard keeps its own.
void check_standard(KeyFacts& keys) {
  const std::string standard = keys.text(KeyPath({"network", "ns3", "standard"}));
  if (standard == "80211a") return;
  const KeyPath params({"network", "mac", "params"});
  for (const char* key : {"slot_s", "sifs_s", "cw_min", "cw_max"}) {
    if (keys.differs_from_default(KeyPath({"network", "mac"}), key)) {
      keys.refuse(params / key, "802." + standard.substr(3) + " in ns-3 has its own " + key,
                  "its default (or network.ns3.standard: 80211a)");
    }
  }
  const YAML::Node bandwidth = keys.at(KeyPath({"network", "phy", "bandwidth_hz"}));
  if (bandwidth.IsDefined() && bandwidth.as<double>() != 20e6 && standard != "80211n" &&
      standard != "80211ac") {
    keys.refuse(KeyPath({"network", "phy", "bandwidth_hz"}),
                "802." + standard.substr(3) + " channels are 20 MHz wide",
                "20e6, or network.ns3.standard 80211n or 80211ac");
  }
}

void check_routing(KeyFacts& keys) {
  const KeyPath routing({"network", "routing"});
  const Ns3Counterpart* counterpart = check_plugin(keys, routing, kNs3Routing, "routing");
  const KeyPath feedback = routing / "params" / "link_layer_feedback";
  if (counterpart != nullptr && counterpart->plugin == "aodv" && keys.text(feedback) == "false" &&
      keys.text(KeyPath({"network", "arp"})) != "static") {
    keys.refuse(feedback,
                "ns-3's AODV takes layer-2 feedback whenever ARP resolved the neighbour; without "
                "it needs the neighbours' entries filled in before the run",
                "network.arp: static with link_layer_feedback: false");
  }
  const KeyPath ip_routing({"network", "ns3", "ip_routing"});
  const std::string ip = keys.text(ip_routing);
  if (counterpart != nullptr && ip != "none" && counterpart->plugin != "direct") {
    keys.refuse(ip_routing,
                "ns-3's " + ip + " routes IP datagrams, which only the `direct` plugin sends; '" +
                    std::string(counterpart->plugin) + "' routes on its own",
                "network.routing: {plugin: direct} with ip_routing " + ip);
  }
}

void check_output(YAML::Node& tree, KeyFacts& keys) {
  const KeyPath trace({"output", "packet_trace"});
  if (!keys.given(trace)) {
    if (tree["output"] && tree["output"].IsMap()) tree["output"]["packet_trace"] = "false";
  } else if (keys.text(trace) == "true") {
    keys.refuse(trace, "the ns-3 engine writes no packet trace (packets.csv)",
                "false with network.engine: ns3 (summary.json has its counters)");
  }
  const KeyPath frames({"output", "frame_trace"});
  if (keys.given(frames) && keys.text(frames) == "true") {
    keys.refuse(frames, "the ns-3 engine writes no frame trace (frames.csv)",
                "false with network.engine: ns3 (summary.json has the MAC's counters)");
  }
  const KeyPath sensing({"output", "sensing_trace"});
  if (keys.given(sensing) && keys.text(sensing) == "true") {
    keys.refuse(sensing,
                "the ns-3 engine writes no sensing trace (sensing.csv): it gives controllers no "
                "neighbour tables, send reports or route answers",
                "false with network.engine: ns3");
  }
}

}  // namespace

void check_network_engine(YAML::Node& tree, const ScenarioChecker& checker, ProblemList& problems,
                          PluginLoader& loader) {
  KeyFacts keys(tree, checker, problems, loader);
  const KeyPath engine({"network", "engine"});
  if (keys.text(engine) != "ns3") {
    const KeyPath ns3({"network", "ns3"});
    const Ns3Options defaults;
    const std::vector<std::pair<const char*, bool>> set = {
        {"standard", keys.text(ns3 / "standard") != defaults.standard},
        {"rate_manager", keys.text(ns3 / "rate_manager") != defaults.rate_manager},
        {"data_mode", !keys.text(ns3 / "data_mode").empty()},
        {"control_mode", !keys.text(ns3 / "control_mode").empty()},
        {"ip_routing", keys.text(ns3 / "ip_routing") != defaults.ip_routing},
        {"error_rate_model", keys.text(ns3 / "error_rate_model") != defaults.error_rate_model},
        {"olsr_hello_interval_s",
         keys.real_differs(ns3 / "olsr_hello_interval_s", defaults.olsr_hello_interval_s)},
        {"olsr_tc_interval_s",
         keys.real_differs(ns3 / "olsr_tc_interval_s", defaults.olsr_tc_interval_s)},
        {"dsdv_periodic_update_interval_s",
         keys.real_differs(ns3 / "dsdv_periodic_update_interval_s",
                           defaults.dsdv_periodic_update_interval_s)},
        {"dsdv_settling_time_s",
         keys.real_differs(ns3 / "dsdv_settling_time_s", defaults.dsdv_settling_time_s)},
    };
    for (const auto& [key, differs] : set) {
      if (differs) {
        keys.refuse(ns3 / key, "applies only to the ns-3 engine",
                    "network.engine: ns3, or its default");
      }
    }
    return;
  }
  check_propagation(keys);
  check_phy(keys);
  check_plugin(keys, KeyPath({"network", "mac"}), kNs3Mac, "MAC");
  // The schema has refused a standard it does not know; the checks that name the standard in
  // their messages ("802.11g ...") run only on one it knows.
  if (ns3_standard_known(keys.text(KeyPath({"network", "ns3", "standard"})))) {
    check_rates(keys);
    check_standard(keys);
  }
  check_routing(keys);
  check_output(tree, keys);
}

}  // namespace swarmnet
