#include "spsc_ring.hpp"

#include <sched.h>

#include <chrono>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "futex.hpp"

namespace swarmnet {

namespace {

bool is_power_of_two(std::uint64_t x) { return x != 0 && (x & (x - 1)) == 0; }

inline void cpu_relax() { __builtin_ia32_pause(); }

}  // namespace

SpscRing SpscRing::create(void* memory, std::uint64_t capacity) {
  if (!is_power_of_two(capacity) || capacity < 64) {
    throw std::invalid_argument("ring capacity " + std::to_string(capacity) +
                                " is not a power of two >= 64");
  }
  SpscRing ring;
  auto* header = new (memory) RingHeader{};
  header->magic = kRingMagic;
  header->layout_version = kRingLayoutVersion;
  header->header_bytes = sizeof(RingHeader);
  header->capacity = capacity;
  ring.header_ = header;
  ring.storage_ = static_cast<std::byte*>(memory) + sizeof(RingHeader);
  ring.mask_ = capacity - 1;
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
  if (!is_power_of_two(header->capacity) || footprint(header->capacity) > memory_bytes) {
    error = "ring capacity " + std::to_string(header->capacity) + " does not fit its " +
            std::to_string(memory_bytes) + "-byte memory";
    return false;
  }
  ring.header_ = header;
  ring.storage_ = static_cast<std::byte*>(memory) + sizeof(RingHeader);
  ring.mask_ = header->capacity - 1;
  ring.cached_head_ = header->head.load(std::memory_order_acquire);
  ring.write_head_ = ring.cached_head_;
  ring.cached_tail_ = header->tail.load(std::memory_order_acquire);
  return true;
}

void SpscRing::copy_in(std::uint64_t position, const std::byte* source, std::size_t bytes) {
  if (bytes == 0) return;  // an empty record's data() may be null, which memcpy must not get
  const std::uint64_t offset = position & mask_;
  const std::size_t first = std::min<std::uint64_t>(bytes, header_->capacity - offset);
  std::memcpy(storage_ + offset, source, first);
  if (first < bytes) std::memcpy(storage_, source + first, bytes - first);
}

void SpscRing::copy_out(std::uint64_t position, std::byte* target, std::size_t bytes) const {
  if (bytes == 0) return;
  const std::uint64_t offset = position & mask_;
  const std::size_t first = std::min<std::uint64_t>(bytes, header_->capacity - offset);
  std::memcpy(target, storage_ + offset, first);
  if (first < bytes) std::memcpy(target + first, storage_, bytes - first);
}

IoStatus SpscRing::try_write(std::span<const std::byte> record) {
  if (record.size() > max_record_bytes()) return IoStatus::too_large;
  if (header_->consumer_closed.load(std::memory_order_acquire) != 0) return IoStatus::closed;
  const std::uint64_t need = padded(kLengthBytes + record.size());
  if (write_head_ + need - cached_tail_ > header_->capacity) {
    cached_tail_ = header_->tail.load(std::memory_order_acquire);
    if (write_head_ + need - cached_tail_ > header_->capacity) return IoStatus::would_block;
  }
  const auto length = static_cast<std::uint32_t>(record.size());
  copy_in(write_head_, reinterpret_cast<const std::byte*>(&length), kLengthBytes);
  copy_in(write_head_ + kLengthBytes, record.data(), record.size());
  write_head_ += need;
  // A large batch is shown in slices, so the consumer decodes while the producer still writes.
  if (write_head_ - header_->head.load(std::memory_order_relaxed) >= kPublishSliceBytes) publish();
  return IoStatus::ok;
}

void SpscRing::publish() {
  if (header_->head.load(std::memory_order_relaxed) == write_head_) return;
  // seq_cst, not release: the store must be ordered before the load of consumer_sleeping in
  // wake_consumer(), or a consumer going to sleep could miss these records.
  header_->head.store(write_head_, std::memory_order_seq_cst);
  wake_consumer();
}

IoStatus SpscRing::try_push(std::span<const std::byte> record) {
  const IoStatus status = try_write(record);
  if (status == IoStatus::ok) publish();
  return status;
}

IoStatus SpscRing::try_pop(std::vector<std::byte>& record) {
  const std::uint64_t tail = header_->tail.load(std::memory_order_relaxed);
  if (cached_head_ - tail < kLengthBytes) {
    // Read `closed` before `head`: records pushed before the close are still delivered.
    const bool closed = header_->producer_closed.load(std::memory_order_acquire) != 0;
    cached_head_ = header_->head.load(std::memory_order_acquire);
    if (cached_head_ == tail) return closed ? IoStatus::closed : IoStatus::would_block;
  }
  const std::uint64_t available = cached_head_ - tail;
  if (available < kLengthBytes || available > header_->capacity) return IoStatus::corrupt;
  std::uint32_t length = 0;
  copy_out(tail, reinterpret_cast<std::byte*>(&length), kLengthBytes);
  const std::uint64_t need = padded(kLengthBytes + length);
  if (length > max_record_bytes() || need > available) return IoStatus::corrupt;
  // assign/insert copy straight in: resize() would zero-fill the buffer first.
  const std::uint64_t offset = (tail + kLengthBytes) & mask_;
  const std::size_t first = std::min<std::uint64_t>(length, header_->capacity - offset);
  record.assign(storage_ + offset, storage_ + offset + first);
  record.insert(record.end(), storage_, storage_ + (length - first));
  header_->tail.store(tail + need, std::memory_order_seq_cst);
  wake_producer();
  return IoStatus::ok;
}

void SpscRing::wake_consumer() {
  if (header_->consumer_sleeping.load(std::memory_order_seq_cst) != 0) {
    header_->data_event.fetch_add(1, std::memory_order_release);
    futex_wake_all(header_->data_event);
  }
}

void SpscRing::wake_producer() {
  if (header_->producer_sleeping.load(std::memory_order_seq_cst) != 0) {
    header_->space_event.fetch_add(1, std::memory_order_release);
    futex_wake_all(header_->space_event);
  }
}

namespace {

// Retries `attempt` until it stops returning would_block: spins first, then sleeps on `event`
// (announcing itself in `sleeping`) in slices, checking the deadline and the peer in between.
template <typename Attempt>
IoStatus wait_for(Attempt&& attempt, std::atomic<std::uint32_t>& event,
                  std::atomic<std::uint32_t>& sleeping, const WaitPolicy& policy) {
  IoStatus status = attempt();
  if (status != IoStatus::would_block) return status;
  // The clock bounds how long we spin and wait; it never reaches a result.
  const auto spin_until = std::chrono::steady_clock::now() + policy.spin_time;
  for (std::uint32_t i = 1; status == IoStatus::would_block; ++i) {
    cpu_relax();
    status = attempt();
    if (i % 32 == 0 && std::chrono::steady_clock::now() >= spin_until) break;
  }
  // On a machine with fewer free cores than runnable threads, spinning only delays the peer we
  // wait for: give the core away a few times before sleeping.
  for (std::uint32_t i = 0; status == IoStatus::would_block && i < policy.yield_iterations; ++i) {
    sched_yield();
    status = attempt();
  }
  if (status != IoStatus::would_block) return status;
  const auto deadline = std::chrono::steady_clock::now() + policy.timeout;
  for (;;) {
    const std::uint32_t seen = event.load(std::memory_order_acquire);
    sleeping.store(1, std::memory_order_seq_cst);
    // Orders the announcement before re-reading the ring, pairing with the seq_cst index store
    // and flag load in the other side's wake_*(): one of the two sides sees the other.
    std::atomic_thread_fence(std::memory_order_seq_cst);
    status = attempt();
    if (status == IoStatus::would_block) futex_wait(event, seen, policy.sleep_slice);
    sleeping.store(0, std::memory_order_relaxed);
    if (status != IoStatus::would_block) return status;
    status = attempt();
    if (status != IoStatus::would_block) return status;
    if (policy.peer_alive && !policy.peer_alive()) return IoStatus::peer_dead;
    if (std::chrono::steady_clock::now() >= deadline) return IoStatus::timeout;
  }
}

}  // namespace

IoStatus SpscRing::write(std::span<const std::byte> record, const WaitPolicy& policy) {
  IoStatus status = try_write(record);
  if (status != IoStatus::would_block) return status;
  publish();  // the consumer can only make room by reading what is staged
  return wait_for([&] { return try_write(record); }, header_->space_event,
                  header_->producer_sleeping, policy);
}

IoStatus SpscRing::push(std::span<const std::byte> record, const WaitPolicy& policy) {
  const IoStatus status = write(record, policy);
  if (status == IoStatus::ok) publish();
  return status;
}

IoStatus SpscRing::pop(std::vector<std::byte>& record, const WaitPolicy& policy) {
  return wait_for([&] { return try_pop(record); }, header_->data_event, header_->consumer_sleeping,
                  policy);
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
