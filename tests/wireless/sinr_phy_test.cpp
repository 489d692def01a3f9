// The SINR PHY: the error-rate model, preamble detection, interference, capture, carrier sense.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "network/nist_error_rate.hpp"
#include "network/phy.hpp"
#include "network/scheduler.hpp"

namespace swarmnet {
namespace {

class RecordingListener final : public PhyListener {
 public:
  void phy_transmit_end() override { log.emplace_back("tx_end"); }
  void phy_receive(const Frame& frame, const RxInfo& info) override {
    log.push_back("rx " + std::to_string(frame.uid));
    last_sinr_db = info.sinr_db;
  }
  void phy_receive_error() override { log.emplace_back("rx_error"); }
  void phy_medium_busy() override { log.emplace_back("busy"); }
  void phy_medium_idle() override { log.emplace_back("idle"); }
  void phy_collision(const Frame& frame) override {
    log.push_back("collision " + std::to_string(frame.uid));
  }
  std::vector<std::string> log;
  double last_sinr_db = 0.0;
};

PhyConfig sinr_config() {
  PhyConfig config;
  config.model = PhyModel::sinr;
  return config;
}

Frame frame(std::uint64_t uid, double rate_bps = 6e6) {
  Frame f;
  f.uid = uid;
  f.bitrate_bps = rate_bps;
  f.header_bytes = 1064;
  return f;
}

constexpr SimTime us(std::int64_t n) { return SimTime{n * 1000}; }
const SimTime kFrameTime = ofdm::frame_duration(1064, ofdm::kModes[0]);

// Schedules a signal from `start` for kFrameTime.
void arrive(Scheduler& scheduler, Phy& phy, std::uint64_t uid, double dbm, SimTime start,
            double rate_bps = 6e6) {
  scheduler.schedule_at(start, [&phy, uid, dbm] { phy.signal_start(uid, dbm); });
  scheduler.schedule_at(start + kFrameTime,
                        [&phy, uid, dbm, rate_bps] { phy.signal_end(frame(uid, rate_bps), dbm); });
}

TEST(WirelessErrorModel, NistCurvesOrderTheRates) {
  // At high SINR everything passes; at 0 dB nothing does; faster rates need more SINR.
  for (const ofdm::Mode& mode : ofdm::kModes) {
    EXPECT_NEAR(chunk_success_rate(mode, std::pow(10.0, 4.0), 8000), 1.0, 1e-9);
    EXPECT_LT(chunk_success_rate(mode, 1.0, 8000), 1e-6);
  }
  const double sinr = std::pow(10.0, 0.6);                           // 6 dB
  EXPECT_GT(chunk_success_rate(ofdm::kModes[0], sinr, 8000), 0.99);  // BPSK 1/2
  EXPECT_LT(chunk_success_rate(ofdm::kModes[7], sinr, 8000), 1e-6);  // 64-QAM 3/4
  // Monotone in SINR and in the number of bits.
  const double at_12db = chunk_success_rate(ofdm::kModes[4], std::pow(10.0, 1.2), 800);
  EXPECT_GT(at_12db, 0.05);
  EXPECT_LT(at_12db, chunk_success_rate(ofdm::kModes[4], std::pow(10.0, 1.4), 800));
  EXPECT_LT(chunk_success_rate(ofdm::kModes[4], std::pow(10.0, 1.2), 8000), at_12db);
}

TEST(WirelessSinrPhy, NoiseFloorAndAudibility) {
  const PhyConfig config = sinr_config();
  EXPECT_NEAR(noise_floor_dbm(config), -174.0 + 73.0103 + 7.0, 1e-3);
  EXPECT_NEAR(audibility_threshold_dbm(config), noise_floor_dbm(config) - 10.0, 1e-12);
}

TEST(WirelessSinrPhy, AFrameAloneIsReceived) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -75.0, us(10));
  scheduler.run_until(us(10) + us(8));
  EXPECT_EQ(phy.state(), Phy::State::receiving);
  scheduler.run_until(us(3000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "rx 1"}));
  EXPECT_NEAR(listener.last_sinr_db, -75.0 - noise_floor_dbm(sinr_config()), 1e-9);
}

TEST(WirelessSinrPhy, AFrameIsLostToInterferenceItWouldSurviveAlone) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -75.0, us(10));
  arrive(scheduler, phy, 2, -77.0, us(500));  // 2 dB weaker, mid-frame
  scheduler.run_until(us(5000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "collision 1", "rx_error", "idle"}));
}

TEST(WirelessSinrPhy, AFrameLostInItsHeaderIsNoReceptionError) {
  // ns-3.37: only a payload failure is a reception error (the MAC's EIFS); interference that
  // destroys the PLCP header (16-20 us after the frame's start) leaves just a busy medium.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -75.0, us(10));
  arrive(scheduler, phy, 2, -70.0, us(10) + us(17));  // after the detection window, in the header
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "collision 1", "idle"}));
}

TEST(WirelessSinrPhy, WeakInterferenceIsTolerated) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -60.0, us(10));
  arrive(scheduler, phy, 2, -85.0, us(500));  // SINR ~25 dB: harmless at 6 Mbit/s
  scheduler.run_until(us(5000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "rx 1"}));
}

TEST(WirelessSinrPhy, NoCaptureOfALaterStrongerFrame) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -80.0, us(10));
  arrive(scheduler, phy, 2, -50.0, us(300));  // 30 dB stronger, but the PHY is locked on 1
  scheduler.run_until(us(5000));
  // Frame 1 drowns, frame 2 was never detected: nothing is received.
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "collision 1", "rx_error", "idle"}));
}

TEST(WirelessSinrPhy, StrongestPreambleInTheDetectionWindowWins) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -80.0, us(10));
  scheduler.schedule_at(us(12), [&] { phy.signal_start(2, -55.0); });  // within 4 us
  scheduler.schedule_at(us(12) + kFrameTime, [&] { phy.signal_end(frame(2), -55.0); });
  scheduler.run_until(us(5000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "rx 2"}));
}

TEST(WirelessSinrPhy, BelowTheDetectionThresholdNothingIsReceivedOrSensed) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -82.5, us(10));
  scheduler.run_until(us(100));
  EXPECT_FALSE(phy.medium_busy());
  EXPECT_EQ(phy.state(), Phy::State::idle);
  scheduler.run_until(us(5000));
  EXPECT_TRUE(listener.log.empty());
}

TEST(WirelessSinrPhy, CarrierSenseUsesTheSumOfTheSignalsAfterTheDetectionWindow) {
  // ns-3.37: CCA is busy while the aggregate of all signals reaches the CCA threshold (-82 dBm),
  // and a new signal is sensed only at the end of its 4 us preamble-detection window.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -84.0, us(10));   // alone: below the threshold, not detected
  arrive(scheduler, phy, 2, -84.0, us(100));  // together: -81 dBm
  scheduler.run_until(us(50));
  EXPECT_FALSE(phy.medium_busy());
  scheduler.run_until(us(102));
  EXPECT_FALSE(phy.medium_busy());  // signal 2 is still in its detection window
  scheduler.run_until(us(105));
  EXPECT_TRUE(phy.medium_busy());
  EXPECT_EQ(phy.state(), Phy::State::busy);
  scheduler.run_until(us(10) + kFrameTime + us(1));  // signal 1 ended: -84 dBm left
  EXPECT_FALSE(phy.medium_busy());
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle"}));
}

TEST(WirelessSinrPhy, EnergyDetectionMakesTheMediumBusyWithoutAFrame) {
  Scheduler scheduler;
  RecordingListener listener;
  PhyConfig config = sinr_config();
  Phy phy(config, listener, &scheduler, 1);
  phy.start_transmission();
  phy.signal_start(1, -55.0);  // arrives while transmitting: never decoded
  phy.end_transmission();
  EXPECT_TRUE(phy.medium_busy());  // -55 dBm >= -62 dBm
  EXPECT_EQ(phy.state(), Phy::State::busy);
  phy.signal_end(frame(1), -55.0);
  EXPECT_FALSE(phy.medium_busy());
  EXPECT_EQ(listener.log, (std::vector<std::string>{"tx_end", "idle"}));
}

TEST(WirelessSinrPhy, HigherRatesNeedMoreSinr) {
  // A 54 Mbit/s frame at 15 dB SNR fails, a 6 Mbit/s frame at the same power succeeds.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -79.0, us(10), 54e6);
  arrive(scheduler, phy, 2, -79.0, us(10) + kFrameTime + us(100), 6e6);
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log,
            (std::vector<std::string>{"busy", "idle", "rx_error", "busy", "idle", "rx 2"}));
}

}  // namespace
}  // namespace swarmnet
