#pragma once
// The BGK-like relaxation term of 003's modified shear flow, F[f] = (1/2) zeta (f - f^(0)) (with the
// Gaussian thermostat (1/2) zeta d/dV.(V f), effects/gaussian_thermostat.hpp): over a step every particle's
// velocity is replaced, independently with probability 1 - exp(-zeta dt / 2), by one drawn from the
// cooling-state distribution f^(0) at the gas's current temperature. 003 states the first-order form,
// probability zeta dt / 2; the exponential is the exact flow of df/dt = -(zeta/2)(f - f^(0)).
//
// zeta is the step's thermostat rate, zeta dt = ln(1 + loss / E) from the collisional loss (the same
// expression as the thermostat's). f^(0) is sampled as the first-Sonine HCS distribution, a Maxwellian
// times 1 + a2 S2 with a2 = c0 / 2 of 003 (core/sonine_maxwellian.hpp, exact; docs/methods/physics.md measures
// what the choice costs against the true HCS), in d = 3 or 2. One species (003 is monodisperse).
//
// Particles are chosen by geometric gaps (O(replaced) work, not O(N)): the gap before the next replaced
// particle is floor(ln u / ln(1 - p)). Random words: purpose relaxation, step = time step, a running
// block index; the stream order is fixed, so the result does not depend on threads.
#include <cmath>
#include <cstdint>
#include <string>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/sonine_maxwellian.hpp"
#include "kernel/effects/step_context.hpp"

namespace granmc {

struct BgkRelaxation {
  static constexpr StepPhase phase = StepPhase::after_collisions;
  static constexpr const char* name = "bgk-relaxation";
  static constexpr bool acts_on_particles = true;

  SonineMaxwellian f0{0.0};  // f^(0) in reduced velocity V / v0, a2 of the scene's alpha (and dimension)
  double mass = 1.0;
  int dimension = 3;

  [[nodiscard]] std::string explanation() const {
    return "BGK-like relaxation to the first-Sonine HCS f^(0) (003), O(replaced) per step";
  }

  /// Returns the change of sum_k m |c_k|^2 (stored units).
  template <class State>
  double apply(State& state, const StepContext& step) const noexcept {
    const double zeta_dt = std::log1p(step.twice_energy_loss / step.twice_energy);
    const double log_keep = -0.5 * zeta_dt;  // ln(1 - p), p = 1 - exp(-zeta dt / 2)
    if (!(log_keep < 0.0)) return 0.0;
    auto& store = state.species[0];
    const double n = static_cast<double>(store.size());
    const double v0 = std::sqrt(2.0 * step.twice_energy / (dimension * n * mass));  // sqrt(2 T / m), T = m <c^2> / d
    std::uint64_t block = 0;
    RandomBlock words{};
    int used = 4;
    auto next_uniform = [&]() {
      if (used == 4) {
        words = step.rng->block(RngPurpose::relaxation, 0, state.step, block++);
        used = 0;
      }
      return uniform_open(words[used++]);
    };
    double change = 0.0;
    for (double k = std::floor(std::log(next_uniform()) / log_keep); k < n;
         k += 1.0 + std::floor(std::log(next_uniform()) / log_keep)) {
      const std::size_t index = static_cast<std::size_t>(k);
      const Vec3 c = v0 * f0.sample(next_uniform);
      change += mass * (norm2(c) - norm2(store.velocity(index)));
      store.set_velocity(index, c);
    }
    return change;
  }
};

static_assert(FreeFlightEffect<BgkRelaxation>);

}  // namespace granmc
