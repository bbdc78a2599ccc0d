#pragma once
// The time-stepped scheme's dispatch for one kernel: shear x thermostat x storage x backend, the supported
// products only (setup/run_plan.hpp, stepped_supported). Included by the files that instantiate it for a family
// of kernels (setup/run_stepped_*.cpp); setup/run_stepped.cpp visits the plan's kernel to them.
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "kernel/schemes/dsmc_replica.hpp"
#include "kernel/schemes/rank_wave_backend.hpp"
#include "kernel/schemes/sample_times.hpp"
#include "kernel/setup/scheme_runs.hpp"

namespace granmc {

/// The time-stepped scheme with the plan's kernel and effects: the replicas over the threads with the batched
/// backend (threads left over inside the replicas, in concurrent collision rounds), or, with the rank waves, every
/// replica spread over options.spread, one after another.
template <class Backend, class Real, class Kernel, class... Effects>
RunResult run_dsmc(const Scene& scene, const RunOptions& options, const ThreadShare& share, const Kernel& kernel,
                   const Effects&... effects) {
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

template <class Kernel>
RunResult run_stepped(const Kernel& kernel, const SteppedPlan& plan, const Scene& scene, const RunOptions& options,
                      const ThreadShare& share) {
  return std::visit(
      [&](const auto& shear, const auto& thermostat, auto storage, auto stage) -> RunResult {
        using Stage = decltype(stage);
        if constexpr (!stepped_supported<Kernel, std::decay_t<decltype(shear)>, std::decay_t<decltype(thermostat)>,
                                         decltype(storage), Stage>) {
          throw std::logic_error("granmc: a plan that make_plan refuses reached the dispatch");
        } else {
          using Backend = std::conditional_t<std::is_same_v<Stage, RankWaveStage>, RankWaveBackend, BatchedBackend>;
          using Real = typename decltype(storage)::type;
          return std::apply(
              [&](const auto&... effects) {
                return run_dsmc<Backend, Real, Kernel>(scene, options, share, kernel, effects...);
              },
              std::tuple_cat(shear.effects, thermostat.effects));
        }
      },
      plan.shear, plan.thermostat, plan.storage, plan.backend);
}

}  // namespace granmc
