// The SINR PHY: the error-rate model, preamble detection, interference, capture, carrier sense.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "network/channel.hpp"
#include "network/nist_error_rate.hpp"
#include "network/phy.hpp"
#include "network/propagation_chain.hpp"
#include "network/scheduler.hpp"
#include "network_test_support.hpp"
#include "recording_phy_listener.hpp"

namespace swarmnet {
namespace {

using RecordingListener = test::RecordingPhyListener;

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

TEST(WirelessErrorModel, CertainSuccessStartsWhereTheSeriesAlreadyGivesExactlyOne) {
  // chunk_success_rate skips the series from certain_success_sinr on. Down to half of that SINR
  // the series itself gives exactly 1 even for ten million bits, so the shortcut changes no
  // result; well below it, long chunks can fail.
  for (const ofdm::Mode& mode : ofdm::kModes) {
    const double threshold = certain_success_sinr(mode);
    EXPECT_GT(threshold, 1.0);
    EXPECT_LT(threshold, 1.0e4);
    for (const double fraction : {0.5, 0.7, 0.9, 0.999}) {
      EXPECT_EQ(chunk_success_rate(mode, threshold * fraction, 1.0e7), 1.0)
          << mode.rate_bps << " at " << fraction;
    }
    EXPECT_LT(chunk_success_rate(mode, threshold / 20.0, 1.0e7), 1.0) << mode.rate_bps;
  }
  // About 14 dB for BPSK 1/2 (6 Mbit/s): 11.2 dB where the error falls below 1e-30, plus 3.
  EXPECT_NEAR(10.0 * std::log10(certain_success_sinr(ofdm::kModes[0])), 14.2, 0.1);
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
  EXPECT_NEAR(listener.last_rx.sinr_db, -75.0 - noise_floor_dbm(sinr_config()), 1e-9);
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

// network.phy.header_failure_cca: ns3. ns-3.37's MAC counts the medium idle from a failed
// header's end when a signal joined during the preamble (after detection) and none during the
// header, until the next signal's detection window ends (network/sinr_reception.hpp).
PhyConfig ns3_header_config() {
  PhyConfig config = sinr_config();
  config.header_failure_cca = HeaderFailureCca::ns3;
  return config;
}

// Frame 1 detected at 14 us; frame 2, 5 dB stronger, joins in its preamble (18 us) and destroys
// its header (26-30 us).
void header_destroyed_from_the_preamble(Scheduler& scheduler, Phy& phy) {
  arrive(scheduler, phy, 1, -75.0, us(10));
  arrive(scheduler, phy, 2, -70.0, us(18));
}

TEST(WirelessSinrPhy, Ns3HeaderFailureTellsTheMacTheMediumIsIdleUntilTheNextSignal) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(ns3_header_config(), listener, &scheduler, 1);
  header_destroyed_from_the_preamble(scheduler, phy);
  arrive(scheduler, phy, 3, -95.0, us(600));  // too weak to detect or sense: any signal will do
  scheduler.run_until(us(29));
  EXPECT_TRUE(phy.medium_busy());  // the header is still being received
  scheduler.run_until(us(31));
  EXPECT_FALSE(phy.medium_busy());  // both frames on the air, at -69 dBm together
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle"}));
  scheduler.run_until(us(603));
  EXPECT_FALSE(phy.medium_busy());  // signal 3 is in its detection window
  scheduler.run_until(us(605));
  EXPECT_TRUE(phy.medium_busy());  // its window's end: what the PHY senses again
  scheduler.run_until(us(10000));
  // The reception's outcome is the same as with `sensed` (next test): frame 1 lost, no EIFS.
  EXPECT_EQ(listener.log,
            (std::vector<std::string>{"busy", "idle", "busy", "collision 1", "idle"}));
}

TEST(WirelessSinrPhy, Ns3HeaderFailureAbortsTheReceptionSoALaterFrameIsReceived) {
  // ns-3.37 aborts a reception whose L-SIG failed; with `sensed` the PHY stays locked on it.
  for (const bool ns3 : {true, false}) {
    Scheduler scheduler;
    RecordingListener listener;
    Phy phy(ns3 ? ns3_header_config() : sinr_config(), listener, &scheduler, 1);
    header_destroyed_from_the_preamble(scheduler, phy);
    arrive(scheduler, phy, 3, -50.0, us(200));  // 19 dB over frames 1 and 2 together
    scheduler.run_until(us(10000));
    if (ns3) {
      EXPECT_EQ(listener.log,
                (std::vector<std::string>{"busy", "idle", "busy", "collision 1", "idle", "rx 3"}));
    } else {
      EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "collision 1", "idle"}));
    }
  }
}

TEST(WirelessSinrPhy, Ns3HeaderFailuresOfOverlappingFramesAreEachACollision) {
  // Frame 1 is aborted at its header; frame 3, locked after it while 1 is still on the air, is
  // aborted too. Each is told as a collision at its own end.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(ns3_header_config(), listener, &scheduler, 1);
  header_destroyed_from_the_preamble(scheduler, phy);
  arrive(scheduler, phy, 3, -60.0, us(100));  // 9 dB over frames 1 and 2: detected
  arrive(scheduler, phy, 4, -55.0, us(108));  // joins 3's preamble, destroys its header
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "busy", "idle", "collision 1",
                                                    "collision 3"}));
}

TEST(WirelessSinrPhy, SensedHeaderFailureKeepsTheMediumBusy) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  header_destroyed_from_the_preamble(scheduler, phy);
  scheduler.run_until(us(31));
  EXPECT_TRUE(phy.medium_busy());
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "collision 1", "idle"}));
}

TEST(WirelessSinrPhy, Ns3HeaderFailureKeepsTheMediumBusyWhenASignalJoinsDuringTheHeader) {
  // ns-3 notifies its MAC again when a signal arrives during the L-SIG.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(ns3_header_config(), listener, &scheduler, 1);
  header_destroyed_from_the_preamble(scheduler, phy);
  arrive(scheduler, phy, 3, -95.0, us(27));
  scheduler.run_until(us(31));
  EXPECT_TRUE(phy.medium_busy());
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "collision 1", "idle"}));
}

TEST(WirelessSinrPhy, Ns3HeaderRuleLeavesAReceivedFrameAlone) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(ns3_header_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -60.0, us(10));
  arrive(scheduler, phy, 2, -90.0, us(18));  // joins the preamble, harmless
  scheduler.run_until(us(31));
  EXPECT_TRUE(phy.medium_busy());
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "rx 1"}));
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

// Quiet signals as a channel would report them: a fixed list, filtered by overlap.
class FixedQuietSignals final : public QuietSignalSource {
 public:
  void quiet_signals(NodeId /*receiver*/, SimTime from, SimTime to,
                     std::vector<QuietSignal>& out) const override {
    for (const QuietSignal& signal : signals) {
      if (signal.start < to && signal.end > from) out.push_back(signal);
    }
  }
  std::vector<QuietSignal> signals;
};

TEST(WirelessSinrPhy, QuietSignalsCountInTheSinr) {
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  FixedQuietSignals quiet;
  quiet.signals.push_back({us(300), us(300) + kFrameTime, dbm_to_milliwatts(-93.0)});
  phy.set_quiet_signal_source(&quiet, 0);
  arrive(scheduler, phy, 1, -75.0, us(10));
  scheduler.run_until(us(5000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "rx 1"}));
  const double noise_mw = dbm_to_milliwatts(noise_floor_dbm(sinr_config()));
  const double expected_db =
      10.0 * std::log10(dbm_to_milliwatts(-75.0) / (noise_mw + dbm_to_milliwatts(-93.0)));
  EXPECT_NEAR(listener.last_rx.sinr_db, expected_db, 1e-9);
}

TEST(WirelessSinrPhy, QuietSignalsDrownAFrameWithoutBeingSensed) {
  // Sixteen quiet signals of -92.5 dBm (each below the -92 dBm sensing threshold) add up to
  // -80.5 dBm: enough to destroy a -79 dBm frame. Carrier sense leaves them out (the documented
  // approximation), so the medium goes idle when the frame ends.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  FixedQuietSignals quiet;
  for (int i = 0; i < 16; ++i) {
    quiet.signals.push_back({us(400), us(400) + 2 * kFrameTime, dbm_to_milliwatts(-92.5)});
  }
  phy.set_quiet_signal_source(&quiet, 0);
  arrive(scheduler, phy, 1, -79.0, us(10));
  scheduler.run_until(us(10) + kFrameTime + us(1));
  EXPECT_FALSE(phy.medium_busy());
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "collision 1", "rx_error"}));
}

TEST(WirelessSinrPhy, QuietSignalsCanPreventPreambleDetection) {
  // A -82 dBm preamble has an SNR of 12 dB, but eight quiet signals of -94 dBm (-85 dBm together)
  // leave it 2.5 dB of SINR, below the 4 dB detection needs. The frame is still sensed.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  FixedQuietSignals quiet;
  for (int i = 0; i < 8; ++i) quiet.signals.push_back({us(0), us(5000), dbm_to_milliwatts(-94.0)});
  phy.set_quiet_signal_source(&quiet, 0);
  arrive(scheduler, phy, 1, -82.0, us(10));
  scheduler.run_until(us(10000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle"}));

  // The same frame without them is received.
  Scheduler alone_scheduler;
  RecordingListener alone_listener;
  Phy alone(sinr_config(), alone_listener, &alone_scheduler, 1);
  arrive(alone_scheduler, alone, 1, -82.0, us(10));
  alone_scheduler.run_until(us(10000));
  EXPECT_EQ(alone_listener.log, (std::vector<std::string>{"busy", "idle", "rx 1"}));
}

TEST(WirelessChannel, QuietSignalsAreTheAudibleOnesBelowTheSensingThreshold) {
  // log_distance with ns-3's defaults, a 120 m nominal range and a sensing floor of -10 dB: the
  // sensing threshold (-92 dBm)
  // falls at about 258 m, the interference floor (-103.97 dBm) at about 648 m. A node at 50 m
  // gets the frame as events; a node at 400 m (-97.7 dBm) only as a quiet signal; a node at
  // 700 m not at all.
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 4, "dcf80211", "direct");
  settings.network.propagation = {test::choose(loader, "log_distance", PluginKind::propagation)};
  settings.network.phy.model = PhyModel::sinr;
  settings.network.phy.tx_power_dbm = -82.0 + 46.6777 + 30.0 * std::log10(120.0);
  settings.network.phy.sensing_floor_db = -10.0;
  Scheduler scheduler;
  const PropagationChain chain(settings, loader);
  const double tx_power = settings.network.phy.tx_power_dbm;
  Channel channel(settings, PropagationChain(settings, loader), scheduler, 4);
  EXPECT_NEAR(channel.event_cutoff_m(), 120.0 * std::pow(10.0, 10.0 / 30.0), 0.01);
  EXPECT_NEAR(channel.cutoff_m(), 648.0, 1.0);
  std::vector<RecordingListener> listeners(4);
  std::vector<std::unique_ptr<Phy>> phys;
  for (NodeId node = 0; node < 4; ++node) {
    phys.push_back(std::make_unique<Phy>(settings.network.phy, listeners[node], &scheduler, node));
    channel.attach(node, *phys.back());
  }
  const std::vector<Vec2> positions{Vec2(0, 0), Vec2(50, 0), Vec2(400, 0), Vec2(700, 0)};
  channel.set_positions(positions);
  const SimTime duration = us(200);
  channel.transmit(0, frame(0), duration);

  std::vector<QuietSignal> quiet;
  channel.quiet_signals(2, kTimeZero, us(1000), quiet);
  ASSERT_EQ(quiet.size(), 1U);
  const RadioLink link{0, 2, positions[0], positions[2], 400.0, 1};
  EXPECT_EQ(quiet[0].start, Channel::propagation_delay(400.0));
  EXPECT_EQ(quiet[0].end, quiet[0].start + duration);
  EXPECT_EQ(quiet[0].power_mw, dbm_to_milliwatts(chain.rx_power_dbm(tx_power, link)));
  // Not overlapping the question's interval: not reported.
  const SimTime quiet_end = quiet[0].end;
  quiet.clear();
  channel.quiet_signals(2, quiet_end, us(2000), quiet);
  EXPECT_TRUE(quiet.empty());
  for (const NodeId node : {NodeId{0}, NodeId{1}, NodeId{3}}) {
    channel.quiet_signals(node, kTimeZero, us(1000), quiet);
    EXPECT_TRUE(quiet.empty()) << "node " << node;
  }
  scheduler.run_until(us(1000));
  EXPECT_EQ(listeners[1].log, (std::vector<std::string>{"busy", "idle", "rx 1"}));
  EXPECT_TRUE(listeners[2].log.empty());
  EXPECT_TRUE(listeners[3].log.empty());

  // The default sensing floor is below the interference floor: every audible signal is an event.
  settings.network.phy.sensing_floor_db = PhyConfig{}.sensing_floor_db;
  Channel exact(settings, PropagationChain(settings, loader), scheduler, 4);
  EXPECT_EQ(exact.event_cutoff_m(), exact.cutoff_m());
}

TEST(WirelessSinrPhy, AWindowOfWeakSignalsCostsNoTimer) {
  // A window whose end can neither detect a frame nor change carrier sense is kept without a
  // timer: a weak signal alone costs its start and its end, nothing more.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -90.0, us(10));
  scheduler.run_until(us(5000));
  EXPECT_EQ(scheduler.events_run(), 2U);
  EXPECT_TRUE(listener.log.empty());
}

TEST(WirelessSinrPhy, AStrongSignalJoiningAWeakWindowIsDetectedWhereThatWindowEnds) {
  // Window 1 opens with a weak signal at 10 us and passes (at 14 us) with nothing to do. A weak
  // signal at 20 us opens window 2; a strong one joins it at 22 us and is detected when window 2
  // ends, at 24 us, not 4 us after its own arrival.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -90.0, us(10));
  arrive(scheduler, phy, 2, -91.0, us(20));
  arrive(scheduler, phy, 3, -55.0, us(22));
  scheduler.run_until(us(24));
  EXPECT_FALSE(phy.medium_busy());
  scheduler.run_until(us(24) + SimTime{1});
  EXPECT_EQ(phy.state(), Phy::State::receiving);
  scheduler.run_until(us(5000));
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "rx 3"}));
}

TEST(WirelessSinrPhy, WeakSignalsThatAddUpMakeTheMediumBusyWhenTheirWindowEnds) {
  // Two -84 dBm signals in one window add up to -81 dBm: busy at the window's end (14 us).
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -84.0, us(10));
  arrive(scheduler, phy, 2, -84.0, us(12));
  scheduler.run_until(us(14));
  EXPECT_FALSE(phy.medium_busy());
  scheduler.run_until(us(14) + SimTime{1});
  EXPECT_TRUE(phy.medium_busy());
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy"}));
}

TEST(WirelessSinrPhy, AWindowMattersAgainWhenASensedSignalEndsDuringIt) {
  // Signals 1 and 2 (-84 dBm each, 3 us apart) keep the medium busy. Signal 3 (-85 dBm) opens a
  // window 2 us before signal 1 ends: the medium goes idle then, and busy again at the window's
  // end, where signals 2 (ending 1 us later) and 3 add up to -81.5 dBm.
  Scheduler scheduler;
  RecordingListener listener;
  Phy phy(sinr_config(), listener, &scheduler, 1);
  arrive(scheduler, phy, 1, -84.0, us(0));
  arrive(scheduler, phy, 2, -84.0, us(3));
  const SimTime window_start = kFrameTime - us(2);
  arrive(scheduler, phy, 3, -85.0, window_start);
  scheduler.run_until(kFrameTime + SimTime{1});
  EXPECT_FALSE(phy.medium_busy());
  scheduler.run_until(window_start + us(4));
  EXPECT_FALSE(phy.medium_busy());
  scheduler.run_until(window_start + us(4) + SimTime{1});
  EXPECT_TRUE(phy.medium_busy());
  scheduler.run_until(us(3) + kFrameTime + SimTime{1});
  EXPECT_FALSE(phy.medium_busy());
  EXPECT_EQ(listener.log, (std::vector<std::string>{"busy", "idle", "busy", "idle"}));
}

TEST(WirelessChannel, LinksAreReusedWithinAStepOnlyWhenNoModelVariesPerFrame) {
  // Node 0 sends three frames one after another to node 1 at 60 m, then node 1 moves to 30 m and
  // node 0 sends a fourth. With log_distance alone the first three arrive with one power and the
  // fourth with a stronger one (links are recomputed when nodes move); with Nakagami fading after
  // it every frame draws its own power.
  const auto powers = [](bool fading) {
    PluginLoader loader;
    NetworkSettings settings = test::make_settings(loader, 2, "dcf80211", "direct");
    settings.network.propagation = {test::choose(loader, "log_distance", PluginKind::propagation)};
    if (fading) {
      settings.network.propagation.push_back(
          test::choose(loader, "nakagami", PluginKind::propagation));
    }
    settings.network.phy.model = PhyModel::sinr;
    settings.network.phy.tx_power_dbm = 40.0;  // -60 dBm at 60 m: received through any fade here
    Scheduler scheduler;
    Channel channel(settings, PropagationChain(settings, loader), scheduler, 2);
    std::vector<RecordingListener> listeners(2);
    std::vector<std::unique_ptr<Phy>> phys;
    for (NodeId node = 0; node < 2; ++node) {
      phys.push_back(
          std::make_unique<Phy>(settings.network.phy, listeners[node], &scheduler, node));
      channel.attach(node, *phys.back());
    }
    std::vector<double> received;
    const auto send = [&] {
      channel.transmit(0, frame(0), us(100));
      scheduler.run_until(scheduler.now() + us(200));
      ASSERT_FALSE(listeners[1].log.empty());
      EXPECT_EQ(listeners[1].log.back(), "rx " + std::to_string(channel.frames_sent()));
      received.push_back(listeners[1].last_rx.rx_power_dbm);
    };
    channel.set_positions(std::vector<Vec2>{Vec2(0, 0), Vec2(60, 0)});
    for (int i = 0; i < 3; ++i) send();
    channel.set_positions(std::vector<Vec2>{Vec2(0, 0), Vec2(30, 0)});
    send();
    return received;
  };
  const std::vector<double> plain = powers(false);
  EXPECT_EQ(plain[0], plain[1]);
  EXPECT_EQ(plain[0], plain[2]);
  EXPECT_NEAR(plain[3] - plain[0], 30.0 * std::log10(2.0), 1e-9);
  const std::vector<double> faded = powers(true);
  EXPECT_NE(faded[0], faded[1]);
  EXPECT_NE(faded[1], faded[2]);
}

TEST(WirelessChannel, APhyIsAttachedBeforeTheFirstFrameOnly) {
  // The links a step keeps hold the receivers' PHYs: replacing one afterwards is refused.
  PluginLoader loader;
  NetworkSettings settings = test::make_settings(loader, 2, "dcf80211", "direct");
  settings.network.propagation = {test::choose(loader, "log_distance", PluginKind::propagation)};
  settings.network.phy.model = PhyModel::sinr;
  Scheduler scheduler;
  Channel channel(settings, PropagationChain(settings, loader), scheduler, 2);
  std::vector<RecordingListener> listeners(3);
  Phy first(settings.network.phy, listeners[0], &scheduler, 0);
  Phy second(settings.network.phy, listeners[1], &scheduler, 1);
  Phy replacement(settings.network.phy, listeners[2], &scheduler, 1);
  channel.attach(0, first);
  channel.attach(1, second);
  channel.attach(1, replacement);  // still before any frame: allowed
  channel.set_positions(std::vector<Vec2>{Vec2(0, 0), Vec2(30, 0)});
  channel.transmit(0, frame(0), us(100));
  EXPECT_THROW(channel.attach(1, second), std::logic_error);
}

}  // namespace
}  // namespace swarmnet
