#pragma once
// A thread pinned to one CPU for a scope: the threads of one replica's concurrent collision rounds
// (schemes/concurrent_rounds.hpp), which wait on each other twice per round. Left to the scheduler, the thread
// that a step's parallel region woke often ran on the CPU of the thread that woke it, and the two took turns on
// one CPU for much of the step: one replica of 10^5 particles took 2 to 6 times longer on two threads in some
// runs than in others, and never so with the threads bound (docs/developer-guide/scaling.md). Pinned to the i-th CPU of
// the set it may run on, each thread of the replicas' teams runs beside the others; the thread's own set comes back at
// the end of the scope. Linux only; elsewhere, or when OpenMP binds its threads already (OMP_PROC_BIND), or when
// the set has one CPU (MPI ranks bound to cores), it does nothing. Processes whose sets overlap (MPI ranks
// started unbound on one host) pin their teams to the same CPUs: bind such ranks.
#include <omp.h>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

namespace granmc {

class PinnedThread {
 public:
  /// Pins the calling thread to the `index`-th CPU (modulo their number) of the CPUs it may run on.
  explicit PinnedThread(int index) noexcept {
#if defined(__linux__)
    if (omp_get_proc_bind() != omp_proc_bind_false) return;
    if (pthread_getaffinity_np(pthread_self(), sizeof(saved_), &saved_) != 0) return;
    const int cpus = CPU_COUNT(&saved_);
    if (cpus < 2) return;
    for (int cpu = 0, seen = 0; cpu < CPU_SETSIZE; ++cpu) {
      if (!CPU_ISSET(cpu, &saved_)) continue;
      if (seen++ != index % cpus) continue;
      cpu_set_t one;
      CPU_ZERO(&one);
      CPU_SET(cpu, &one);
      pinned_ = pthread_setaffinity_np(pthread_self(), sizeof(one), &one) == 0;
      return;
    }
#endif
  }
  ~PinnedThread() {
#if defined(__linux__)
    if (pinned_) pthread_setaffinity_np(pthread_self(), sizeof(saved_), &saved_);
#endif
  }
  /// The index for the calling thread of a replica's team (`team` threads, inside the replicas' team of an
  /// enclosing parallel region, schemes/replica_runner.hpp): thread t of the replica in slot k takes CPU k team + t,
  /// so that the replicas' teams run side by side.
  static int replica_thread_index(int team) noexcept {
    const int level = omp_get_level();
    const int slot = level > 1 ? omp_get_ancestor_thread_num(level - 1) : 0;
    return slot * team + omp_get_thread_num();
  }
  PinnedThread(const PinnedThread&) = delete;
  PinnedThread& operator=(const PinnedThread&) = delete;

 private:
#if defined(__linux__)
  cpu_set_t saved_{};
#endif
  bool pinned_ = false;
};

}  // namespace granmc
