#include "kernel/collide/pair_coefficients.hpp"

#include <numbers>

#include "kernel/collide/collision_kernel.hpp"
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
      const double phi = scene.collision.packing_fraction;
      // Disks: Henderson's form for one species, its mixture form for two (collide/enskog_chi.hpp).
      double chi = 1.0;
      if (phi > 0.0 && scene.run.dimension == 2)
        chi = ns == 1 ? enskog_chi_disks(phi) : enskog_chi_disks(phi, x, sigma, i, j);
      else if (phi > 0.0)
        chi = enskog_chi(phi, x, sigma, i, j);
      const double alpha = scene.collision.restitution[i][j];
      PairCoefficients p;
      p.i = i;
      p.j = j;
      // 000: 4 pi sigma_ij^2 n_j chi_ij; for disks 2 pi sigma_ij n_j chi_ij (collide/hard_sphere.hpp). The
      // kernel form of 001 (collision.rate > 0, one species): |S^(d-1)| rate over the mean of the kernel's
      // angular weight, so that the mean over sigma-hat gives the total rate |S^(d-1)| rate |g|^lambda per
      // pair (collide/maxwell_pseudomolecules.hpp): 16 pi rate for spheres, 2 pi^2 rate for hard disks,
      // 4 pi rate for Maxwell and VHS disks (for hard spheres n sigma^2 = 4 rate, for hard disks n sigma =
      // pi rate).
      const bool disks = scene.run.dimension == 2;
      const double contact = disks ? 2.0 * std::numbers::pi * sigma_ij : 4.0 * std::numbers::pi * sigma_ij * sigma_ij;
      const ImpactLaw law =
          scene.collision.kernel == CollisionKernel::hard_sphere ? ImpactLaw::hard_core : ImpactLaw::isotropic;
      p.rate_prefactor = scene.collision.rate > 0.0 ? unit_sphere_area(scene.run.dimension) * scene.collision.rate /
                                                          mean_angular_weight(scene.run.dimension, law)
                                                    : contact * b.density * chi;
      p.mu_ji = b.mass / (a.mass + b.mass);
      p.mu_ij = a.mass / (a.mass + b.mass);
      p.one_plus_alpha = 1.0 + alpha;
      p.reduced_mass = a.mass * b.mass / (a.mass + b.mass);
      p.energy_loss = 0.5 * (1.0 - alpha * alpha) * a.mass * b.mass / (a.mass + b.mass);
      p.diameter = sigma_ij;
      if (rough(scene.collision)) {  // collide/rough_rule.hpp
        const double kappa = scene.collision.reduced_inertia, beta = scene.collision.tangential_restitution;
        p.tangential = (1.0 + beta) / (1.0 + p.reduced_mass * (1.0 / (kappa * a.mass) + 1.0 / (kappa * b.mass)));
        p.tangential_k = p.mu_ji * p.tangential;
        p.tangential_l = p.mu_ij * p.tangential;
        p.spin_k = p.tangential_k / kappa;
        p.spin_l = p.tangential_l / kappa;
      }
      pairs.push_back(p);
    }
  }
  return pairs;
}

}  // namespace granmc
