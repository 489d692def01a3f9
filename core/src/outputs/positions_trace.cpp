#include "outputs/positions_trace.hpp"

#include <array>
#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "outputs/file_buffer.hpp"
#include "outputs/run_error.hpp"

namespace swarmnet {

namespace {

constexpr std::array<char, 8> kMagic = {'S', 'N', 'P', 'O', 'S', '\0', '\0', '\0'};

template <typename T>
void put_le(char* out, T value) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  const auto bits = std::bit_cast<Bits>(value);
  for (std::size_t i = 0; i < sizeof(T); ++i) out[i] = static_cast<char>(bits >> (8 * i));
}

template <typename T>
T get_le(const char* in) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  Bits bits = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    bits |= static_cast<Bits>(static_cast<unsigned char>(in[i])) << (8 * i);
  return std::bit_cast<T>(bits);
}

}  // namespace

PositionsTraceWriter::PositionsTraceWriter(std::ostream& out, std::uint32_t robots,
                                           std::uint64_t steps, SimTime step)
    : out_(out), declared_steps_(steps) {
  std::array<char, kPositionsHeaderBytes> header{};
  std::memcpy(header.data(), kMagic.data(), kMagic.size());
  put_le(header.data() + 8, kPositionsTraceVersion);
  put_le(header.data() + 12, robots);
  put_le(header.data() + 16, steps);
  put_le(header.data() + 24, static_cast<std::int64_t>(step.count()));
  out_.write(header.data(), static_cast<std::streamsize>(header.size()));
}

void PositionsTraceWriter::sample(std::span<const Vec2> positions) {
  buffer_.resize(positions.size() * 16);
  char* out = buffer_.data();
  for (const Vec2& p : positions) {
    put_le(out, p.x());
    put_le(out + 8, p.y());
    out += 16;
  }
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  ++written_steps_;
}

void PositionsTraceWriter::finish() {
  if (written_steps_ == declared_steps_) return;
  std::array<char, 8> steps{};
  put_le(steps.data(), written_steps_);
  const std::streampos end = out_.tellp();
  out_.seekp(16);
  out_.write(steps.data(), static_cast<std::streamsize>(steps.size()));
  out_.seekp(end);
  if (!out_) {
    throw RunError("cannot record the step count in the positions trace's header: " +
                   write_failure(out_));
  }
}

PositionsTrace read_positions_trace(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RunError("cannot open " + path.string());
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
  auto bad = [&](const std::string& what) {
    return RunError(path.string() + ": not a valid positions record: " + what);
  };
  if (bytes.size() < kPositionsHeaderBytes) throw bad("shorter than its header");
  if (std::memcmp(bytes.data(), kMagic.data(), kMagic.size()) != 0) throw bad("wrong magic");
  const auto version = get_le<std::uint32_t>(bytes.data() + 8);
  if (version != kPositionsTraceVersion) {
    throw bad("version " + std::to_string(version) + ", this build reads version " +
              std::to_string(kPositionsTraceVersion));
  }
  PositionsTrace trace;
  trace.robots = get_le<std::uint32_t>(bytes.data() + 12);
  trace.steps = get_le<std::uint64_t>(bytes.data() + 16);
  trace.step = SimTime{get_le<std::int64_t>(bytes.data() + 24)};
  if (trace.step.count() <= 0) throw bad("step_ns is not positive");
  const std::uint64_t values = trace.steps * trace.robots;
  if (bytes.size() != kPositionsHeaderBytes + values * 16) {
    throw bad(std::to_string(bytes.size()) + " bytes where " + std::to_string(trace.robots) +
              " robots over " + std::to_string(trace.steps) + " steps need " +
              std::to_string(kPositionsHeaderBytes + values * 16));
  }
  trace.positions.resize(values);
  const char* p = bytes.data() + kPositionsHeaderBytes;
  for (Vec2& v : trace.positions) {
    v = Vec2(get_le<double>(p), get_le<double>(p + 8));
    p += 16;
  }
  return trace;
}

}  // namespace swarmnet
