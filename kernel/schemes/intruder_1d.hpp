#pragma once
// The Gillespie algorithm for a point intruder of mass M in a bath of point particles of mass m = 1 on a
// line (002 sec. 3.1), one replica. Between collisions the intruder's velocity v1 is constant, so the
// collision rate phi(v1) = phi_+(v1) + phi_-(v1) (002 eq. 7) is too:
//   1. waiting time dt = -ln(xi_1) / phi(v1) (002 eq. 10); observations that fall inside it see v1, and
//      v1^2 dt adds to the exact time integral of v1^2 over the stationary window;
//   2. side: right with probability phi_+ / phi (002 eq. 11);
//   3. the bath particle's velocity from g_+ or g_- (002 eqs. 14, 17), sampled exactly by the bath law
//      (collide/bath_*.hpp; g_-(v; v1) = g_+(-v; -v1) by symmetry of the bath);
//   4. v1 -> v1 + (1 + alpha) / (1 + M) (v - v1) (002 eq. 21).
// Random numbers: event e uses block (intruder_event, e, 0) for xi_1, xi_2 and blocks 1, 2, ... for the
// rejection attempts of step 3.
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/intruder_record.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

template <class Bath>
ReplicaSeries run_intruder_1d(const Scene& scene, std::uint64_t replica, const std::vector<double>& times,
                              const RunOptions& options, const Bath& bath) {
  const IntruderConfig& in = *scene.intruder;
  const RandomStream rng(scene.run.seed, replica);
  const double kick = (1.0 + in.restitution) / (1.0 + in.mass);  // 002 eq. (21), m = 1
  IntruderRecord1D record(scene, times.size());
  double v1 = initial_intruder_velocity(scene, rng);

  const std::pair<double, double> window = stationary_window(times);  // of the exact time average of v1^2
  double t = 0.0;
  std::uint64_t event = 0;
  auto observe = [&] {
    record.observe(v1, event);
    if (options.on_sample) options.on_sample();
  };
  while (record.samples() < times.size()) {
    const double flux_plus = bath.flux_right(v1), flux_minus = bath.flux_right(-v1);
    const double flux = flux_plus + flux_minus;  // 002 eq. (7)
    const RandomBlock draw = rng.block(RngPurpose::intruder_event, 0, event, 0);
    const double next = t - std::log(uniform_open(draw[0])) / flux;  // 002 eq. (10)
    record.add_stationary_v2(v1, t, next, window);
    while (record.samples() < times.size() && times[record.samples()] <= next) observe();
    if (record.samples() == times.size()) break;
    t = next;
    const bool right = uniform_open(draw[1]) * flux < flux_plus;  // 002 eq. (11)
    double v = 0.0;
    for (std::uint64_t attempt = 1;; ++attempt) {
      record.count_sampling_attempt();
      const RandomBlock u = rng.block(RngPurpose::intruder_event, 0, event, attempt);
      if (right ? bath.try_sample_right(v1, u, v) : bath.try_sample_right(-v1, u, v)) break;
    }
    if (!right) v = -v;     // g_-(v; v1) = g_+(-v; -v1)
    v1 += kick * (v - v1);  // 002 eq. (21)
    ++event;
  }
  return record.finish(record.sampling_attempts());
}

}  // namespace granmc
