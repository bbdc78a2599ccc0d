#pragma once
// The theory that applies to a scene, for `granmc theory`, comparison lines and tests.
#include <optional>
#include <vector>

#include "kernel/core/scene.hpp"
#include "kernel/theory/mixture_hcs.hpp"

namespace granmc::theory {

/// Monodisperse hard-sphere (or hard-disk, run.dimension = 2) homogeneous cooling state (no thermostat, no
/// shear).
struct CoolingStatePrediction {
  double alpha = 1.0;
  double chi = 1.0;               // Carnahan-Starling chi (000 eq. 3), Henderson's for disks; 1 when dilute
  double a2 = 0.0;                // first-Sonine a2 (van Noije and Ernst 1998)
  double a2_model_error = 0.0;    // |second - first Sonine a2|: the first-Sonine truncation error
  double a2_second_sonine = 0.0;  // second-Sonine a2 and a3 (docs/methods/derivations/sonine-hcs.md)
  double a3_second_sonine = 0.0;
  double cooling_rate0 = 0.0;               // zeta at T(0) with the second-Sonine factor mu_2(a2, a3) / mu_2(0, 0)
  double cooling_rate0_first_sonine = 0.0;  // zeta at T(0) with the first-Sonine factor 1 + 3 a2 / 16
  double cooling_rate0_maxwell = 0.0;       // zeta at T(0) for a Maxwellian (a2 = a3 = 0)
  double cooling_rate_model_error = 0.0;  // relative: bound on |zeta(t) / zeta_theory(t) - 1| (docs/methods/physics.md)
  double collision_frequency0 = 0.0;      // nu at T(0), Maxwellian (theory::collision_frequency)
  std::vector<double> temperature;        // Haff's law with cooling_rate0 at the sample times
};

/// The HCS prediction if the scene is a monodisperse hard-sphere cooling state, else nothing.
std::optional<CoolingStatePrediction> cooling_state(const Scene& scene, const std::vector<double>& times);

/// The scaled state of the HCS, which the Gaussian-thermostat HSS shares (000 sec. 2): one species.
struct ScaledStatePrediction {
  double a2 = 0.0;                // first Sonine (van Noije and Ernst 1998)
  double a2_model_error = 0.0;    // |second - first Sonine a2|
  double a2_second_sonine = 0.0;  // docs/methods/derivations/sonine-hcs.md
  double a3_second_sonine = 0.0;
};

/// Two species: temperature ratio and a2_i (docs/methods/derivations/mixture-hcs.md).
struct MixturePrediction {
  double temperature_ratio_maxwell = 1.0;  // gamma = T_1/T_2 from zeta_1 = zeta_2, Maxwellians
  /// gamma with the first-Sonine corrections and the first-Sonine a2_i (c_i = 2 a2_i, 000 Fig. 1), spheres or
  /// disks.
  MixtureSonine first_sonine{};
  double chi[2][2] = {{1.0, 1.0}, {1.0, 1.0}};
};

/// For a hard-sphere DSMC scene without shear or relaxation, cooling or with a Gaussian thermostat.
std::optional<ScaledStatePrediction> scaled_state(const Scene& scene);
std::optional<MixturePrediction> mixture_state(const Scene& scene);

/// The mechanical parameters of a two-species scene (chi_ij of its packing_fraction: Carnahan-Starling's for
/// spheres, Jenkins and Mancini's for disks; 1 when dilute).
MixtureParameters mixture_parameters(const Scene& scene);

}  // namespace granmc::theory
