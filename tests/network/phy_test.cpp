#include "network/phy.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "recording_phy_listener.hpp"

namespace swarmnet {
namespace {

using RecordingListener = test::RecordingPhyListener;

Frame frame_with_uid(std::uint64_t uid) {
  Frame frame;
  frame.uid = uid;
  return frame;
}

TEST(NetworkPhy, ThresholdDecidesAudibility) {
  // The threshold model notices exactly the signals at or above its sensitivity (the channel
  // hands it nothing weaker).
  const PhyConfig config{16.0, -90.0};
  EXPECT_GE(-90.0, audibility_threshold_dbm(config));
  EXPECT_GE(-20.0, audibility_threshold_dbm(config));
  EXPECT_LT(-90.001, audibility_threshold_dbm(config));
  EXPECT_EQ(event_threshold_dbm(config), audibility_threshold_dbm(config));
}

TEST(NetworkPhy, OverlappingFramesAreAllReceivedAndCarrierSenseFollowsThem) {
  RecordingListener listener;
  Phy phy(PhyConfig{16.0, -90.0}, listener);
  EXPECT_EQ(phy.state(), Phy::State::idle);
  EXPECT_FALSE(phy.medium_busy());

  phy.signal_start(1, -50.0);
  EXPECT_EQ(phy.state(), Phy::State::receiving);
  EXPECT_TRUE(phy.medium_busy());
  phy.signal_start(2, -60.0);  // overlaps: no interference in the threshold PHY
  phy.signal_end(frame_with_uid(1), -50.0);
  EXPECT_TRUE(phy.medium_busy());
  phy.signal_end(frame_with_uid(2), -60.0);
  EXPECT_FALSE(phy.medium_busy());
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "rx 1", "idle", "rx 2"}));
  EXPECT_EQ(listener.last_rx.rx_power_dbm, -60.0);
}

TEST(NetworkPhy, OwnTransmissionMakesTheMediumBusyWithoutCallbacks) {
  RecordingListener listener;
  Phy phy(PhyConfig{16.0, -90.0}, listener);
  phy.start_transmission();
  EXPECT_EQ(phy.state(), Phy::State::transmitting);
  EXPECT_TRUE(phy.medium_busy());
  EXPECT_THROW(phy.start_transmission(), std::logic_error);
  phy.signal_start(7, -40.0);  // already busy: no busy callback
  EXPECT_EQ(phy.state(), Phy::State::transmitting);
  phy.end_transmission();
  EXPECT_EQ(phy.state(), Phy::State::receiving);
  EXPECT_TRUE(phy.medium_busy());
  phy.signal_end(frame_with_uid(7), -40.0);
  EXPECT_EQ(phy.state(), Phy::State::idle);
  EXPECT_EQ(listener.log, (std::vector<std::string>{"tx_end", "idle", "rx 7"}));
}

}  // namespace
}  // namespace swarmnet
