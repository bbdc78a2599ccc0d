#pragma once
// The dispatch: a plan (setup/run_plan.hpp) -> the replicas of its scheme, run (schemes/). It only visits the
// plan; the choices were made in make_plan, and only the supported products of them are compiled.
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/schemes/run_options.hpp"
#include "kernel/setup/run_plan.hpp"

namespace granmc {

/// Runs `plan`, made from `scene` by make_plan (with Spread::particles exactly when options.spread is set).
RunResult run_plan(const RunPlan& plan, const Scene& scene, const RunOptions& options);

/// make_plan, then run_plan. Throws PlanRefusal for a scene granmc cannot run.
RunResult run_scene(const Scene& scene, const RunOptions& options);

}  // namespace granmc
