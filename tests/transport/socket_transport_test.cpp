// The socket transport: records encoded in place into the send buffer and shown in place from
// the receive buffer arrive whole and in order, whatever their size against the buffers and the
// system calls that carry them; closing drains, then reports closed.
#include "socket_transport.hpp"

#include <gtest/gtest.h>
#include <sys/socket.h>

#include <algorithm>
#include <thread>
#include <vector>

#include "transport_test_support.hpp"

namespace swarmnet {
namespace {

using test::pattern;
using test::quick_policy;

struct SocketPair {
  SocketPair() {
    int fds[2] = {-1, -1};
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) std::abort();
    a = std::make_unique<SocketTransport>(fds[0], quick_policy(), "a");
    b = std::make_unique<SocketTransport>(fds[1], quick_policy(), "b");
  }
  std::unique_ptr<SocketTransport> a;
  std::unique_ptr<SocketTransport> b;
};

// Sizes from empty to several receive reads (64 KiB) and past the send buffer's flush threshold
// (1 MiB), so records straddle reads and flushes.
std::size_t size_of(std::uint64_t i) {
  constexpr std::size_t kSizes[] = {0, 1, 7, 64, 1000, 65535, 65536, 65537, 300'000, 1'500'000};
  return kSizes[i % std::size(kSizes)];
}

TEST(SocketTransport, RecordsWrittenAndReadInPlaceArriveWholeAndInOrder) {
  SocketPair pair;
  constexpr std::uint64_t kCount = 60;
  std::thread sender([&] {
    for (std::uint64_t i = 0; i < kCount; ++i) {
      const auto record = pattern(size_of(i), i);
      std::span<std::byte> space;
      if (pair.a->reserve(record.size(), space) != IoStatus::ok || space.size() != record.size()) {
        std::abort();
      }
      std::copy(record.begin(), record.end(), space.begin());
      if (pair.a->commit() != IoStatus::ok) std::abort();
      if (i % 7 == 6 && pair.a->flush() != IoStatus::ok) std::abort();
    }
    pair.a->close();  // flushes the rest
  });
  std::span<const std::byte> view;
  for (std::uint64_t i = 0; i < kCount; ++i) {
    ASSERT_EQ(pair.b->receive_view(view), IoStatus::ok) << "record " << i;
    const auto expected = pattern(size_of(i), i);
    EXPECT_TRUE(std::equal(view.begin(), view.end(), expected.begin(), expected.end()))
        << "record " << i << " of " << expected.size() << " bytes";
  }
  EXPECT_EQ(pair.b->receive_view(view), IoStatus::closed);
  sender.join();
}

TEST(SocketTransport, AnOversizedRecordIsRefused) {
  SocketPair pair;
  std::span<std::byte> space;
  EXPECT_EQ(pair.a->reserve(std::size_t{SocketTransport::kMaxRecordBytes} + 1, space),
            IoStatus::too_large);
  EXPECT_EQ(pair.a->send(pattern(3, 1)), IoStatus::ok);
  ASSERT_EQ(pair.a->flush(), IoStatus::ok);
  std::vector<std::byte> out;
  ASSERT_EQ(pair.b->receive(out), IoStatus::ok);
  EXPECT_EQ(out, pattern(3, 1));
}

}  // namespace
}  // namespace swarmnet
