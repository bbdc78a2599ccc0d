// The time-stepped scheme's dispatch (setup/scheme_runs.hpp): the plan's kernel to run_stepped, instantiated by
// family of kernels in setup/run_stepped_hard_core.cpp, run_stepped_rough.cpp and run_stepped_kernel_form.cpp.
#include <variant>

#include "kernel/setup/scheme_runs.hpp"

namespace granmc {

RunResult run_scheme(const SteppedPlan& plan, const Scene& scene, const RunOptions& options, const ThreadShare& share) {
  return std::visit([&](const auto& kernel) { return run_stepped(kernel, plan, scene, options, share); }, plan.kernel);
}

}  // namespace granmc
