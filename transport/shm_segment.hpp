// The shared-memory segment that joins the two processes of a run: a header and two SpscRings
// (robot -> network, network -> robot), in a POSIX shared-memory object (Boost.Interprocess).
//
// The segment is private to the user (mode 0600) and named "swarmnet-<pid>-<128 random bits>",
// so another user's process can neither open nor guess it. The creator removes the name as soon
// as the peer has attached (both keep their mappings), so a crash after that leaves nothing
// behind; remove_stale_segments() cleans names left by a run that died before.
#pragma once

#include <boost/interprocess/mapped_region.hpp>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "spsc_ring.hpp"

namespace swarmnet {

inline constexpr std::uint64_t kSegmentMagic = 0x544e454d'47455357ULL;  // "SWSEGMENT"-ish
// 2: the rings inside it are ring layout version 2 (a larger ring header moves the second ring).
inline constexpr std::uint32_t kSegmentLayoutVersion = 2;

struct SegmentHeader {
  alignas(kCacheLineBytes) std::uint64_t magic;
  std::uint32_t layout_version;
  std::uint32_t creator_pid;
  std::uint64_t ring_bytes;
  std::uint64_t total_bytes;
};

class ShmSegment {
 public:
  // Creates a new segment with two rings of `ring_bytes` each. Throws TransportError.
  static std::unique_ptr<ShmSegment> create(std::uint64_t ring_bytes);
  // Opens the segment `name` created by another process and checks its header and rings.
  // Throws TransportError naming the segment and what does not match.
  static std::unique_ptr<ShmSegment> attach(const std::string& name);

  ShmSegment(const ShmSegment&) = delete;
  ShmSegment& operator=(const ShmSegment&) = delete;
  ShmSegment(ShmSegment&&) = delete;
  ShmSegment& operator=(ShmSegment&&) = delete;
  ~ShmSegment();  // the creator removes the name if still there

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] std::uint64_t ring_bytes() const { return header()->ring_bytes; }
  // Removes the segment's name; the mappings stay valid. Idempotent.
  void remove_name();

  [[nodiscard]] SpscRing robot_to_network() const { return to_network_; }
  [[nodiscard]] SpscRing network_to_robot() const { return to_robot_; }

  // Offsets of the two rings in a segment with `ring_bytes` rings; total size.
  static std::size_t ring_offset(int index, std::uint64_t ring_bytes);
  static std::size_t total_bytes(std::uint64_t ring_bytes);

 private:
  ShmSegment() = default;
  [[nodiscard]] SegmentHeader* header() const {
    return static_cast<SegmentHeader*>(region_.get_address());
  }

  std::string name_;
  bool creator_ = false;
  bool named_ = false;
  boost::interprocess::mapped_region region_;
  SpscRing to_network_;
  SpscRing to_robot_;
};

// Removes segments named swarmnet-<pid>-* whose creating process no longer runs; returns their
// names. Segments of live runs are left alone.
std::vector<std::string> remove_stale_segments();

}  // namespace swarmnet
