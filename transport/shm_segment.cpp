#include "shm_segment.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <boost/interprocess/permissions.hpp>
#include <boost/interprocess/shared_memory_object.hpp>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "transport_error.hpp"

namespace swarmnet {

namespace bip = boost::interprocess;

namespace {

constexpr const char* kNamePrefix = "swarmnet-";
constexpr std::size_t kHeaderBytes = 2 * kCacheLineBytes;

// 128 bits from the kernel's random source: the name must not be guessable. Never reaches a
// simulation result.
std::string random_hex() {
  std::ifstream urandom("/dev/urandom", std::ios::binary);
  unsigned char bytes[16] = {};
  urandom.read(reinterpret_cast<char*>(bytes), sizeof bytes);
  if (!urandom) throw TransportError("cannot read /dev/urandom to name the shared-memory segment");
  std::string hex;
  char digits[3];
  for (unsigned char b : bytes) {
    std::snprintf(digits, sizeof digits, "%02x", b);
    hex += digits;
  }
  return hex;
}

}  // namespace

std::size_t ShmSegment::ring_offset(int index, std::uint64_t ring_bytes) {
  return kHeaderBytes + static_cast<std::size_t>(index) * SpscRing::footprint(ring_bytes);
}

std::size_t ShmSegment::total_bytes(std::uint64_t ring_bytes) { return ring_offset(2, ring_bytes); }

std::unique_ptr<ShmSegment> ShmSegment::create(std::uint64_t ring_bytes) {
  std::unique_ptr<ShmSegment> segment(new ShmSegment());
  segment->name_ = kNamePrefix + std::to_string(::getpid()) + "-" + random_hex();
  try {
    bip::permissions owner_only(0600);
    bip::shared_memory_object object(bip::create_only, segment->name_.c_str(), bip::read_write,
                                     owner_only);
    segment->creator_ = true;
    segment->named_ = true;
    object.truncate(static_cast<bip::offset_t>(total_bytes(ring_bytes)));
    segment->region_ = bip::mapped_region(object, bip::read_write);
  } catch (const bip::interprocess_exception& error) {
    throw TransportError("cannot create shared-memory segment /dev/shm/" + segment->name_ + ": " +
                         error.what());
  }
  auto* base = static_cast<std::byte*>(segment->region_.get_address());
  segment->to_network_ = SpscRing::create(base + ring_offset(0, ring_bytes), ring_bytes);
  segment->to_robot_ = SpscRing::create(base + ring_offset(1, ring_bytes), ring_bytes);
  SegmentHeader* header = segment->header();
  header->layout_version = kSegmentLayoutVersion;
  header->creator_pid = static_cast<std::uint32_t>(::getpid());
  header->ring_bytes = ring_bytes;
  header->total_bytes = total_bytes(ring_bytes);
  // Magic last: a peer that sees it sees a complete segment.
  __atomic_store_n(&header->magic, kSegmentMagic, __ATOMIC_RELEASE);
  return segment;
}

std::unique_ptr<ShmSegment> ShmSegment::attach(const std::string& name) {
  std::unique_ptr<ShmSegment> segment(new ShmSegment());
  segment->name_ = name;
  try {
    bip::shared_memory_object object(bip::open_only, name.c_str(), bip::read_write);
    segment->region_ = bip::mapped_region(object, bip::read_write);
  } catch (const bip::interprocess_exception& error) {
    throw TransportError("cannot open shared-memory segment /dev/shm/" + name + ": " +
                         error.what());
  }
  const std::size_t mapped = segment->region_.get_size();
  const SegmentHeader* header = segment->header();
  auto refuse = [&](const std::string& why) {
    return TransportError("shared-memory segment /dev/shm/" + name + " " + why);
  };
  if (mapped < sizeof(SegmentHeader) ||
      __atomic_load_n(&header->magic, __ATOMIC_ACQUIRE) != kSegmentMagic) {
    throw refuse("is not a SwarmNet segment (bad magic number)");
  }
  if (header->layout_version != kSegmentLayoutVersion) {
    throw refuse("has layout version " + std::to_string(header->layout_version) +
                 ", this SwarmNet expects " + std::to_string(kSegmentLayoutVersion));
  }
  if (header->total_bytes != mapped || total_bytes(header->ring_bytes) != mapped) {
    throw refuse("is " + std::to_string(mapped) + " bytes, its header says " +
                 std::to_string(header->total_bytes));
  }
  auto* base = static_cast<std::byte*>(segment->region_.get_address());
  const std::uint64_t ring_bytes = header->ring_bytes;
  std::string error;
  if (!SpscRing::attach(base + ring_offset(0, ring_bytes), SpscRing::footprint(ring_bytes),
                        segment->to_network_, error) ||
      !SpscRing::attach(base + ring_offset(1, ring_bytes), SpscRing::footprint(ring_bytes),
                        segment->to_robot_, error)) {
    throw refuse("has a bad ring: " + error);
  }
  return segment;
}

ShmSegment::~ShmSegment() {
  if (creator_) remove_name();
}

void ShmSegment::remove_name() {
  if (!named_ && !creator_) return;
  if (named_) bip::shared_memory_object::remove(name_.c_str());
  named_ = false;
}

std::vector<std::string> remove_stale_segments() {
  std::vector<std::string> removed;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/dev/shm", ec)) {
    const std::string file = entry.path().filename().string();
    if (!file.starts_with(kNamePrefix)) continue;
    const std::string rest = file.substr(std::char_traits<char>::length(kNamePrefix));
    const auto dash = rest.find('-');
    if (dash == std::string::npos) continue;
    const long pid = std::strtol(rest.substr(0, dash).c_str(), nullptr, 10);
    if (pid <= 0) continue;
    // Only our own segments can be opened (mode 0600); ESRCH: the creator is gone.
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      if (bip::shared_memory_object::remove(file.c_str())) removed.push_back(file);
    }
  }
  std::sort(removed.begin(), removed.end());
  return removed;
}

}  // namespace swarmnet
