// The time-stepped scheme of 001's kernel form: Maxwell pseudomolecules and variable hard spheres, in three
// dimensions and in the plane.
#include "kernel/setup/run_stepped.hpp"

namespace granmc {

template RunResult run_stepped(const MaxwellPseudomolecules&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);
template RunResult run_stepped(const VariableHardSpheres&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);
template RunResult run_stepped(const MaxwellDisks&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);
template RunResult run_stepped(const VariableHardDisks&, const SteppedPlan&, const Scene&, const RunOptions&,
                               const ThreadShare&);

}  // namespace granmc
