#include "spsc_ring.hpp"

#include <chrono>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "asymmetric_fence.hpp"
#include "futex.hpp"

namespace swarmnet {

namespace {

bool is_power_of_two(std::uint64_t x) { return x != 0 && (x & (x - 1)) == 0; }

}  // namespace

SpscRing SpscRing::create(void* memory, std::uint64_t capacity) {
  if (!is_power_of_two(capacity) || capacity < 64) {
    throw std::invalid_argument("ring capacity " + std::to_string(capacity) +
                                " is not a power of two >= 64");
  }
  auto* header = new (memory) RingHeader{};
  header->magic = kRingMagic;
  header->layout_version = kRingLayoutVersion;
  header->header_bytes = sizeof(RingHeader);
  header->capacity = capacity;
  SpscRing ring;
  std::string ignored;
  attach(memory, footprint(capacity), ring, ignored);
  return ring;
}

bool SpscRing::attach(void* memory, std::size_t memory_bytes, SpscRing& ring, std::string& error) {
  if (memory_bytes < sizeof(RingHeader)) {
    error = "ring memory of " + std::to_string(memory_bytes) + " bytes is smaller than its header";
    return false;
  }
  auto* header = static_cast<RingHeader*>(memory);
  if (header->magic != kRingMagic) {
    error = "not a SwarmNet ring (bad magic number)";
    return false;
  }
  if (header->layout_version != kRingLayoutVersion || header->header_bytes != sizeof(RingHeader)) {
    error = "ring layout version " + std::to_string(header->layout_version) + " (header " +
            std::to_string(header->header_bytes) + " bytes), expected version " +
            std::to_string(kRingLayoutVersion) + " (header " + std::to_string(sizeof(RingHeader)) +
            " bytes)";
    return false;
  }
  if (!is_power_of_two(header->capacity) || header->capacity < 64 ||
      footprint(header->capacity) > memory_bytes) {
    error = "ring capacity " + std::to_string(header->capacity) + " does not fit its " +
            std::to_string(memory_bytes) + "-byte memory";
    return false;
  }
  ring = SpscRing();
  ring.header_ = header;
  ring.storage_ = static_cast<std::byte*>(memory) + sizeof(RingHeader);
  ring.capacity_ = header->capacity;
  ring.mask_ = header->capacity - 1;
  ring.release_slice_ = release_slice_bytes(header->capacity);
  ring.max_record_bytes_ = max_record_bytes(header->capacity);
  ring.asymmetric_fences_ = asymmetric_fences_available();
  ring.published_head_ = header->head.load(std::memory_order_acquire);
  ring.write_head_ = ring.published_head_;
  ring.cached_head_ = ring.published_head_;
  ring.published_tail_ = header->tail.load(std::memory_order_acquire);
  ring.read_tail_ = ring.published_tail_;
  ring.cached_tail_ = ring.published_tail_;
  return true;
}

IoStatus SpscRing::try_reserve(std::size_t bytes, std::span<std::byte>& space) {
  if (bytes > max_record_bytes_) return IoStatus::too_large;
  if (header_->consumer_closed.load(std::memory_order_acquire) != 0) return IoStatus::closed;
  const std::uint64_t need = padded(kLengthBytes + bytes);
  const std::uint64_t offset = write_head_ & mask_;
  // A record never wraps: one that would cross the end starts again at the beginning.
  const std::uint64_t skip = offset + need > capacity_ ? capacity_ - offset : 0;
  const std::uint64_t end = write_head_ + skip + need;
  if (end - cached_tail_ > capacity_) {
    cached_tail_ = header_->tail.load(std::memory_order_acquire);
    if (end - cached_tail_ > capacity_) return IoStatus::would_block;
  }
  // The marker lies in free space and is published only together with the record after it.
  if (skip != 0) std::memcpy(storage_ + offset, &kRingPaddingMarker, kLengthBytes);
  reserved_at_ = write_head_ + skip;
  reserved_bytes_ = bytes;
  reserved_ = true;
  space = {storage_ + (reserved_at_ & mask_) + kLengthBytes, bytes};
  return IoStatus::ok;
}

void SpscRing::commit() {
  if (!reserved_) return;
  const auto length = static_cast<std::uint32_t>(reserved_bytes_);
  std::memcpy(storage_ + (reserved_at_ & mask_), &length, kLengthBytes);
  write_head_ = reserved_at_ + padded(kLengthBytes + reserved_bytes_);
  reserved_ = false;
  // A large batch is shown in slices, so the consumer decodes while the producer still writes.
  if (write_head_ - published_head_ >= kPublishSliceBytes) publish();
}

void SpscRing::publish() {
  if (write_head_ == published_head_) return;
  published_head_ = write_head_;
  // We store head, then load consumer_sleeping (wake_consumer); a consumer going to sleep stores
  // consumer_sleeping, then loads head (wait_for). A fence between store and load on each side
  // makes at least one of the two see the other's store: no wake-up is lost. A full fence here
  // (a seq_cst store) waits for every earlier store to reach the cache, which is half the cost
  // of publishing a lone record. When the consumer fences heavily (membarrier: a full fence on
  // this CPU at some instant T during its call), a compiler barrier does: if T falls between our
  // store and our load, or before our store, our load sees its flag; if T falls after our load,
  // our store was visible before the consumer re-reads head.
  if (asymmetric_fences_ && header_->consumer_fences_heavily.load(std::memory_order_relaxed) != 0) {
    header_->head.store(write_head_, std::memory_order_release);
    light_fence();
  } else {
    header_->head.store(write_head_, std::memory_order_seq_cst);
  }
  wake_consumer();
}

IoStatus SpscRing::try_write(std::span<const std::byte> record) {
  std::span<std::byte> space;
  const IoStatus status = try_reserve(record.size(), space);
  if (status == IoStatus::ok) commit_copy(space, record);
  return status;
}

void SpscRing::commit_copy(std::span<std::byte> space, std::span<const std::byte> record) {
  // An empty record's data() may be null, which memcpy must not get.
  if (!record.empty()) std::memcpy(space.data(), record.data(), record.size());
  commit();
}

IoStatus SpscRing::try_push(std::span<const std::byte> record) {
  const IoStatus status = try_write(record);
  if (status == IoStatus::ok) publish();
  return status;
}

IoStatus SpscRing::try_read(std::span<const std::byte>& record) {
  if (!announced_) announce_consumer();
  release();
  for (;;) {
    if (cached_head_ == read_tail_) {
      // Read `closed` before `head`: records published before the close are still delivered.
      const bool closed = header_->producer_closed.load(std::memory_order_acquire) != 0;
      cached_head_ = header_->head.load(std::memory_order_acquire);
      if (cached_head_ == read_tail_) return closed ? IoStatus::closed : IoStatus::would_block;
    }
    const std::uint64_t available = cached_head_ - read_tail_;
    const std::uint64_t offset = read_tail_ & mask_;
    // A length field always fits before the storage's end (records are padded): indices that
    // say otherwise were written by a faulty peer (found by fuzzing).
    if (available > capacity_ || available < kLengthBytes || offset + kLengthBytes > capacity_) {
      return IoStatus::corrupt;
    }
    std::uint32_t length = 0;
    std::memcpy(&length, storage_ + offset, kLengthBytes);
    if (length == kRingPaddingMarker) {
      if (capacity_ - offset > available) return IoStatus::corrupt;
      consume(capacity_ - offset);
      continue;
    }
    const std::uint64_t need = padded(kLengthBytes + length);
    if (length > max_record_bytes_ || need > available || offset + need > capacity_) {
      return IoStatus::corrupt;
    }
    record = {storage_ + offset + kLengthBytes, length};
    held_bytes_ = need;
    return IoStatus::ok;
  }
}

void SpscRing::announce_consumer() {
  // Before this consumer's first wait, so that every sleep after a producer saw the flag fences
  // heavily.
  announced_ = true;
  if (asymmetric_fences_) header_->consumer_fences_heavily.store(1, std::memory_order_seq_cst);
}

void SpscRing::release() {
  if (held_bytes_ == 0) return;
  consume(held_bytes_);
  held_bytes_ = 0;
}

void SpscRing::consume(std::uint64_t bytes) {
  read_tail_ += bytes;
  // One index store per slice rather than per record: the line holding `tail` then moves to the
  // producer's core once per slice. max_record_bytes() leaves room for what is held back.
  if (read_tail_ - published_tail_ >= release_slice_) publish_tail();
}

void SpscRing::publish_tail() {
  published_tail_ = read_tail_;
  // seq_cst for the same reason as in publish(), pairing with producer_sleeping.
  header_->tail.store(read_tail_, std::memory_order_seq_cst);
  wake_producer();
}

IoStatus SpscRing::try_pop(std::vector<std::byte>& record) {
  std::span<const std::byte> view;
  const IoStatus status = try_read(view);
  if (status != IoStatus::ok) return status;
  record.assign(view.begin(), view.end());
  release();
  return IoStatus::ok;
}

// The flag is taken, not only read: a batch shown in several slices, or a publish and a close,
// wake a sleeping peer once, not once per publish, and the wake is one system call.
void SpscRing::wake_consumer() {
  if (header_->consumer_sleeping.load(std::memory_order_seq_cst) != 0 &&
      header_->consumer_sleeping.exchange(0, std::memory_order_seq_cst) != 0) {
    header_->data_event.fetch_add(1, std::memory_order_release);
    futex_wake_all(header_->data_event);
  }
}

void SpscRing::wake_producer() {
  if (header_->producer_sleeping.load(std::memory_order_seq_cst) != 0 &&
      header_->producer_sleeping.exchange(0, std::memory_order_seq_cst) != 0) {
    header_->space_event.fetch_add(1, std::memory_order_release);
    futex_wake_all(header_->space_event);
  }
}

namespace {

// Retries `attempt` until it stops returning would_block: spins and yields as `pace` plans, then
// sleeps on `event` (announcing itself in `sleeping`) in slices, checking the deadline and the
// peer in between. A waker clears `sleeping` when it wakes this side.
// `heavy`: the side that wakes this one may fence lightly (see publish()), so this one fences
// heavily; that costs microseconds, once per sleep, after tens of microseconds of spinning.
template <typename Attempt>
IoStatus wait_for(Attempt&& attempt, std::atomic<std::uint32_t>& event,
                  std::atomic<std::uint32_t>& sleeping, const WaitPolicy& policy, WaitPace& pace,
                  bool heavy) {
  IoStatus status = attempt();
  if (status != IoStatus::would_block) return status;
  const auto start = std::chrono::steady_clock::now();
  const auto done = [&] {
    status = attempt();
    return status != IoStatus::would_block;
  };
  const auto answered = [&] {
    pace.record(std::chrono::steady_clock::now() - start, policy);
    return status;
  };
  if (spin_then_yield(pace.plan(policy, spinning_can_pay(start)), start, done)) return answered();
  WaitDeadline deadline(policy);
  for (;;) {
    const std::uint32_t seen = event.load(std::memory_order_acquire);
    sleeping.store(1, std::memory_order_seq_cst);
    // Orders the announcement before re-reading the ring, pairing with the fenced index store
    // and flag load in the other side's wake_*(): one of the two sides sees the other.
    if (heavy) {
      heavy_fence();
    } else {
      std::atomic_thread_fence(std::memory_order_seq_cst);
    }
    status = attempt();
    if (status == IoStatus::would_block) futex_wait(event, seen, policy.sleep_slice);
    sleeping.store(0, std::memory_order_relaxed);
    if (status != IoStatus::would_block) return answered();
    status = attempt();
    if (status != IoStatus::would_block) return answered();
    if (policy.peer_alive && !policy.peer_alive()) return IoStatus::peer_dead;
    if (deadline.passed(std::chrono::steady_clock::now())) return IoStatus::timeout;
  }
}

}  // namespace

IoStatus SpscRing::reserve(std::size_t bytes, std::span<std::byte>& space,
                           const WaitPolicy& policy) {
  IoStatus status = try_reserve(bytes, space);
  if (status != IoStatus::would_block) return status;
  publish();  // the consumer can only make room by reading what is staged
  // The consumer gives space back with a full fence (once per release slice): no heavy fence.
  return wait_for([&] { return try_reserve(bytes, space); }, header_->space_event,
                  header_->producer_sleeping, policy, space_pace_, false);
}

IoStatus SpscRing::write(std::span<const std::byte> record, const WaitPolicy& policy) {
  std::span<std::byte> space;
  const IoStatus status = reserve(record.size(), space, policy);
  if (status == IoStatus::ok) commit_copy(space, record);
  return status;
}

IoStatus SpscRing::push(std::span<const std::byte> record, const WaitPolicy& policy) {
  const IoStatus status = write(record, policy);
  if (status == IoStatus::ok) publish();
  return status;
}

IoStatus SpscRing::read(std::span<const std::byte>& record, const WaitPolicy& policy) {
  return wait_for([&] { return try_read(record); }, header_->data_event, header_->consumer_sleeping,
                  policy, data_pace_, asymmetric_fences_);
}

IoStatus SpscRing::pop(std::vector<std::byte>& record, const WaitPolicy& policy) {
  return wait_for([&] { return try_pop(record); }, header_->data_event, header_->consumer_sleeping,
                  policy, data_pace_, asymmetric_fences_);
}

void SpscRing::close_producer() {
  publish();
  header_->producer_closed.store(1, std::memory_order_seq_cst);
  header_->data_event.fetch_add(1, std::memory_order_release);
  futex_wake_all(header_->data_event);
}

void SpscRing::close_consumer() {
  header_->consumer_closed.store(1, std::memory_order_seq_cst);
  header_->space_event.fetch_add(1, std::memory_order_release);
  futex_wake_all(header_->space_event);
}

}  // namespace swarmnet
