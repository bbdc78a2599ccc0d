// Philox streams: reproducible, distinct by (seed, replica) and by purpose; exact variate conversions.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"

using namespace granmc;

TEST(Philox, SameAddressSameBlock) {
  const RandomStream a(42, 3), b(42, 3);
  EXPECT_EQ(a.block(RngPurpose::collision_pair, 0, 17, 123456789), b.block(RngPurpose::collision_pair, 0, 17, 123456789));
}

TEST(Philox, KeyAndCounterFieldsAllMatter) {
  const RandomStream s(42, 3);
  const RandomBlock base = s.block(RngPurpose::collision_pair, 0, 17, 5);
  EXPECT_NE(base, RandomStream(43, 3).block(RngPurpose::collision_pair, 0, 17, 5));
  EXPECT_NE(base, RandomStream(42, 4).block(RngPurpose::collision_pair, 0, 17, 5));
  EXPECT_NE(base, RandomStream(42ull << 32, 3).block(RngPurpose::collision_pair, 0, 17, 5));
  EXPECT_NE(base, s.block(RngPurpose::initial_velocity, 0, 17, 5));
  EXPECT_NE(base, s.block(RngPurpose::collision_pair, 1, 17, 5));
  EXPECT_NE(base, s.block(RngPurpose::collision_pair, 0, 18, 5));
  EXPECT_NE(base, s.block(RngPurpose::collision_pair, 0, 17, 6));
  EXPECT_NE(base, s.block(RngPurpose::collision_pair, 0, 17 + (1ull << 32), 5));  // high step bits
  EXPECT_NE(base, s.block(RngPurpose::collision_pair, 0, 17, 5 + (1ull << 32)));  // high index bits
}

TEST(Philox, SeedReplicaPairsGiveDistinctKeys) {
  std::set<RandomBlock> seen;
  for (std::uint64_t seed = 0; seed < 64; ++seed)
    for (std::uint64_t replica = 0; replica < 64; ++replica)
      seen.insert(RandomStream(seed, replica).block(RngPurpose::collision_pair, 0, 0, 0));
  EXPECT_EQ(seen.size(), 64u * 64u);
}

TEST(Sampling, UniformsStayInsideOpenInterval) {
  EXPECT_GT(uniform_open(0), 0.0);
  EXPECT_LT(uniform_open(0xFFFFFFFFu), 1.0);
  EXPECT_GT(uniform_open52(0, 0), 0.0);
  EXPECT_LT(uniform_open52(0xFFFFFFFFu, 0xFFFFFFFFu), 1.0);
}

TEST(Sampling, IndexCoversRangeAndStaysBelowN) {
  EXPECT_EQ(uniform_index(0, 0, 10), 0u);
  EXPECT_EQ(uniform_index(0xFFFFFFFFu, 0xFFFFFFFFu, 10), 9u);
  EXPECT_EQ(uniform_index(0x80000000u, 0, 10), 5u);
}

TEST(Sampling, UnitVectorsAreUnitAndIsotropic) {
  // Mean of each component and of z^2 over a Philox sample: 0 and 1/3 within 5 standard errors.
  const RandomStream s(7, 0);
  const int n = 200000;
  double mx = 0, my = 0, mz = 0, mzz = 0;
  for (int k = 0; k < n; ++k) {
    const RandomBlock r = s.block(RngPurpose::collision_pair, 0, 0, k);
    const Vec3 e = unit_vector(uniform_open(r[0]), uniform_open(r[1]));
    ASSERT_NEAR(norm2(e), 1.0, 1e-15);
    mx += e.x; my += e.y; mz += e.z; mzz += e.z * e.z;
  }
  const double se = std::sqrt(1.0 / 3.0 / n);  // std of one component is 1/sqrt(3)
  EXPECT_NEAR(mx / n, 0.0, 5 * se);
  EXPECT_NEAR(my / n, 0.0, 5 * se);
  EXPECT_NEAR(mz / n, 0.0, 5 * se);
  EXPECT_NEAR(mzz / n, 1.0 / 3.0, 5 * std::sqrt(4.0 / 45.0 / n));  // Var(z^2) = 1/5 - 1/9
}

TEST(Sampling, BoxMullerGivesUnitNormals) {
  const RandomStream s(7, 1);
  const int n = 100000;
  double m1 = 0, m2 = 0, m4 = 0;
  for (int k = 0; k < n; ++k) {
    const RandomBlock r = s.block(RngPurpose::initial_velocity, 0, 0, k);
    double z1, z2;
    standard_normal_pair(uniform_open(r[0]), uniform_open(r[1]), z1, z2);
    for (double z : {z1, z2}) { m1 += z; m2 += z * z; m4 += z * z * z * z; }
  }
  const double N = 2.0 * n;
  EXPECT_NEAR(m1 / N, 0.0, 5 / std::sqrt(N));
  EXPECT_NEAR(m2 / N, 1.0, 5 * std::sqrt(2.0 / N));
  EXPECT_NEAR(m4 / N, 3.0, 5 * std::sqrt(96.0 / N));  // Var(z^4) = 105 - 9
}
