// The time-stepped scheme of smooth hard spheres and disks (000, 003): every shear, thermostat, storage and
// backend they support.
#include "kernel/setup/run_stepped.hpp"

namespace granmc {

template RunResult run_stepped(const HardSphere&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);
template RunResult run_stepped(const HardDisk&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);

}  // namespace granmc
