// libFuzzer target: a shared-memory ring whose header and storage another process corrupted.
// The input overwrites the header's fields and the storage; attach() must refuse a bad header
// and reads must report corrupt framing, never read outside the ring.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "spsc_ring.hpp"

namespace {

constexpr std::uint64_t kCapacity = 4096;

struct AlignedFree {
  void operator()(void* p) const { std::free(p); }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace swarmnet;
  const std::size_t bytes = SpscRing::footprint(kCapacity);
  std::unique_ptr<void, AlignedFree> memory(std::aligned_alloc(kCacheLineBytes, bytes));
  (void)SpscRing::create(memory.get(), kCapacity);
  auto* header = static_cast<RingHeader*>(memory.get());
  // The first bytes choose which header fields a faulty peer changed, then their new values;
  // the rest is the storage's content.
  std::size_t at = 0;
  auto take = [&](void* field, std::size_t n) {
    if (at + n > size) return false;
    std::memcpy(field, data + at, n);
    at += n;
    return true;
  };
  std::uint8_t which = 0;
  if (take(&which, 1)) {
    std::uint64_t value = 0;
    if ((which & 1U) != 0 && take(&value, 8)) header->magic = value;
    if ((which & 2U) != 0 && take(&value, 4))
      header->layout_version = static_cast<std::uint32_t>(value);
    if ((which & 4U) != 0 && take(&value, 8)) header->capacity = value;
    if ((which & 8U) != 0 && take(&value, 8)) header->head.store(value);
    if ((which & 16U) != 0 && take(&value, 8)) header->tail.store(value);
  }
  auto* storage = static_cast<std::uint8_t*>(memory.get()) + sizeof(RingHeader);
  const std::size_t rest = size - at < kCapacity ? size - at : kCapacity;
  if (rest > 0) std::memcpy(storage, data + at, rest);

  SpscRing ring;
  std::string error;
  if (!SpscRing::attach(memory.get(), bytes, ring, error)) return 0;
  std::span<const std::byte> record;
  for (int i = 0; i < 256; ++i) {
    if (ring.try_read(record) != IoStatus::ok) break;
    ring.release();
  }
  return 0;
}
