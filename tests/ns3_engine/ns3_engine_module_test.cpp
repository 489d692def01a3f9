// The ns-3 engine module as the kernel sees it: loaded with dlopen, two entry points, the
// boundary header (ns3_engine_api.hpp) and nothing else.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "ns3_engine/ns3_engine_api.hpp"

namespace swarmnet::ns3engine {
namespace {

using VersionFunction = std::uint32_t (*)();
using CreateFunction = Network* (*)(const Config&);

void* module() {
  static void* handle = [] {
    // Never closed: ns-3's libraries keep process-wide registries.
    void* opened = dlopen(SWARMNET_NS3_ENGINE_MODULE, RTLD_NOW | RTLD_LOCAL);
    if (opened == nullptr) ADD_FAILURE() << dlerror();
    return opened;
  }();
  return handle;
}

Config two_nodes() {
  Config config;
  config.nodes = 2;
  config.loss_chain = {{"ns3::LogDistancePropagationLossModel", {{"Exponent", "3"}}}};
  config.rate_manager = {"ns3::ConstantRateWifiManager", {{"DataMode", "OfdmRate6Mbps"}}};
  return config;
}

TEST(Ns3EngineModule, ExportsItsEntryPointsOnly) {
  ASSERT_NE(module(), nullptr);
  const auto version =
      reinterpret_cast<VersionFunction>(dlsym(module(), "swarmnet_ns3_engine_api_version"));
  ASSERT_NE(version, nullptr);
  EXPECT_EQ(version(), kApiVersion);
  EXPECT_NE(dlsym(module(), "swarmnet_ns3_engine_create"), nullptr);
  // The model's own symbols stay inside (ns3_engine.map).
  EXPECT_EQ(dlsym(module(), "_ZN8swarmnet9ns3engine10Ns3NetworkC1ERKNS0_6ConfigE"), nullptr);
}

TEST(Ns3EngineModule, CreatesANetworkAndThrowsAcrossTheBoundary) {
  ASSERT_NE(module(), nullptr);
  const auto create =
      reinterpret_cast<CreateFunction>(dlsym(module(), "swarmnet_ns3_engine_create"));
  ASSERT_NE(create, nullptr);
  Config bad = two_nodes();
  bad.loss_chain[0].type_id = "ns3::NoSuchModel";
  try {
    delete create(bad);
    ADD_FAILURE() << "a bad TypeId was accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("ns3::NoSuchModel"), std::string::npos);
  }
  // 802.11n: its channel settings are checked through ns-3's own value types (RTTI across the
  // module's boundary, whose symbols are all local).
  Config config = two_nodes();
  config.standard = "80211n";
  config.rate_manager.attributes = {{"DataMode", "HtMcs0"}, {"ControlMode", "HtMcs0"}};
  const std::unique_ptr<Network> network(create(config));
  Message message;
  message.message_id = 42;
  message.source = 0;
  message.destination = kBroadcastNode;
  message.inject_ns = 1'000'000;
  message.payload = {1, 2, 3};
  std::vector<Arrival> arrivals;
  network->run_window(10'000'000, {0.0, 0.0, 10.0, 0.0}, {message}, arrivals);
  ASSERT_EQ(arrivals.size(), 1U);
  EXPECT_EQ(arrivals[0].message_id, 42U);
  EXPECT_EQ(arrivals[0].receiver, 1U);
  EXPECT_GT(network->report().events, 0U);
}

}  // namespace
}  // namespace swarmnet::ns3engine
