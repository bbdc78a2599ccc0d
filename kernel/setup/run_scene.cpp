#include "kernel/setup/run_scene.hpp"

#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "kernel/schemes/dsmc_replica.hpp"
#include "kernel/schemes/event_replica.hpp"
#include "kernel/schemes/intruder_1d.hpp"
#include "kernel/schemes/intruder_dsmc_1d.hpp"
#include "kernel/schemes/intruder_needle.hpp"
#include "kernel/schemes/rank_wave_backend.hpp"
#include "kernel/schemes/replica_runner.hpp"
#include "kernel/schemes/sample_times.hpp"
#include "kernel/schemes/swpm_replica.hpp"

namespace granmc {

namespace {

/// A replica's round counts into the run's, from the replicas' threads.
void add_round_counts(CollisionRoundCounts& run, const CollisionRoundCounts& replica) {
#pragma omp critical(granmc_round_counts)
  {
    run.rounds += replica.rounds;
    run.deferred += replica.deferred;
    run.in_order += replica.in_order;
  }
}

/// The time-stepped scheme with the plan's kernel and effects: the replicas over the threads with the batched
/// backend (threads left over inside the replicas, in concurrent collision rounds), or, with the rank waves, every
/// replica spread over options.spread, one after another.
template <class Backend, class Real, class Kernel, class... Effects>
RunResult run_dsmc(const Scene& scene, const RunOptions& options, const Kernel& kernel, const Effects&... effects) {
  if constexpr (std::is_same_v<Backend, RankWaveBackend>) {
    RunResult result;
    result.times = sample_times(scene.run);
    result.species_names.push_back(scene.species[0].name);
    result.threads = 1;
    for (int r = 0; r < scene.run.replicas; ++r) {
      BasicDsmc<Backend, Real, Kernel, Effects...> sim(scene, static_cast<std::uint64_t>(r),
                                                       Backend(scene, *options.spread), kernel, effects...);
      result.replicas.push_back(run_dsmc_replica(sim, scene, result.times, static_cast<std::uint64_t>(r), options));
    }
    return result;
  } else {
    const ThreadShare share = share_threads(scene, options, stepped_rounds_inside);
    CollisionRoundCounts rounds;
    RunResult result =
        run_replicas(scene, options, share, [&](std::uint64_t replica, const std::vector<double>& times) {
          BasicDsmc<Backend, Real, Kernel, Effects...> sim(scene, replica, Backend(scene, share.inside), kernel,
                                                           effects...);
          ReplicaSeries series = run_dsmc_replica(sim, scene, times, replica, options);
          add_round_counts(rounds, sim.backend().rounds().counts);
          return series;
        });
    result.rounds = rounds;
    return result;
  }
}

RunResult run(const SteppedPlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit(
      [&](const auto& kernel, const auto& shear, const auto& thermostat, auto storage, auto stage) -> RunResult {
        using Kernel = std::decay_t<decltype(kernel)>;
        using Stage = decltype(stage);
        if constexpr (!stepped_supported<Kernel, std::decay_t<decltype(shear)>, std::decay_t<decltype(thermostat)>,
                                         decltype(storage), Stage>) {
          throw std::logic_error("granmc: a plan that make_plan refuses reached the dispatch");
        } else {
          using Backend = std::conditional_t<std::is_same_v<Stage, RankWaveStage>, RankWaveBackend, BatchedBackend>;
          using Real = typename decltype(storage)::type;
          return std::apply(
              [&](const auto&... effects) {
                return run_dsmc<Backend, Real, Kernel>(scene, options, kernel, effects...);
              },
              std::tuple_cat(shear.effects, thermostat.effects));
        }
      },
      plan.kernel, plan.shear, plan.thermostat, plan.storage, plan.backend);
}

RunResult run(const EventPlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit(
      [&](const auto& kernel, auto storage) {
        using Real = typename decltype(storage)::type;
        const ThreadShare share = share_threads(scene, options, event_rounds_inside);
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

RunResult run(const WeightedPlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit(
      [&](const auto& kernel) {
        return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_swpm_replica(scene, replica, times, options, kernel);
        });
      },
      plan.kernel);
}

RunResult run(const IntruderLinePlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit(
      [&](const auto& bath) {
        return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_intruder_1d(scene, replica, times, options, bath);
        });
      },
      plan.bath);
}

RunResult run(const NeedlePlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit(
      [&](const auto& bath) {
        return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_intruder_needle(scene, replica, times, options, bath);
        });
      },
      plan.bath);
}

RunResult run(const IntruderDsmcPlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit(
      [&](const auto& bath) {
        return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_intruder_dsmc_1d(scene, replica, times, options, bath);
        });
      },
      plan.bath);
}

}  // namespace

RunResult run_plan(const RunPlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit([&](const auto& scheme) { return run(scheme, scene, options); }, plan.scheme);
}

RunResult run_scene(const Scene& scene, const RunOptions& options) {
  return run_plan(make_plan(scene, options.spread ? Spread::particles : Spread::replicas), scene, options);
}

}  // namespace granmc
