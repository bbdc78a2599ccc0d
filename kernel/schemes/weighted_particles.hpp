#pragma once
// The particles of the stochastic weighted particle method (Rjasanow and Wagner, J. Comput. Phys. 124 (1996)
// 243): particle k is (v_k, t_k, w_k), a velocity in stored units, the time of its last Brownian update (as
// in the event scheme, 001 eq. 23) and a weight; the particles represent the measure sum_k w_k delta(v - v_k).
//
// The scheme chooses a particle with probability proportional to its weight. Particles are kept in weight
// classes, class e holding the weights in [2^(e-1), 2^e) (std::frexp's exponent): a class is chosen with
// probability n_e 2^e / W_hat, W_hat = sum_e n_e 2^e, a member uniformly, and the choice is kept with
// probability w_k / 2^e >= 1/2 (thinning; schemes/swpm_scheme.hpp). The counts n_e are integers, so the
// choice depends only on the particles, never on the history of a sum.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/core/sampling.hpp"
#include "kernel/core/vec3.hpp"

namespace granmc {

class WeightedParticles {
 public:
  [[nodiscard]] std::size_t size() const noexcept { return velocity_.size(); }
  [[nodiscard]] const Vec3& velocity(std::size_t k) const noexcept { return velocity_[k]; }
  [[nodiscard]] double last_update(std::size_t k) const noexcept { return last_update_[k]; }
  [[nodiscard]] double weight(std::size_t k) const noexcept { return weight_[k]; }

  void set_velocity(std::size_t k, const Vec3& v) noexcept { velocity_[k] = v; }
  void set_last_update(std::size_t k, double t) noexcept { last_update_[k] = t; }

  /// w_k := w (> 0), moving the particle to its new class.
  void set_weight(std::size_t k, double w) {
    const int e = weight_class(w);
    weight_[k] = w;
    if (e == class_[k]) return;
    leave_class(k);
    join_class(k, e);
  }

  /// Appends a particle; returns its index.
  std::size_t add(const Vec3& v, double t, double w) {
    const std::size_t k = size();
    velocity_.push_back(v);
    last_update_.push_back(t);
    weight_.push_back(w);
    class_.push_back(0);
    position_.push_back(0);
    join_class(k, weight_class(w));
    return k;
  }

  /// Replaces every particle (after a reduction), in the given order.
  void assign(std::vector<Vec3> velocity, std::vector<double> last_update, std::vector<double> weight) {
    velocity_ = std::move(velocity);
    last_update_ = std::move(last_update);
    weight_ = std::move(weight);
    class_.assign(size(), 0);
    position_.assign(size(), 0);
    for (auto& members : members_) members.clear();
    lowest_ = members_.size();
    highest_ = 0;
    for (std::size_t k = 0; k < size(); ++k) join_class(k, weight_class(weight_[k]));
    resum_weight_bound();
  }

  /// Every member, in one order (a checkpoint's packing walks it, io/replica_bytes.hpp): the members' order in
  /// their classes too, on which the choices depend.
  template <class Self, class Visit>
  static void visit_fields(Self& p, Visit&& visit) {
    visit("velocity", p.velocity_);
    visit("last_update", p.last_update_);
    visit("weight", p.weight_);
    visit("class", p.class_);
    visit("position", p.position_);
    visit("members", p.members_);
    visit("lowest", p.lowest_);
    visit("highest", p.highest_);
    visit("bound_total", p.bound_total_);
  }

  /// weight_bound() summed afresh from the counts, from the heaviest class.
  void resum_weight_bound() noexcept {
    bound_total_ = 0.0;
    for (std::size_t c = highest_ + 1; c-- > lowest_;)
      if (!members_[c].empty()) bound_total_ += class_bound(c);
  }

  /// W_hat = sum over classes of n_e 2^e, a bound on the total weight: sum_k w_k < W_hat <= 2 sum_k w_k. Kept
  /// up to date as particles join and leave classes (2^e added or taken away), and summed afresh by
  /// resum_weight_bound() at every control, so that its rounding does not accumulate.
  [[nodiscard]] double weight_bound() const noexcept { return bound_total_; }

  /// The particle of a draw by class bound: `share` in (0, 1) of weight_bound() picks the class (from the
  /// heaviest), the two words a member uniformly; `bound` receives the class's 2^e.
  [[nodiscard]] std::size_t pick(double share, double bound_total, std::uint32_t hi, std::uint32_t lo,
                                 double& bound) const noexcept {
    double rest = share * bound_total;
    std::size_t chosen = members_.size();
    for (std::size_t c = highest_ + 1; c-- > lowest_;) {
      if (members_[c].empty()) continue;
      chosen = c;
      rest -= class_bound(c);
      if (rest < 0.0) break;  // (rounding past the last class leaves the lightest class chosen)
    }
    bound = std::ldexp(1.0, exponent_of(chosen));
    const std::vector<std::uint32_t>& members = members_[chosen];
    return members[uniform_index(hi, lo, members.size())];
  }

  /// Totals of the measure: sum w, sum w v, sum w |v|^2 (stored units), summed in index order.
  struct Totals {
    double weight = 0.0;
    Vec3 momentum;
    double twice_energy = 0.0;
  };
  [[nodiscard]] Totals totals() const noexcept {
    Totals t;
    for (std::size_t k = 0; k < size(); ++k) {
      t.weight += weight_[k];
      t.momentum += weight_[k] * velocity_[k];
      t.twice_energy += weight_[k] * norm2(velocity_[k]);
    }
    return t;
  }

 private:
  // Class e of a weight w = m 2^e, m in [1/2, 1), lives at index e + offset (weights are normal doubles).
  static constexpr int offset = 1100;
  static int weight_class(double w) noexcept {
    int e = 0;
    static_cast<void>(std::frexp(w, &e));
    return e;
  }
  static int exponent_of(std::size_t c) noexcept { return static_cast<int>(c) - offset; }
  /// n_e 2^e of the class at index c.
  [[nodiscard]] double class_bound(std::size_t c) const noexcept {
    return std::ldexp(static_cast<double>(members_[c].size()), exponent_of(c));
  }

  void join_class(std::size_t k, int e) {
    const std::size_t c = static_cast<std::size_t>(e + offset);
    if (members_.size() <= c) members_.resize(c + 1);
    lowest_ = std::min(lowest_, c);
    highest_ = std::max(highest_, c);
    class_[k] = e;
    position_[k] = static_cast<std::uint32_t>(members_[c].size());
    members_[c].push_back(static_cast<std::uint32_t>(k));
    bound_total_ += std::ldexp(1.0, e);
  }
  void leave_class(std::size_t k) {
    std::vector<std::uint32_t>& members = members_[static_cast<std::size_t>(class_[k] + offset)];
    const std::uint32_t last = members.back();
    members[position_[k]] = last;
    position_[last] = position_[k];
    members.pop_back();
    bound_total_ -= std::ldexp(1.0, class_[k]);
  }

  std::vector<Vec3> velocity_;
  std::vector<double> last_update_;
  std::vector<double> weight_;
  std::vector<int> class_;                           // e of particle k
  std::vector<std::uint32_t> position_;              // its place in members_ of its class
  std::vector<std::vector<std::uint32_t>> members_;  // particles of each class, at e + offset
  std::size_t lowest_ = SIZE_MAX, highest_ = 0;      // every class outside [lowest_, highest_] is empty
  double bound_total_ = 0.0;                         // weight_bound()
};

}  // namespace granmc
