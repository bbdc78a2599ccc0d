#include "kernel/collide/enskog_chi.hpp"

namespace granmc {

double enskog_chi(double phi, const std::vector<double>& x, const std::vector<double>& sigma, int i, int j) {
  double s2 = 0.0, s3 = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    s2 += x[k] * sigma[k] * sigma[k];
    s3 += x[k] * sigma[k] * sigma[k] * sigma[k];
  }
  const double hat_phi = phi * s2 / s3;
  const double sigma_ij = 0.5 * (sigma[i] + sigma[j]);
  const double tilde_sigma = sigma[i] * sigma[j] / sigma_ij;  // 000 after eq. (3)
  const double a = hat_phi * tilde_sigma;
  const double q = 1.0 - phi;
  return 1.0 / q + 1.5 * a / (q * q) + 0.5 * a * a / (q * q * q);  // 000 eq. (3)
}

double enskog_chi_disks(double phi) noexcept { return (1.0 - 7.0 * phi / 16.0) / ((1.0 - phi) * (1.0 - phi)); }

double enskog_chi_disks(double phi, const std::vector<double>& x, const std::vector<double>& sigma, int i, int j) {
  double m1 = 0.0, m2 = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    m1 += x[k] * sigma[k];
    m2 += x[k] * sigma[k] * sigma[k];
  }
  const double sigma_ij = 0.5 * (sigma[i] + sigma[j]);
  const double q = 1.0 - phi;
  return 1.0 / q + 9.0 / 16.0 * phi / (q * q) * sigma[i] * sigma[j] * m1 / (sigma_ij * m2);
}

}  // namespace granmc
