#pragma once
// Progress of a run on stderr, unless the user asked for --quiet. On a terminal, one line rewritten in
// place (every 250 ms, from 2 s on); otherwise (stderr sent to a log file, a batch job) one line per
// minute, so that a long run's log shows how far it got and the time left. tick() may be called from any
// thread.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>

namespace granmc {

class ProgressLine {
 public:
  enum class Mode { off, terminal, log };
  /// `log_interval`: the time between two lines in Mode::log.
  ProgressLine(std::uint64_t total_ticks, Mode mode, std::chrono::milliseconds log_interval = std::chrono::minutes(1));
  ~ProgressLine();
  void tick();
  /// Ends the progress line (if one was printed in place) so that later output starts on a fresh line.
  void finish();

 private:
  using clock = std::chrono::steady_clock;
  std::uint64_t total_;
  Mode mode_;
  std::chrono::milliseconds log_interval_;
  std::atomic<std::uint64_t> done_{0};
  std::mutex print_mutex_;
  clock::time_point start_ = clock::now();
  clock::time_point last_print_ = start_;
  bool printed_ = false;
};

}  // namespace granmc
