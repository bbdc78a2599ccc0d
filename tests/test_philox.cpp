// Philox streams: reproducible, distinct by (seed, replica) and by purpose; exact variate conversions.
#include <array>
#include <cmath>
#include <cstdint>
#include <set>

#include <gtest/gtest.h>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"

using namespace granmc;

TEST(Philox, SameAddressSameBlock) {
  const RandomStream a(42, 3), b(42, 3);
  EXPECT_EQ(a.block(RngPurpose::collision_pair, 0, 17, 123456789),
            b.block(RngPurpose::collision_pair, 0, 17, 123456789));
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
    mx += e.x;
    my += e.y;
    mz += e.z;
    mzz += e.z * e.z;
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
    for (double z : {z1, z2}) {
      m1 += z;
      m2 += z * z;
      m4 += z * z * z * z;
    }
  }
  const double N = 2.0 * n;
  EXPECT_NEAR(m1 / N, 0.0, 5 / std::sqrt(N));
  EXPECT_NEAR(m2 / N, 1.0, 5 * std::sqrt(2.0 / N));
  EXPECT_NEAR(m4 / N, 3.0, 5 * std::sqrt(96.0 / N));  // Var(z^4) = 105 - 9
}

TEST(Philox, LaneWiseBlocksAreRandom123s) {
  // RandomStream::blocks against block() word for word, over counters that fill every field, including
  // steps and indices above 2^32 and the top of their 2^48 range.
  constexpr std::size_t lanes = 64;
  const RandomStream s(2026, 12);
  for (std::uint64_t trial = 0; trial < 4096; ++trial) {
    std::array<std::uint64_t, lanes> step, index;
    for (std::size_t k = 0; k < lanes; ++k) {
      const RandomBlock r = s.block(RngPurpose::initial_velocity, 0, trial, k);
      step[k] = ((std::uint64_t{r[0]} << 32) | r[1]) % RandomStream::counter_limit;
      index[k] = k % 3 == 0 ? RandomStream::counter_limit - 1 - k : ((std::uint64_t{r[2]} << 32) | r[3]) >> 16;
    }
    const auto sub = static_cast<std::uint16_t>(trial % 7);
    const RandomBlocks<lanes> b = s.blocks(RngPurpose::event_candidate, sub, step, index);
    for (std::size_t k = 0; k < lanes; ++k) {
      const RandomBlock one = s.block(RngPurpose::event_candidate, sub, step[k], index[k]);
      for (std::size_t w = 0; w < 4; ++w) ASSERT_EQ(b.word[w][k], one[w]) << trial << " " << k << " " << w;
    }
  }
}
