#include "kernel/setup/run_scene.hpp"

#include <stdexcept>
#include <tuple>
#include <type_traits>

#include "kernel/schemes/dsmc_replica.hpp"
#include "kernel/schemes/event_replica.hpp"
#include "kernel/schemes/intruder_1d.hpp"
#include "kernel/schemes/intruder_dsmc_1d.hpp"
#include "kernel/schemes/intruder_needle.hpp"
#include "kernel/schemes/replica_runner.hpp"
#include "kernel/schemes/sample_times.hpp"
#include "kernel/schemes/spread_dsmc.hpp"

namespace granmc {

namespace {

/// Every replica spread over options.spread, one after another (schemes/spread_dsmc.hpp).
template <class Kernel>
RunResult run_spread(const Scene& scene, const RunOptions& options) {
  RunResult result;
  result.times = sample_times(scene.run);
  result.species_names.push_back(scene.species[0].name);
  result.threads = 1;
  for (int r = 0; r < scene.run.replicas; ++r)
    result.replicas.push_back(run_spread_replica<Kernel>(scene, static_cast<std::uint64_t>(r), result.times,
                                                         *options.spread, options.on_sample));
  return result;
}

RunResult run(const SteppedPlan& plan, const Scene& scene, const RunOptions& options) {
  return std::visit(
      [&](const auto& kernel, const auto& shear, const auto& thermostat, auto storage, auto backend) -> RunResult {
        using Kernel = std::decay_t<decltype(kernel)>;
        using Backend = decltype(backend);
        if constexpr (!stepped_supported<Kernel, std::decay_t<decltype(shear)>, std::decay_t<decltype(thermostat)>,
                                         decltype(storage), Backend>) {
          throw std::logic_error("granmc: a plan that make_plan refuses reached the dispatch");
        } else if constexpr (std::is_same_v<Backend, RankWaveStage>) {
          return run_spread<Kernel>(scene, options);
        } else {
          using Real = typename decltype(storage)::type;
          return std::apply(
              [&](const auto&... effects) {
                return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
                  return run_dsmc_replica<Real, Kernel>(scene, replica, times, options, effects...);
                });
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
        return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_event_replica<Real>(scene, replica, times, options, kernel);
        });
      },
      plan.kernel, plan.storage);
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

RunResult run(const NeedlePlan&, const Scene& scene, const RunOptions& options) {
  return run_replicas(scene, options, [&](std::uint64_t replica, const std::vector<double>& times) {
    return run_intruder_needle(scene, replica, times, options);
  });
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
