// The flooding plugin's packet format and duplicate cache, tested as units.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace swarmnet::flooding
