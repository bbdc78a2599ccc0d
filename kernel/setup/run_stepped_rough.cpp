// The time-stepped scheme of rough hard spheres and disks (collide/rough_rule.hpp).
#include "kernel/setup/run_stepped.hpp"

namespace granmc {

template RunResult run_stepped(const RoughHardSphere&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);
template RunResult run_stepped(const RoughHardDisk&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);

}  // namespace granmc
