// The ring: framing, edges (empty, full, across the end with a padding marker), writing and
// reading in place, the release slice, header checks, closing, and a stress run across two
// threads and across two processes (fork, shared anonymous mapping).
#include "spsc_ring.hpp"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <thread>
#include <vector>

#include "asymmetric_fence.hpp"
#include "swarmnet/random.hpp"
#include "transport_test_support.hpp"

namespace swarmnet {
namespace {

struct RingMemory {
  explicit RingMemory(std::uint64_t capacity) : bytes(SpscRing::footprint(capacity)) {
    memory = std::aligned_alloc(kCacheLineBytes, bytes);
  }
  ~RingMemory() { std::free(memory); }
  RingMemory(const RingMemory&) = delete;
  RingMemory& operator=(const RingMemory&) = delete;
  std::size_t bytes;
  void* memory;
};

using test::pattern;
using test::quick_policy;

TEST(SpscRing, RecordsComeOutWhole) {
  RingMemory m(1024);
  SpscRing ring = SpscRing::create(m.memory, 1024);
  std::vector<std::byte> out;
  EXPECT_EQ(ring.try_pop(out), IoStatus::would_block);
  const auto a = pattern(3, 1);
  const auto b = pattern(0, 2);
  const auto c = pattern(100, 3);
  ASSERT_EQ(ring.try_push(a), IoStatus::ok);
  ASSERT_EQ(ring.try_push(b), IoStatus::ok);
  ASSERT_EQ(ring.try_push(c), IoStatus::ok);
  ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
  EXPECT_EQ(out, a);
  ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
  EXPECT_EQ(out, b);
  ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
  EXPECT_EQ(out, c);
  EXPECT_EQ(ring.try_pop(out), IoStatus::would_block);
}

TEST(SpscRing, FullAndEmptyEdgesAcrossTheEnd) {
  constexpr std::uint64_t kCapacity = 256;
  RingMemory m(kCapacity);
  SpscRing ring = SpscRing::create(m.memory, kCapacity);
  // 4-byte length + 60 bytes = 64 bytes per record (one release slice): exactly four fill the
  // ring, whichever 64-byte boundary they start at.
  std::vector<std::byte> out;
  for (int round = 0; round < 10; ++round) {
    for (int i = 0; i < 4; ++i) ASSERT_EQ(ring.try_push(pattern(60, round * 4 + i)), IoStatus::ok);
    EXPECT_EQ(ring.try_push(pattern(0, 99)), IoStatus::would_block) << "round " << round;
    for (int i = 0; i < 4; ++i) {
      ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
      EXPECT_EQ(out, pattern(60, round * 4 + i));
    }
    EXPECT_EQ(ring.try_pop(out), IoStatus::would_block);
    // Shift the start by one record, so the next round's four records run across the end.
    ASSERT_EQ(ring.try_push(pattern(60, 7)), IoStatus::ok);
    ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
    EXPECT_EQ(out, pattern(60, 7));
  }
}

std::byte* storage_of(const RingMemory& m) {
  return static_cast<std::byte*>(m.memory) + sizeof(RingHeader);
}

std::uint32_t length_field_at(const RingMemory& m, std::size_t offset) {
  std::uint32_t length = 0;
  std::memcpy(&length, storage_of(m) + offset, sizeof length);
  return length;
}

TEST(SpscRing, ARecordThatWouldCrossTheEndStartsAfterAPaddingMarker) {
  constexpr std::uint64_t kCapacity = 256;
  RingMemory m(kCapacity);
  SpscRing ring = SpscRing::create(m.memory, kCapacity);
  std::vector<std::byte> out;
  for (int i = 0; i < 3; ++i) ASSERT_EQ(ring.try_push(pattern(60, i)), IoStatus::ok);  // 0..192
  for (int i = 0; i < 2; ++i) ASSERT_EQ(ring.try_pop(out), IoStatus::ok);  // frees 0..128
  // 92 bytes need 96; 192 + 96 crosses the end, so the record goes to offset 0.
  const auto big = pattern(ring.max_record_bytes(), 5);
  ASSERT_EQ(ring.try_push(big), IoStatus::ok);
  EXPECT_EQ(length_field_at(m, 192), kRingPaddingMarker);
  EXPECT_EQ(length_field_at(m, 0), big.size());
  ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
  EXPECT_EQ(out, pattern(60, 2));
  std::span<const std::byte> view;
  ASSERT_EQ(ring.try_read(view), IoStatus::ok);  // skips the marker
  EXPECT_EQ(view.data(), storage_of(m) + 4) << "read in place, from the start of the storage";
  EXPECT_TRUE(std::equal(view.begin(), view.end(), big.begin(), big.end()));
  ring.release();
  EXPECT_EQ(ring.try_read(view), IoStatus::would_block);
}

TEST(SpscRing, TheLongestRecordFitsWhereverTheRingStands) {
  constexpr std::uint64_t kCapacity = 256;
  RingMemory m(kCapacity);
  SpscRing ring = SpscRing::create(m.memory, kCapacity);
  std::vector<std::byte> out;
  // Every 8-byte position: a longest record must fit once the consumer has read everything, even
  // though it may have to skip the end and the consumer holds back part of a release slice.
  for (std::size_t shift = 0; shift < kCapacity / 8; ++shift) {
    ASSERT_EQ(ring.try_push(pattern(4 + 8 * (shift % 5), shift)), IoStatus::ok);
    ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
    const auto big = pattern(ring.max_record_bytes(), shift);
    ASSERT_EQ(ring.try_push(big), IoStatus::ok) << "at shift " << shift;
    ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
    EXPECT_EQ(out, big);
  }
}

TEST(SpscRing, ReservedSpaceIsWrittenInPlaceAndShownOnlyWhenCommitted) {
  RingMemory m(1024);
  SpscRing producer = SpscRing::create(m.memory, 1024);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  std::span<std::byte> space;
  ASSERT_EQ(producer.try_reserve(10, space), IoStatus::ok);
  ASSERT_EQ(space.size(), 10U);
  EXPECT_EQ(space.data(), storage_of(m) + 4) << "the ring's own bytes, after the length field";
  std::memset(space.data(), 0x11, space.size());
  producer.publish();
  std::span<const std::byte> view;
  EXPECT_EQ(consumer.try_read(view), IoStatus::would_block) << "not committed, not shown";
  // A new reservation abandons the uncommitted one.
  ASSERT_EQ(producer.try_reserve(3, space), IoStatus::ok);
  const auto three = pattern(3, 3);
  std::memcpy(space.data(), three.data(), three.size());
  producer.commit();
  EXPECT_EQ(consumer.try_read(view), IoStatus::would_block) << "committed, not yet published";
  producer.publish();
  ASSERT_EQ(consumer.try_read(view), IoStatus::ok);
  EXPECT_TRUE(std::equal(view.begin(), view.end(), three.begin(), three.end()));
  EXPECT_EQ(consumer.try_read(view), IoStatus::would_block);
}

// Found by fuzzing (fuzz/corpus/fuzz_ring_framing/tail_past_the_end): a peer that wrote a tail
// one byte short of a wrap made the consumer read a length field across the storage's end.
TEST(SpscRing, IndicesThatPutALengthFieldPastTheEndAreCorrupt) {
  constexpr std::uint64_t kCapacity = 4096;
  RingMemory m(kCapacity);
  (void)SpscRing::create(m.memory, kCapacity);
  auto* header = static_cast<RingHeader*>(m.memory);
  header->tail.store(std::numeric_limits<std::uint64_t>::max());  // head 0: "1 byte available"
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error)) << error;
  std::span<const std::byte> view;
  EXPECT_EQ(consumer.try_read(view), IoStatus::corrupt);
}

TEST(SpscRing, AViewStaysValidUntilReleased) {
  constexpr std::uint64_t kCapacity = 256;
  RingMemory m(kCapacity);
  SpscRing producer = SpscRing::create(m.memory, kCapacity);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  for (int i = 0; i < 4; ++i) ASSERT_EQ(producer.try_push(pattern(60, i)), IoStatus::ok);
  std::span<const std::byte> view;
  ASSERT_EQ(consumer.try_read(view), IoStatus::ok);
  const auto first = pattern(60, 0);
  // The producer cannot take the bytes the view shows, however hard it tries.
  EXPECT_EQ(producer.try_push(pattern(60, 9)), IoStatus::would_block);
  EXPECT_EQ(producer.try_push(pattern(0, 9)), IoStatus::would_block);
  EXPECT_TRUE(std::equal(view.begin(), view.end(), first.begin(), first.end()));
  consumer.release();  // 64 bytes: a whole release slice, given back at once
  EXPECT_EQ(producer.try_push(pattern(60, 4)), IoStatus::ok);
  for (int i = 1; i <= 4; ++i) {
    ASSERT_EQ(consumer.try_read(view), IoStatus::ok);  // releases the previous record
    const auto expected = pattern(60, i);
    EXPECT_TRUE(std::equal(view.begin(), view.end(), expected.begin(), expected.end()));
  }
}

TEST(SpscRing, TheConsumerGivesSpaceBackOncePerReleaseSlice) {
  constexpr std::uint64_t kCapacity = 1024;
  RingMemory m(kCapacity);
  SpscRing producer = SpscRing::create(m.memory, kCapacity);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  const std::uint64_t slice = SpscRing::release_slice_bytes(kCapacity);
  ASSERT_EQ(slice, 256U);
  // Empty records take 8 bytes each.
  for (int i = 0; i < 40; ++i) ASSERT_EQ(producer.try_write({}), IoStatus::ok);
  producer.publish();
  const auto& tail = static_cast<RingHeader*>(m.memory)->tail;
  std::span<const std::byte> view;
  for (std::uint64_t i = 1; i <= 40; ++i) {
    ASSERT_EQ(consumer.try_read(view), IoStatus::ok);
    consumer.release();
    EXPECT_EQ(tail.load(), (8 * i / slice) * slice) << "after " << i << " records";
  }
}

TEST(SpscRing, StagedRecordsAppearOnlyWhenPublished) {
  RingMemory m(1024);
  SpscRing producer = SpscRing::create(m.memory, 1024);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  std::vector<std::byte> out;
  ASSERT_EQ(producer.try_write(pattern(10, 1)), IoStatus::ok);
  ASSERT_EQ(producer.try_write(pattern(20, 2)), IoStatus::ok);
  EXPECT_EQ(consumer.try_pop(out), IoStatus::would_block);
  producer.publish();
  ASSERT_EQ(consumer.try_pop(out), IoStatus::ok);
  EXPECT_EQ(out, pattern(10, 1));
  ASSERT_EQ(consumer.try_pop(out), IoStatus::ok);
  EXPECT_EQ(out, pattern(20, 2));
}

TEST(SpscRing, AFullRingPublishesWhatIsStagedBeforeWaiting) {
  RingMemory m(256);
  SpscRing producer = SpscRing::create(m.memory, 256);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  std::thread reader([&] {
    std::vector<std::byte> out;
    for (int i = 0; i < 20; ++i) {
      if (consumer.pop(out, quick_policy()) != IoStatus::ok || out != pattern(60, i)) std::abort();
    }
  });
  // 20 records of 64 bytes through a 256-byte ring, never published by hand: write() must
  // publish when it runs out of room, or both sides would wait forever.
  for (int i = 0; i < 20; ++i)
    ASSERT_EQ(producer.write(pattern(60, i), quick_policy()), IoStatus::ok);
  producer.publish();
  reader.join();
}

TEST(SpscRing, OversizedRecordIsRefusedNotDropped) {
  RingMemory m(256);
  SpscRing ring = SpscRing::create(m.memory, 256);
  // (256 - a 64-byte release slice) / 2, less the length field.
  EXPECT_EQ(ring.max_record_bytes(), 92U);
  EXPECT_EQ(SpscRing::max_record_bytes(std::uint64_t{1} << 22U),
            (std::size_t{1} << 21U) - 2048 - 4);
  std::span<std::byte> space;
  EXPECT_EQ(ring.try_reserve(93, space), IoStatus::too_large);
  EXPECT_EQ(ring.reserve(93, space, quick_policy()), IoStatus::too_large);
  EXPECT_EQ(ring.try_push(pattern(93, 1)), IoStatus::too_large);
  EXPECT_EQ(ring.push(pattern(93, 1), quick_policy()), IoStatus::too_large);
  EXPECT_EQ(ring.try_push(pattern(92, 1)), IoStatus::ok);
  std::vector<std::byte> out;
  ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
  EXPECT_EQ(out, pattern(92, 1));
}

TEST(SpscRing, CapacityMustBeAPowerOfTwo) {
  RingMemory m(1024);
  EXPECT_THROW(SpscRing::create(m.memory, 1000), std::invalid_argument);
  EXPECT_THROW(SpscRing::create(m.memory, 32), std::invalid_argument);
}

TEST(SpscRing, AttachChecksTheHeader) {
  RingMemory m(1024);
  SpscRing::create(m.memory, 1024);
  SpscRing attached;
  std::string error;
  EXPECT_TRUE(SpscRing::attach(m.memory, m.bytes, attached, error)) << error;

  auto* header = static_cast<RingHeader*>(m.memory);
  header->layout_version = kRingLayoutVersion + 1;
  EXPECT_FALSE(SpscRing::attach(m.memory, m.bytes, attached, error));
  EXPECT_NE(error.find("layout version " + std::to_string(kRingLayoutVersion + 1)),
            std::string::npos)
      << error;
  header->layout_version = kRingLayoutVersion;

  EXPECT_FALSE(SpscRing::attach(m.memory, m.bytes - 1, attached, error));
  EXPECT_NE(error.find("does not fit"), std::string::npos) << error;

  header->magic = 0;
  EXPECT_FALSE(SpscRing::attach(m.memory, m.bytes, attached, error));
  EXPECT_NE(error.find("bad magic"), std::string::npos) << error;
}

TEST(SpscRing, CorruptFramingIsReported) {
  RingMemory m(256);
  SpscRing ring = SpscRing::create(m.memory, 256);
  ASSERT_EQ(ring.try_push(pattern(8, 1)), IoStatus::ok);
  std::vector<std::byte> out;
  // A length larger than any record, one larger than what was published, and a padding marker
  // that would skip past what was published.
  for (const std::uint32_t bogus : {200U, 20U, kRingPaddingMarker}) {
    std::memcpy(storage_of(m), &bogus, sizeof bogus);
    EXPECT_EQ(ring.try_pop(out), IoStatus::corrupt) << "length field " << bogus;
  }
}

TEST(SpscRing, CloseDrainsThenReportsClosed) {
  RingMemory m(1024);
  SpscRing producer = SpscRing::create(m.memory, 1024);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  ASSERT_EQ(producer.try_push(pattern(5, 1)), IoStatus::ok);
  producer.close_producer();
  std::vector<std::byte> out;
  EXPECT_EQ(consumer.pop(out, quick_policy()), IoStatus::ok);
  EXPECT_EQ(out, pattern(5, 1));
  EXPECT_EQ(consumer.pop(out, quick_policy()), IoStatus::closed);
  consumer.close_consumer();
  EXPECT_EQ(producer.try_push(pattern(5, 1)), IoStatus::closed);
}

TEST(SpscRing, WaitingEndsAtTheTimeoutOrWhenThePeerIsGone) {
  RingMemory m(1024);
  SpscRing ring = SpscRing::create(m.memory, 1024);
  std::vector<std::byte> out;
  WaitPolicy policy;
  policy.timeout = std::chrono::milliseconds(50);
  EXPECT_EQ(ring.pop(out, policy), IoStatus::timeout);
  policy.timeout = std::chrono::seconds(30);
  policy.peer_alive = [] { return false; };
  EXPECT_EQ(ring.pop(out, policy), IoStatus::peer_dead);
}

// A peer that takes longer than the timeout but computes all along is waited for; once it
// stops computing, the wait ends. The peer's CPU time is simulated: each look finds a second
// more while it works, so the test does not depend on how this machine schedules threads.
TEST(SpscRing, APeerThatComputesIsWaitedForPastTheTimeout) {
  RingMemory m(1024);
  SpscRing producer = SpscRing::create(m.memory, 1024);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  std::atomic<bool> computing{true};
  std::atomic<std::int64_t> cpu_s{0};
  WaitPolicy policy;
  policy.timeout = std::chrono::milliseconds(40);
  policy.sleep_slice = std::chrono::milliseconds(5);
  policy.peer_cpu = [&] {
    if (computing.load()) cpu_s.fetch_add(1);
    return std::chrono::nanoseconds(std::chrono::seconds(cpu_s.load()));
  };
  std::thread peer([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(400));  // ten timeouts
    EXPECT_EQ(producer.try_push(pattern(8, 3)), IoStatus::ok);
    computing.store(false);
  });
  std::vector<std::byte> out;
  EXPECT_EQ(consumer.pop(out, policy), IoStatus::ok);
  EXPECT_EQ(out, pattern(8, 3));
  peer.join();
  EXPECT_EQ(consumer.pop(out, policy), IoStatus::timeout) << "the peer no longer computes";
}

TEST(WaitDeadline, PassesAfterATimeoutWithLittleCpuAndMovesOnRealWork) {
  std::chrono::nanoseconds cpu{std::chrono::seconds(7)};
  WaitPolicy policy;
  policy.timeout = std::chrono::seconds(10);
  policy.peer_cpu = [&cpu] { return cpu; };
  WaitDeadline deadline(policy);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(deadline.passed(start + std::chrono::seconds(1)));  // the baseline: 7 s
  cpu += std::chrono::seconds(2);  // the peer computed 2 s (a fifth of the window)
  EXPECT_FALSE(deadline.passed(start + std::chrono::seconds(11)));
  cpu += std::chrono::milliseconds(50);  // then only woke now and then (a twentieth of 1 s)
  EXPECT_FALSE(deadline.passed(start + std::chrono::seconds(20))) << "the new window ends at 21 s";
  EXPECT_TRUE(deadline.passed(start + std::chrono::seconds(22))) << "too little CPU since 11 s";
  WaitPolicy fixed;  // no CPU to look at: the timeout is a fixed bound
  fixed.timeout = std::chrono::seconds(10);
  WaitDeadline bound(fixed);
  EXPECT_TRUE(bound.passed(std::chrono::steady_clock::now() + std::chrono::seconds(11)));
}

TEST(SpscRing, AConsumerThatFencesHeavilySaysSo) {
  RingMemory m(1024);
  SpscRing producer = SpscRing::create(m.memory, 1024);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  const auto& flag = static_cast<RingHeader*>(m.memory)->consumer_fences_heavily;
  EXPECT_EQ(flag.load(), 0U) << "nobody has consumed yet";
  ASSERT_EQ(producer.try_push(pattern(8, 1)), IoStatus::ok);
  std::vector<std::byte> out;
  ASSERT_EQ(consumer.try_pop(out), IoStatus::ok);
  // Where the kernel offers membarrier(2), the producer may now publish with a light fence.
  EXPECT_EQ(flag.load(), asymmetric_fences_available() ? 1U : 0U);
}

// Two processes hand a token back and forth, and each waits by sleeping at once (no spinning,
// no yielding) with a sleep slice as long as its timeout: a publish that did not wake a sleeping
// peer would end that wait with IoStatus::timeout instead of the token. (This checks the wake-up
// protocol, with the fences the process may use; the ordering races the fences exclude are too
// narrow to provoke in a test, and their pairing is argued in spsc_ring.cpp.)
TEST(SpscRing, SleepingProcessesAreWokenByEveryPublish) {
  constexpr std::uint64_t kCapacity = 4096;
  const std::size_t one = SpscRing::footprint(kCapacity);
  void* memory = mmap(nullptr, 2 * one, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(memory, MAP_FAILED);
  auto* there_memory = static_cast<std::byte*>(memory);
  auto* back_memory = there_memory + one;
  SpscRing::create(there_memory, kCapacity);
  SpscRing::create(back_memory, kCapacity);
  WaitPolicy sleepy;
  sleepy.spin_time = std::chrono::nanoseconds(0);
  sleepy.yield_iterations = 0;
  sleepy.sleep_slice = std::chrono::seconds(20);
  sleepy.timeout = std::chrono::seconds(20);
  constexpr int kRounds = 2000;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // echoes every token
    SpscRing in;
    SpscRing out;
    std::string error;
    if (!SpscRing::attach(there_memory, one, in, error) ||
        !SpscRing::attach(back_memory, one, out, error)) {
      _exit(3);
    }
    std::vector<std::byte> token;
    for (int i = 0; i < kRounds; ++i) {
      if (in.pop(token, sleepy) != IoStatus::ok || out.push(token, sleepy) != IoStatus::ok) {
        _exit(4);
      }
    }
    _exit(0);
  }
  SpscRing out;
  SpscRing in;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(there_memory, one, out, error)) << error;
  ASSERT_TRUE(SpscRing::attach(back_memory, one, in, error)) << error;
  std::vector<std::byte> token;
  int returned = 0;
  for (int i = 0; i < kRounds; ++i) {
    const auto sent = pattern(16, i);
    if (out.push(sent, sleepy) != IoStatus::ok) break;
    const IoStatus status = in.pop(token, sleepy);
    if (status != IoStatus::ok) {
      ADD_FAILURE() << "round " << i << ": " << to_string(status);
      break;
    }
    returned += token == sent ? 1 : 0;
  }
  EXPECT_EQ(returned, kRounds);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  munmap(memory, 2 * one);
}

// Producer sends `count` records of random sizes with contents derived from their index; the
// consumer checks each, in order. Returns the number of mismatches.
constexpr std::uint64_t kStressSeed = 42;

// `batch` > 1 stages records and publishes every `batch` of them, as the transport does per step.
void produce(SpscRing& ring, std::uint64_t count, std::uint64_t batch) {
  RandomStream sizes(kStressSeed);
  std::vector<std::byte> record;
  for (std::uint64_t i = 0; i < count; ++i) {
    record.resize(sizes.below(300));
    RandomStream content(i);
    for (auto& b : record) b = static_cast<std::byte>(content.next());
    if (i % 2 == 0) {
      if (ring.write(record, quick_policy()) != IoStatus::ok) std::abort();
    } else {  // in place
      std::span<std::byte> space;
      if (ring.reserve(record.size(), space, quick_policy()) != IoStatus::ok) std::abort();
      std::copy(record.begin(), record.end(), space.begin());
      ring.commit();
    }
    if ((i + 1) % batch == 0) ring.publish();
  }
  ring.close_producer();  // publishes the rest
}

std::uint64_t consume(SpscRing& ring, std::uint64_t count) {
  RandomStream sizes(kStressSeed);
  std::vector<std::byte> copy;
  std::span<const std::byte> record;
  std::uint64_t bad = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    if (i % 3 == 0) {  // copied out
      if (ring.pop(copy, quick_policy()) != IoStatus::ok) return bad + (count - i);
      record = copy;
    } else if (ring.read(record, quick_policy()) != IoStatus::ok) {  // in place
      return bad + (count - i);
    }
    const std::uint64_t size = sizes.below(300);
    RandomStream content(i);
    bool same = record.size() == size;
    for (std::size_t k = 0; same && k < record.size(); ++k) {
      same = record[k] == static_cast<std::byte>(content.next());
    }
    bad += same ? 0 : 1;
  }
  if (ring.pop(copy, quick_policy()) != IoStatus::closed) ++bad;
  return bad;
}

TEST(SpscRing, StressAcrossTwoThreads) {
  constexpr std::uint64_t kCapacity = 4096;  // small: forces constant wrap-around and full waits
  RingMemory m(kCapacity);
  SpscRing producer = SpscRing::create(m.memory, kCapacity);
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(m.memory, m.bytes, consumer, error));
  constexpr std::uint64_t kCount = 500'000;
  std::thread thread([&] { produce(producer, kCount, 1); });
  EXPECT_EQ(consume(consumer, kCount), 0U);
  thread.join();
}

TEST(SpscRing, StressAcrossTwoProcesses) {
  constexpr std::uint64_t kCapacity = 8192;
  const std::size_t bytes = SpscRing::footprint(kCapacity);
  void* memory = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(memory, MAP_FAILED);
  SpscRing::create(memory, kCapacity);
  constexpr std::uint64_t kCount = 10'000'000;
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    SpscRing producer;
    std::string error;
    if (!SpscRing::attach(memory, bytes, producer, error)) _exit(3);
    produce(producer, kCount, 64);
    _exit(0);
  }
  SpscRing consumer;
  std::string error;
  ASSERT_TRUE(SpscRing::attach(memory, bytes, consumer, error)) << error;
  EXPECT_EQ(consume(consumer, kCount), 0U);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  munmap(memory, bytes);
}

}  // namespace
}  // namespace swarmnet
