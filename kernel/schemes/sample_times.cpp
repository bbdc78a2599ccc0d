#include "kernel/schemes/sample_times.hpp"

#include <cmath>

namespace granmc {

std::vector<double> sample_times(const RunConfig& run) {
  std::vector<double> t(static_cast<std::size_t>(run.samples) + 1, 0.0);
  const int s = run.samples;
  for (int k = 1; k <= s; ++k) {
    if (run.sample_spacing == SampleSpacing::linear || s == 1) {
      t[k] = run.t_end * k / s;
    } else {
      t[k] = run.dt * std::pow(run.t_end / run.dt, static_cast<double>(k - 1) / (s - 1));
    }
  }
  t[s] = run.t_end;
  return t;
}

}  // namespace granmc
