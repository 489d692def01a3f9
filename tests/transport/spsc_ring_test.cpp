// The ring: framing, edges (empty, full, wrap-around), header checks, closing, and a stress run
// across two threads and across two processes (fork, shared anonymous mapping).
#include "spsc_ring.hpp"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

#include "swarmnet/random.hpp"

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

std::vector<std::byte> pattern(std::size_t size, std::uint64_t seed) {
  std::vector<std::byte> bytes(size);
  RandomStream random(seed);
  for (auto& b : bytes) b = static_cast<std::byte>(random.next());
  return bytes;
}

WaitPolicy quick_policy() {
  WaitPolicy policy;
  policy.timeout = std::chrono::seconds(20);
  return policy;
}

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

TEST(SpscRing, FullAndEmptyEdgesAndWrapAround) {
  constexpr std::uint64_t kCapacity = 256;
  RingMemory m(kCapacity);
  SpscRing ring = SpscRing::create(m.memory, kCapacity);
  // 4-byte length + 60 bytes = 64 bytes per record: exactly four fill the ring.
  std::vector<std::byte> out;
  for (int round = 0; round < 10; ++round) {
    for (int i = 0; i < 4; ++i) ASSERT_EQ(ring.try_push(pattern(60, round * 4 + i)), IoStatus::ok);
    EXPECT_EQ(ring.try_push(pattern(1, 99)), IoStatus::would_block) << "round " << round;
    for (int i = 0; i < 4; ++i) {
      ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
      EXPECT_EQ(out, pattern(60, round * 4 + i));
    }
    EXPECT_EQ(ring.try_pop(out), IoStatus::would_block);
    // Shift the start so the next round's records straddle the end of the storage.
    ASSERT_EQ(ring.try_push(pattern(13, 7)), IoStatus::ok);
    ASSERT_EQ(ring.try_pop(out), IoStatus::ok);
    EXPECT_EQ(out, pattern(13, 7));
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
  EXPECT_EQ(ring.max_record_bytes(), 252U);
  EXPECT_EQ(ring.try_push(pattern(253, 1)), IoStatus::too_large);
  EXPECT_EQ(ring.push(pattern(253, 1), quick_policy()), IoStatus::too_large);
  EXPECT_EQ(ring.try_push(pattern(252, 1)), IoStatus::ok);
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

TEST(SpscRing, CorruptLengthIsReported) {
  RingMemory m(256);
  SpscRing ring = SpscRing::create(m.memory, 256);
  ASSERT_EQ(ring.try_push(pattern(8, 1)), IoStatus::ok);
  // Overwrite the record's length with one larger than what was published.
  auto* storage = static_cast<std::byte*>(m.memory) + sizeof(RingHeader);
  const std::uint32_t bogus = 200;
  std::memcpy(storage, &bogus, sizeof bogus);
  std::vector<std::byte> out;
  EXPECT_EQ(ring.try_pop(out), IoStatus::corrupt);
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
    if (ring.write(record, quick_policy()) != IoStatus::ok) std::abort();
    if ((i + 1) % batch == 0) ring.publish();
  }
  ring.close_producer();  // publishes the rest
}

std::uint64_t consume(SpscRing& ring, std::uint64_t count) {
  RandomStream sizes(kStressSeed);
  std::vector<std::byte> record;
  std::uint64_t bad = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    if (ring.pop(record, quick_policy()) != IoStatus::ok) return bad + (count - i);
    const std::uint64_t size = sizes.below(300);
    RandomStream content(i);
    bool same = record.size() == size;
    for (std::size_t k = 0; same && k < record.size(); ++k) {
      same = record[k] == static_cast<std::byte>(content.next());
    }
    bad += same ? 0 : 1;
  }
  if (ring.pop(record, quick_policy()) != IoStatus::closed) ++bad;
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
