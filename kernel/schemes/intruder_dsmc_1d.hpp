#pragma once
// The DSMC alternative for the point intruder of mass M in a bath of point particles of mass m = 1 on a
// line (002 sec. 4), one replica, time-stepped with run.dt; the same outputs as the Gillespie scheme
// (schemes/intruder_1d.hpp).
//
// 002 sec. 4 draws candidates at a rate omega_max: a side sigma = +-1 at random and a bath particle i with
// v ~ f, accepted with probability Theta(sigma v_i1) omega_i1 / omega_max, omega_i1 = 2 rho |v_i1|, v_i1 = v - v1;
// an accepted candidate changes v1 by 002 eq. (21); omega_max is an estimate, raised when exceeded. Here:
//  1. Side. Drawing sigma and accepting with Theta(sigma v_i1) 2 rho |v_i1| / omega_max is, for each v, accepting
//     with rho |v_i1| / omega_max on the side the particle comes from (v < v1: the right). That is done
//     directly: the same law with half the candidates.
//  2. Majorant. No constant omega_max bounds rho |v1 - v|: v is unbounded in both baths (heavy-tailed in the
//     power law), so a raised estimate truncates the tail of the collision law, and keeps lowering the
//     acceptance. Instead the bound |v1 - v| <= |v1| + |v| holds for each candidate: candidates come at the rate
//     Lambda(v1) = rho (|v1| + <|v|>) >= phi(v1) (002 eq. 7) with the velocity law (|v1| + |v|) f(v) / (|v1| + <|v|>),
//     i.e. v ~ f with probability |v1| / (|v1| + <|v|>), else v ~ |v| f(v) / <|v|>, and are accepted with
//     probability |v1 - v| / (|v1| + |v|) <= 1. Accepted velocities then come at the rate rho |v1 - v| f(v), i.e.
//     at the total rate phi(v1) with the side and law of 002 eqs. (11), (14), (17): exact, no truncation, and the
//     acceptance phi / Lambda is >= 0.648 (Gaussian) and >= 0.655 (power law) for every v1. In x = sqrt(a) v,
//     <|x|> = 1/sqrt(pi) (Gaussian), 1/sqrt(2) (power law).
//  3. Candidates per step: the NTC count with a fractional carry (000 sec. 3). A step of length dt holds
//     Lambda(v1) dt candidates plus the fraction carried from the previous step; v1 is updated after each
//     accepted collision (never held over the step), and since Lambda depends on v1 the rest of the step is then
//     recounted at the new rate: each candidate takes 1 / Lambda(v1) of the step. As a clock: candidate j is at
//     t_j, with t_{j+1} = t_j + 1 / Lambda(v1 after candidate j), and belongs to the step floor(t_j / dt); steps
//     without a candidate cost nothing. An observation at t sees v1 after the candidates with t_j < t.
// Exact and approximate. The bath law f is sampled exactly (Gaussian: Box-Muller; power law: ratio of
// uniforms, below), |v| f / <|v|> by inversion, the majorant is exact and v1 is current at every candidate, so
// the sequence of candidates is exactly the embedded chain of the Boltzmann jump process (002 eq. 8)
// uniformised at the rate Lambda(v1). The one approximation is the clock: gaps 1 / Lambda(v1) are deterministic
// where the uniformised process has exponential gaps with the same mean. That changes the dynamics on the
// scale of a mean free time (time correlations, transients), not the stationary law: after each candidate the
// state v1 is held for a time of mean 1 / Lambda(v1) in both, and a semi-Markov process spends in each state a
// time fraction proportional to visits x mean holding time. The stationary law of v1, hence T/T_B, is exact for
// every dt: nothing here is split over a step (no free flight, a homogeneous bath), dt only groups the
// candidates and addresses their random numbers (so run.dt_scaling changes nothing and is not read).
// (Exponential gaps would make the dynamics exact too, at one logarithm per candidate: that is the Gillespie
// scheme with null events.)
// Random numbers: block (intruder_event, sub = 1, step, j), step = floor(t_j / dt), j = 0, 1, ... counting the
// blocks drawn in that step: each candidate takes the next block (u0: which law v comes from, u1 u2: v, u3:
// acceptance); each rejected ratio-of-uniforms attempt at the power-law f takes the next block for the next
// attempt (its words 0, 1). The start is the Gillespie scheme's: block (initial_velocity, 0, 0, 0).
// Counts: series.candidates = candidates tested; intruder->sampling_attempts = draws from the velocity laws
// (candidates plus the rejected attempts at the power-law f).
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "kernel/collide/bath_gaussian.hpp"
#include "kernel/collide/bath_power_law.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/intruder_record.hpp"
#include "kernel/schemes/run_options.hpp"

namespace granmc {

/// The bath laws as the DSMC candidates need them, in x = sqrt(a) v.
namespace intruder_dsmc {

/// <|x|> over f: 002 eq. (18) in x is exp(-x^2) / sqrt(pi).
inline double mean_speed(const GaussianBath&) noexcept { return 1.0 / std::sqrt(std::numbers::pi); }
/// <|x|> over f: 002 eq. (23) in x is (sqrt 2 / pi) / (1 + x^4), and int_0^inf x / (1 + x^4) dx = pi / 4.
inline double mean_speed(const PowerLawBath&) noexcept { return 1.0 / std::numbers::sqrt2; }

/// One attempt at x ~ f from two uniforms; false if rejected. Gaussian: Box-Muller (never rejects).
inline bool try_sample_law(const GaussianBath&, double u1, double u2, double& x) noexcept {
  x = std::sqrt(-std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);  // variance 1/2
  return true;
}

/// Power law: ratio of uniforms for h(x) = 1 / (1 + x^4). (s, w) uniform on (0, 1) x (-1/sqrt 2, 1/sqrt 2), a box
/// holding {0 < s <= sqrt(h(w / s))} (sup sqrt(h) = 1, sup |x| sqrt(h(x)) = 1/sqrt 2 at |x| = 1); inside it, i.e.
/// s^4 + w^4 <= s^2, x = w / s has the law h exactly. Acceptance (pi / (2 sqrt 2)) / sqrt 2 = pi / 4.
inline bool try_sample_law(const PowerLawBath&, double u1, double u2, double& x) noexcept {
  const double s = u1, w = (2.0 * u2 - 1.0) / std::numbers::sqrt2;
  const double s2 = s * s, w2 = w * w;
  if (s2 * s2 + w2 * w2 > s2) return false;
  x = w / s;
  return true;
}

/// |x| from the law |x| f(x) / <|x|> on x >= 0, by inversion. Gaussian: P(|x| > r) = exp(-r^2).
inline double sample_size_biased(const GaussianBath&, double u) noexcept { return std::sqrt(-std::log(u)); }
/// Power law: y = x^2 has the law (2 / pi) / (1 + y^2) on y >= 0, y = tan(pi u / 2).
inline double sample_size_biased(const PowerLawBath&, double u) noexcept {
  return std::sqrt(std::tan(0.5 * std::numbers::pi * u));
}

}  // namespace intruder_dsmc

/// Requires scene.run.dt > 0 and t_end / dt below RandomStream::counter_limit.
template <class Bath>
ReplicaSeries run_intruder_dsmc_1d(const Scene& scene, std::uint64_t replica, const std::vector<double>& times,
                                   const RunOptions& options, const Bath& bath) {
  const IntruderConfig& in = *scene.intruder;
  const RandomStream rng(scene.run.seed, replica);
  const double dt = scene.run.dt;
  const double kick = (1.0 + in.restitution) / (1.0 + in.mass);  // 002 eq. (21), m = 1
  const double sqrt_a = std::sqrt(bath.a);
  const double mean_x = intruder_dsmc::mean_speed(bath);  // <|x|>
  IntruderRecord1D record(scene, times.size());
  double v1 = initial_intruder_velocity(scene, rng);  // as the Gillespie scheme

  // 1 / Lambda(v1), Lambda = rho (|v1| + <|v|>) >= phi(v1) (002 eq. 7): the gap to the next candidate.
  auto gap = [&](double v) { return sqrt_a / (bath.rho * (sqrt_a * std::fabs(v) + mean_x)); };
  double clock = gap(v1);  // time of the next candidate
  std::uint64_t step = 0, block = 0, candidates = 0, collisions = 0;
  auto observe = [&] {
    record.observe(v1, collisions);
    if (options.on_sample) options.on_sample();
  };
  while (true) {
    while (record.samples() < times.size() && times[record.samples()] <= clock) observe();
    if (record.samples() == times.size()) break;
    if (const auto s = static_cast<std::uint64_t>(clock / dt); s != step) {  // the candidate's step
      step = s;
      block = 0;
    }
    const RandomBlock u = rng.block(RngPurpose::intruder_event, 1, step, block++);
    ++candidates;
    record.count_sampling_attempt();
    const double c = sqrt_a * std::fabs(v1);  // |x1|
    double x;
    if (uniform_open(u[0]) * (c + mean_x) < c) {  // v ~ f, weight |v1|
      bool drawn = intruder_dsmc::try_sample_law(bath, uniform_open(u[1]), uniform_open(u[2]), x);
      while (!drawn) {
        record.count_sampling_attempt();
        const RandomBlock r = rng.block(RngPurpose::intruder_event, 1, step, block++);
        drawn = intruder_dsmc::try_sample_law(bath, uniform_open(r[0]), uniform_open(r[1]), x);
      }
    } else {  // v ~ |v| f / <|v|>, weight <|v|>
      x = intruder_dsmc::sample_size_biased(bath, uniform_open(u[1]));
      if (uniform_open(u[2]) < 0.5) x = -x;
    }
    if (uniform_open(u[3]) * (c + std::fabs(x)) < std::fabs(sqrt_a * v1 - x)) {  // |v1 - v| / (|v1| + |v|)
      v1 += kick * (x / sqrt_a - v1);                                            // 002 eq. (21)
      ++collisions;
    }
    clock += gap(v1);
  }
  return record.finish(candidates);
}

}  // namespace granmc
