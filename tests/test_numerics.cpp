// Numerical hygiene: the sums behind moments of 10^7 particles are compensated, and the
// random unit vectors and Gaussians have the statistics they claim (moments with CIs, a chi-square test
// of the direction distribution on equal-area cells). Each check would fail without what it checks.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <span>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "kernel/core/batch_variates.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/simd.hpp"
#include "kernel/core/turn_sincos.hpp"
#include "kernel/observe/compensated_sum.hpp"
#include "kernel/observe/moments.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "tests/statistical_check.hpp"

using namespace granmc;
using granmc::testing::within_ci;

TEST(Numerics, MomentsOfTenMillionParticlesAreCompensated) {
  // <c^2> of 10^7 velocities c = (1 + k eps, 0, 0): exact sum known in closed form. A plain running sum
  // loses about N eps_machine relative (1e-9 here); the compensated one stays at rounding.
  const std::size_t n = 10'000'000;
  const double eps = 1e-7;
  SpeciesStore store(n);
  for (std::size_t k = 0; k < n; ++k) store.set_velocity(k, {1.0 + eps * static_cast<double>(k), 0.0, 0.0});
  const SpeciesMoments m = species_moments(store);
  // sum (1 + eps k)^2 = n + 2 eps n(n-1)/2 + eps^2 (n-1) n (2n-1)/6, evaluated in long double.
  const long double N = n, e = eps;
  const long double exact = N + e * N * (N - 1) + e * e * (N - 1) * N * (2 * N - 1) / 6;
  double naive = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double c = 1.0 + eps * static_cast<double>(k);
    naive += c * c;
  }
  const double compensated_error = std::fabs(static_cast<double>((m.sum_c2 - exact) / exact));
  const double naive_error = std::fabs(static_cast<double>((naive - exact) / exact));
  std::printf("[ measured ] relative error of sum c^2 over 1e7: compensated %.2e, plain %.2e\n", compensated_error,
              naive_error);
  EXPECT_LT(compensated_error, 1e-15);
  EXPECT_GT(naive_error, 100.0 * compensated_error) << "the test no longer distinguishes the two sums";
}

TEST(Numerics, UnitVectorsAreUniformOnTheSphere) {
  // Equal-area cells: cos(theta) and phi both uniform, 20 x 20 cells; chi-square with 399 degrees of
  // freedom, rejected above its 0.999 quantile (about 399 + 3.09 sqrt(2 x 399) = 486). Moments
  // <n_x^2> = <n_y^2> = <n_z^2> = 1/3 and <n_x n_y> = 0 within their CIs (lambda_p = 3.2).
  const RandomStream rng(2024, 0);
  const int cells = 20;
  const std::uint64_t samples = 4'000'000;
  std::vector<double> counts(cells * cells, 0.0);
  double sxx = 0, syy = 0, szz = 0, sxy = 0, sxx2 = 0, sxy2 = 0;
  for (std::uint64_t s = 0; s < samples; ++s) {
    const RandomBlock r = rng.block(RngPurpose::collision_pair, 0, 0, s);
    const Vec3 v = unit_vector(uniform_open(r[0]), uniform_open(r[1]));
    EXPECT_NEAR(norm2(v), 1.0, 1e-15);
    const double phi = std::atan2(v.y, v.x) + std::numbers::pi;
    const int a = std::min(cells - 1, static_cast<int>((v.z + 1.0) / 2.0 * cells));
    const int b = std::min(cells - 1, static_cast<int>(phi / (2.0 * std::numbers::pi) * cells));
    counts[a * cells + b] += 1.0;
    sxx += v.x * v.x;
    syy += v.y * v.y;
    szz += v.z * v.z;
    sxy += v.x * v.y;
    sxx2 += v.x * v.x * v.x * v.x;
    sxy2 += v.x * v.x * v.y * v.y;
  }
  const double expected = static_cast<double>(samples) / (cells * cells);
  double chi2 = 0.0;
  for (double c : counts) chi2 += (c - expected) * (c - expected) / expected;
  std::printf("[ measured ] chi-square over %d equal-area cells: %.1f (0.999 quantile about 486)\n", cells * cells,
              chi2);
  EXPECT_LT(chi2, 486.0);
  const double ns = static_cast<double>(samples);
  const double ci_xx = 3.2 * std::sqrt((sxx2 / ns - (sxx / ns) * (sxx / ns)) / ns);
  const double ci_xy = 3.2 * std::sqrt(sxy2 / ns / ns);
  // Bounds: the same CIs from the exact variances on the sphere, Var n_x^2 = 1/5 - 1/9 = 4/45 and
  // Var n_x n_y = <n_x^2 n_y^2> = 1/15; the sample variances of 4 10^6 draws scatter by 0.1 % or less: 1.05x.
  const double bound_xx = 1.05 * 3.2 * std::sqrt(4.0 / 45.0 / ns), bound_xy = 1.05 * 3.2 * std::sqrt(1.0 / 15.0 / ns);
  EXPECT_TRUE(within_ci("<n_x^2>", sxx / ns, ci_xx, 1.0 / 3.0, bound_xx));
  EXPECT_TRUE(within_ci("<n_y^2>", syy / ns, ci_xx, 1.0 / 3.0, bound_xx));
  EXPECT_TRUE(within_ci("<n_z^2>", szz / ns, ci_xx, 1.0 / 3.0, bound_xx));
  EXPECT_TRUE(within_ci("<n_x n_y>", sxy / ns, ci_xy, 0.0, bound_xy));
}

TEST(Numerics, BoxMullerNormalsHaveGaussianMoments) {
  // Mean 0, variance 1, <z^4> = 3, <z^6> = 15 within CIs (lambda_p = 3.2; the empirical variances, and
  // the Gaussian's own for z^6), from 4 10^6 normals; and the two normals of a pair uncorrelated.
  const RandomStream rng(7, 3);
  const std::uint64_t pairs = 2'000'000;
  CompensatedSum s1, s2, s4, s6, s12, s8, s12sq;
  for (std::uint64_t s = 0; s < pairs; ++s) {
    const RandomBlock r = rng.block(RngPurpose::initial_velocity, 0, 0, s);
    double z1, z2;
    standard_normal_pair(uniform_open(r[0]), uniform_open(r[1]), z1, z2);
    for (double z : {z1, z2}) {
      s1.add(z);
      s2.add(z * z);
      s4.add(z * z * z * z);
      s6.add(z * z * z * z * z * z);
      s8.add(z * z * z * z * z * z * z * z);
    }
    s12.add(z1 * z2);
    s12sq.add(z1 * z1 * z2 * z2);
  }
  const double n = 2.0 * static_cast<double>(pairs);
  const double m2 = s2.value() / n, m4 = s4.value() / n, m6 = s6.value() / n, m8 = s8.value() / n;
  // Bounds: the same CIs from the Gaussian's own variances, Var z = 1, Var z^2 = 2, Var z^4 = 105 - 9 = 96 and
  // Var z1 z2 = 1; the sample variances of 4 10^6 normals estimate them to 1 % or better (the worst, that of z^4,
  // scatters by sqrt((<(z^4 - 3)^4> - 96^2) / n) / 96 = 0.7 %): 1.05x.
  const double pairs_n = n / 2.0;
  EXPECT_TRUE(within_ci("<z>", s1.value() / n, 3.2 * std::sqrt(m2 / n), 0.0, 1.05 * 3.2 * std::sqrt(1.0 / n)));
  EXPECT_TRUE(within_ci("<z^2>", m2, 3.2 * std::sqrt((m4 - m2 * m2) / n), 1.0, 1.05 * 3.2 * std::sqrt(2.0 / n)));
  EXPECT_TRUE(within_ci("<z^4>", m4, 3.2 * std::sqrt((m8 - m4 * m4) / n), 3.0, 1.05 * 3.2 * std::sqrt(96.0 / n)));
  EXPECT_NEAR(m6, 15.0, 3.2 * std::sqrt((10395.0 - 225.0) / n));  // Var z^6 = <z^12> - <z^6>^2 for a Gaussian
  EXPECT_TRUE(within_ci("<z1 z2>", s12.value() / pairs_n, 3.2 * std::sqrt(s12sq.value() / pairs_n / pairs_n), 0.0,
                        1.05 * 3.2 * std::sqrt(1.0 / pairs_n)));
  std::printf("[ measured ] <z^2> = %.5f, <z^4> = %.4f, <z^6> = %.3f\n", m2, m4, m6);
}

TEST(Numerics, TurnSincosIsAccurateToTwoUlp) {
  // core/turn_sincos.hpp against cos and sin of 2 pi t in long double, on a grid through every quadrant
  // boundary and at 10^6 random t: the absolute error stays below 2 ulp of 1 (values are at most 1 in
  // size), the quadrant points are exact, and cos^2 + sin^2 = 1 to rounding.
  double worst = 0.0;
  auto check = [&](double t) {
    const CosSin z = turn_sincos(t);
    // The reference in long double: libm in double would first round 2 pi t, by up to 4.4e-16 near 2 pi.
    const long double phi = 2.0L * std::numbers::pi_v<long double> * static_cast<long double>(t);
    worst = std::max({worst, static_cast<double>(std::abs(z.cos - std::cos(phi))),
                      static_cast<double>(std::abs(z.sin - std::sin(phi)))});
    ASSERT_NEAR(z.cos * z.cos + z.sin * z.sin, 1.0, 4e-16) << t;
  };
  for (int k = 0; k <= 400000; ++k) check(k / 400000.0);
  const RandomStream rng(11, 0);
  for (std::uint64_t s = 0; s < 1'000'000; ++s)
    check(uniform_open(rng.block(RngPurpose::initial_velocity, 0, 0, s)[0]));
  EXPECT_LT(worst, 2.0 * 0x1p-52);
  for (const auto& [t, c, s] :
       {std::tuple{0.0, 1.0, 0.0}, {0.25, 0.0, 1.0}, {0.5, -1.0, 0.0}, {0.75, 0.0, -1.0}, {1.0, 1.0, 0.0}}) {
    EXPECT_EQ(turn_sincos(t).cos, c) << t;
    EXPECT_EQ(turn_sincos(t).sin, s) << t;
  }
  std::printf("[ measured ] largest |error| against long double: %.2g (ulp of 1: %.2g)\n", worst, 0x1p-52);
}

TEST(Numerics, SimdVariatesMatchTheScalarConversions) {
  // core/batch_variates.hpp against core/sampling.hpp on 2^20 uniforms from Philox, including the extreme
  // words 0 and 2^32 - 1: directions (sphere and circle) and Box-Muller angles use the same operations, so they agree
  // bit for bit; the logarithm is xsimd's, so exponentials and normals may differ from libm's in the last bit (bound: 2
  // ulp of the value), and xsimd's pow, exp(p log u), loses more (bound: 64 ulp; measured about 20, printed).
  constexpr std::size_t lanes = 64;
  const RandomStream rng(13, 0);
  double worst_log = 0.0, worst_normal = 0.0, worst_power = 0.0;
  auto ulps = [](double simd, double scalar) { return std::abs(simd - scalar) / (std::abs(scalar) * 0x1p-52); };
  for (std::uint64_t chunk = 0; chunk < (1u << 14); ++chunk) {
    std::array<double, lanes> u1, u2, e, z1, z2, x, y, z, p, cx, cy, cz, lx, ly, lz, hx, hy, hz;
    for (std::size_t k = 0; k < lanes; ++k) {
      const RandomBlock r = rng.block(RngPurpose::initial_velocity, 0, chunk, k);
      u1[k] = uniform_open(chunk == 0 && k == 0 ? 0u : r[0]);
      u2[k] = uniform_open(chunk == 0 && k == 1 ? 0xFFFFFFFFu : r[1]);
    }
    e = u1;
    p = u1;
    negative_log_in_place(std::span(e));
    power_in_place(std::span(p), 2.5);
    standard_normal_pairs(std::span<const double, lanes>(u1), std::span<const double, lanes>(u2), std::span(z1),
                          std::span(z2));
    unit_vectors(std::span<const double, lanes>(u1), std::span<const double, lanes>(u2), std::span(x), std::span(y),
                 std::span(z));
    unit_circle_vectors(std::span<const double, lanes>(u1), std::span(cx), std::span(cy), std::span(cz));
    lambert_circle_vectors(std::span<const double, lanes>(u1), std::span(lx), std::span(ly), std::span(lz));
    half_circle_vectors(std::span<const double, lanes>(u1), std::span(hx), std::span(hy), std::span(hz));
    for (std::size_t k = 0; k < lanes; ++k) {
      worst_log = std::max(worst_log, ulps(e[k], -std::log(u1[k])));
      worst_power = std::max(worst_power, ulps(p[k], std::pow(u1[k], 2.5)));
      double s1, s2;
      standard_normal_pair(u1[k], u2[k], s1, s2);
      const double radius_ulp = std::sqrt(-2.0 * std::log(u1[k])) * 0x1p-52;
      worst_normal = std::max({worst_normal, std::abs(z1[k] - s1) / radius_ulp, std::abs(z2[k] - s2) / radius_ulp});
      const Vec3 v = unit_vector(u1[k], u2[k]);
      ASSERT_EQ(x[k], v.x);
      ASSERT_EQ(y[k], v.y);
      ASSERT_EQ(z[k], v.z);
      const Vec3 c = unit_circle_vector(u1[k]), l = lambert_circle_vector(u1[k]);  // disks
      ASSERT_EQ(cx[k], c.x);
      ASSERT_EQ(cy[k], c.y);
      ASSERT_EQ(cz[k], c.z);
      ASSERT_EQ(lx[k], l.x);
      ASSERT_EQ(ly[k], l.y);
      ASSERT_EQ(lz[k], l.z);
      const Vec3 h = half_circle_vector(u1[k]);
      ASSERT_EQ(hx[k], h.x);
      ASSERT_EQ(hy[k], h.y);
      ASSERT_EQ(hz[k], h.z);
      ASSERT_GE(h.x, 0.0);
    }
  }
  EXPECT_LE(worst_log, 2.0);
  EXPECT_LE(worst_normal, 2.0);  // in units of the ulp of the radius sqrt(-2 log u1)
  EXPECT_LE(worst_power, 64.0);
  std::printf("[ measured ] largest SIMD - scalar differences in ulp: -log %.2f, normals %.2f, u^2.5 %.2f\n", worst_log,
              worst_normal, worst_power);
}

TEST(Numerics, IndicesLaneByLaneAreTheScalarIndices) {
  // uniform_indices (two 32-bit products) against uniform_index (one 128-bit product) for 2^20 word pairs
  // from Philox and ranges from 1 to 2^32 - 1, with the extreme words 0 and 2^32 - 1 in every batch: every
  // index equal, and every index below its range.
  constexpr std::size_t lanes = 64;
  const RandomStream rng(17, 0);
  constexpr std::array<std::uint32_t, 8> edge_ranges = {1u,      2u,          3u,          10u,
                                                        99'999u, 10'000'000u, 0x80000001u, 0xFFFFFFFFu};
  for (std::uint64_t chunk = 0; chunk < (1u << 14); ++chunk) {
    std::array<std::uint32_t, lanes> hi, lo, n;
    for (std::size_t k = 0; k < lanes; ++k) {
      const RandomBlock r = rng.block(RngPurpose::initial_velocity, 0, chunk, k);
      hi[k] = k == 0 ? 0u : k == 1 ? 0xFFFFFFFFu : r[0];
      lo[k] = k == 0 ? 0u : k == 1 ? 0xFFFFFFFFu : r[1];
      n[k] = k < 2 * edge_ranges.size() ? edge_ranges[k % edge_ranges.size()] : std::max(r[2] >> (r[3] % 32), 1u);
    }
    std::array<std::uint64_t, lanes> out;
    uniform_indices(std::span<const std::uint32_t, lanes>(hi), std::span<const std::uint32_t, lanes>(lo), n, out);
    for (std::size_t k = 0; k < lanes; ++k) {
      ASSERT_EQ(out[k], uniform_index(hi[k], lo[k], n[k])) << "words " << hi[k] << ", " << lo[k] << ", range " << n[k];
      ASSERT_LT(out[k], n[k]);
    }
  }
}

TEST(Numerics, NotGreaterBitsAreTheScalarComparisons) {
  // not_greater_bits (core/simd.hpp) against !(a > b) lane by lane, with equal values, signed zeros,
  // infinities and NaN on either side: the collision stage's screen sends a candidate to the full test
  // exactly where the scalar comparison would.
  constexpr std::size_t w = SimdDouble::size;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const std::array<double, 8> special = {0.0, -0.0, 1.0, 1.0 + 0x1p-52, -inf, inf, nan, 0.5};
  const RandomStream rng(19, 0);
  for (std::uint64_t round = 0; round < 4096; ++round) {
    std::array<double, w> a, b;
    for (std::size_t k = 0; k < w; ++k) {
      const RandomBlock r = rng.block(RngPurpose::initial_velocity, 0, round, k);
      a[k] = r[0] % 4 == 0 ? special[r[1] % special.size()] : uniform_open(r[1]);
      b[k] = r[2] % 4 == 0 ? special[r[3] % special.size()] : uniform_open(r[3]);
      if (r[0] % 16 == 1) b[k] = a[k];
    }
    const std::uint64_t bits =
        not_greater_bits(SimdDouble::load_unaligned(a.data()), SimdDouble::load_unaligned(b.data()));
    for (std::size_t k = 0; k < w; ++k)
      ASSERT_EQ((bits >> k) & 1u, static_cast<std::uint64_t>(!(a[k] > b[k]))) << a[k] << " " << b[k];
    ASSERT_EQ(bits >> w, 0u);
  }
}

namespace {

/// lane_bits, rounded_to and all_different (core/simd.hpp) for registers of Arch against their scalar forms.
template <class Arch>
void check_lane_helpers() {
  using Doubles = xsimd::batch<double, Arch>;
  using Indices = xsimd::batch<std::uint64_t, Arch>;
  constexpr std::size_t w = Doubles::size;
  const RandomStream rng(23, 0);
  for (std::uint64_t round = 0; round < 4096; ++round) {
    alignas(64) std::array<double, w> a, b;
    alignas(64) std::array<std::uint64_t, w> i, j;
    for (std::size_t k = 0; k < w; ++k) {
      const RandomBlock r = rng.block(RngPurpose::initial_velocity, 0, round, k);
      a[k] =
          std::ldexp(uniform_open(r[0]) - 0.5, static_cast<int>(r[1] % 300) - 150);  // below, in, above float's range
      b[k] = uniform_open(r[2]) - 0.5;
      i[k] = r[3] % (2 * w * w);  // often equal to another lane's value
      j[k] = r[1] % (2 * w * w);
    }
    const std::uint64_t bits = lane_bits(Doubles::load_aligned(a.data()) < Doubles::load_aligned(b.data()));
    alignas(64) std::array<double, w> rounded, same;
    rounded_to<float>(Doubles::load_aligned(a.data())).store_aligned(rounded.data());
    rounded_to<double>(Doubles::load_aligned(a.data())).store_aligned(same.data());
    bool different = true;
    for (std::size_t k = 0; k < w; ++k) {
      ASSERT_EQ((bits >> k) & 1u, static_cast<std::uint64_t>(a[k] < b[k]));
      ASSERT_EQ(std::bit_cast<std::uint64_t>(rounded[k]),
                std::bit_cast<std::uint64_t>(static_cast<double>(static_cast<float>(a[k]))))
          << Arch::name() << ": " << a[k];
      ASSERT_EQ(std::bit_cast<std::uint64_t>(same[k]), std::bit_cast<std::uint64_t>(a[k]));
      for (std::size_t l = 0; l < w; ++l)
        different = different && i[k] != j[l] && (k == l || (i[k] != i[l] && j[k] != j[l]));
    }
    ASSERT_EQ(bits >> w, 0u);
    ASSERT_EQ(all_different(Indices::load_aligned(i.data()), Indices::load_aligned(j.data())), different);
  }
}

}  // namespace

TEST(Numerics, LaneHelpersAreTheScalarOperations) {
  // The event scheme's candidates in registers (schemes/event_scheme.hpp) take their outcomes as
  // bits, round velocities as a float store does, and check that a register's pairs share no particle
  // with these; each for the build's registers and for two narrower ones (other branches of the helpers).
  check_lane_helpers<SimdDouble::arch_type>();
  check_lane_helpers<xsimd::sse2>();
#if XSIMD_WITH_AVX2
  check_lane_helpers<xsimd::avx2>();
#endif
}

TEST(Numerics, MaxwellianStartIsTheSameForAnyPartOfTheParticles) {
  // schemes/initial_state.cpp: particle first + k gets the normals of its own block whatever batch it is
  // computed in, so a part filled from `first` (a rank of a spread system) is the same bits as that part
  // of the whole start; and each velocity is width times the scalar Box-Muller normals of its block (to
  // the 2 ulp of the SIMD logarithm, above).
  const RandomStream rng(2026, 3);
  const double width = 0.75;
  SpeciesStore whole(1000), part(301);
  maxwellian_velocities(whole, rng, 1, 0, width, 3);
  maxwellian_velocities(part, rng, 1, 123, width, 3);
  for (std::size_t k = 0; k < part.size(); ++k) {
    ASSERT_EQ(part.velocity(k).x, whole.velocity(123 + k).x) << k;
    ASSERT_EQ(part.velocity(k).y, whole.velocity(123 + k).y) << k;
    ASSERT_EQ(part.velocity(k).z, whole.velocity(123 + k).z) << k;
  }
  for (std::size_t k = 0; k < whole.size(); ++k) {
    const RandomBlock r = rng.block(RngPurpose::initial_velocity, 1, 0, k);
    double z0, z1, z2, unused;
    standard_normal_pair(uniform_open(r[0]), uniform_open(r[1]), z0, z1);
    standard_normal_pair(uniform_open(r[2]), uniform_open(r[3]), z2, unused);
    // 2 ulp of the radius for the normals (as above) and 1 for rounding the two products by width
    const Vec3 v = whole.velocity(k);
    const double bound01 = 3.0 * width * std::sqrt(-2.0 * std::log(uniform_open(r[0]))) * 0x1p-52;
    const double bound2 = 3.0 * width * std::sqrt(-2.0 * std::log(uniform_open(r[2]))) * 0x1p-52;
    EXPECT_NEAR(v.x, width * z0, bound01) << k;
    EXPECT_NEAR(v.y, width * z1, bound01) << k;
    EXPECT_NEAR(v.z, width * z2, bound2) << k;
  }
}

TEST(Numerics, SpeciesMomentsAreCompensatedSumsToTwoUlp) {
  // 1003 particles (not a whole number of SIMD registers) with x velocities of +-10^8 in turn plus a
  // normal: their sum cancels to the sum of the normals, which a plain sum loses to rounding (about 10^-5
  // of about 30) and a compensated one keeps. Compared with a long double Neumaier sum of the same terms.
  const std::size_t n = 1003;
  const Vec3 centre{0.0, 1000.0, 0.0};
  SpeciesStore store(n);
  const RandomStream rng(11, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const RandomBlock r = rng.block(RngPurpose::initial_velocity, 0, 0, k);
    double z0, z1, z2, z3;
    standard_normal_pair(uniform_open(r[0]), uniform_open(r[1]), z0, z1);
    standard_normal_pair(uniform_open(r[2]), uniform_open(r[3]), z2, z3);
    store.set_velocity(k, Vec3{k % 2 == 0 ? 1e8 : -1e8, 1000.0, 0.0} + Vec3{z0, z1, z2});
  }
  struct Exact {
    long double sum = 0.0L, carry = 0.0L;
    void add(long double x) {
      const long double t = sum + x;
      carry += std::fabs(sum) >= std::fabs(x) ? (sum - t) + x : (x - t) + sum;
      sum = t;
    }
    [[nodiscard]] double value() const { return static_cast<double>(sum + carry); }
  };
  Exact s2, s4, s6, px, py, pz;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 v = store.velocity(k);
    const long double dx = static_cast<long double>(v.x) - centre.x, dy = static_cast<long double>(v.y) - centre.y,
                      dz = static_cast<long double>(v.z) - centre.z;
    const long double c2 = dx * dx + dy * dy + dz * dz;
    s2.add(c2);
    s4.add(c2 * c2);
    s6.add(c2 * c2 * c2);
    px.add(v.x);
    py.add(v.y);
    pz.add(v.z);
  }
  const SpeciesMoments m = species_moments(store, centre);
  EXPECT_EQ(m.particles, n);
  const auto two_ulp = [](double x) { return 2.0 * std::numeric_limits<double>::epsilon() * std::fabs(x); };
  EXPECT_NEAR(m.sum_c2, s2.value(), two_ulp(s2.value()));
  EXPECT_NEAR(m.sum_c4, s4.value(), two_ulp(s4.value()));
  EXPECT_NEAR(m.sum_c6, s6.value(), two_ulp(s6.value()));
  EXPECT_NEAR(m.sum_c.x, px.value(), two_ulp(px.value()));
  EXPECT_NEAR(m.sum_c.y, py.value(), two_ulp(py.value()));
  EXPECT_NEAR(m.sum_c.z, pz.value(), two_ulp(pz.value()));
}
