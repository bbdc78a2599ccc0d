#include "kernel/observe/speed_histogram.hpp"

#include <cmath>

namespace granmc {

double scaled_speed_unit(const Scene& scene, double theta_mixture) noexcept {
  double m_hat = scene.species[0].mass;
  if (scene.species.size() == 2) {
    const double m1 = scene.species[0].mass, m2 = scene.species[1].mass;
    m_hat = m1 * m2 / (m1 + m2);  // 000 eq. (7): v0^2 = 2 T (m_1 + m_2) / (m_1 m_2)
  }
  return std::sqrt(2.0 * theta_mixture / m_hat);
}

double histogram_speed_unit(const Scene& scene, const VelocityScale& scale, double theta_mixture) noexcept {
  const HistogramSpeed speed = scene.histogram.speed.value_or(
      scene.run.method == Method::event ? HistogramSpeed::velocity : HistogramSpeed::scaled);
  if (speed == HistogramSpeed::velocity) return 1.0 / scale.u();
  return scaled_speed_unit(scene, theta_mixture);
}

template <class Real>
void add_speeds(const BasicSpeciesStore<Real>& store, double unit, double radius,
                std::vector<double>& counts) noexcept {
  const double per_shell = static_cast<double>(counts.size()) / (radius * unit);
  store.for_each_velocity([&](const Vec3& c) {
    const double shell = norm(c) * per_shell;
    if (shell < static_cast<double>(counts.size())) counts[static_cast<std::size_t>(shell)] += 1.0;
  });
}

template void add_speeds(const SpeciesStore&, double, double, std::vector<double>&) noexcept;
template void add_speeds(const FloatSpeciesStore&, double, double, std::vector<double>&) noexcept;

}  // namespace granmc
