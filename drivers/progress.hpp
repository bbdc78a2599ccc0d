#pragma once
// A progress line on stderr for runs longer than about 2 s: only when stderr is a terminal and the
// user did not ask for --quiet. tick() may be called from any thread.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>

namespace granmc {

class ProgressLine {
 public:
  ProgressLine(std::uint64_t total_ticks, bool enabled);
  ~ProgressLine();
  void tick();
  /// Ends the progress line (if one was printed) so that later output starts on a fresh line.
  void finish();

 private:
  using clock = std::chrono::steady_clock;
  std::uint64_t total_;
  bool enabled_;
  std::atomic<std::uint64_t> done_{0};
  std::mutex print_mutex_;
  clock::time_point start_ = clock::now();
  clock::time_point last_print_ = start_;
  bool printed_ = false;
};

}  // namespace granmc
