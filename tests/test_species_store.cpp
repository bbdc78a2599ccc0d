#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "kernel/core/species_store.hpp"

using namespace granmc;

TEST(SpeciesStore, ThirtyTwoBytesPerParticleAlignedAndRoundTrips) {
  EXPECT_EQ(SpeciesStore::bytes_per_particle(), 32u);
  SpeciesStore s(1000);
  ASSERT_EQ(s.size(), 1000u);
  for (std::size_t k = 0; k < s.size(); ++k) s.set_velocity(k, {1.0 * k, -2.0 * k, 0.5 * k});
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Vec3 v = s.velocity(k);
    EXPECT_EQ(v.x, 1.0 * k);
    EXPECT_EQ(v.y, -2.0 * k);
    EXPECT_EQ(v.z, 0.5 * k);
  }
  double sum = 0.0;
  s.for_each_velocity([&](const Vec3& v) { sum += v.x; });
  EXPECT_EQ(sum, 999.0 * 1000.0 / 2.0);
}

TEST(SpeciesStore, LargeBuffersAreHugePageAligned) {
  AlignedBuffer<double> big(1 << 20);  // 8 MiB
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % AlignedBuffer<double>::huge_page, 0u);
  AlignedBuffer<double> small(10);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(small.data()) % AlignedBuffer<double>::cache_line, 0u);
}

TEST(SpeciesStore, FloatRecordsAreSixteenBytesAndRoundToNearest) {
  EXPECT_EQ(FloatSpeciesStore::bytes_per_particle(), 16u);
  FloatSpeciesStore s(3);
  s.set_velocity(1, {1.0 / 3.0, -2.0 / 3.0, 1e-30});
  const Vec3 v = s.velocity(1);
  EXPECT_EQ(v.x, static_cast<double>(1.0f / 3.0f));
  EXPECT_EQ(v.y, static_cast<double>(-2.0f / 3.0f));
  EXPECT_EQ(v.z, static_cast<double>(1e-30f));
  EXPECT_NE(v.x, 1.0 / 3.0);  // rounded, not kept
}

namespace {

/// A velocity update and its read-back in one function, as the schemes do it (not inlined into the test,
/// so that the values are not constants).
[[gnu::noinline]] Vec3 kick_and_read_back(FloatSpeciesStore& s, std::size_t k, const Vec3& kick, double c) {
  s.set_velocity(k, s.velocity(k) + c * kick);
  return s.velocity(k);
}

}  // namespace

TEST(SpeciesStore, FloatVelocityReadBackRightAfterAStoreIsRounded) {
  // GCC 12.2 at -O2 and above stored x and y as one converted pair and handed the load right after the
  // store the unrounded doubles (core/species_store.hpp, store). Every component read back must be a float.
  FloatSpeciesStore s(2);
  s.set_velocity(0, {0.1, 0.2, 0.3});
  const Vec3 w = kick_and_read_back(s, 0, {0.123456789, 0.987654321, 0.5}, 0.3333333);
  EXPECT_EQ(w.x, static_cast<double>(static_cast<float>(w.x)));
  EXPECT_EQ(w.y, static_cast<double>(static_cast<float>(w.y)));
  EXPECT_EQ(w.z, static_cast<double>(static_cast<float>(w.z)));
  const Vec3 stored = s.velocity(0);
  EXPECT_EQ(w.x, stored.x);
  EXPECT_EQ(w.y, stored.y);
  EXPECT_EQ(w.z, stored.z);
}

TEST(SpeciesStore, FloatLastUpdateTimesKeepTheirResolutionAfterARestart) {
  // At t = 10^6 a float time has a resolution of 0.06; relative to the last restart it keeps 2^-24 of
  // the time since then. The event scheme restarts the clock at every full synchronisation.
  FloatSpeciesStore s(2);
  const double t0 = 1e6;
  s.set_last_update(0, t0);
  s.set_last_update(1, t0);
  s.restart_clock(t0);
  EXPECT_EQ(s.last_update(0), t0);
  const double step = 1e-3;
  s.set_last_update(1, t0 + step);
  EXPECT_NEAR(s.last_update(1) - t0, step, step * 0x1p-23);
  EXPECT_EQ(s.last_update(0), t0);
  SpeciesStore d(1);  // double: restart_clock changes nothing
  d.set_last_update(0, t0 + step);
  d.restart_clock(t0 + step);
  EXPECT_EQ(d.last_update(0), t0 + step);
}

namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

/// load_lanes and store_lanes against velocity / last_update and set_velocity / set_last_update, particle
/// by particle, for registers of scattered particles and stores of every lane count.
template <class Real, class Arch>
void check_lanes() {
  using Batch = xsimd::batch<double, Arch>;
  constexpr std::size_t w = Batch::size;
  BasicSpeciesStore<Real> store(1000), expected(1000);
  for (std::size_t k = 0; k < store.size(); ++k) {  // values that float rounds, and a restarted clock
    const Vec3 v{std::sqrt(2.0 + k), -1.0 / (3.0 + k),
                 std::ldexp(1.0 + 1.0 / (7.0 + k), static_cast<int>(k % 40) - 20)};
    store.set_velocity(k, v);
    expected.set_velocity(k, v);
  }
  store.restart_clock(0.125);
  expected.restart_clock(0.125);
  for (std::size_t round = 0; round < 200; ++round) {
    alignas(64) std::array<std::size_t, w> index;
    for (std::size_t l = 0; l < w; ++l) index[l] = (round * 37 + l * 101 + l * l * round) % store.size();
    std::sort(index.begin(), index.end());
    if (std::adjacent_find(index.begin(), index.end()) != index.end()) continue;  // distinct, as a register's are
    Batch x, y, z, t;
    store.load_lanes(index.data(), x, y, z, t);
    alignas(64) std::array<double, w> lx, ly, lz, lt;
    x.store_aligned(lx.data()), y.store_aligned(ly.data()), z.store_aligned(lz.data()), t.store_aligned(lt.data());
    for (std::size_t l = 0; l < w; ++l) {
      const Vec3 v = expected.velocity(index[l]);
      ASSERT_EQ(bits(lx[l]), bits(v.x));
      ASSERT_EQ(bits(ly[l]), bits(v.y));
      ASSERT_EQ(bits(lz[l]), bits(v.z));
      ASSERT_EQ(bits(lt[l]), bits(expected.last_update(index[l])));
      lx[l] = 0.5 * lx[l] + 1.0 / (3.0 + static_cast<double>(round));  // new values, to be rounded when stored
      ly[l] = -ly[l] * (1.0 + 1e-9);
      lz[l] = lz[l] + 1e-3 * std::sqrt(static_cast<double>(l + 1));
      lt[l] = 0.125 + 1.0 / (5.0 + static_cast<double>(round + l));
    }
    const std::size_t count = round % (w + 1);
    store.store_lanes(index.data(), count, Batch::load_aligned(lx.data()), Batch::load_aligned(ly.data()),
                      Batch::load_aligned(lz.data()), Batch::load_aligned(lt.data()));
    for (std::size_t l = 0; l < count; ++l) {
      expected.set_velocity(index[l], {lx[l], ly[l], lz[l]});
      expected.set_last_update(index[l], lt[l]);
    }
    for (std::size_t k = 0; k < store.size(); ++k) {  // lanes past count untouched
      ASSERT_EQ(bits(store.velocity(k).x), bits(expected.velocity(k).x)) << k;
      ASSERT_EQ(bits(store.velocity(k).y), bits(expected.velocity(k).y)) << k;
      ASSERT_EQ(bits(store.velocity(k).z), bits(expected.velocity(k).z)) << k;
      ASSERT_EQ(bits(store.last_update(k)), bits(expected.last_update(k))) << k;
    }
  }
}

}  // namespace

TEST(SpeciesStore, RegistersOfParticlesLoadAndStoreAsOneByOne) {
  // The event scheme's candidates in registers (schemes/event_scheme.hpp) read and write their
  // particles a register at a time; with AVX-512 the records are transposed, which must give what the
  // one-by-one accessors give, rounding included; narrower registers take the lane-by-lane branch.
  check_lanes<double, SimdDouble::arch_type>();
  check_lanes<float, SimdDouble::arch_type>();
  check_lanes<double, xsimd::sse2>();
  check_lanes<float, xsimd::sse2>();
}
