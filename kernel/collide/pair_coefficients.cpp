#include "kernel/collide/pair_coefficients.hpp"

#include <numbers>

#include "kernel/collide/enskog_chi.hpp"

namespace granmc {

std::vector<PairCoefficients> pair_coefficients(const Scene& scene) {
  const int ns = static_cast<int>(scene.species.size());
  const double n = total_density(scene);
  std::vector<double> x, sigma;
  for (const auto& s : scene.species) {
    x.push_back(s.density / n);
    sigma.push_back(s.diameter);
  }
  std::vector<PairCoefficients> pairs;
  for (int i = 0; i < ns; ++i) {
    for (int j = 0; j < ns; ++j) {
      const SpeciesConfig& a = scene.species[i];
      const SpeciesConfig& b = scene.species[j];
      const double sigma_ij = 0.5 * (a.diameter + b.diameter);
      const double chi =
          scene.collision.packing_fraction > 0.0 ? enskog_chi(scene.collision.packing_fraction, x, sigma, i, j) : 1.0;
      const double alpha = scene.collision.restitution[i][j];
      PairCoefficients p;
      p.i = i;
      p.j = j;
      // 000: 4 pi sigma_ij^2 n_j chi_ij. The kernel form of 001 (collision.rate > 0, one species):
      // 16 pi rate, whose mean over sigma-hat gives the total rate 4 pi rate |g|^lambda per pair
      // (collide/maxwell_pseudomolecules.hpp; for hard spheres n sigma^2 = 4 rate).
      p.rate_prefactor = scene.collision.rate > 0.0 ? 16.0 * std::numbers::pi * scene.collision.rate
                                                    : 4.0 * std::numbers::pi * sigma_ij * sigma_ij * b.density * chi;
      p.mu_ji = b.mass / (a.mass + b.mass);
      p.mu_ij = a.mass / (a.mass + b.mass);
      p.one_plus_alpha = 1.0 + alpha;
      p.reduced_mass = a.mass * b.mass / (a.mass + b.mass);
      p.energy_loss = 0.5 * (1.0 - alpha * alpha) * a.mass * b.mass / (a.mass + b.mass);
      p.diameter = sigma_ij;
      pairs.push_back(p);
    }
  }
  return pairs;
}

}  // namespace granmc
