#include <gtest/gtest.h>

#include <cstdint>

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
