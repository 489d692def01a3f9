// A Config checked whole before ns-3 is given any of it, and turned into what the network is
// built from: factories and attribute values ns-3 will take without ending the process. Beyond
// what attribute_check.hpp checks one attribute at a time, this checks what ns-3 aborts on
// later, when values meet: a channel the standard lacks, a rate the PHY lacks, a rate manager
// without the standard's HT rates, AODV TTLs beyond its network diameter, a queue size in bytes,
// a slot too short for the secondary channels of a wide channel.
#pragma once

#include <ns3/object-factory.h>
#include <ns3/wifi-phy-band.h>
#include <ns3/wifi-standards.h>

#include <optional>
#include <vector>

#include "ns3_engine/attribute_check.hpp"
#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet::ns3engine {

struct Plan {
  ns3::WifiStandard standard = ns3::WIFI_STANDARD_UNSPECIFIED;
  ns3::WifiPhyBand band = ns3::WIFI_PHY_BAND_UNSPECIFIED;
  bool qos = false;  // ns-3 gives an 802.11n or later MAC four EDCA queues instead of one Txop
  std::vector<ns3::ObjectFactory> loss_chain;
  std::vector<CheckedAttribute> phy;                // at construction
  std::vector<CheckedAttribute> phy_after_install;  // again after install: the standard's own
                                                    // Slot, Sifs and Pifs overwrite them there
  ns3::ObjectFactory preamble_detection;
  std::optional<ns3::ObjectFactory> error_rate_model;  // none: ns-3's default
  ns3::ObjectFactory rate_manager;
  std::vector<CheckedAttribute> txop;       // on the live Txop (AC_BE's with QoS)
  std::vector<CheckedAttribute> mac_queue;  // on the live WifiMacQueues
  std::vector<CheckedAttribute> routing;    // on the routing helper
};

// Throws std::runtime_error("ns-3 engine: ...") naming the first thing it cannot accept.
Plan make_plan(const Config& config);

}  // namespace swarmnet::ns3engine
