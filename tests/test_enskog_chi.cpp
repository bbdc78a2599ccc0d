#include <gtest/gtest.h>

#include "kernel/collide/enskog_chi.hpp"

using namespace granmc;

TEST(EnskogChi, MonodisperseIsCarnahanStarling) {
  for (double phi : {0.0, 0.1, 0.3, 0.5}) {
    const double cs = (1.0 - 0.5 * phi) / ((1.0 - phi) * (1.0 - phi) * (1.0 - phi));
    EXPECT_NEAR(enskog_chi(phi, {1.0}, {1.0}, 0, 0), cs, 1e-14 * cs);
    // Two mechanically identical species give the same chi for every pair.
    EXPECT_NEAR(enskog_chi(phi, {0.3, 0.7}, {2.0, 2.0}, 0, 1), cs, 1e-14 * cs);
  }
}

namespace {

/// chi_ij grows with sigma_i sigma_j / sigma_ij: chi_22 > chi_12 > chi_11 when sigma_2 > sigma_1; symmetric.
template <class Chi>
void expect_larger_partners_see_more_contacts(Chi chi) {
  const std::vector<double> x{0.5, 0.5}, sigma{1.0, 2.0};
  const double c11 = chi(0.3, x, sigma, 0, 0), c12 = chi(0.3, x, sigma, 0, 1), c22 = chi(0.3, x, sigma, 1, 1);
  EXPECT_LT(c11, c12);
  EXPECT_LT(c12, c22);
  EXPECT_DOUBLE_EQ(c12, chi(0.3, x, sigma, 1, 0));
}

}  // namespace

TEST(EnskogChi, LargerPartnersSeeMoreContacts) {
  expect_larger_partners_see_more_contacts([](double phi, const std::vector<double>& x,
                                              const std::vector<double>& sigma, int i,
                                              int j) { return enskog_chi(phi, x, sigma, i, j); });
}

TEST(EnskogChi, DiskMixtureIsHendersonForOneSpecies) {
  // collide/enskog_chi.hpp's disk-mixture form at one species, or two identical ones, is Henderson's.
  for (double phi : {0.0, 0.1, 0.3, 0.6}) {
    const double henderson = enskog_chi_disks(phi);
    EXPECT_NEAR(enskog_chi_disks(phi, {1.0}, {1.0}, 0, 0), henderson, 1e-14 * henderson);
    EXPECT_NEAR(enskog_chi_disks(phi, {0.3, 0.7}, {2.0, 2.0}, 0, 1), henderson, 1e-14 * henderson);
  }
  expect_larger_partners_see_more_contacts([](double phi, const std::vector<double>& x,
                                              const std::vector<double>& sigma, int i,
                                              int j) { return enskog_chi_disks(phi, x, sigma, i, j); });
}
