// Little-endian field encoding for transport records, written into and read from a record's
// bytes where they lie (the transport's buffer), bounds-checked both ways: a writer never writes
// past its space, a short or inconsistent record is reported, never read past.
//
// A field is a number (or an enum) as its bytes, or a byte string as a 4-byte length and the
// bytes. encoded_bytes() of a record's fields is the space to reserve for it.
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

template <typename T>
concept RecordScalar = std::is_arithmetic_v<T> || std::is_enum_v<T>;

template <RecordScalar T>
constexpr std::size_t encoded_bytes(T /*value*/) {
  return sizeof(T);
}
inline std::size_t encoded_bytes(std::span<const std::byte> bytes) {
  return sizeof(std::uint32_t) + bytes.size();
}

class RecordWriter {
 public:
  explicit RecordWriter(std::span<std::byte> space) : space_(space) {}

  template <RecordScalar T>
  RecordWriter& put(T value) {
    if (space_.size() - position_ < sizeof(T)) return *this;  // sized by encoded_bytes: never
    std::memcpy(space_.data() + position_, &value, sizeof(T));
    position_ += sizeof(T);
    return *this;
  }
  RecordWriter& put(std::span<const std::byte> bytes) {
    if (space_.size() - position_ < encoded_bytes(bytes)) return *this;
    put(static_cast<std::uint32_t>(bytes.size()));
    if (!bytes.empty()) std::memcpy(space_.data() + position_, bytes.data(), bytes.size());
    position_ += bytes.size();
    return *this;
  }

 private:
  std::span<std::byte> space_;
  std::size_t position_ = 0;
};

class RecordReader {
 public:
  explicit RecordReader(std::span<const std::byte> record) : record_(record) {}

  // Each get returns false (and leaves `value` untouched) when the record is too short.
  template <RecordScalar T>
  bool get(T& value) {
    if (record_.size() - position_ < sizeof(T)) return false;
    std::memcpy(&value, record_.data() + position_, sizeof(T));
    position_ += sizeof(T);
    return true;
  }
  // A byte string as a view of the record's bytes (valid as long as the record is). On failure
  // the read position may have moved: the caller discards the record as malformed.
  bool get_view(std::span<const std::byte>& bytes, std::uint32_t max_bytes) {
    std::uint32_t length = 0;
    if (!get(length) || length > max_bytes || remaining() < length) return false;
    bytes = record_.subspan(position_, length);
    position_ += length;
    return true;
  }
  // A byte string copied into `bytes`, reusing its capacity.
  bool get_bytes(std::vector<std::byte>& bytes, std::uint32_t max_bytes) {
    std::span<const std::byte> view;
    if (!get_view(view, max_bytes)) return false;
    bytes.assign(view.begin(), view.end());
    return true;
  }
  [[nodiscard]] bool at_end() const { return position_ == record_.size(); }
  [[nodiscard]] std::size_t remaining() const { return record_.size() - position_; }

 private:
  std::span<const std::byte> record_;
  std::size_t position_ = 0;
};

// Text fields: the longest text a record may carry, and a text's bytes seen both ways.
inline constexpr std::uint32_t kMaxTextBytes = 1U << 24U;

inline std::span<const std::byte> as_bytes(const std::string& text) {
  return {reinterpret_cast<const std::byte*>(text.data()), text.size()};
}

inline std::string as_text(std::span<const std::byte> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

}  // namespace swarmnet
