#pragma once
// Pair correlation at contact chi_ij of a hard-sphere mixture, Carnahan-Starling form (000 eq. 3,
// Boublik-Mansoori-Carnahan-Starling-Leland). In a homogeneous state chi_ij only rescales the
// collision rate of the pair i-j (000 eq. 2).
#include <vector>

namespace granmc {

/// chi_ij for a mixture with packing fraction phi, mole fractions x_k and diameters sigma_k.
/// The packing fraction fixes the density scale: hat-phi = (pi n / 6) sum_k x_k sigma_k^2 is taken as
/// phi * sum_k x_k sigma_k^2 / sum_k x_k sigma_k^3, so that phi = (pi n / 6) sum_k x_k sigma_k^3.
/// Monodisperse: chi = (1 - phi/2) / (1 - phi)^3.
double enskog_chi(double phi, const std::vector<double>& x, const std::vector<double>& sigma, int i, int j);

/// chi at contact of monodisperse hard disks (d = 2) with area fraction phi = pi n sigma^2 / 4, Henderson's
/// form (Mol. Phys. 30 (1975) 971): (1 - 7 phi / 16) / (1 - phi)^2.
double enskog_chi_disks(double phi) noexcept;

/// chi_ij of a hard-disk mixture with area fraction phi = (pi n / 4) sum_k x_k sigma_k^2, mole fractions x_k and
/// diameters sigma_k (Jenkins and Mancini, J. Appl. Mech. 54 (1987) 27; the form of Montanero, Garzo, Alam and
/// Luding, Granular Matter 8 (2006) 103), which is Henderson's form for one species:
///   chi_ij = 1 / (1 - phi) + (9/16) phi / (1 - phi)^2 sigma_i sigma_j M_1 / (sigma_ij M_2),
///   M_k = sum_l x_l sigma_l^k.
double enskog_chi_disks(double phi, const std::vector<double>& x, const std::vector<double>& sigma, int i, int j);

}  // namespace granmc
