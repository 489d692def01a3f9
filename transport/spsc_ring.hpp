// A single-producer/single-consumer lock-free ring of variable-length records, laid out in a
// caller-provided block of memory that may be shared between processes: inline storage (no
// pointers), a header both sides check on attach, producer and consumer indices on separate
// 64-byte lines, acquire/release ordering only on the fast path. One producer and one consumer
// for the ring's life, each attached in the process that uses it.
//
// Record framing (layout version 2): a 4-byte little-endian length, the bytes, padding to 8
// bytes. A record never wraps around the end of the storage, so that it can be written and read
// in place: when it does not fit before the end, the producer writes a padding marker (a length
// of kRingPaddingMarker) and the record starts again at the beginning; the consumer skips the
// rest of the storage when it meets the marker. A record longer than max_record_bytes() (a little
// under half the ring) can never be written and is refused with IoStatus::too_large — it is never
// dropped silently.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ring_status.hpp"
#include "wait_pace.hpp"
#include "wait_policy.hpp"

namespace swarmnet {

// Fixed rather than std::hardware_destructive_interference_size, which may differ between the
// two builds that share a segment.
inline constexpr std::size_t kCacheLineBytes = 64;
inline constexpr std::uint64_t kRingMagic = 0x474e4952'544e5753ULL;  // "SWNTRING"
// 2: records never wrap (padding marker); closed flags and the fence flag on their own line.
inline constexpr std::uint32_t kRingLayoutVersion = 2;
// In a record's length field: "nothing more before the end of the storage; go to its start".
inline constexpr std::uint32_t kRingPaddingMarker = 0xFFFF'FFFFU;

struct RingHeader {
  // Written once by create(), read-only afterwards.
  alignas(kCacheLineBytes) std::uint64_t magic;
  std::uint32_t layout_version;
  std::uint32_t header_bytes;
  std::uint64_t capacity;  // storage bytes, a power of two
  // Producer's line: written on every publish, read by the consumer when its copy says empty.
  alignas(kCacheLineBytes) std::atomic<std::uint64_t> head;  // bytes ever published
  // Consumer's line: written once per release slice, read by the producer when its copy says
  // full.
  alignas(kCacheLineBytes) std::atomic<std::uint64_t> tail;  // bytes ever released
  // Written once each, read often: on a line of their own, which then stays in both caches
  // instead of moving between cores with every index update.
  alignas(kCacheLineBytes) std::atomic<std::uint32_t> producer_closed;
  std::atomic<std::uint32_t> consumer_closed;
  // Set (never cleared) by a consumer that fences heavily before it sleeps: from then on, a
  // producer registered for asymmetric fences publishes without a full fence.
  std::atomic<std::uint32_t> consumer_fences_heavily;
  // Wake-up words: bumped by the side that made progress, slept on by the other.
  alignas(kCacheLineBytes) std::atomic<std::uint32_t> data_event;
  std::atomic<std::uint32_t> consumer_sleeping;
  alignas(kCacheLineBytes) std::atomic<std::uint32_t> space_event;
  std::atomic<std::uint32_t> producer_sleeping;
};

static_assert(std::atomic<std::uint64_t>::is_always_lock_free);
static_assert(std::atomic<std::uint32_t>::is_always_lock_free);
static_assert(sizeof(RingHeader) == 6 * kCacheLineBytes);
static_assert(offsetof(RingHeader, head) == kCacheLineBytes);
static_assert(offsetof(RingHeader, tail) == 2 * kCacheLineBytes);
static_assert(offsetof(RingHeader, producer_closed) == 3 * kCacheLineBytes);
static_assert(offsetof(RingHeader, data_event) == 4 * kCacheLineBytes);
static_assert(offsetof(RingHeader, space_event) == 5 * kCacheLineBytes);

class SpscRing {
 public:
  // Bytes of memory a ring with `capacity` storage bytes occupies.
  static std::size_t footprint(std::uint64_t capacity) { return sizeof(RingHeader) + capacity; }
  // Bytes the consumer reads before it releases them to the producer in one index store.
  static std::uint64_t release_slice_bytes(std::uint64_t capacity) {
    return std::min<std::uint64_t>(capacity / 4, kMaxReleaseSliceBytes);
  }
  // Longest record a ring of `capacity` bytes takes. A record may have to skip the end of the
  // storage (at most its own size) and the consumer may hold back up to a release slice, so two
  // of the longest records plus a slice fit in the ring: a producer waiting for room always
  // gets it once the consumer has read what was published.
  static std::size_t max_record_bytes(std::uint64_t capacity) {
    return static_cast<std::size_t>((capacity - release_slice_bytes(capacity)) / 2) - kLengthBytes;
  }

  // Initialises a new ring in `memory` (footprint(capacity) bytes, 64-byte aligned).
  // `capacity` must be a power of two >= 64 (else std::invalid_argument).
  static SpscRing create(void* memory, std::uint64_t capacity);
  // Attaches to a ring another party created; on a wrong magic, layout version or size, returns
  // false and says why in `error`.
  static bool attach(void* memory, std::size_t memory_bytes, SpscRing& ring, std::string& error);

  SpscRing() = default;

  [[nodiscard]] std::uint64_t capacity() const { return header_->capacity; }
  [[nodiscard]] std::size_t max_record_bytes() const { return max_record_bytes_; }

  // Producer side, writing in place: reserve() hands out `bytes` contiguous bytes of the ring
  // for one record; the caller fills them and commit() stages the record. A reservation that is
  // not committed is abandoned by the next one.
  //
  // Staged records are invisible to the consumer until publish() shows them all at once, so a
  // batch costs one shared-index store and at most one wake-up instead of one per record (a
  // batch larger than 16 KiB is shown in 16 KiB slices, so that the consumer can start on it).
  // A producer that runs out of room publishes what it staged before it waits.
  IoStatus try_reserve(std::size_t bytes, std::span<std::byte>& space);
  IoStatus reserve(std::size_t bytes, std::span<std::byte>& space, const WaitPolicy& policy);
  void commit();
  void publish();
  // Copying conveniences: write() is reserve(), a copy and commit(); push() also publishes.
  IoStatus try_write(std::span<const std::byte> record);
  IoStatus write(std::span<const std::byte> record, const WaitPolicy& policy);
  IoStatus try_push(std::span<const std::byte> record);
  IoStatus push(std::span<const std::byte> record, const WaitPolicy& policy);
  void close_producer();

  // Consumer side, reading in place: read() hands out the next record as a view of the ring's
  // bytes, valid until release() or the next read (which releases it). Released bytes go back
  // to the producer in slices of release_slice_bytes(), one index store per slice.
  IoStatus try_read(std::span<const std::byte>& record);
  IoStatus read(std::span<const std::byte>& record, const WaitPolicy& policy);
  void release();
  // Copying conveniences: `record` is resized to the record's length.
  IoStatus try_pop(std::vector<std::byte>& record);
  IoStatus pop(std::vector<std::byte>& record, const WaitPolicy& policy);
  void close_consumer();

 private:
  static constexpr std::size_t kLengthBytes = 4;
  static constexpr std::uint64_t kAlign = 8;
  static constexpr std::uint64_t kPublishSliceBytes = std::uint64_t{16} * 1024;
  static constexpr std::uint64_t kMaxReleaseSliceBytes = std::uint64_t{4} * 1024;
  static std::uint64_t padded(std::uint64_t bytes) { return (bytes + kAlign - 1) & ~(kAlign - 1); }

  void consume(std::uint64_t bytes);
  void announce_consumer();
  void publish_tail();
  // Copies `record` into reserved `space` and commits it.
  void commit_copy(std::span<std::byte> space, std::span<const std::byte> record);
  void wake_consumer();
  void wake_producer();

  RingHeader* header_ = nullptr;
  std::byte* storage_ = nullptr;
  std::uint64_t capacity_ = 0;  // private copies of header fields that never change
  std::uint64_t mask_ = 0;
  std::uint64_t release_slice_ = 0;
  std::size_t max_record_bytes_ = 0;
  bool asymmetric_fences_ = false;  // this process may use light and heavy fences
  // Producer. Each side keeps a private copy of the other side's index and re-reads it (acquire)
  // only when the copy says the ring is full (producer) or empty (consumer), and a private copy
  // of its own published index, so the common case touches no line the other side writes.
  std::uint64_t cached_tail_ = 0;
  std::uint64_t write_head_ = 0;      // end of staged records, published or not
  std::uint64_t published_head_ = 0;  // last value stored to header_->head
  std::uint64_t reserved_at_ = 0;     // the open reservation's length field
  std::size_t reserved_bytes_ = 0;
  bool reserved_ = false;
  // Consumer.
  std::uint64_t cached_head_ = 0;
  std::uint64_t read_tail_ = 0;       // end of what was read (and skipped), released or not
  std::uint64_t held_bytes_ = 0;      // footprint of the record handed out by read(), if any
  std::uint64_t published_tail_ = 0;  // last value stored to header_->tail
  bool announced_ = false;            // consumer_fences_heavily settled for this consumer
  // How quickly the peer lately answered this end's waits for data (consumer) and for room
  // (producer).
  WaitPace data_pace_;
  WaitPace space_pace_;
};

}  // namespace swarmnet
