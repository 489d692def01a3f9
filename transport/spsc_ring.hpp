// A single-producer/single-consumer lock-free ring of variable-length records, laid out in a
// caller-provided block of memory that may be shared between processes: inline storage (no
// pointers), a header both sides check on attach, producer and consumer indices on separate
// 64-byte lines, acquire/release ordering only on the fast path.
//
// Record framing: a 4-byte little-endian length, the bytes, padding to 8 bytes; records wrap
// around the end of the storage. A record longer than max_record_bytes() can never be pushed and
// is refused with IoStatus::too_large — it is never dropped silently.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ring_status.hpp"
#include "wait_policy.hpp"

namespace swarmnet {

// Fixed rather than std::hardware_destructive_interference_size, which may differ between the
// two builds that share a segment.
inline constexpr std::size_t kCacheLineBytes = 64;
inline constexpr std::uint64_t kRingMagic = 0x474e4952'544e5753ULL;  // "SWNTRING"
inline constexpr std::uint32_t kRingLayoutVersion = 1;

struct RingHeader {
  // Written once by create(), read-only afterwards.
  alignas(kCacheLineBytes) std::uint64_t magic;
  std::uint32_t layout_version;
  std::uint32_t header_bytes;
  std::uint64_t capacity;  // storage bytes, a power of two
  // Producer's line.
  alignas(kCacheLineBytes) std::atomic<std::uint64_t> head;  // bytes ever written
  std::atomic<std::uint32_t> producer_closed;
  // Consumer's line.
  alignas(kCacheLineBytes) std::atomic<std::uint64_t> tail;  // bytes ever consumed
  std::atomic<std::uint32_t> consumer_closed;
  // Wake-up words: bumped by the side that made progress, slept on by the other.
  alignas(kCacheLineBytes) std::atomic<std::uint32_t> data_event;
  std::atomic<std::uint32_t> consumer_sleeping;
  alignas(kCacheLineBytes) std::atomic<std::uint32_t> space_event;
  std::atomic<std::uint32_t> producer_sleeping;
};

static_assert(std::atomic<std::uint64_t>::is_always_lock_free);
static_assert(std::atomic<std::uint32_t>::is_always_lock_free);
static_assert(sizeof(RingHeader) == 5 * kCacheLineBytes);
static_assert(offsetof(RingHeader, head) == kCacheLineBytes);
static_assert(offsetof(RingHeader, tail) == 2 * kCacheLineBytes);

class SpscRing {
 public:
  // Bytes of memory a ring with `capacity` storage bytes occupies.
  static std::size_t footprint(std::uint64_t capacity) { return sizeof(RingHeader) + capacity; }

  // Initialises a new ring in `memory` (footprint(capacity) bytes, 64-byte aligned).
  // `capacity` must be a power of two >= 64 (else std::invalid_argument).
  static SpscRing create(void* memory, std::uint64_t capacity);
  // Attaches to a ring another party created; on a wrong magic, layout version or size, returns
  // false and says why in `error`.
  static bool attach(void* memory, std::size_t memory_bytes, SpscRing& ring, std::string& error);

  SpscRing() = default;

  [[nodiscard]] std::uint64_t capacity() const { return header_->capacity; }
  [[nodiscard]] std::size_t max_record_bytes() const {
    return static_cast<std::size_t>(header_->capacity) - kLengthBytes;
  }

  // Producer side. write() stages a record without showing it to the consumer; publish() shows
  // every staged record at once, so a batch costs one shared-index store and at most one wake-up
  // instead of one per record (a batch larger than 16 KiB is shown in 16 KiB slices, so that the
  // consumer can start on it). push() is write() then publish().
  IoStatus try_write(std::span<const std::byte> record);
  IoStatus write(std::span<const std::byte> record, const WaitPolicy& policy);
  void publish();
  IoStatus try_push(std::span<const std::byte> record);
  IoStatus push(std::span<const std::byte> record, const WaitPolicy& policy);
  void close_producer();

  // Consumer side. `record` is resized to the record's length.
  IoStatus try_pop(std::vector<std::byte>& record);
  IoStatus pop(std::vector<std::byte>& record, const WaitPolicy& policy);
  void close_consumer();

 private:
  static constexpr std::size_t kLengthBytes = 4;
  static constexpr std::uint64_t kAlign = 8;
  static constexpr std::uint64_t kPublishSliceBytes = std::uint64_t{16} * 1024;
  static std::uint64_t padded(std::uint64_t bytes) { return (bytes + kAlign - 1) & ~(kAlign - 1); }

  void copy_in(std::uint64_t position, const std::byte* source, std::size_t bytes);
  void copy_out(std::uint64_t position, std::byte* target, std::size_t bytes) const;
  void wake_consumer();
  void wake_producer();

  RingHeader* header_ = nullptr;
  std::byte* storage_ = nullptr;
  std::uint64_t mask_ = 0;
  // Each side's private copy of the other side's index: re-read (acquire) only when it says the
  // ring is full (producer) or empty (consumer), so the common case touches no shared line.
  std::uint64_t cached_tail_ = 0;
  std::uint64_t cached_head_ = 0;
  std::uint64_t write_head_ = 0;  // producer: end of staged records, published or not
};

}  // namespace swarmnet
