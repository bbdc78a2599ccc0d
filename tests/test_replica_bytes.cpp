// The replica byte format (io/replica_bytes.hpp) that MPI ranks and checkpoints use: every field of every
// kind of replica survives the round trip bit for bit, and malformed bytes throw.
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "io/replica_bytes.hpp"

namespace granmc {
namespace {

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

template <class T>
bool same_bytes(const T& a, const T& b) {
  static_assert(std::is_trivially_copyable_v<T>);
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// Every field of two replicas' series, bit for bit (a NaN equals itself, -0 differs from +0).
void expect_same(const ReplicaSeries& a, const ReplicaSeries& b) {
  EXPECT_TRUE(same_bytes(a.temperature, b.temperature));
  EXPECT_TRUE(same_bytes(a.log_temperature, b.log_temperature));
  ASSERT_EQ(a.species.size(), b.species.size());
  for (std::size_t i = 0; i < a.species.size(); ++i) {
    EXPECT_TRUE(same_bytes(a.species[i].temperature, b.species[i].temperature)) << i;
    EXPECT_TRUE(same_bytes(a.species[i].log_temperature, b.species[i].log_temperature)) << i;
    EXPECT_TRUE(same_bytes(a.species[i].a2, b.species[i].a2)) << i;
    EXPECT_TRUE(same_bytes(a.species[i].a3, b.species[i].a3)) << i;
    EXPECT_TRUE(same_bytes(a.species[i].speed_counts, b.species[i].speed_counts)) << i;
  }
  EXPECT_TRUE(same_bytes(a.momentum, b.momentum));
  EXPECT_TRUE(same_bytes(a.momentum_relative, b.momentum_relative));
  EXPECT_TRUE(same_bytes(a.collisions, b.collisions));
  EXPECT_TRUE(same_bytes(a.pair_collisions, b.pair_collisions));
  EXPECT_EQ(a.histogram_samples, b.histogram_samples);
  EXPECT_EQ(a.candidates, b.candidates);
  EXPECT_EQ(a.majorant_updates, b.majorant_updates);
  EXPECT_EQ(a.majorant_violations, b.majorant_violations);
  EXPECT_TRUE(same_bytes(a.majorant_growth, b.majorant_growth));
  ASSERT_EQ(a.shear.has_value(), b.shear.has_value());
  if (a.shear) {
    EXPECT_TRUE(same_bytes(a.shear->pressure_kinetic, b.shear->pressure_kinetic));
    EXPECT_TRUE(same_bytes(a.shear->pressure_collisional, b.shear->pressure_collisional));
    EXPECT_TRUE(same_bytes(a.shear->reduced_shear_rate, b.shear->reduced_shear_rate));
  }
  EXPECT_EQ(a.rescales, b.rescales);
  EXPECT_TRUE(same_bytes(a.momentum_removed_relative, b.momentum_removed_relative));
  ASSERT_EQ(a.energy_residual.has_value(), b.energy_residual.has_value());
  if (a.energy_residual) {
    EXPECT_TRUE(same_bytes(*a.energy_residual, *b.energy_residual));
  }
  ASSERT_EQ(a.weighted.has_value(), b.weighted.has_value());
  if (a.weighted) {
    const WeightedSeries &p = *a.weighted, &q = *b.weighted;
    EXPECT_TRUE(same_bytes(p.particles, q.particles));
    EXPECT_EQ(p.transfers, q.transfers);
    EXPECT_EQ(p.controls, q.controls);
    EXPECT_EQ(p.split_copies, q.split_copies);
    EXPECT_EQ(p.reductions, q.reductions);
    EXPECT_EQ(p.reduced, q.reduced);
    EXPECT_TRUE(same_bytes(p.conservation_residual, q.conservation_residual));
  }
  ASSERT_EQ(a.intruder.has_value(), b.intruder.has_value());
  if (!a.intruder) return;
  const IntruderSeries &x = *a.intruder, &y = *b.intruder;
  EXPECT_TRUE(same_bytes(x.velocity, y.velocity));
  EXPECT_TRUE(same_bytes(x.speed_counts, y.speed_counts));
  EXPECT_EQ(x.sampling_attempts, y.sampling_attempts);
  EXPECT_TRUE(same_bytes(x.velocity_y, y.velocity_y));
  EXPECT_TRUE(same_bytes(x.angular_velocity, y.angular_velocity));
  EXPECT_TRUE(same_bytes(x.angular_counts, y.angular_counts));
  EXPECT_EQ(x.newton_iterations, y.newton_iterations);
  EXPECT_EQ(x.bisection_fallbacks, y.bisection_fallbacks);
  EXPECT_TRUE(same_bytes(std::vector<double>{x.v2_time_integral, x.w2_time_integral, x.v2w2_time_integral},
                         std::vector<double>{y.v2_time_integral, y.w2_time_integral, y.v2w2_time_integral}));
}

/// Distinct values in every field; `r` varies them between replicas. Odd doubles included.
ReplicaSeries filled_replica(int r, bool intruder) {
  double x = 1.0 + r;
  auto doubles = [&](std::size_t n) {
    std::vector<double> v(n);
    for (double& d : v) d = (x += 0.37);
    return v;
  };
  ReplicaSeries s;
  s.temperature = {1.0,
                   std::numeric_limits<double>::quiet_NaN(),
                   -0.0,
                   std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::denorm_min(),
                   0.1 * r};
  s.log_temperature = doubles(6);
  for (int i = 0; i < 2; ++i)
    s.species.push_back(
        {doubles(6), doubles(6), doubles(6), doubles(6), doubles(11), doubles(6), doubles(6), doubles(6)});
  s.momentum = {{1.0, 2.0, 3.0 + r}, {-4.0, 5.5, -0.0}};
  s.momentum_relative = doubles(6);
  s.collisions = doubles(6);
  s.pair_collisions = {7, 8, 9, (std::uint64_t{1} << 63) + static_cast<std::uint64_t>(r)};
  s.histogram_samples = 11 + r;
  s.candidates = 12 + r;
  s.majorant_updates = 13;
  s.majorant_violations = 14;
  s.majorant_growth = doubles(4);
  if (!intruder)
    s.shear = ShearSeries{
        {{1, 2, 3, 4, 5, 6.0 + r}, {-1, -2, -3, -4, -5, -6}}, {{0.1, 0.2, 0.3, 0.4, 0.5, 0.6}, {}}, doubles(2)};
  s.rescales = 15;
  s.momentum_removed_relative = 1e-300 * (r + 1);
  if (!intruder) s.energy_residual = 1e-15 * (r + 1);
  if (!intruder && r % 4 == 0) s.weighted = WeightedSeries{doubles(6), 19, 20, 21, 22, 23, 1e-17 * (r + 1)};
  if (intruder) {
    IntruderSeries in;
    in.velocity = doubles(6);
    in.speed_counts = doubles(5);
    in.sampling_attempts = 16;
    in.velocity_y = doubles(6);
    in.angular_velocity = doubles(6);
    in.angular_counts = doubles(3);
    in.newton_iterations = 17;
    in.bisection_fallbacks = 18;
    in.v2_time_integral = 1e-200 * (r + 1);
    in.w2_time_integral = 2e-200 * (r + 1);
    in.v2w2_time_integral = 3e-200 * (r + 1);
    s.intruder = in;
  }
  return s;
}

TEST(ReplicaBytes, RoundTripKeepsEveryFieldBitForBit) {
  std::vector<ReplicaSeries> all;
  for (int r = 0; r < 7; ++r) all.push_back(filled_replica(r, r % 2 == 1));
  all.push_back(ReplicaSeries{});  // empty vectors, no intruder
  for (int stride : {1, 2, 3, 8, 11}) {
    for (int offset = 0; offset < stride; ++offset) {
      const std::vector<std::byte> bytes = serialise_replicas(all, offset, stride);
      std::vector<ReplicaSeries> back(all.size());
      deserialise_replicas(bytes, back, offset, stride);
      for (std::size_t r = 0; r < all.size(); ++r) {
        SCOPED_TRACE("stride " + std::to_string(stride) + " offset " + std::to_string(offset) + " replica " +
                     std::to_string(r));
        expect_same(static_cast<int>(r) % stride == offset ? all[r] : ReplicaSeries{}, back[r]);
      }
    }
  }
}

TEST(ReplicaBytes, MalformedBytesThrow) {
  const std::vector<ReplicaSeries> all{filled_replica(0, true), filled_replica(1, false)};
  std::vector<std::byte> bytes = serialise_replicas(all, 0, 1);
  std::vector<ReplicaSeries> back(2);
  EXPECT_THROW(deserialise_replicas(std::span(bytes).first(bytes.size() - 1), back, 0, 1), std::runtime_error);
  std::vector<std::byte> longer = bytes;
  longer.push_back(std::byte{0});
  EXPECT_THROW(deserialise_replicas(longer, back, 0, 1), std::runtime_error);
  std::vector<ReplicaSeries> three(3);  // expects 3 replicas, the message has 2
  EXPECT_THROW(deserialise_replicas(bytes, three, 0, 1), std::runtime_error);
}

}  // namespace
}  // namespace granmc
