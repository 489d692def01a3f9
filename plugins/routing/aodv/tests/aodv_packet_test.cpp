// AODV message formats: sizes, byte layout, round trips and refusal of malformed bytes.
#include "aodv_packet.hpp"

#include <gtest/gtest.h>

namespace swarmnet::aodv {
namespace {

TEST(AodvPacket, RreqRoundTripsWithRfcSizeAndLayout) {
  Rreq rreq;
  rreq.gratuitous = true;
  rreq.destination_only = true;
  rreq.unknown_seq = true;
  rreq.ttl = 7;
  rreq.hop_count = 3;
  rreq.id = 0x01020304;
  rreq.destination = 9;
  rreq.destination_seq = 0xfffffffe;
  rreq.originator = 2;
  rreq.originator_seq = 17;
  const auto bytes = encode(Message{rreq});
  ASSERT_EQ(bytes.size(), Rreq::kSize);
  EXPECT_EQ(bytes[0], 1);                   // type
  EXPECT_EQ(bytes[1], 0x20 | 0x10 | 0x08);  // G D U
  EXPECT_EQ(bytes[2], 7);                   // ttl in the reserved byte
  EXPECT_EQ(bytes[3], 3);                   // hop count
  EXPECT_EQ(bytes[4], 0x01);                // network byte order
  EXPECT_EQ(bytes[7], 0x04);
  const auto decoded = decode(bytes);
  ASSERT_TRUE(decoded.has_value());
  EXPECT_EQ(std::get<Rreq>(*decoded), rreq);
}

TEST(AodvPacket, RrepRoundTripsAndRecognisesHello) {
  Rrep rrep;
  rrep.ack_required = true;
  rrep.prefix_size = 5;
  rrep.ttl = 6;
  rrep.hop_count = 4;
  rrep.destination = 11;
  rrep.destination_seq = 42;
  rrep.originator = 3;
  rrep.lifetime_ms = 11200;
  const auto bytes = encode(Message{rrep});
  ASSERT_EQ(bytes.size(), Rrep::kSize);
  EXPECT_EQ(bytes[0], 2);
  EXPECT_EQ(bytes[1], 0x45);  // A, and the prefix size in the low bits
  EXPECT_EQ(bytes[2], 6);     // the TTL in the reserved bits
  const auto decoded = decode(bytes);
  ASSERT_TRUE(decoded.has_value());
  EXPECT_EQ(std::get<Rrep>(*decoded), rrep);
  EXPECT_FALSE(rrep.is_hello());
  rrep.originator = rrep.destination;
  EXPECT_TRUE(rrep.is_hello());
}

TEST(AodvPacket, RerrCarriesEveryDestination) {
  Rerr rerr;
  rerr.no_delete = true;
  rerr.destinations = {{4, 10}, {5, 0}, {kNoNode, 0xffffffff}};
  const auto bytes = encode(Message{rerr});
  ASSERT_EQ(bytes.size(), 4U + 3U * 8U);
  EXPECT_EQ(bytes[0], 3);
  EXPECT_EQ(bytes[1], 0x80);
  EXPECT_EQ(bytes[3], 3);
  const auto decoded = decode(bytes);
  ASSERT_TRUE(decoded.has_value());
  EXPECT_EQ(std::get<Rerr>(*decoded), rerr);
}

TEST(AodvPacket, RrepAckIsTwoBytes) {
  const auto bytes = encode(Message{RrepAck{}});
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{4, 0}));
  const auto decoded = decode(bytes);
  ASSERT_TRUE(decoded.has_value());
  EXPECT_TRUE(std::holds_alternative<RrepAck>(*decoded));
}

TEST(AodvPacket, MalformedBytesAreRefused) {
  EXPECT_FALSE(decode({}).has_value());
  EXPECT_FALSE(decode(std::vector<std::uint8_t>{0, 0}).has_value());  // unknown type
  EXPECT_FALSE(decode(std::vector<std::uint8_t>{9, 0}).has_value());
  auto rreq = encode(Message{Rreq{}});
  rreq.pop_back();
  EXPECT_FALSE(decode(rreq).has_value());
  auto rrep = encode(Message{Rrep{}});
  rrep.push_back(0);
  EXPECT_FALSE(decode(rrep).has_value());
  // RERR: zero destinations, or a count that disagrees with the length.
  EXPECT_FALSE(decode(std::vector<std::uint8_t>{3, 0, 0, 0}).has_value());
  auto rerr = encode(Message{Rerr{false, {{1, 1}, {2, 2}}}});
  rerr[3] = 3;
  EXPECT_FALSE(decode(rerr).has_value());
  EXPECT_FALSE(decode(std::vector<std::uint8_t>{4, 0, 0}).has_value());
}

}  // namespace
}  // namespace swarmnet::aodv
