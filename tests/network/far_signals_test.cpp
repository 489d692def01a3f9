// Far signals (issue 13): FarSignals as an index of the frames on the air, checked against a
// brute-force scan over every frame sent; ChannelLinks' far-link index against a scan of the
// links; and what a receiver sees: frames forgotten once no question can reach them, far signals
// handed over as events exactly while the far power arriving at a receiver could reach the
// carrier-sense threshold. FarSignals is driven directly, with links made here as the channel
// makes them (arrival order, far flag from is_far_signal, power in the bookkeeping's units).
#include "network/far_signals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "network/channel.hpp"
#include "network/channel_links.hpp"
#include "network/phy.hpp"
#include "network/scheduler.hpp"
#include "recording_phy_listener.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {
namespace {

using test::RecordingPhyListener;

constexpr SimTime us(std::int64_t n) { return SimTime{n * 1000}; }

PhyConfig sinr_config() {
  PhyConfig config;
  config.model = PhyModel::sinr;
  return config;
}

std::string describe(const FarSignal& s) {
  std::ostringstream out;
  out << "{uid " << s.frame_uid << ", " << s.power_dbm << " dBm, start (" << s.start.time.count()
      << ", " << s.start.sequence << "), end (" << s.end.time.count() << ", " << s.end.sequence
      << ")}";
  return out.str();
}

std::string describe(const std::vector<FarSignal>& signals) {
  std::string text;
  for (const FarSignal& s : signals) text += describe(s) + "\n";
  return text.empty() ? "(none)\n" : text;
}

bool same(const FarSignal& a, const FarSignal& b) {
  return a.frame_uid == b.frame_uid && a.power_dbm == b.power_dbm && a.power_mw == b.power_mw &&
         a.start == b.start && a.end == b.end;
}

bool same(const std::vector<FarSignal>& a, const std::vector<FarSignal>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const FarSignal& x, const FarSignal& y) { return same(x, y); });
}

void sort_by_start(std::vector<FarSignal>& signals) {
  std::sort(signals.begin(), signals.end(),
            [](const FarSignal& a, const FarSignal& b) { return a.start < b.start; });
}

// ---------------------------------------------------------------------------------------------
// ChannelLinks' far-link index

// Random links to random receivers among `nodes` (always including the bit-word edges 0, 63,
// 64, 127, 128 and nodes - 1 when they exist), far or not at random, in arrival order.
void random_links(RandomStream& random, std::uint32_t nodes, ChannelLinks& set) {
  set.clear();
  std::vector<NodeId> receivers;
  for (const NodeId edge : {0U, 1U, 62U, 63U, 64U, 65U, 127U, 128U, nodes - 1}) {
    if (edge < nodes && random.bernoulli(0.7)) receivers.push_back(edge);
  }
  for (NodeId node = 0; node < nodes; ++node) {
    if (random.bernoulli(0.3)) receivers.push_back(node);
  }
  std::sort(receivers.begin(), receivers.end());
  receivers.erase(std::unique(receivers.begin(), receivers.end()), receivers.end());
  for (const NodeId receiver : receivers) {
    const bool far = random.bernoulli(0.6);
    // Delays from a handful of values: receivers at equal distance are ordered by id.
    const SimTime delay{static_cast<std::int64_t>(random.below(8)) * 100};
    // Units differ per link, so that an entry carrying another link's units is seen.
    const std::int64_t units = far ? 1 + static_cast<std::int64_t>(random.below(1000)) : 0;
    set.links.push_back(
        ChannelLink{delay, receiver, far, nullptr, far ? -90.0 : -70.0, 0.0, units});
  }
  std::sort(set.links.begin(), set.links.end(), [](const ChannelLink& a, const ChannelLink& b) {
    return a.delay != b.delay ? a.delay < b.delay : a.receiver < b.receiver;
  });
}

TEST(FarSignalIndex, FarByReceiverListsEveryFarLinkByAscendingReceiver) {
  RandomStream random(13);
  ChannelLinks set;  // reused across rounds and sizes, as the channel reuses a frame's links
  std::size_t far_found = 0;
  for (const std::uint32_t nodes : {1U, 2U, 63U, 64U, 65U, 127U, 128U, 129U, 200U, 1000U}) {
    for (int round = 0; round < 30; ++round) {
      random_links(random, nodes, set);
      FarIndexScratch scratch(nodes);
      scratch.link_of_receiver.assign(nodes, 0xdeadbeefU);
      scratch.has_far_link.assign(nodes / 64 + 1, ~std::uint64_t{0});  // stale bits
      set.index_far(scratch);
      // Exactly the far links, receivers ascending, each with its link and that link's units.
      std::vector<FarLink> expected;
      for (std::uint32_t i = 0; i < set.links.size(); ++i) {
        if (set.links[i].far)
          expected.push_back(FarLink{set.links[i].receiver, i, set.links[i].far_units});
      }
      std::sort(expected.begin(), expected.end(),
                [](const FarLink& a, const FarLink& b) { return a.receiver < b.receiver; });
      ASSERT_EQ(set.far_by_receiver.size(), expected.size()) << nodes << " nodes, round " << round;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        ASSERT_EQ(set.far_by_receiver[k].receiver, expected[k].receiver) << k;
        ASSERT_EQ(set.far_by_receiver[k].link, expected[k].link) << k;
        ASSERT_EQ(set.far_by_receiver[k].units, expected[k].units) << k;
      }
      far_found += expected.size();
    }
  }
  EXPECT_GT(far_found, 1000U);
}

TEST(FarSignalIndex, AnEmptyOrNearOnlyLinkSetHasNoFarLink) {
  ChannelLinks set;
  FarIndexScratch scratch(130);
  set.index_far(scratch);
  EXPECT_TRUE(set.far_by_receiver.empty());
  set.links.push_back(ChannelLink{SimTime{5}, 64, false, nullptr, -60.0, 1e-6, 0});
  set.links.push_back(ChannelLink{SimTime{7}, 0, false, nullptr, -60.0, 1e-6, 0});
  set.index_far(scratch);
  EXPECT_TRUE(set.far_by_receiver.empty());
  // A far link found once is gone when the set is indexed again without it.
  set.links.push_back(ChannelLink{SimTime{9}, 129, true, nullptr, -90.0, 1e-9, 3});
  set.index_far(scratch);
  ASSERT_EQ(set.far_by_receiver.size(), 1U);
  EXPECT_EQ(set.far_by_receiver[0].receiver, 129U);
  set.links.pop_back();
  set.index_far(scratch);
  EXPECT_TRUE(set.far_by_receiver.empty());
}

TEST(FarSignalIndex, NearListsEveryLinkThatIsNotFarInArrivalOrder) {
  // The fan-out's streams walk `near`: each link that is not far, once, in link order.
  RandomStream random(11);
  ChannelLinks set;
  for (const std::uint32_t nodes : {1U, 2U, 64U, 200U}) {
    for (int round = 0; round < 30; ++round) {
      random_links(random, nodes, set);
      set.index_near();
      std::vector<std::uint32_t> expected;
      for (std::uint32_t i = 0; i < set.links.size(); ++i) {
        if (!set.links[i].far) expected.push_back(i);
      }
      ASSERT_EQ(set.near, expected) << nodes << " nodes, round " << round;
    }
  }
  set.clear();
  EXPECT_TRUE(set.near.empty());
}

// ---------------------------------------------------------------------------------------------
// FarSignals against a brute-force scan

// The channel's link as log_distance with ns-3's defaults and configs/paper's transmit power
// would give it (-82 dBm at 120 m; the interference floor, -103.97 dBm, at about 648 m).
constexpr double kTxPowerDbm = 27.0531;
double link_power_dbm(double distance_m) {
  return kTxPowerDbm - 46.6777 - 30.0 * std::log10(std::max(distance_m, 1.0));
}

struct Layout {
  double width_m;
  double height_m;
  std::uint32_t nodes;
};

// Nodes spread over the arena, with its corners, edge midpoints and other edge points among
// them, some on the bit-index edges' ids (0, 63, 64, the last).
std::vector<Vec2> place(RandomStream& random, const Layout& layout) {
  const double w = layout.width_m;
  const double h = layout.height_m;
  std::vector<Vec2> positions(layout.nodes);
  for (Vec2& p : positions) p = Vec2(random.uniform(0.0, w), random.uniform(0.0, h));
  const std::vector<Vec2> special = {{0, 0},         {w, 0},        {0, h},         {w, h},
                                     {w / 2, 0},     {w / 2, h},    {0, h / 2},     {w, h / 2},
                                     {0, h * 0.137}, {w * 0.71, h}, {w, h * 0.9},   {w * 0.2, 0},
                                     {w, 0.001},     {0.001, h},    {w - 0.001, 0}, {0, 0.5}};
  const std::vector<NodeId> ids = {0, layout.nodes - 1, 63, 64, 1, 62, 65, 2};
  std::size_t s = 0;
  for (const NodeId id : ids) {
    if (id < layout.nodes && s < special.size()) positions[id] = special[s++];
  }
  for (NodeId id = 3; id < layout.nodes && s < special.size(); id += 7)
    positions[id] = special[s++];
  return positions;
}

// One frame sent, as the brute force remembers it: with each receiver's far link, found by a
// scan of the links (not by the index under test).
struct Sent {
  std::uint64_t uid;
  SimTime sent;
  SimTime duration;
  std::uint64_t first_sequence;
  std::shared_ptr<const ChannelLinks> links;
  std::vector<std::int64_t> far_link_of;  // by receiver; -1: none

  Sent(std::uint64_t uid_, SimTime sent_, SimTime duration_, std::uint64_t first_sequence_,
       std::shared_ptr<const ChannelLinks> links_, std::size_t nodes)
      : uid(uid_),
        sent(sent_),
        duration(duration_),
        first_sequence(first_sequence_),
        links(std::move(links_)),
        far_link_of(nodes, -1) {
    for (std::size_t i = 0; i < links->links.size(); ++i) {
      if (links->links[i].far) far_link_of[links->links[i].receiver] = static_cast<std::int64_t>(i);
    }
  }
};

// Every far signal of every frame sent that reaches `receiver` and satisfies `keep`.
template <typename Keep>
std::vector<FarSignal> brute_force(const std::vector<Sent>& sent, NodeId receiver, Keep keep) {
  std::vector<FarSignal> out;
  for (const Sent& frame : sent) {
    if (frame.far_link_of[receiver] < 0) continue;
    const auto i = static_cast<std::size_t>(frame.far_link_of[receiver]);
    const ChannelLink& link = frame.links->links[i];
    const EventKey start{frame.sent + link.delay, frame.first_sequence + 2 * i};
    const FarSignal signal{frame.uid, link.power_dbm, link.power_mw, start,
                           EventKey{start.time + frame.duration, start.sequence + 1}};
    if (keep(signal)) out.push_back(signal);
  }
  sort_by_start(out);
  return out;
}

// Builds a transmitter's links as Channel::compute_links does (every node visited).
std::shared_ptr<const ChannelLinks> make_links(const std::vector<Vec2>& positions,
                                               NodeId transmitter, const PhyConfig& config,
                                               const FarSignals& far,
                                               const std::vector<Phy*>& phys) {
  auto set = std::make_shared<ChannelLinks>();
  const double audible_dbm = audibility_threshold_dbm(config);
  for (NodeId receiver = 0; receiver < positions.size(); ++receiver) {
    if (receiver == transmitter) continue;
    const double distance_m = (positions[receiver] - positions[transmitter]).norm();
    const double dbm = link_power_dbm(distance_m);
    if (dbm < audible_dbm) continue;
    const double mw = dbm_to_milliwatts(dbm);
    const bool is_far = is_far_signal(config, dbm, mw);
    set->links.push_back(ChannelLink{Channel::propagation_delay(distance_m), receiver, is_far,
                                     phys[receiver], dbm, mw, is_far ? far.units(mw) : 0});
  }
  std::sort(set->links.begin(), set->links.end(), [](const ChannelLink& a, const ChannelLink& b) {
    return a.delay != b.delay ? a.delay < b.delay : a.receiver < b.receiver;
  });
  FarIndexScratch scratch(positions.size());
  set->index_far(scratch);
  return set;
}

// A key to ask with: a random instant in [lo, hi], or one of the recent frames' signal keys
// exactly (the bounds are strict), or just beside it.
EventKey random_key(RandomStream& random, const std::vector<Sent>& sent, SimTime lo, SimTime hi) {
  if (!sent.empty() && random.bernoulli(0.5)) {
    const Sent& frame = sent[sent.size() - 1 - random.below(std::min<std::size_t>(sent.size(), 6))];
    const std::vector<ChannelLink>& links = frame.links->links;
    if (!links.empty()) {
      const std::size_t i = random.below(links.size());
      EventKey key{frame.sent + links[i].delay, frame.first_sequence + 2 * i};
      if (random.bernoulli(0.5)) {
        key.time += frame.duration;
        ++key.sequence;
      }
      const std::uint64_t shift = random.below(3);  // the key itself, or one sequence either side
      if (shift == 1) ++key.sequence;
      if (shift == 2 && key.sequence > 0) --key.sequence;
      if (key.time >= lo) return key;
    }
  }
  const auto span = static_cast<std::uint64_t>((hi - lo).count()) + 1;
  return EventKey{lo + SimTime{static_cast<std::int64_t>(random.below(span))},
                  random.bernoulli(0.5) ? 0 : random.below(1U << 20)};
}

TEST(FarSignalIndex, FarStartsAndFarSignalsDuringMatchABruteForceScan) {
  // The sensing threshold is set out of reach, so that no receiver turns hot (its far signals
  // would then be handed over as events, and not listed): this checks the index alone. Queries
  // start no earlier than kFarStartHistory before now, as the PHY's do.
  const PhyConfig config = sinr_config();
  RandomStream random(2026);
  const std::vector<Layout> layouts = {
      {1000, 1000, 150}, {300, 2000, 100}, {1400, 1400, 70}, {600, 600, 200}, {2500, 100, 129}};
  std::size_t listed_starts = 0;  // questions with a non-empty answer
  std::size_t listed_during = 0;
  std::size_t queries = 0;
  for (const Layout& layout : layouts) {
    const std::vector<Vec2> positions = place(random, layout);
    Scheduler scheduler;
    std::vector<RecordingPhyListener> listeners(layout.nodes);
    std::vector<std::unique_ptr<Phy>> owned;
    std::vector<Phy*> phys;
    for (NodeId node = 0; node < layout.nodes; ++node) {
      owned.push_back(std::make_unique<Phy>(config, listeners[node], &scheduler, node));
      phys.push_back(owned.back().get());
    }
    FarSignals far(scheduler, phys, 1e30);
    for (NodeId node = 0; node < layout.nodes; ++node)
      phys[node]->set_far_signal_source(&far, node);

    std::vector<Sent> sent;
    std::vector<std::shared_ptr<const ChannelLinks>> step_links(layout.nodes);
    SimTime now{};
    for (std::uint64_t uid = 1; uid <= 250; ++uid) {
      // Several frames at once: gaps from 0 (same instant) to 400 us, now and then a long pause
      // past the history; a new step (links recomputed) every few frames.
      const double pause = random.uniform();
      if (pause < 0.1) {
        // same instant
      } else if (pause < 0.95) {
        now += SimTime{static_cast<std::int64_t>(random.below(400'000))};
      } else {
        now += SimTime{static_cast<std::int64_t>(1'000'000 + random.below(3'000'000))};
      }
      if (random.bernoulli(0.15)) step_links.assign(layout.nodes, nullptr);
      scheduler.run_until(now);
      const NodeId transmitter = static_cast<NodeId>(random.below(layout.nodes));
      std::shared_ptr<const ChannelLinks>& links = step_links[transmitter];
      if (!links) links = make_links(positions, transmitter, config, far, phys);
      const SimTime duration{static_cast<std::int64_t>(20'000 + random.below(2'500'000))};
      const std::uint64_t first = scheduler.reserve_sequences(2 * links->links.size());
      far.frame_sent(uid, duration, first, links);
      sent.emplace_back(uid, now, duration, first, links, layout.nodes);
      ASSERT_EQ(scheduler.pending_count(), 0U) << "a far signal was handed over as events";

      for (int q = 0; q < 12; ++q) {
        // Mostly receivers of the recent frames' far links, sometimes any node.
        NodeId receiver = static_cast<NodeId>(random.below(layout.nodes));
        const ChannelLinks& recent =
            *sent[sent.size() - 1 - random.below(std::min<std::size_t>(sent.size(), 4))].links;
        if (!recent.far_by_receiver.empty() && random.bernoulli(0.8)) {
          receiver = recent.far_by_receiver[random.below(recent.far_by_receiver.size())].receiver;
        }
        const SimTime lo = std::max(SimTime{}, now - FarSignalSource::kFarStartHistory);
        const SimTime hi = now + us(3000);
        EventKey from = random_key(random, sent, lo, hi);
        EventKey to = random_key(random, sent, lo, hi);
        if (to < from) std::swap(from, to);
        if (random.bernoulli(0.1)) to = from;  // a point, as detect_preamble asks
        ++queries;

        std::vector<FarSignal> starts{FarSignal{0, 0.0, 0.0, {}, {}}};  // appended to
        far.far_starts(receiver, from, to, starts);
        starts.erase(starts.begin());
        const std::vector<FarSignal> expected_starts = brute_force(
            sent, receiver, [&](const FarSignal& s) { return from < s.start && s.start < to; });
        ASSERT_TRUE(same(starts, expected_starts))
            << "far_starts(" << receiver << ", (" << from.time.count() << ", " << from.sequence
            << "), (" << to.time.count() << ", " << to.sequence << ")) at " << now.count()
            << " ns, frame " << uid << "\ngot:\n"
            << describe(starts) << "expected:\n"
            << describe(expected_starts);
        listed_starts += starts.empty() ? 0 : 1;

        std::vector<FarSignal> during;
        far.far_signals_during(receiver, from, to, during);
        sort_by_start(during);
        const std::vector<FarSignal> expected_during = brute_force(
            sent, receiver, [&](const FarSignal& s) { return s.start < to && from < s.end; });
        ASSERT_TRUE(same(during, expected_during))
            << "far_signals_during(" << receiver << ", (" << from.time.count() << ", "
            << from.sequence << "), (" << to.time.count() << ", " << to.sequence << ")) at "
            << now.count() << " ns, frame " << uid << "\ngot:\n"
            << describe(during) << "expected:\n"
            << describe(expected_during);
        listed_during += during.empty() ? 0 : 1;
      }
    }
    // The pauses past the history let frames go: far fewer kept than sent.
    EXPECT_LT(far.frames_kept(), sent.size() / 2) << layout.nodes << " nodes";
  }
  // Not vacuous: many questions found something.
  std::printf("%zu queries: %zu found far starts, %zu far signals during\n", queries, listed_starts,
              listed_during);
  EXPECT_GT(listed_starts, queries / 4);
  EXPECT_GT(listed_during, queries / 2);
}

// ---------------------------------------------------------------------------------------------
// Expiry, and far signals handed over while they could reach the threshold

// One receiver (node 0, with a PHY that takes its far signals from `far`) and frames sent to it
// by hand.
class FarSignalsAtOneReceiver : public ::testing::Test {
 protected:
  static constexpr std::uint32_t kNodes = 4;

  FarSignalsAtOneReceiver() {
    for (NodeId node = 0; node < kNodes; ++node) {
      owned_.push_back(std::make_unique<Phy>(config_, listeners_[node], &scheduler_, node));
      phys_.push_back(owned_.back().get());
    }
    far_ = std::make_unique<FarSignals>(scheduler_, phys_, sensing_threshold_mw(config_));
    for (NodeId node = 0; node < kNodes; ++node)
      phys_[node]->set_far_signal_source(far_.get(), node);
  }

  // Runs the clock to `at` and sends a frame reaching node 0 at `dbm` after 1 us.
  void send(SimTime at, double dbm, SimTime duration) {
    auto set = std::make_shared<ChannelLinks>();
    const double mw = dbm_to_milliwatts(dbm);
    const bool is_far = is_far_signal(config_, dbm, mw);
    set->links.push_back(
        ChannelLink{us(1), 0, is_far, phys_[0], dbm, mw, is_far ? far_->units(mw) : 0});
    FarIndexScratch scratch(kNodes);
    set->index_far(scratch);
    scheduler_.run_until(at);
    far_->frame_sent(next_uid_++, duration, scheduler_.reserve_sequences(2), std::move(set));
  }
  // Whether the receiver got far signals as events: anything scheduled is theirs (no channel).
  [[nodiscard]] bool handed_over() const { return scheduler_.pending_count() > 0; }
  const std::vector<std::string>& log() const { return listeners_[0].log; }
  [[nodiscard]] bool busy() const { return phys_[0]->medium_busy(); }

  PhyConfig config_ = sinr_config();
  Scheduler scheduler_;
  RecordingPhyListener listeners_[kNodes];
  std::vector<std::unique_ptr<Phy>> owned_;
  std::vector<Phy*> phys_;
  std::unique_ptr<FarSignals> far_;
  std::uint64_t next_uid_ = 1;
};

TEST_F(FarSignalsAtOneReceiver, FramesAreForgottenOnceNoQuestionCanReachThem) {
  // Frame 1 ends at the receiver at 10 + 1 + 300 = 311 us, frame 2 at 321 us. far_starts looks
  // kFarStartHistory (1 ms) back: they are kept to 1311 and 1321 us, forgotten after.
  const SimTime history = FarSignalSource::kFarStartHistory;
  ASSERT_EQ(history, us(1000));
  send(us(10), -90.0, us(300));
  send(us(20), -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 2U);
  send(us(400), -90.0, us(300));  // over, but still within reach of a question
  EXPECT_EQ(far_->frames_kept(), 3U);
  send(us(311) + history, -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 4U) << "frame 1 forgotten while still within the history";
  send(us(311) + history + SimTime{1}, -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 4U) << "frame 1 kept past the history";
  send(us(321) + history + SimTime{1}, -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 4U) << "frame 2 kept past the history";
  // Long after everything ended, only the frame just sent is kept.
  send(us(20000), -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 1U);
  // A frame without a far link is not kept at all.
  send(us(20010), -70.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 1U);
  // None of this was handed over, and the medium never went busy.
  scheduler_.run_until(us(30000));
  EXPECT_TRUE(log().empty());
  EXPECT_EQ(scheduler_.events_run(), 0U);
}

TEST_F(FarSignalsAtOneReceiver, AReceiversListForgetsFramesNoLongerKept) {
  // Each receiver keeps its own list of the frames that reach it far; a receiver that never asks
  // must not collect every frame ever sent. 5,000 frames, a burst of ten every 5 ms (the history
  // is 1 ms; ten -95 dBm signals stay below the threshold): the list never holds more than twice
  // the most frames kept at once.
  std::size_t most_kept = 0;
  std::size_t largest = 0;
  for (std::int64_t burst = 0; burst < 500; ++burst) {
    for (std::int64_t k = 0; k < 10; ++k) {
      send(us(5000 * burst + 20 * k), -95.0, us(300));
      most_kept = std::max(most_kept, far_->frames_kept());
      largest = std::max(largest, far_->entries_kept(0));
      ASSERT_LE(far_->entries_kept(0), 2 * most_kept) << "burst " << burst << ", frame " << k;
    }
  }
  EXPECT_EQ(most_kept, 10U);
  EXPECT_GE(largest, 10U);
  // The frames of the last burst are still found after all that pruning.
  std::vector<FarSignal> listed;
  const SimTime last = us(std::int64_t{5000} * 499);
  far_->far_signals_during(0, EventKey{last, 0}, EventKey{last + us(400), 0}, listed);
  EXPECT_EQ(listed.size(), 10U) << describe(listed);
}

TEST_F(FarSignalsAtOneReceiver, LongFramesAreKeptForTheReceptionsTheyOverlap) {
  // A reception rebuilds its interference back to its start: with frames longer than the
  // history, frames are kept for a frame's length and reach after they end.
  send(us(10), -90.0, us(3000));  // ends at 3011 us; kept to 3011 + 3000 + 1 us
  send(us(5000), -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 2U);
  send(us(6012), -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 3U) << "frame 1 forgotten within a frame's length of its end";
  send(us(6012) + SimTime{1}, -90.0, us(300));
  EXPECT_EQ(far_->frames_kept(), 3U) << "frame 1 kept past a frame's length and reach";
}

TEST_F(FarSignalsAtOneReceiver, FramesAreKeptForLongReceptionsOfFramesWithoutFarLinks) {
  // A 3 ms frame heard only near (no far link) is a reception that rebuilds its interference
  // back to its detection at its end: the short far frame that overlapped its start must still
  // be there to be listed, though no frame with far links was ever that long.
  send(us(10), -90.0, us(100));    // far, ends at 111 us
  send(us(20), -60.0, us(3000));   // near only: arrives at 21 us, ends at 3021 us
  send(us(3020), -90.0, us(100));  // retires what no question can reach any more
  std::vector<FarSignal> listed;
  far_->far_signals_during(0, EventKey{us(25), 0}, EventKey{us(3021), 0}, listed);
  ASSERT_EQ(listed.size(), 1U) << describe(listed);  // the third starts at 3021 us, not before
  EXPECT_EQ(listed[0].frame_uid, 1U);
}

TEST_F(FarSignalsAtOneReceiver, FarSignalsBecomeEventsOnlyWhileTheyCouldReachTheThreshold) {
  // Two far signals of -85.02 dBm add up to -82.01 dBm, below the -82 dBm CCA threshold: never
  // handed over, the medium stays idle.
  send(us(10), -85.02, us(300));
  send(us(20), -85.02, us(300));
  EXPECT_FALSE(handed_over());
  scheduler_.run_until(us(200));
  EXPECT_FALSE(busy());

  // Two of -84.98 dBm add up to -81.99 dBm: the second makes the receiver hot, and both are
  // handed over (the first is already arriving). The medium is busy from the end of the
  // second's detection window (1021 + 4 us) until the first ends (1001 + 300 us).
  send(us(1000), -84.98, us(300));
  EXPECT_FALSE(handed_over());
  send(us(1020), -84.98, us(300));
  EXPECT_TRUE(handed_over());
  scheduler_.run_until(us(1025));
  EXPECT_FALSE(busy()) << "sensed before the detection window ended";
  scheduler_.run_until(us(1025) + SimTime{1});
  EXPECT_TRUE(busy());
  EXPECT_EQ(phys_[0]->state(), Phy::State::busy);
  scheduler_.run_until(us(1301));
  EXPECT_TRUE(busy());
  scheduler_.run_until(us(1301) + SimTime{1});
  EXPECT_FALSE(busy());
  EXPECT_EQ(log(), (std::vector<std::string>{"busy", "idle"}));
  scheduler_.run_until(us(1400));
  EXPECT_FALSE(handed_over());

  // Both over: the next frame finds the receiver cold again, and is not handed over.
  send(us(1400), -84.98, us(300));
  EXPECT_FALSE(handed_over());
  // The source answers only for what was not handed over: frames 3 and 4 went as events while
  // it was hot, frame 5 did not (frames 1 and 2 ended before the history's start).
  const EventKey history_start{us(1400) - FarSignalSource::kFarStartHistory, 0};
  std::vector<FarSignal> listed;
  far_->far_signals_during(0, EventKey{us(1310), 0}, EventKey{us(1310), 0}, listed);
  EXPECT_TRUE(listed.empty()) << describe(listed);  // frame 4 was arriving then, as events
  far_->far_starts(0, history_start, EventKey{us(1402), 0}, listed);
  ASSERT_EQ(listed.size(), 1U) << describe(listed);
  EXPECT_EQ(listed[0].frame_uid, 5U);
  listed.clear();
  far_->far_signals_during(0, history_start, EventKey{us(1402), 0}, listed);
  ASSERT_EQ(listed.size(), 1U) << describe(listed);
  EXPECT_EQ(listed[0].frame_uid, 5U);
  // A second one overlapping it makes it hot again: busy once more.
  send(us(1450), -84.98, us(300));
  EXPECT_TRUE(handed_over());
  scheduler_.run_until(us(1460));
  EXPECT_TRUE(busy());
  scheduler_.run_until(us(2000));
  EXPECT_FALSE(busy());
  EXPECT_EQ(log(), (std::vector<std::string>{"busy", "idle", "busy", "idle"}));
  // And cold again after them.
  send(us(2000), -84.98, us(300));
  EXPECT_FALSE(handed_over());
  scheduler_.run_until(us(3000));
  EXPECT_EQ(log().size(), 4U);
}

TEST_F(FarSignalsAtOneReceiver, AHeldReceiverGetsEveryFarSignalAsEventsUntilReleased) {
  // One far signal of -90 dBm is far from the threshold: not handed over.
  send(us(10), -90.0, us(300));
  EXPECT_FALSE(handed_over());
  // Held (a PHY whose MAC counts the medium idle under header_failure_cca ns3): the one still
  // arriving is handed over at once, and so is each one sent while the hold lasts.
  far_->hold_far_events(0, true);
  EXPECT_TRUE(handed_over());
  scheduler_.run_until(us(400));
  EXPECT_FALSE(handed_over());
  send(us(500), -90.0, us(300));
  EXPECT_TRUE(handed_over());
  scheduler_.run_until(us(900));
  // Still held after its frames retired: the bound is not what keeps it hot.
  send(us(1000), -90.0, us(300));
  EXPECT_TRUE(handed_over());
  scheduler_.run_until(us(1400));
  // Released below the threshold: cold again, and the source answers for what follows.
  far_->hold_far_events(0, false);
  send(us(1500), -90.0, us(300));
  EXPECT_FALSE(handed_over());
  std::vector<FarSignal> listed;
  far_->far_starts(0, EventKey{us(1450), 0}, EventKey{us(1502), 0}, listed);
  ASSERT_EQ(listed.size(), 1U) << describe(listed);
  EXPECT_EQ(listed[0].frame_uid, 4U);
  // Nothing a held receiver was handed is listed again (frames 2 and 3 went as events).
  listed.clear();
  far_->far_starts(0, EventKey{us(400), 0}, EventKey{us(1450), 0}, listed);
  EXPECT_TRUE(listed.empty()) << describe(listed);
  // Never sensed: one far signal at a time stays below the threshold, held or not.
  EXPECT_TRUE(log().empty());
}

TEST_F(FarSignalsAtOneReceiver, ManyWeakFarSignalsTogetherMakeTheReceiverHot) {
  // Ten far signals of -92 dBm (-82 dBm together, less rounding) overlap: none alone is anywhere
  // near the threshold, the tenth takes the sum there.
  for (int k = 0; k < 9; ++k) {
    send(us(10 + 10 * k), -91.99, us(500));
    EXPECT_FALSE(handed_over()) << k + 1 << " signals";
  }
  send(us(100), -91.99, us(500));
  EXPECT_TRUE(handed_over());
  scheduler_.run_until(us(106));
  EXPECT_TRUE(busy());
  scheduler_.run_until(us(1000));
  EXPECT_EQ(log(), (std::vector<std::string>{"busy", "idle"}));
}

}  // namespace
}  // namespace swarmnet
