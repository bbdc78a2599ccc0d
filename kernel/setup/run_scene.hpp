#pragma once
// The dispatch: a plan (setup/run_plan.hpp) -> the replicas of its scheme, run (schemes/). It only visits the
// plan; the choices were made in make_plan, and only the supported products of them are compiled.
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/replica_runner.hpp"
#include "kernel/schemes/run_options.hpp"
#include "kernel/setup/run_plan.hpp"

namespace granmc {

/// The threads a replica of `plan` can take (schemes/replica_runner.hpp, share_threads): the threads left over by
/// the replicas go inside a replica where its scheme runs them in concurrent collision rounds, the time-stepped
/// scheme's batched stage (schemes/concurrent_rounds.hpp) and the event scheme (schemes/event_rounds.hpp); every
/// other scheme runs a replica on one thread. run_plan shares the threads by it, and `--explain` says how.
ThreadsInside threads_inside(const RunPlan& plan);

/// Runs `plan`, made from `scene` by make_plan (with Spread::particles exactly when options.spread is set).
RunResult run_plan(const RunPlan& plan, const Scene& scene, const RunOptions& options);

/// make_plan, then run_plan. Throws PlanRefusal for a scene granmc cannot run.
RunResult run_scene(const Scene& scene, const RunOptions& options);

}  // namespace granmc
