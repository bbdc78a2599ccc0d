// The time-step-free schemes' dispatch (setup/scheme_runs.hpp): the event scheme (kernel x storage) and weighted
// particles (kernel).
#include "kernel/schemes/event_replica.hpp"
#include "kernel/schemes/swpm_replica.hpp"
#include "kernel/setup/scheme_runs.hpp"

namespace granmc {

RunResult run_scheme(const EventPlan& plan, const Scene& scene, const RunOptions& options, const ThreadShare& share) {
  return std::visit(
      [&](const auto& kernel, auto storage) {
        using Real = typename decltype(storage)::type;
        CollisionRoundCounts rounds;
        RunResult result =
            run_replicas(scene, options, share, [&](std::uint64_t replica, const std::vector<double>& times) {
              CollisionRoundCounts its;
              ReplicaSeries series =
                  run_event_replica<Real>(scene, replica, times, options, kernel, share.inside, &its);
              add_round_counts(rounds, its);
              return series;
            });
        result.rounds = rounds;
        return result;
      },
      plan.kernel, plan.storage);
}

RunResult run_scheme(const WeightedPlan& plan, const Scene& scene, const RunOptions& options,
                     const ThreadShare& share) {
  return std::visit(
      [&](const auto& kernel) {
        return run_replicas(scene, options, share, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_swpm_replica(scene, replica, times, options, kernel);
        });
      },
      plan.kernel);
}

}  // namespace granmc
