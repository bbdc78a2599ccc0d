#include "kernel/theory/steady_shear.hpp"

#include <cmath>
#include <numbers>

#include "kernel/theory/viscosity.hpp"

namespace granmc::theory {

SteadyShearFlow steady_shear_grad(double alpha) noexcept {
  const double beta = (1.0 + alpha) * (3.0 - alpha) / 4.0;  // nu_eta* of a Maxwellian (viscosity.hpp, c0 = 0)
  const double zeta = 5.0 / 12.0 * (1.0 - alpha * alpha);   // zeta* of a Maxwellian
  SteadyShearFlow s;
  s.shear_rate_nu0 = std::sqrt(1.5 * zeta * beta * beta / (beta - zeta));  // trace: (2/3) a* |P_xy*| = zeta*
  s.pressure_yy = 1.0 - zeta / beta;                                       // yy balance
  s.pressure_xx = 1.0 + 2.0 * zeta / beta;                                 // P_xx + 2 P_yy = 3 p
  s.pressure_xy = -s.shear_rate_nu0 * s.pressure_yy / beta;                // xy balance
  s.eta_over_eta0 = (beta - zeta) / (beta * beta);                         // -P_xy* / a*
  // nu0 / nu = (16/5) sqrt(pi) / (sqrt(pi) sqrt(2)) = 16 / (5 sqrt(2)).
  s.shear_rate_star = 16.0 / (5.0 * std::numbers::sqrt2) * s.shear_rate_nu0;
  s.eta_star = reduced_viscosity_one_species(s.eta_over_eta0);
  return s;
}

double steady_shear_temperature(const SteadyShearFlow& s, double shear_rate, double density, double diameter,
                                double mass) noexcept {
  // a = shear_rate_nu0 (16/5) n sigma^2 sqrt(pi T / m), solved for T.
  const double root_t =
      shear_rate / (s.shear_rate_nu0 * 3.2 * density * diameter * diameter * std::sqrt(std::numbers::pi / mass));
  return root_t * root_t;
}

}  // namespace granmc::theory
