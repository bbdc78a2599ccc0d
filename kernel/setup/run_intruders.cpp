// The intruders' dispatch (setup/scheme_runs.hpp): the bath of the Gillespie intruder on a line, the needle and
// the time-stepped intruder.
#include "kernel/schemes/intruder_1d.hpp"
#include "kernel/schemes/intruder_dsmc_1d.hpp"
#include "kernel/schemes/intruder_needle.hpp"
#include "kernel/setup/scheme_runs.hpp"

namespace granmc {

RunResult run_scheme(const IntruderLinePlan& plan, const Scene& scene, const RunOptions& options,
                     const ThreadShare& share) {
  return std::visit(
      [&](const auto& bath) {
        return run_replicas(scene, options, share, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_intruder_1d(scene, replica, times, options, bath);
        });
      },
      plan.bath);
}

RunResult run_scheme(const NeedlePlan& plan, const Scene& scene, const RunOptions& options, const ThreadShare& share) {
  return std::visit(
      [&](const auto& bath) {
        return run_replicas(scene, options, share, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_intruder_needle(scene, replica, times, options, bath);
        });
      },
      plan.bath);
}

RunResult run_scheme(const IntruderDsmcPlan& plan, const Scene& scene, const RunOptions& options,
                     const ThreadShare& share) {
  return std::visit(
      [&](const auto& bath) {
        return run_replicas(scene, options, share, [&](std::uint64_t replica, const std::vector<double>& times) {
          return run_intruder_dsmc_1d(scene, replica, times, options, bath);
        });
      },
      plan.bath);
}

}  // namespace granmc
