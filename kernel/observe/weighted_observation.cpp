#include "kernel/observe/weighted_observation.hpp"

#include <cmath>

#include "kernel/observe/gas_observation.hpp"
#include "kernel/observe/speed_histogram.hpp"

namespace granmc {

namespace {

/// The weighted moments about `centre`, as the moments of N equal particles: sums times to_counts = N / W.
SpeciesMoments weighted_moments(const WeightedParticles& p, const Vec3& centre, double particles,
                                double to_counts) noexcept {
  double c2 = 0.0, c4 = 0.0, c6 = 0.0;
  Vec3 c;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const double wk = p.weight(k), r2 = norm2(p.velocity(k) - centre);
    c += wk * p.velocity(k);
    c2 += wk * r2;
    c4 += wk * r2 * r2;
    c6 += wk * r2 * r2 * r2;
  }
  SpeciesMoments m;
  m.particles = static_cast<std::size_t>(particles);
  m.sum_c2 = to_counts * c2;
  m.sum_c4 = to_counts * c4;
  m.sum_c6 = to_counts * c6;
  m.sum_c = to_counts * c;
  return m;
}

}  // namespace

void observe_weighted(const Scene& scene, const WeightedParticles& particles, const VelocityScale& scale,
                      ReplicaSeries& series, bool histogram) {
  const double n = static_cast<double>(scene.species[0].particles);
  const double to_counts = n / particles.totals().weight;
  const SpeciesMoments origin = weighted_moments(particles, {}, n, to_counts);
  const Vec3 flow = (1.0 / n) * origin.sum_c;
  const Observed o =
      record_observation(scene, scale, {origin}, {weighted_moments(particles, flow, n, to_counts)}, series);
  if (!histogram) return;
  std::vector<double>& counts = series.species[0].speed_counts;
  counts.resize(static_cast<std::size_t>(scene.histogram.shells), 0.0);
  const double unit = histogram_speed_unit(scene, scale, o.theta_mixture);
  const double per_shell = static_cast<double>(counts.size()) / (scene.histogram.radius * unit);
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const double shell = norm(particles.velocity(k)) * per_shell;
    if (shell < static_cast<double>(counts.size()))
      counts[static_cast<std::size_t>(shell)] += to_counts * particles.weight(k);
  }
  ++series.histogram_samples;
}

}  // namespace granmc
