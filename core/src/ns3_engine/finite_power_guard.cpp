#include "ns3_engine/finite_power_guard.hpp"

#include <cmath>

namespace swarmnet::ns3engine {

ns3::TypeId FinitePowerGuard::GetTypeId() {
  // Registered once per process, as MessageTag's (message_tag.cpp).
  static const ns3::TypeId tid = [] {
    constexpr const char* kName = "swarmnet::ns3engine::FinitePowerGuard";
    ns3::TypeId existing;
    if (ns3::TypeId::LookupByNameFailSafe(kName, &existing)) return existing;
    return ns3::TypeId(kName)
        .SetParent<ns3::PropagationLossModel>()
        .SetGroupName("SwarmNet")
        .AddConstructor<FinitePowerGuard>();
  }();
  return tid;
}

double FinitePowerGuard::DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> /*a*/,
                                       ns3::Ptr<ns3::MobilityModel> /*b*/) const {
  return std::isfinite(tx_power_dbm) ? tx_power_dbm : kNoPowerDbm;
}

int64_t FinitePowerGuard::DoAssignStreams(int64_t /*stream*/) { return 0; }

}  // namespace swarmnet::ns3engine
