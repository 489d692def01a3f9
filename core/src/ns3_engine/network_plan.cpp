#include "ns3_engine/network_plan.hpp"

#include <ns3/aodv-routing-protocol.h>
#include <ns3/dsdv-routing-protocol.h>
#include <ns3/enum.h>
#include <ns3/error-rate-model.h>
#include <ns3/olsr-routing-protocol.h>
#include <ns3/preamble-detection-model.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/qos-txop.h>
#include <ns3/queue-size.h>
#include <ns3/tuple.h>
#include <ns3/txop.h>
#include <ns3/uinteger.h>
#include <ns3/wifi-mac-queue.h>
#include <ns3/wifi-mode.h>
#include <ns3/wifi-phy-operating-channel.h>
#include <ns3/wifi-remote-station-manager.h>
#include <ns3/yans-wifi-phy.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

namespace swarmnet::ns3engine {

namespace {

constexpr std::uint32_t kMaxNodes = 65534;  // hosts of the engine's 10.1.0.0/16

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("ns-3 engine: " + what);
}

ns3::WifiStandard standard_of(const std::string& name) {
  if (name == "80211a") return ns3::WIFI_STANDARD_80211a;
  if (name == "80211b") return ns3::WIFI_STANDARD_80211b;
  if (name == "80211g") return ns3::WIFI_STANDARD_80211g;
  if (name == "80211n") return ns3::WIFI_STANDARD_80211n;
  if (name == "80211ac") return ns3::WIFI_STANDARD_80211ac;
  fail("standard " + name + ": unknown (80211a, 80211b, 80211g, 80211n or 80211ac)");
}

struct ChannelChoice {
  ns3::WifiPhyBand band;
  std::uint16_t width_mhz;
};

// The PHY's channel for ChannelSettings `settings`, which must name exactly one channel of
// `standard` (ns-3 throws or aborts at install otherwise). Mirrors WifiPhy::DoChannelSwitch.

ChannelChoice checked_channel(const CheckedAttribute& settings, const Attribute& text,
                              ns3::WifiStandard standard) {
  using ChannelValue =
      ns3::TupleValue<ns3::UintegerValue, ns3::UintegerValue, ns3::EnumValue, ns3::UintegerValue>;
  const std::string type = ns3::YansWifiPhy::GetTypeId().GetName();
  const auto value = ns3::DynamicCast<ChannelValue>(settings.value);
  if (!value) reject_attribute(type, text, "not a channel tuple");
  const auto [number_value, width_value, band_value, primary20] = value->Get();
  auto number = static_cast<std::uint8_t>(number_value);
  auto width = static_cast<std::uint16_t>(width_value);
  auto band = static_cast<ns3::WifiPhyBand>(band_value);
  if (band == ns3::WIFI_PHY_BAND_UNSPECIFIED) band = ns3::GetDefaultPhyBand(standard);
  const auto& bands = ns3::wifiStandards.at(standard);
  if (std::find(bands.begin(), bands.end(), band) == bands.end()) {
    reject_attribute(type, text, "a band the standard does not use");
  }
  if (width == 0 && number == 0) width = ns3::GetDefaultChannelWidth(standard, band);
  if (number == 0) {
    try {
      number = ns3::WifiPhyOperatingChannel::GetDefaultChannelNumber(width, standard, band);
    } catch (const std::runtime_error&) {
      reject_attribute(type, text, "the standard has no channel of that width in that band");
    }
  }
  using Channel = ns3::WifiPhyOperatingChannel;
  const auto first = Channel::FindFirst(number, 0, width, standard, band);
  if (first == Channel::m_frequencyChannels.end() ||
      Channel::FindFirst(number, 0, width, standard, band, std::next(first)) !=
          Channel::m_frequencyChannels.end()) {
    reject_attribute(type, text, "names no single channel of the standard in that band");
  }
  const std::uint16_t channel_width = std::get<2>(*first);
  if (primary20 > 0 && primary20 >= channel_width / 20U) {
    reject_attribute(type, text, "primary20 index beyond the channel's 20 MHz subchannels");
  }
  return {band, channel_width};
}

// The modulation classes a PHY of `standard` in `band` has (WifiPhy::ConfigureStandard): a mode
// of another class aborts ns-3 when a frame is sent with it.
std::vector<ns3::WifiModulationClass> modulation_classes(ns3::WifiStandard standard,
                                                         ns3::WifiPhyBand band) {
  using C = ns3::WifiModulationClass;
  std::vector<C> a = {ns3::WIFI_MOD_CLASS_OFDM};
  std::vector<C> b = {ns3::WIFI_MOD_CLASS_DSSS, ns3::WIFI_MOD_CLASS_HR_DSSS};
  std::vector<C> g = b;
  g.push_back(ns3::WIFI_MOD_CLASS_ERP_OFDM);
  std::vector<C> n = band == ns3::WIFI_PHY_BAND_2_4GHZ ? g : a;
  n.push_back(ns3::WIFI_MOD_CLASS_HT);
  std::vector<C> ac = n;
  ac.push_back(ns3::WIFI_MOD_CLASS_VHT);
  switch (standard) {
    case ns3::WIFI_STANDARD_80211a:
      return a;
    case ns3::WIFI_STANDARD_80211b:
      return b;
    case ns3::WIFI_STANDARD_80211g:
      return g;
    case ns3::WIFI_STANDARD_80211n:
      return n;
    default:
      return ac;
  }
}

// Every Wi-Fi mode the rate manager will use must be one the PHY has: each value given, or the
// default of a mode attribute of the manager's own (WifiRemoteStationManager's NonUnicastMode
// defaults to "unset").
void check_rate_modes(const ObjectSpec& spec, const Plan& plan, const std::string& standard) {
  const ns3::TypeId base = ns3::WifiRemoteStationManager::GetTypeId();
  const auto classes = modulation_classes(plan.standard, plan.band);
  const ns3::TypeId manager = plan.rate_manager.GetTypeId();
  const auto check = [&](const Attribute& attribute, bool given) {
    const auto mode_class = wifi_mode_class(attribute.value);
    if (mode_class && std::find(classes.begin(), classes.end(), *mode_class) == classes.end()) {
      reject_attribute(manager.GetName(), attribute,
                       "a mode the 802." + standard.substr(3) + " PHY does not have" +
                           (given ? "" : " (the default; name one)"));
    }
  };
  for (ns3::TypeId tid = manager;; tid = tid.GetParent()) {
    for (std::size_t i = 0; i < tid.GetAttributeN(); ++i) {
      const ns3::TypeId::AttributeInformation info = tid.GetAttribute(i);
      if (!ns3::DynamicCast<const ns3::WifiModeChecker>(info.checker)) continue;
      bool given = false;
      for (const Attribute& attribute : spec.attributes) {
        if (attribute.name != info.name) continue;
        given = true;
        check(attribute, true);
      }
      if (!given && tid != base) {
        check({info.name, info.initialValue->SerializeToString(info.checker)}, false);
      }
    }
    if (tid == base || tid.GetParent() == tid) break;
  }
}

// ns-3's rate managers from before 802.11n end the process when the PHY has HT rates.
void check_rate_manager_for_ht(const Plan& plan, const std::string& standard) {
  static const char* const kWithoutHt[] = {
      "ns3::AarfWifiManager",     "ns3::AarfcdWifiManager", "ns3::AmrrWifiManager",
      "ns3::AparfWifiManager",    "ns3::ArfWifiManager",    "ns3::CaraWifiManager",
      "ns3::MinstrelWifiManager", "ns3::OnoeWifiManager",   "ns3::ParfWifiManager",
      "ns3::RraaWifiManager",     "ns3::RrpaaWifiManager"};
  if (plan.standard < ns3::WIFI_STANDARD_80211n) return;
  const std::string manager = plan.rate_manager.GetTypeId().GetName();
  for (const char* name : kWithoutHt) {
    if (manager == name) {
      fail(manager + ": has no HT rates, which the 802." + standard.substr(3) +
           " PHY has (rate_manager)");
    }
  }
}

// The value the object will have for `name`: the last one given, else the TypeId's default.
std::uint64_t effective_count(const ns3::TypeId& tid, const std::vector<CheckedAttribute>& given,
                              const std::string& name) {
  for (auto attribute = given.rbegin(); attribute != given.rend(); ++attribute) {
    if (attribute->name != name) continue;
    if (const auto count = ns3::DynamicCast<ns3::UintegerValue>(attribute->value)) {
      return count->Get();
    }
  }
  ns3::TypeId::AttributeInformation info;
  tid.LookupAttributeByName(name, &info);
  const auto count = ns3::DynamicCast<const ns3::UintegerValue>(info.initialValue);
  return count ? count->Get() : 0;
}

// ns-3's AODV aborts when an expanding-ring search reaches a TTL beyond NetDiameter before
// NetDiameter itself (ScheduleRreqRetry): TtlStart and TtlThreshold may not exceed it.
void check_aodv_ttls(const Plan& plan) {
  const ns3::TypeId aodv = ns3::aodv::RoutingProtocol::GetTypeId();
  const std::uint64_t diameter = effective_count(aodv, plan.routing, "NetDiameter");
  for (const char* name : {"TtlStart", "TtlThreshold"}) {
    const std::uint64_t ttl = effective_count(aodv, plan.routing, name);
    if (ttl > diameter) {
      fail(aodv.GetName() + ": " + name + " " + std::to_string(ttl) + " exceeds NetDiameter " +
           std::to_string(diameter));
    }
  }
}

void check_flooding(const FloodingParams& params) {
  if (params.ttl < 1 || params.ttl > 255) {
    fail("flooding: ttl " + std::to_string(params.ttl) + " outside [1, 255]");
  }
  if (!std::isfinite(params.jitter_max_s) || params.jitter_max_s < 0.0 ||
      params.jitter_max_s > 1e6) {
    fail("flooding: jitter_max_s " + std::to_string(params.jitter_max_s) + " outside [0, 1e6] s");
  }
  if (params.cache_size < 1) fail("flooding: cache_size must be at least 1");
}

}  // namespace

Plan make_plan(const Config& config) {
  if (config.nodes < 1 || config.nodes > kMaxNodes) {
    fail("nodes " + std::to_string(config.nodes) + " outside [1, " + std::to_string(kMaxNodes) +
         "]");
  }
  Plan plan;
  plan.standard = standard_of(config.standard);
  plan.qos = plan.standard >= ns3::WIFI_STANDARD_80211n;

  if (config.loss_chain.empty()) fail("loss_chain is empty: the channel needs a loss model");
  for (std::size_t i = 0; i < config.loss_chain.size(); ++i) {
    plan.loss_chain.push_back(checked_factory(config.loss_chain[i],
                                              ns3::PropagationLossModel::GetTypeId(),
                                              "loss_chain[" + std::to_string(i) + "]"));
  }

  const ns3::TypeId phy = ns3::YansWifiPhy::GetTypeId();
  plan.band = ns3::GetDefaultPhyBand(plan.standard);
  std::uint16_t width_mhz = ns3::GetDefaultChannelWidth(plan.standard, plan.band);
  std::vector<Attribute> phy_attributes = config.phy;
  const auto has_channel = [](const Attribute& a) { return a.name == "ChannelSettings"; };
  if (plan.standard == ns3::WIFI_STANDARD_80211n &&
      std::none_of(phy_attributes.begin(), phy_attributes.end(), has_channel)) {
    // 802.11n defaults to 2.4 GHz in ns-3; the engine's 802.11n is the 5 GHz one.
    phy_attributes.insert(phy_attributes.begin(), {"ChannelSettings", "{0, 0, BAND_5GHZ, 0}"});
  }
  for (const Attribute& attribute : phy_attributes) {
    plan.phy.push_back(checked_attribute(phy, attribute, ns3::TypeId::ATTR_CONSTRUCT));
    if (has_channel(attribute)) {
      const ChannelChoice channel = checked_channel(plan.phy.back(), attribute, plan.standard);
      plan.band = channel.band;
      width_mhz = channel.width_mhz;
    }
    // The standard's own values overwrite these when it is configured at install.
    if (attribute.name == "Slot" || attribute.name == "Sifs" || attribute.name == "Pifs") {
      plan.phy_after_install.push_back(checked_attribute(phy, attribute, ns3::TypeId::ATTR_SET));
    }
  }
  // Before each access on a channel wider than 20 MHz ns-3 asks which secondary channels were
  // idle for PIFS, and aborts when the access comes sooner (SIFS + AIFSN slots < PIFS): such
  // channels keep the standard's own timing, which cannot.
  for (const Attribute& attribute : phy_attributes) {
    if (width_mhz > 20 &&
        (attribute.name == "Slot" || attribute.name == "Sifs" || attribute.name == "Pifs")) {
      reject_attribute(phy.GetName(), attribute,
                       "the engine keeps the standard's timing on a channel of " +
                           std::to_string(width_mhz) + " MHz");
    }
  }
  plan.preamble_detection =
      checked_factory({"ns3::ThresholdPreambleDetectionModel", config.preamble_detection},
                      ns3::PreambleDetectionModel::GetTypeId(), "preamble_detection");

  if (!config.error_rate_model.type_id.empty()) {
    plan.error_rate_model = checked_factory(config.error_rate_model,
                                            ns3::ErrorRateModel::GetTypeId(), "error_rate_model");
  }

  if (config.rate_manager.type_id.empty()) fail("rate_manager: no TypeId given");
  plan.rate_manager = checked_factory(config.rate_manager,
                                      ns3::WifiRemoteStationManager::GetTypeId(), "rate_manager");
  check_rate_manager_for_ht(plan, config.standard);
  check_rate_modes(config.rate_manager, plan, config.standard);

  const ns3::TypeId txop = plan.qos ? ns3::QosTxop::GetTypeId() : ns3::Txop::GetTypeId();
  plan.txop = checked_attributes(txop, config.txop, ns3::TypeId::ATTR_SET);
  plan.mac_queue =
      checked_attributes(ns3::WifiMacQueue::GetTypeId(), config.mac_queue, ns3::TypeId::ATTR_SET);
  for (std::size_t i = 0; i < plan.mac_queue.size(); ++i) {
    // Only asserted by ns-3: a size in bytes would be compared with a count of packets.
    const auto size = ns3::DynamicCast<ns3::QueueSizeValue>(plan.mac_queue[i].value);
    if (size && size->Get().GetUnit() != ns3::QueueSizeUnit::PACKETS) {
      reject_attribute(ns3::WifiMacQueue::GetTypeId().GetName(), config.mac_queue[i],
                       "a WifiMacQueue holds a number of packets (e.g. 100p)");
    }
  }

  ns3::TypeId routing;
  switch (config.routing) {
    case Routing::aodv:
      routing = ns3::aodv::RoutingProtocol::GetTypeId();
      break;
    case Routing::olsr:
      routing = ns3::olsr::RoutingProtocol::GetTypeId();
      break;
    case Routing::dsdv:
      routing = ns3::dsdv::RoutingProtocol::GetTypeId();
      break;
    case Routing::flooding:
      check_flooding(config.flooding);
      [[fallthrough]];
    case Routing::direct:
      if (!config.routing_attributes.empty()) {
        fail("routing_attributes: routing direct and flooding have no ns-3 routing protocol");
      }
      return plan;
    default:
      fail("routing " + std::to_string(static_cast<int>(config.routing)) + ": unknown");
  }
  plan.routing =
      checked_attributes(routing, config.routing_attributes, ns3::TypeId::ATTR_CONSTRUCT);
  if (config.routing == Routing::aodv) check_aodv_ttls(plan);
  return plan;
}

}  // namespace swarmnet::ns3engine
