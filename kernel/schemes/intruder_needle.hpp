#pragma once
// The Gillespie algorithm for a needle intruder in a 2D bath of point particles of mass m = 1 (002 sec. 3.2),
// one replica; the bath's normal-velocity law is Gaussian (002 eq. 18) or the power law of 002 eq. (23). Between
// collisions v1 and omega are constant and the needle turns, theta(t) = theta_0 + omega t, so the total rate Phi(t) =
// Phi(v1.n(t), omega) varies (002 eqs. 24-26; constant only when v1 = 0 or omega = 0). Each event:
//   1. event time: int_0^t Phi = -ln xi_3 (002 eq. 27), Newton (002 eq. 28) with a bisection fallback
//      (collide/needle_flux.hpp); observations inside the flight see the constant v1 and omega;
//   2. turn the needle to the event time, v_n = v1.n (002 eq. 24);
//   3. impact point x from phi(v_n + omega x) / Phi (002 eq. 29), exactly by rejection;
//   4. side: + with probability phi_+(u) / phi(u), u = v_n + omega x (002 eq. 30);
//   5. the bath particle's normal velocity from g_+-(c; u) (002 eqs. 14, 17), exactly by rejection;
//   6. v1, omega from 002 eqs. (31)-(33).
// Start: v1 ~ N(0, T(0) / M) per component, omega ~ N(0, T(0) / I), theta_0 = 0 (the bath is isotropic and
// the direction of v1 is uniform, so only beta - theta matters).
// Random numbers: RngPurpose::needle_event; event e uses block (0, e, 0) for xi_3 (words 0, 1, 52 bits)
// and the side (word 2), blocks (1, e, k) for the impact-point attempts and (2, e, k) for the bath
// velocity attempts; the start uses block (3, 0, 0).
// Recorded at each sample: v1_x (velocity), v1_y, omega; temperature is the kinetic energy per degree of
// freedom (M |v1|^2 + I omega^2) / 3. T_tr = M <|v1|^2> / 2, T_rot = I <omega^2> and
// R = <|v1|^2 omega^2> / (<|v1|^2> <omega^2>) (002 eq. 34) are formed from these by the caller.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "kernel/collide/needle_flux.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/intruder_record.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

template <class Bath>
ReplicaSeries run_intruder_needle(const Scene& scene, std::uint64_t replica, const std::vector<double>& times,
                                  const RunOptions& options, const Bath& bath) {
  const IntruderConfig& in = *scene.intruder;
  const RandomStream rng(scene.run.seed, replica);
  const NeedleBath<Bath> needle{bath, in.length};
  const NeedleBody body{in.mass, needle_inertia(in)};
  const double radius = scene.histogram.radius;
  const std::size_t shells = static_cast<std::size_t>(scene.histogram.shells);
  const std::size_t first_stationary = first_stationary_sample(times.size());
  const std::pair<double, double> window = stationary_window(times);  // of the exact time integrals

  ReplicaSeries series;
  IntruderSeries record;
  record.speed_counts.assign(shells, 0.0);
  record.angular_counts.assign(shells, 0.0);
  NeedleState state;
  {
    const RandomBlock start = rng.block(RngPurpose::needle_event, 3, 0, 0);
    double z1, z2, z3, unused;
    standard_normal_pair(uniform_open(start[0]), uniform_open(start[1]), z1, z2);
    standard_normal_pair(uniform_open(start[2]), uniform_open(start[3]), z3, unused);
    const double scale = std::sqrt(scene.initial_temperature / body.mass);
    state.vx = z1 * scale;
    state.vy = z2 * scale;
    state.omega = z3 * std::sqrt(scene.initial_temperature / body.inertia);
  }

  double t = 0.0;
  std::uint64_t event = 0;
  std::size_t k = 0;
  EventTimeCounters counters;
  auto observe = [&] {
    const double v2 = state.vx * state.vx + state.vy * state.vy;
    const double temperature = (body.mass * v2 + body.inertia * state.omega * state.omega) / 3.0;
    series.temperature.push_back(temperature);
    series.log_temperature.push_back(std::log(temperature));
    series.collisions.push_back(static_cast<double>(event));
    record.velocity.push_back(state.vx);
    record.velocity_y.push_back(state.vy);
    record.angular_velocity.push_back(state.omega);
    if (k >= first_stationary) {
      add_to_shells(record.speed_counts, std::sqrt(v2), radius);
      add_to_shells(record.angular_counts, state.omega, radius);
      ++series.histogram_samples;
    }
    if (options.on_sample) options.on_sample();
    ++k;
  };
  while (k < times.size()) {
    const RandomBlock draw = rng.block(RngPurpose::needle_event, 0, event, 0);
    const double e = -std::log(uniform_open52(draw[0], draw[1]));               // -ln xi_3, 002 eq. (27)
    const double flight = NeedleFlight(needle, state).event_time(e, counters);  // 002 eqs. (27)-(28)
    const double next = t + flight;
    {  // v1 and omega are constant over the flight: their exact time integrals over the stationary window
      const double inside = time_inside(t, next, window);
      const double v2 = state.vx * state.vx + state.vy * state.vy, w2 = state.omega * state.omega;
      record.v2_time_integral += v2 * inside;
      record.w2_time_integral += w2 * inside;
      record.v2w2_time_integral += v2 * w2 * inside;
    }
    while (k < times.size() && times[k] <= next) observe();
    if (k == times.size()) break;
    t = next;
    state.theta = std::remainder(state.theta + state.omega * flight, 2.0 * std::numbers::pi);
    const double vn = state.normal_velocity();  // 002 eq. (24)
    double x = 0.0;
    for (std::uint64_t attempt = 0;; ++attempt) {  // 002 eq. (29)
      ++record.sampling_attempts;
      if (needle.try_sample_position(vn, state.omega, rng.block(RngPurpose::needle_event, 1, event, attempt), x)) break;
    }
    const double u = vn + state.omega * x;
    const bool right = needle.side_is_right(u, uniform_open(draw[2]));  // 002 eq. (30)
    double c = 0.0;
    for (std::uint64_t attempt = 0;; ++attempt) {  // 002 eqs. (14), (17)
      ++record.sampling_attempts;
      if (needle.try_sample_normal_velocity(u, right, rng.block(RngPurpose::needle_event, 2, event, attempt), c)) break;
    }
    needle_collision(state, body, in.restitution, x, c);  // 002 eqs. (31)-(33)
    ++event;
  }
  record.newton_iterations = counters.newton_iterations;
  record.bisection_fallbacks = counters.bisection_fallbacks;
  series.candidates = record.sampling_attempts;
  series.intruder = std::move(record);
  return series;
}

}  // namespace granmc
