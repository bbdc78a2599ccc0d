#pragma once
// The dispatch of each scheme: run_plan (setup/run_scene.cpp) visits the plan to one of these, which instantiate
// the supported products of the plan's choices. They are apart, one file per scheme (and the time-stepped
// scheme's kernels by family), so that a build compiles them side by side: setup/run_stepped.cpp,
// setup/run_event.cpp, setup/run_intruders.cpp.
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/replica_runner.hpp"
#include "kernel/schemes/run_options.hpp"
#include "kernel/setup/run_plan.hpp"

namespace granmc {

RunResult run_scheme(const SteppedPlan& plan, const Scene& scene, const RunOptions& options, const ThreadShare& share);
RunResult run_scheme(const EventPlan& plan, const Scene& scene, const RunOptions& options, const ThreadShare& share);
RunResult run_scheme(const WeightedPlan& plan, const Scene& scene, const RunOptions& options, const ThreadShare& share);
RunResult run_scheme(const IntruderLinePlan& plan, const Scene& scene, const RunOptions& options,
                     const ThreadShare& share);
RunResult run_scheme(const NeedlePlan& plan, const Scene& scene, const RunOptions& options, const ThreadShare& share);
RunResult run_scheme(const IntruderDsmcPlan& plan, const Scene& scene, const RunOptions& options,
                     const ThreadShare& share);

/// The time-stepped scheme for one of the plan's kernels (setup/run_stepped.hpp), instantiated for every
/// alternative of KernelChoice by family: setup/run_stepped_hard_core.cpp, run_stepped_rough.cpp,
/// run_stepped_kernel_form.cpp.
template <class Kernel>
RunResult run_stepped(const Kernel& kernel, const SteppedPlan& plan, const Scene& scene, const RunOptions& options,
                      const ThreadShare& share);

/// A replica's round counts into the run's, from the replicas' threads.
inline void add_round_counts(CollisionRoundCounts& run, const CollisionRoundCounts& replica) {
#pragma omp critical(granmc_round_counts)
  {
    run.rounds += replica.rounds;
    run.deferred += replica.deferred;
    run.in_order += replica.in_order;
  }
}

}  // namespace granmc
