#include "kernel/theory/steady_shear.hpp"

#include <cmath>
#include <numbers>

#include "kernel/theory/viscosity.hpp"

namespace granmc::theory {

SteadyShearFlow steady_shear_grad(double alpha, int dimension) noexcept {
  const bool disks = dimension == 2;
  // nu_eta* and zeta* of a Maxwellian (viscosity.hpp, c0 = 0), in the forms that reduce for each d.
  const double beta = disks ? (1.0 + alpha) * (7.0 - 3.0 * alpha) / 8.0 : (1.0 + alpha) * (3.0 - alpha) / 4.0;
  const double zeta = disks ? 0.5 * (1.0 - alpha * alpha) : 5.0 / 12.0 * (1.0 - alpha * alpha);
  const double d = dimension;
  SteadyShearFlow s;
  s.dimension = dimension;
  s.shear_rate_nu0 = std::sqrt(0.5 * d * zeta * beta * beta / (beta - zeta));  // trace: (2/d) a* |P_xy*| = zeta*
  s.pressure_yy = 1.0 - zeta / beta;                                           // yy balance
  s.pressure_xx = 1.0 + (d - 1.0) * zeta / beta;                               // P_xx + (d - 1) P_yy = d p
  s.pressure_xy = -s.shear_rate_nu0 * s.pressure_yy / beta;                    // xy balance
  s.eta_over_eta0 = (beta - zeta) / (beta * beta);                             // -P_xy* / a*
  // nu0 / nu = 16 / ((d + 2) sqrt 2) (theory/viscosity.hpp, reduced_viscosity_one_species).
  s.shear_rate_star = 16.0 / ((d + 2.0) * std::numbers::sqrt2) * s.shear_rate_nu0;
  s.eta_star = reduced_viscosity_one_species(s.eta_over_eta0, dimension);
  return s;
}

double steady_shear_temperature(const SteadyShearFlow& s, double shear_rate, double density, double diameter,
                                double mass) noexcept {
  // a = shear_rate_nu0 (16/5) n sigma^2 sqrt(pi T / m), disks 2 n sigma sqrt(pi T / m), solved for T.
  const double root_pi_m = std::sqrt(std::numbers::pi / mass);
  const double root_t = s.dimension == 2
                            ? shear_rate / (s.shear_rate_nu0 * 2.0 * density * diameter * root_pi_m)
                            : shear_rate / (s.shear_rate_nu0 * 3.2 * density * diameter * diameter * root_pi_m);
  return root_t * root_t;
}

}  // namespace granmc::theory
