// The last model of every loss chain. ns-3 checks few model parameters, and a model given one it
// cannot use (a negative distance, a zero loss ratio) computes a received power that is NaN or
// infinite, on which the PHY crashes later. Here a power that is not a finite number becomes
// one far too weak to receive; any other passes unchanged.
#pragma once

#include <ns3/propagation-loss-model.h>

namespace swarmnet::ns3engine {

class FinitePowerGuard final : public ns3::PropagationLossModel {
 public:
  static constexpr double kNoPowerDbm = -1000.0;

  static ns3::TypeId GetTypeId();

 private:
  double DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override;
  int64_t DoAssignStreams(int64_t stream) override;
};

}  // namespace swarmnet::ns3engine
