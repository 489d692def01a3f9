// The flooding plugin's packet format and duplicate cache, tested as units.
#include <gtest/gtest.h>

#include <deque>
#include <set>
#include <utility>
#include <vector>

#include "duplicate_cache.hpp"
#include "flooding_header.hpp"

namespace swarmnet::flooding {
namespace {

TEST(FloodingHeader, EncodesAFixedLittleEndianLayout) {
  const FloodingHeader header{0x04030201U, 0xa0b0c0d0U, 17};
  const std::vector<std::uint8_t> bytes = encode(header);
  const std::vector<std::uint8_t> expected = {0x01, 0x02, 0x03, 0x04, 0xd0, 0xc0, 0xb0, 0xa0, 17};
  EXPECT_EQ(bytes, expected);
  ASSERT_EQ(bytes.size(), FloodingHeader::kSize);
}

TEST(FloodingHeader, DecodeInvertsEncode) {
  for (const FloodingHeader header :
       {FloodingHeader{0, 0, 1}, FloodingHeader{kNoNode, 0xffffffffU, 255},
        FloodingHeader{42, 123456, 32}}) {
    const auto decoded = decode(encode(header));
    ASSERT_TRUE(decoded.has_value());
    EXPECT_EQ(*decoded, header);
  }
}

TEST(FloodingHeader, RejectsWrongSizes) {
  std::vector<std::uint8_t> bytes = encode(FloodingHeader{1, 2, 3});
  bytes.pop_back();
  EXPECT_FALSE(decode(bytes).has_value());
  bytes.push_back(3);
  bytes.push_back(0);
  EXPECT_FALSE(decode(bytes).has_value());
  EXPECT_FALSE(decode({}).has_value());
}

TEST(FloodingHeader, EncodeReplacesTheBufferContents) {
  std::vector<std::uint8_t> buffer(30, 0xff);
  encode(FloodingHeader{5, 6, 7}, buffer);
  EXPECT_EQ(buffer, encode(FloodingHeader{5, 6, 7}));
}

TEST(FloodingDuplicateCache, DetectsRepeats) {
  DuplicateCache cache(8);
  EXPECT_TRUE(cache.insert(1, 10));
  EXPECT_FALSE(cache.insert(1, 10));
  EXPECT_TRUE(cache.insert(2, 10));  // another originator
  EXPECT_TRUE(cache.insert(1, 11));  // another sequence
  EXPECT_TRUE(cache.contains(1, 10));
  EXPECT_FALSE(cache.contains(3, 10));
  EXPECT_EQ(cache.size(), 3U);
}

TEST(FloodingDuplicateCache, EvictsInInsertionOrder) {
  DuplicateCache cache(3);
  EXPECT_TRUE(cache.insert(0, 1));
  EXPECT_TRUE(cache.insert(0, 2));
  EXPECT_TRUE(cache.insert(0, 3));
  EXPECT_FALSE(cache.insert(0, 1));  // a repeat does not refresh (FIFO, not LRU)
  EXPECT_TRUE(cache.insert(0, 4));   // evicts (0, 1), the oldest
  EXPECT_EQ(cache.size(), 3U);
  EXPECT_FALSE(cache.contains(0, 1));
  EXPECT_TRUE(cache.contains(0, 2));
  EXPECT_TRUE(cache.insert(0, 5));  // evicts (0, 2)
  EXPECT_FALSE(cache.contains(0, 2));
  EXPECT_TRUE(cache.contains(0, 3));
  EXPECT_TRUE(cache.contains(0, 4));
  EXPECT_TRUE(cache.contains(0, 5));
  EXPECT_TRUE(cache.insert(0, 1));  // forgotten: new again
}

TEST(FloodingDuplicateCache, MatchesAReferenceFifoSet) {
  // Many originators and sequences through a small cache, against a std::set + deque model.
  DuplicateCache cache(37);
  std::set<std::pair<NodeId, std::uint32_t>> model;
  std::deque<std::pair<NodeId, std::uint32_t>> order;
  std::uint64_t state = 12345;
  for (int i = 0; i < 20000; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto originator = static_cast<NodeId>((state >> 33U) % 7U);
    const auto sequence = static_cast<std::uint32_t>((state >> 40U) % 60U);
    const std::pair<NodeId, std::uint32_t> pair{originator, sequence};
    const bool fresh = !model.contains(pair);
    if (fresh) {
      if (order.size() == 37U) {
        model.erase(order.front());
        order.pop_front();
      }
      model.insert(pair);
      order.push_back(pair);
    }
    ASSERT_EQ(cache.insert(originator, sequence), fresh) << "step " << i;
    ASSERT_EQ(cache.size(), model.size());
  }
  for (NodeId o = 0; o < 7; ++o) {
    for (std::uint32_t s = 0; s < 60; ++s) EXPECT_EQ(cache.contains(o, s), model.contains({o, s}));
  }
  // The all-ones key is a valid pair too.
  EXPECT_TRUE(cache.insert(0xffffffffU, 0xffffffffU));
  EXPECT_TRUE(cache.contains(0xffffffffU, 0xffffffffU));
  EXPECT_FALSE(cache.insert(0xffffffffU, 0xffffffffU));
}

}  // namespace
// The cache holds what it was given, not its limit: a limit of 10^7 cost 240 MB a node up front.
TEST(FloodingDuplicateCache, GrowsWithWhatItHoldsUpToItsCapacity) {
  DuplicateCache cache(10'000'000);
  EXPECT_LT(cache.allocated_bytes(), 1024U);
  for (std::uint32_t s = 0; s < 1000; ++s) ASSERT_TRUE(cache.insert(3, s));
  EXPECT_LT(cache.allocated_bytes(), 64U * 1024U);  // about 3 x 1000 keys of 8 bytes, doubled
  for (std::uint32_t s = 0; s < 1000; ++s) EXPECT_TRUE(cache.contains(3, s)) << s;
  EXPECT_EQ(cache.capacity(), 10'000'000U);
  // Grown to its capacity it evicts the oldest, as a cache made full from the start did.
  DuplicateCache small(100);
  for (std::uint32_t s = 0; s < 250; ++s) ASSERT_TRUE(small.insert(1, s));
  EXPECT_EQ(small.size(), 100U);
  EXPECT_FALSE(small.contains(1, 149));
  EXPECT_TRUE(small.contains(1, 150));
  EXPECT_TRUE(small.insert(1, 0));
  EXPECT_FALSE(small.contains(1, 150));
}

}  // namespace swarmnet::flooding
