#include "kernel/theory/viscosity.hpp"

#include <cmath>
#include <numbers>

#include "kernel/collide/enskog_chi.hpp"
#include "kernel/theory/sonine.hpp"

namespace granmc::theory {

double elastic_dilute_viscosity(double mass, double diameter, double temperature) noexcept {
  return 5.0 / (16.0 * diameter * diameter) * std::sqrt(mass * temperature / std::numbers::pi);  // 003, eta0
}

ShearViscosity shear_viscosity(double alpha, double phi, double chi, ViscosityReference reference,
                               int dimension) noexcept {
  const bool disks = dimension == 2;
  const double c0 = 2.0 * hcs_a2(alpha, dimension);  // 003's c0(alpha): c = 6 <V^4> / (5 <V^2>^2) - 2 = 2 a2
  const double e = 1.0 + alpha;
  ShearViscosity v;
  // Boltzmann-Enskog collision integral of the first Sonine f^(1) against the HCS f^(0), and the cooling
  // rate, both reduced by nu0 = n T / eta0 (docs/methods/derivations/viscosity.md, items 1-2, and "Disks"):
  // nu_eta* = (3 / (4 d)) chi (1 - alpha + 2 d / 3)(1 + alpha)(1 - c0 / 64), zeta* = ((d + 2) / (4 d)) chi
  // (1 - alpha^2)(1 + 3 c0 / 32). For spheres 003's denominator (1/384) chi (1 + alpha) [16 (13 - alpha) -
  // 3 (4 - 3 alpha) c0] is nu_eta - zeta / 2.
  v.nu_eta = disks ? chi * (1.0 + alpha) * (7.0 - 3.0 * alpha) / 8.0 * (1.0 - c0 / 64.0)
                   : chi * (1.0 - 0.25 * (1.0 - alpha) * (1.0 - alpha)) * (1.0 - c0 / 64.0);
  v.zeta = (disks ? 0.5 : 5.0 / 12.0) * chi * (1.0 - alpha * alpha) * (1.0 + 3.0 * c0 / 32.0);
  // The P_xy balance gets -(zeta/2) P_xy from the cooling of the reference state (eta ~ sqrt(T)), and
  // -zeta P_xy from the Gaussian thermostat (1/2) zeta d/dV . (V f) (000 eq. 9, with the 1/2 of eq. 8).
  const double rate = reference == ViscosityReference::cooling ? v.nu_eta - 0.5 * v.zeta : v.nu_eta - v.zeta;
  // Kinetic part: the numerator is the collisional source (Enskog gradient term) of the P^k balance,
  // 1 - (2^(d-2) / (d + 2)) phi chi (1 + alpha)(1 - 3 alpha) (003 for d = 3; Garzo and Montanero 2002 in d).
  v.kinetic = (1.0 - (disks ? 0.25 : 0.4) * phi * chi * e * (1.0 - 3.0 * alpha)) / rate;
  // Total: the collisional transfer of f^(1), (2^(d-1) / (d + 2)) phi chi (1 + alpha), and of the gradient of
  // f^(0) (000 eq. 18's continuum form), the bulk-viscosity term (d / (d + 2)) (2^(2d+1) / (pi (d + 2))) phi^2
  // chi (1 + alpha)(1 - c0 / 32): 384 / (25 pi) for spheres, 4 / pi for disks. For elastic disks this is Gass's
  // Enskog viscosity 1/chi + 2 phi + (1 + 8/pi) phi^2 chi (tests/test_viscosity_theory.cpp).
  v.total =
      v.kinetic * (1.0 + (disks ? 0.5 : 0.8) * phi * chi * e) +
      (disks ? 4.0 / std::numbers::pi : 384.0 / (25.0 * std::numbers::pi)) * phi * phi * chi * e * (1.0 - c0 / 32.0);
  return v;
}

ShearViscosity shear_viscosity(double alpha, double phi, ViscosityReference reference, int dimension) {
  const double chi = dimension == 2 ? enskog_chi_disks(phi) : enskog_chi(phi, {1.0}, {1.0}, 0, 0);
  return shear_viscosity(alpha, phi, chi, reference, dimension);
}

double reduced_viscosity_one_species(double eta_over_eta0, int dimension) noexcept {
  return (dimension + 2.0) * std::numbers::sqrt2 / 16.0 * eta_over_eta0;  // nu eta0 / (n T) = nu / nu0
}

double reduced_viscosity(double eta, double temperature, double sigma_12, double v0) noexcept {
  return std::sqrt(std::numbers::pi) * sigma_12 * sigma_12 * v0 * eta / temperature;  // 000, Figs. 10-11 text
}

double mixture_thermal_speed(double temperature, double mass_1, double mass_2) noexcept {
  return std::sqrt(2.0 * temperature * (mass_1 + mass_2) / (mass_1 * mass_2));  // 000 eq. (7)
}

}  // namespace granmc::theory
