#include "kernel/setup/run_scene.hpp"

#include <variant>

#include "kernel/schemes/replica_runner.hpp"
#include "kernel/setup/scheme_runs.hpp"

namespace granmc {

ThreadsInside threads_inside(const RunPlan& plan) {
  if (std::holds_alternative<EventPlan>(plan.scheme)) return event_rounds_inside;
  const auto* stepped = std::get_if<SteppedPlan>(&plan.scheme);
  return stepped != nullptr && std::holds_alternative<BatchedStage>(stepped->backend) ? stepped_rounds_inside
                                                                                      : one_thread_inside;
}

RunResult run_plan(const RunPlan& plan, const Scene& scene, const RunOptions& options) {
  const ThreadShare share = share_threads(scene, options, threads_inside(plan));
  return std::visit([&](const auto& scheme) { return run_scheme(scheme, scene, options, share); }, plan.scheme);
}

RunResult run_scene(const Scene& scene, const RunOptions& options) {
  return run_plan(make_plan(scene, options.spread ? Spread::particles : Spread::replicas), scene, options);
}

}  // namespace granmc
