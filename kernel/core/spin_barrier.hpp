#pragma once
// A barrier for the threads of one replica's concurrent collision rounds (schemes/concurrent_rounds.hpp), two
// per round of some tens of microseconds. It waits by spinning, then by yielding the core. OpenMP's barrier may
// put a waiting thread to sleep after a short spin (libgomp shortens its spin when it counts more threads than
// cores, as nested teams can make it), and waking a thread costs about as long as a round. Yielding after the
// spin keeps a team that outnumbers the cores (the tests run 8 threads on 2) moving.
#include <atomic>
#include <cstdint>
#include <thread>

namespace granmc {

class SpinBarrier {
 public:
  explicit SpinBarrier(int threads) noexcept : threads_(threads) {}

  /// Returns when all `threads` threads have called it: what each wrote before its call is visible to every
  /// thread after the return (the arrivals form one release sequence that the last arrival acquires, and the
  /// last arrival's release of the generation is acquired by the others).
  void arrive_and_wait() noexcept {
    const std::uint64_t generation = generation_.load(std::memory_order_acquire);
    if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == threads_) {
      arrived_.store(0, std::memory_order_relaxed);
      generation_.store(generation + 1, std::memory_order_release);
      return;
    }
    for (int spins = 0; generation_.load(std::memory_order_acquire) == generation; ++spins) {
      if (spins < spins_before_yield)
        pause();
      else
        std::this_thread::yield();
    }
  }

  /// How many threads wait in arrive_and_wait now (a hint: it may be out of date when it returns). A thread that
  /// calls it between two of its own arrive_and_wait calls counts the others that have reached the next.
  [[nodiscard]] int waiting() const noexcept { return arrived_.load(std::memory_order_relaxed); }

 private:
  static constexpr int spins_before_yield = 4096;
  static void pause() noexcept {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  }

  std::atomic<int> arrived_{0};
  std::atomic<std::uint64_t> generation_{0};
  const int threads_;
};

}  // namespace granmc
