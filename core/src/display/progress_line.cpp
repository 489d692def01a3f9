#include "display/progress_line.hpp"

#include <unistd.h>

namespace swarmnet {

namespace {
constexpr auto kFirstShownAfter = std::chrono::seconds(1);
constexpr auto kRefreshEvery = std::chrono::milliseconds(250);
}  // namespace

ProgressLine::ProgressLine(std::FILE* terminal, std::uint64_t total_steps, double step_s)
    : out_(terminal),
      enabled_(terminal != nullptr && isatty(fileno(terminal)) != 0),
      total_steps_(total_steps),
      step_s_(step_s),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::update(std::uint64_t step) {
  if (!enabled_ || (step % 64) != 0) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < kFirstShownAfter || now - last_ < kRefreshEvery) return;
  last_ = now;
  const double wall_s = std::chrono::duration<double>(now - start_).count();
  const double sim_s = static_cast<double>(step) * step_s_;
  const double percent = 100.0 * static_cast<double>(step) / static_cast<double>(total_steps_);
  std::fprintf(out_, "\r  step %llu/%llu  %5.1f%%  t = %.1f s  %.1fx real time   ",
               static_cast<unsigned long long>(step), static_cast<unsigned long long>(total_steps_),
               percent, sim_s, sim_s / wall_s);
  std::fflush(out_);
  shown_ = true;
}

void ProgressLine::clear() {
  if (!shown_) return;
  std::fprintf(out_, "\r%*s\r", 72, "");
  std::fflush(out_);
  shown_ = false;
}

}  // namespace swarmnet
