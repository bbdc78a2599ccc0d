#include "kernel/schemes/weight_control.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "kernel/core/sym_tensor.hpp"

namespace granmc {

namespace {

/// Targets are kept above this fraction of the total weight, far above the smallest normal double.
constexpr double lightest_target = 1e-280;

/// A key along the sphere: the octahedral map of the direction of c to the square [-1, 1]^2, 16 bits per
/// axis, interleaved (Morton), so that particles close in direction are mostly close in key.
std::uint32_t direction_key(const Vec3& c) noexcept {
  const double l1 = std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z);
  if (!(l1 > 0.0)) return 0;
  double px = c.x / l1, py = c.y / l1;
  if (c.z < 0.0) {
    const double qx = (1.0 - std::fabs(py)) * (px < 0.0 ? -1.0 : 1.0);
    py = (1.0 - std::fabs(px)) * (py < 0.0 ? -1.0 : 1.0);
    px = qx;
  }
  auto bits = [](double x) {
    const double scaled = std::clamp((x + 1.0) * 32767.5, 0.0, 65535.0);
    std::uint32_t v = static_cast<std::uint32_t>(scaled);
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
  };
  return bits(px) | (bits(py) << 1);
}

/// The unit principal axis of a symmetric 3 x 3 matrix (power iteration from its largest column); e_x when
/// the matrix vanishes.
Vec3 principal_axis(const SymTensor& m) noexcept {
  const Vec3 columns[3] = {{m.xx, m.xy, m.xz}, {m.xy, m.yy, m.yz}, {m.xz, m.yz, m.zz}};
  Vec3 x = columns[0];
  for (const Vec3& c : columns)
    if (norm2(c) > norm2(x)) x = c;
  if (!(norm2(x) > 0.0)) return {1.0, 0.0, 0.0};
  for (int iteration = 0; iteration < 32; ++iteration) {
    const Vec3 y{m.xx * x.x + m.xy * x.y + m.xz * x.z, m.xy * x.x + m.yy * x.y + m.yz * x.z,
                 m.xz * x.x + m.yz * x.y + m.zz * x.z};
    const double n = norm(y);
    if (!(n > 0.0)) break;
    x = (1.0 / n) * y;
  }
  return (1.0 / norm(x)) * x;
}

/// The direction e of a reduced pair V +- sqrt(eps) e (unit). Their |v|^2 = |V|^2 + eps +- 2 sqrt(eps) (V.e):
/// the mean is the group's sum w |v|^2 / W whatever e, and V.e = sqrt(variance_v2) / (2 sqrt(eps)), where
/// that is at most |V|, also gives the group's variance of |v|^2, so that sum w |v|^4 is kept too (the
/// fourth moment, hence a2). e lies in the plane of V and the group's principal axis; the part across V
/// follows the axis. Where the variance cannot be met, e is along V (the nearest).
Vec3 pair_direction(const SymTensor& spread, const Vec3& mean, double eps, double variance_v2) noexcept {
  const Vec3 axis = principal_axis(spread);
  const double m2 = norm2(mean);
  if (!(m2 > 0.0) || !(eps > 0.0)) return axis;
  const double m = std::sqrt(m2);
  const Vec3 along = (1.0 / m) * mean;
  Vec3 across = axis - dot(axis, along) * along;
  if (!(norm2(across) > 1e-24)) {  // the axis along V: any direction across it
    const Vec3 trial = std::fabs(along.x) < std::fabs(along.y) ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
    across = trial - dot(trial, along) * along;
  }
  across = (1.0 / norm(across)) * across;
  const double cosine = std::min(1.0, std::sqrt(variance_v2) / (2.0 * std::sqrt(eps) * m));
  return cosine * along + std::sqrt(std::max(0.0, 1.0 - cosine * cosine)) * across;
}

}  // namespace

std::size_t split_particle(WeightedParticles& particles, std::size_t k, std::size_t copies) {
  if (copies < 2) return 0;
  const double w = particles.weight(k) / static_cast<double>(copies);
  const Vec3 v = particles.velocity(k);
  const double t = particles.last_update(k);
  particles.set_weight(k, w);
  for (std::size_t c = 1; c < copies; ++c) particles.add(v, t, w);
  return copies - 1;
}

WeightControl::WeightControl(std::size_t shells, double width, int per_shell, double growth)
    : per_speed_(1.0 / width), per_shell_(static_cast<std::size_t>(per_shell)), growth_(growth), target_(shells, 0.0) {}

std::size_t WeightControl::shell_of(const Vec3& c) const noexcept {
  const double s = norm(c) * per_speed_;
  return s < static_cast<double>(target_.size()) ? static_cast<std::size_t>(s) : target_.size();
}

std::size_t WeightControl::copies(double w, const Vec3& c) const noexcept {
  const std::size_t s = shell_of(c);
  if (s == target_.size() || !(w > 2.0 * target_[s])) return 1;
  return static_cast<std::size_t>(std::min(std::floor(w / target_[s] + 0.5), static_cast<double>(per_shell_)));
}

void WeightControl::set_targets(const WeightedParticles& particles) {
  std::vector<double> mass(target_.size(), 0.0);
  double total = 0.0;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    total += particles.weight(k);
    const std::size_t s = shell_of(particles.velocity(k));
    if (s < mass.size()) mass[s] += particles.weight(k);
  }
  // The ratio of the two outermost populated shells' targets continues them outwards (at most 1).
  std::size_t outer = mass.size(), inner = mass.size();
  for (std::size_t s = 0; s < mass.size(); ++s)
    if (mass[s] > 0.0) inner = std::exchange(outer, s);
  const double per_shell = static_cast<double>(per_shell_);
  double ratio = 1.0;
  if (inner < mass.size())
    ratio = std::clamp(std::pow(mass[outer] / mass[inner], 1.0 / static_cast<double>(outer - inner)), 1e-3, 1.0);
  for (std::size_t s = 0; s < mass.size(); ++s) {
    double t = mass[s] / per_shell;
    if (!(mass[s] > 0.0)) t = s > 0 ? target_[s - 1] * ratio : total / per_shell;
    target_[s] = std::max(t, lightest_target * total);
  }
}

void WeightControl::split_all(WeightedParticles& particles) {
  const std::size_t n = particles.size();  // the copies are at their targets already
  for (std::size_t k = 0; k < n; ++k)
    tally_.split_copies += split_particle(particles, k, copies(particles.weight(k), particles.velocity(k)));
}

void WeightControl::reduce(WeightedParticles& particles, double t) {
  std::vector<std::vector<std::uint32_t>> in_shell(target_.size());
  for (std::size_t k = 0; k < particles.size(); ++k) {
    const std::size_t s = shell_of(particles.velocity(k));
    if (s < target_.size()) in_shell[s].push_back(static_cast<std::uint32_t>(k));
  }
  std::vector<char> removed(particles.size(), 0);
  std::vector<Vec3> added_velocity;
  std::vector<double> added_weight;
  for (std::size_t s = 0; s < target_.size(); ++s) {
    std::vector<std::uint32_t>& members = in_shell[s];
    if (members.size() <= 2 * per_shell_) continue;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> order;  // (key, particle): a total order
    order.reserve(members.size());
    for (std::uint32_t k : members) order.emplace_back(direction_key(particles.velocity(k)), k);
    std::sort(order.begin(), order.end());
    const double closing = 2.0 * target_[s];
    std::size_t first = 0;
    while (first < order.size()) {
      std::size_t last = first;
      double w = 0.0;
      while (last < order.size() && w < closing) w += particles.weight(order[last++].second);
      if (last - first >= 3) {
        Vec3 p;
        for (std::size_t g = first; g < last; ++g) {
          const std::uint32_t k = order[g].second;
          p += particles.weight(k) * particles.velocity(k);
        }
        const Vec3 mean = (1.0 / w) * p;
        SymTensor spread;
        double mean_v2 = 0.0;  // sum w |v|^2 / W
        for (std::size_t g = first; g < last; ++g) {
          const std::uint32_t k = order[g].second;
          const Vec3 d = particles.velocity(k) - mean;
          const double wk = particles.weight(k) / w;
          spread.xx += wk * d.x * d.x, spread.yy += wk * d.y * d.y, spread.zz += wk * d.z * d.z;
          spread.xy += wk * d.x * d.y, spread.xz += wk * d.x * d.z, spread.yz += wk * d.y * d.z;
          mean_v2 += wk * norm2(particles.velocity(k));
          removed[k] = 1;
        }
        double variance_v2 = 0.0;  // sum w (|v|^2 - mean_v2)^2 / W
        for (std::size_t g = first; g < last; ++g) {
          const std::uint32_t k = order[g].second;
          const double x = norm2(particles.velocity(k)) - mean_v2;
          variance_v2 += particles.weight(k) / w * x * x;
        }
        const double eps = spread.xx + spread.yy + spread.zz;
        const Vec3 d = std::sqrt(eps) * pair_direction(spread, mean, eps, variance_v2);
        added_velocity.push_back(mean + d);
        added_velocity.push_back(mean - d);
        added_weight.push_back(0.5 * w);
        added_weight.push_back(0.5 * w);
        ++tally_.reductions;
        tally_.reduced += last - first - 2;
      }
      first = last;
    }
  }
  if (added_weight.empty()) return;
  std::vector<Vec3> velocity;
  std::vector<double> last_update, weight;
  for (std::size_t k = 0; k < particles.size(); ++k) {
    if (removed[k]) continue;
    velocity.push_back(particles.velocity(k));
    last_update.push_back(particles.last_update(k));
    weight.push_back(particles.weight(k));
  }
  velocity.insert(velocity.end(), added_velocity.begin(), added_velocity.end());
  weight.insert(weight.end(), added_weight.begin(), added_weight.end());
  last_update.resize(velocity.size(), t);
  particles.assign(std::move(velocity), std::move(last_update), std::move(weight));
}

void WeightControl::control(WeightedParticles& particles, double t) {
  const WeightedParticles::Totals before = particles.totals();
  set_targets(particles);
  split_all(particles);
  reduce(particles, t);
  particles.resum_weight_bound();
  const WeightedParticles::Totals after = particles.totals();
  const double scale = std::sqrt(before.weight * before.twice_energy);
  tally_.residual = std::max({tally_.residual, std::fabs(after.weight / before.weight - 1.0),
                              norm(after.momentum - before.momentum) / scale,
                              std::fabs(after.twice_energy / before.twice_energy - 1.0)});
  ++tally_.controls;
  next_control_ = static_cast<std::size_t>(std::ceil(growth_ * static_cast<double>(particles.size())));
}

}  // namespace granmc
