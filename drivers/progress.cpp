#include "drivers/progress.hpp"

#include <cstdio>

namespace granmc {

ProgressLine::ProgressLine(std::uint64_t total_ticks, bool enabled) : total_(total_ticks), enabled_(enabled) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::finish() {
  const std::lock_guard lock(print_mutex_);
  if (printed_) std::fputc('\n', stderr);
  printed_ = false;
  enabled_ = false;
}

void ProgressLine::tick() {
  const std::uint64_t done = ++done_;
  if (!enabled_) return;
  std::unique_lock lock(print_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  const auto now = clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 2.0 || now - last_print_ < std::chrono::milliseconds(250)) return;
  last_print_ = now;
  const double fraction = static_cast<double>(done) / static_cast<double>(total_);
  const double remaining = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  std::fprintf(stderr, "\r  %5.1f%%  %7.1f s elapsed  ~%7.1f s left ", 100.0 * fraction, elapsed, remaining);
  std::fflush(stderr);
  printed_ = true;
}

}  // namespace granmc
