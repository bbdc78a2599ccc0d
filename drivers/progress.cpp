#include "drivers/progress.hpp"

#include <cstdio>

namespace granmc {

ProgressLine::ProgressLine(std::uint64_t total_ticks, Mode mode, std::chrono::milliseconds log_interval)
    : total_(total_ticks), mode_(mode), log_interval_(log_interval) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::finish() {
  const std::lock_guard lock(print_mutex_);
  if (printed_ && mode_ == Mode::terminal) std::fputc('\n', stderr);
  printed_ = false;
  mode_ = Mode::off;
}

void ProgressLine::tick() {
  const std::uint64_t done = ++done_;
  if (mode_ == Mode::off) return;
  std::unique_lock lock(print_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const auto now = clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const bool in_place = mode_ == Mode::terminal;
  if (in_place ? elapsed < 2.0 || now - last_print_ < std::chrono::milliseconds(250)
               : now - last_print_ < log_interval_)
    return;
  last_print_ = now;
  const double fraction = static_cast<double>(done) / static_cast<double>(total_);
  const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  if (in_place)
    std::fprintf(stderr, "\r  %5.1f%%  %7.1f s elapsed  ~%7.1f s left ", 100.0 * fraction, elapsed, remaining);
  else
    std::fprintf(stderr, "granmc: %5.1f%%  %7.1f s elapsed  ~%7.1f s left\n", 100.0 * fraction, elapsed, remaining);
  std::fflush(stderr);
  printed_ = true;
}

}  // namespace granmc
