// The lines of a CSV trace (packets.csv, frames.csv, sensing.csv) on their way to a stream: fields
// appended to the line being written, integers in decimal, node ids with -1 for broadcast and reals
// in their shortest round-trip form, without locale or allocation per field (a trace is the same
// text on every platform); lines batched in memory and handed to the stream in large writes.
#pragma once

#include <charconv>
#include <cstddef>
#include <iterator>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>

#include "swarmnet/ids.hpp"

namespace swarmnet {

class TraceLines {
 public:
  // `out` may be null: nothing is written and enabled() is false. Otherwise `header` (a whole
  // line, with its newline) is the first line.
  TraceLines(std::ostream* out, std::string_view header) : out_(out) {
    if (out_ != nullptr) buffer_.append(header);
  }
  TraceLines(const TraceLines&) = delete;
  TraceLines& operator=(const TraceLines&) = delete;
  TraceLines(TraceLines&&) = delete;
  TraceLines& operator=(TraceLines&&) = delete;
  // Writes nothing: lines not yet flushed are discarded (the stream may be gone by then).
  ~TraceLines() = default;

  [[nodiscard]] bool enabled() const { return out_ != nullptr; }

  template <typename Integer>
  void integer(Integer value) {
    static_assert(std::is_integral_v<Integer>);
    char digits[24];
    const auto result = std::to_chars(std::begin(digits), std::end(digits), value);
    buffer_.append(digits, result.ptr);
  }
  // The shortest decimal that reads back as the same double (std::to_chars), as
  // text/shortest_number.hpp writes reals; "inf", "-inf" or "nan" for those.
  void real(double value) {
    char digits[32];
    const auto result = std::to_chars(std::begin(digits), std::end(digits), value);
    buffer_.append(digits, result.ptr);
  }
  void node(NodeId id) {
    if (id == kBroadcast) {
      buffer_ += "-1";
    } else {
      integer(id);
    }
  }
  void text(std::string_view words) { buffer_ += words; }
  void comma() { buffer_ += ','; }
  // Ends the line; hands the batch to the stream once it is large.
  void end_line() {
    buffer_ += '\n';
    if (buffer_.size() >= kFlushBytes) flush();
  }

  // Hands the lines batched so far to the stream.
  void flush() {
    if (out_ == nullptr || buffer_.empty()) return;
    out_->write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
  }
  // flush(), then flushes the stream itself.
  void finish() {
    flush();
    if (out_ != nullptr) out_->flush();
  }

 private:
  static constexpr std::size_t kFlushBytes = std::size_t{1} << 16U;

  std::ostream* out_;
  std::string buffer_;
};

}  // namespace swarmnet
