// ns-3's names for the Wi-Fi modes (WifiMode) of each standard, and the mode that carries a
// SwarmNet MAC's bit rate: what `network.ns3.data_mode` may name and what data_rate_bps becomes.
#pragma once

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace swarmnet {

// Whether `standard` names a Wi-Fi standard the ns-3 engine maps (network.ns3.standard's
// choices in scenario_schema.cpp).
inline bool ns3_standard_known(std::string_view standard) {
  return standard == "80211a" || standard == "80211b" || standard == "80211g" ||
         standard == "80211n" || standard == "80211ac";
}

// The constant-rate mode of `standard` ("80211a", ...) sending `bps`, or nothing when the
// standard has no such rate (802.11n and ac are named by MCS: no mode is derived for them).
inline std::optional<std::string> ns3_mode_for_rate(std::string_view standard, double bps) {
  const double mbps = bps / 1e6;
  const auto whole = [&](std::initializer_list<int> rates) -> std::optional<int> {
    for (const int rate : rates) {
      if (std::fabs(mbps - rate) < 1e-9) return rate;
    }
    return std::nullopt;
  };
  if (standard == "80211a" || standard == "80211g") {
    const auto rate = whole({6, 9, 12, 18, 24, 36, 48, 54});
    if (!rate) return std::nullopt;
    return std::string(standard == "80211a" ? "OfdmRate" : "ErpOfdmRate") + std::to_string(*rate) +
           "Mbps";
  }
  if (standard == "80211b") {
    if (std::fabs(mbps - 5.5) < 1e-9) return std::string("DsssRate5_5Mbps");
    const auto rate = whole({1, 2, 11});
    if (!rate) return std::nullopt;
    return "DsssRate" + std::to_string(*rate) + "Mbps";
  }
  return std::nullopt;
}

// True when `mode` is a WifiMode ns-3.37 defines for `standard`.
inline bool ns3_mode_known(std::string_view standard, const std::string& mode) {
  const auto one_of_rates = [&](const char* prefix, std::initializer_list<const char*> rates) {
    for (const char* rate : rates) {
      if (mode == std::string(prefix) + rate + "Mbps") return true;
    }
    return false;
  };
  const auto mcs = [&](const char* prefix, int last) {
    for (int i = 0; i <= last; ++i) {
      if (mode == prefix + std::to_string(i)) return true;
    }
    return false;
  };
  const bool ofdm = one_of_rates("OfdmRate", {"6", "9", "12", "18", "24", "36", "48", "54"});
  const bool dsss = one_of_rates("DsssRate", {"1", "2", "5_5", "11"});
  const bool erp = one_of_rates("ErpOfdmRate", {"6", "9", "12", "18", "24", "36", "48", "54"});
  if (standard == "80211a") return ofdm;
  if (standard == "80211b") return dsss;
  if (standard == "80211g") return erp || dsss;
  if (standard == "80211n") return ofdm || mcs("HtMcs", 31);
  if (standard == "80211ac") return ofdm || mcs("HtMcs", 31) || mcs("VhtMcs", 9);
  return false;
}

}  // namespace swarmnet
