// Little-endian field encoding for transport records, with bounds-checked decoding: a short or
// inconsistent record is reported, never read past.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace swarmnet {

static_assert(std::endian::native == std::endian::little,
              "records are little-endian; a big-endian port needs byte swaps here");

class RecordWriter {
 public:
  explicit RecordWriter(std::vector<std::byte>& buffer) : buffer_(buffer) { buffer_.clear(); }

  template <typename T>
  RecordWriter& put(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* bytes = reinterpret_cast<const std::byte*>(&value);
    buffer_.insert(buffer_.end(), bytes, bytes + sizeof(T));
    return *this;
  }
  RecordWriter& put_bytes(std::span<const std::byte> bytes) {
    put(static_cast<std::uint32_t>(bytes.size()));
    buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
    return *this;
  }

 private:
  std::vector<std::byte>& buffer_;
};

class RecordReader {
 public:
  explicit RecordReader(std::span<const std::byte> record) : record_(record) {}

  // Each get returns false (and leaves `value` untouched) when the record is too short.
  template <typename T>
  bool get(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    if (record_.size() - position_ < sizeof(T)) return false;
    std::memcpy(&value, record_.data() + position_, sizeof(T));
    position_ += sizeof(T);
    return true;
  }
  bool get_bytes(std::vector<std::byte>& bytes, std::uint32_t max_bytes) {
    std::uint32_t length = 0;
    if (!get(length) || length > max_bytes || record_.size() - position_ < length) return false;
    bytes.assign(record_.begin() + static_cast<std::ptrdiff_t>(position_),
                 record_.begin() + static_cast<std::ptrdiff_t>(position_ + length));
    position_ += length;
    return true;
  }
  [[nodiscard]] bool at_end() const { return position_ == record_.size(); }
  [[nodiscard]] std::size_t remaining() const { return record_.size() - position_; }

 private:
  std::span<const std::byte> record_;
  std::size_t position_ = 0;
};

}  // namespace swarmnet
