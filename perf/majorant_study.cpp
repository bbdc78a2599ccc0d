// How many candidates a better majorant would save in paper 001's Example 8 (hard spheres, beta = 30,
// alpha = 1/10, rate 4/pi, Maxwellian start at T = 1, t in [0, 0.25]): a study, not granmc's scheme.
// It runs the same gas two ways, one candidate after the other, with std::mt19937_64:
//
//  - the paper's: candidates at pi_hat = 2 pi rate (n - 1) U_max (001 eq. 25), i and j uniform, both brought
//    to the candidate time (001 eq. 23), real with probability |v_i - v_j| / U_max (001 eq. 26), U_max raised
//    as in kernel/schemes/event_scheme.hpp;
//  - per-particle bounds (001 eq. 24 allows B_max(i, j) to depend on the pair): in an epoch [t_0, t_e],
//        W_k = |v_k - V| + kappa sqrt(2 beta (t_e - t_k))
//    bounds |v_k(t) - V| for every t <= t_e unless the particle's Brownian increment since its last update
//    t_k is longer than kappa standard deviations, so |v_i - v_j| <= W_i + W_j and the pairs' majorant
//    4 pi rate (W_i + W_j) gives pi_hat = 4 pi rate (n - 1) / n sum_k W_k. i is drawn in proportion to W_i
//    (uniform i accepted with probability W_i / max W: "selection draws"), j uniformly, the candidate is
//    real with probability |v_i - v_j| / (W_i + W_j), and the two bounds are renewed after each candidate.
//    At t_e every bound is recomputed (an "epoch").
//
// Both count candidates, real collisions, violations (|v_i - v_j| above the pair's bound: such a
// candidate collides) and T(0.25); the second also counts particles found above their own bound and the
// selection draws. docs/developer-guide/performance.md ("Per-particle bounds under white noise") has the table and the
// commands; `majorant_study --help` lists the options.
//
// With --costs it times instead, on n particles in granmc's 16-byte float records, what such a scheme
// would add to the event loop: the pass that renews every bound at an epoch's end, and a selection draw
// (a uniform index, the read of its bound from an array of n floats, prefetched 32 draws ahead, and the
// comparison); next to them the limit kernel's random pair gather/scatter on the same records
// (perf/gather_scatter_limit.hpp). Wall time with std::chrono, the fastest of 5 passes: indicative only
// on this shared host.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <CLI/CLI.hpp>

#include "kernel/collide/isotropic_scattering.hpp"
#include "kernel/core/aligned_buffer.hpp"
#include "kernel/core/vec3.hpp"
#include "perf/gather_scatter_limit.hpp"

namespace {

using granmc::Vec3;

constexpr double kBeta = 30.0, kRestitution = 0.1, kRate = 4.0 / std::numbers::pi, kEnd = 0.25;  // Example 8

struct Count {
  double candidates = 0, collisions = 0, violations = 0, temperature = 0;
  double selection_draws = 0, above_own_bound = 0, epochs = 0;  // per-particle bounds only
};

/// n particles (v_k, t_k) from a Maxwellian at T = 1, and the operations both schemes share.
class Gas {
 public:
  Gas(std::size_t n, std::uint64_t seed) : velocity_(n), last_(n, 0.0), random_(seed) {
    for (Vec3& v : velocity_) v = {normal_(random_), normal_(random_), normal_(random_)};
    Vec3 sum;
    for (const Vec3& v : velocity_) sum += v;
    reference_ = (1.0 / static_cast<double>(n)) * sum;
  }
  [[nodiscard]] std::size_t size() const noexcept { return velocity_.size(); }
  double uniform() { return uniform_(random_); }
  std::size_t index(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(random_); }
  /// |v_k - V| with V the initial bulk velocity.
  [[nodiscard]] double far(std::size_t k) const noexcept { return granmc::norm(velocity_[k] - reference_); }
  [[nodiscard]] double last_update(std::size_t k) const noexcept { return last_[k]; }
  [[nodiscard]] double relative_speed(std::size_t i, std::size_t j) const noexcept {
    return granmc::norm(velocity_[i] - velocity_[j]);
  }
  /// 001 eq. (23): v_k += sqrt(2 beta (t - t_k)) xi.
  void bring_to(std::size_t k, double t) {
    const double width = std::sqrt(2.0 * kBeta * (t - last_[k]));
    last_[k] = t;
    velocity_[k] += width * Vec3{normal_(random_), normal_(random_), normal_(random_)};
  }
  /// 001 eq. (4) with e uniform on the sphere.
  void collide(std::size_t i, std::size_t j) {
    const double cos_theta = 2.0 * uniform() - 1.0, phi = 2.0 * std::numbers::pi * uniform();
    const double sin_theta = std::sqrt(1.0 - cos_theta * cos_theta);
    granmc::isotropic_scattering(velocity_[i], velocity_[j],
                                 {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta}, kRestitution);
  }
  /// Every particle to t, then T = <|v - V|^2> / 3.
  double temperature(double t) {
    double sum = 0.0;
    for (std::size_t k = 0; k < size(); ++k) {
      bring_to(k, t);
      sum += far(k) * far(k);
    }
    return sum / (3.0 * static_cast<double>(size()));
  }

 private:
  std::vector<Vec3> velocity_;
  std::vector<double> last_;
  Vec3 reference_;
  std::mt19937_64 random_;
  std::normal_distribution<double> normal_;
  std::uniform_real_distribution<double> uniform_;
};

/// 001 sec. 4, steps 2.1-2.10, with the raise of U_max as granmc does it (event_scheme.hpp).
Count paper_majorant(Gas& gas) {
  Count count;
  const std::size_t n = gas.size();
  double majorant = 0.0;
  for (std::size_t k = 0; k < n; ++k) majorant = std::max(majorant, 2.0 * gas.far(k));
  for (double t = 0.0;;) {
    const double drawn_with = majorant;
    t -= std::log(gas.uniform()) / (2.0 * std::numbers::pi * kRate * static_cast<double>(n - 1) * majorant);
    if (t >= kEnd) break;
    const std::size_t i = gas.index(n), j_other = gas.index(n - 1), j = j_other + (j_other >= i ? 1 : 0);
    gas.bring_to(i, t);
    gas.bring_to(j, t);
    ++count.candidates;
    majorant = std::max({majorant, 2.0 * gas.far(i), 2.0 * gas.far(j)});
    const double g = gas.relative_speed(i, j);
    if (g > drawn_with) {
      ++count.violations;
    } else if (gas.uniform() * drawn_with >= g) {
      continue;
    }
    gas.collide(i, j);
    ++count.collisions;
    majorant = std::max({majorant, 2.0 * gas.far(i), 2.0 * gas.far(j)});
  }
  count.temperature = gas.temperature(kEnd);
  return count;
}

/// The per-particle bounds W_k described at the top, epochs of length `epoch`.
Count particle_majorants(Gas& gas, double kappa, double epoch) {
  Count count;
  const std::size_t n = gas.size();
  std::vector<double> bound(n);
  double sum = 0.0, largest = 0.0, epoch_end = 0.0, t = 0.0;
  auto bound_of = [&](std::size_t k) {
    return gas.far(k) + kappa * std::sqrt(2.0 * kBeta * (epoch_end - gas.last_update(k)));
  };
  auto new_epoch = [&] {
    epoch_end = std::min(t + epoch, kEnd);
    sum = largest = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      bound[k] = bound_of(k);
      sum += bound[k];
      largest = std::max(largest, bound[k]);
    }
    ++count.epochs;
  };
  new_epoch();
  for (;;) {
    const double next = t - std::log(gas.uniform()) / (4.0 * std::numbers::pi * kRate * static_cast<double>(n - 1) /
                                                       static_cast<double>(n) * sum);
    if (next >= epoch_end) {  // memoryless: restart at the epoch's end with the new bounds
      if (epoch_end >= kEnd) break;
      t = epoch_end;
      new_epoch();
      continue;
    }
    t = next;
    std::size_t i = 0;
    do {
      i = gas.index(n);
      ++count.selection_draws;
    } while (gas.uniform() * largest >= bound[i]);
    const std::size_t j_other = gas.index(n - 1), j = j_other + (j_other >= i ? 1 : 0);
    gas.bring_to(i, t);
    gas.bring_to(j, t);
    ++count.candidates;
    if (gas.far(i) > bound[i] || gas.far(j) > bound[j]) ++count.above_own_bound;
    const double pair_bound = bound[i] + bound[j], g = gas.relative_speed(i, j);
    bool real = true;
    if (g > pair_bound) {
      ++count.violations;
    } else {
      real = gas.uniform() * pair_bound < g;
    }
    if (real) {
      gas.collide(i, j);
      ++count.collisions;
    }
    for (const std::size_t k : {i, j}) {
      const double renewed = bound_of(k);
      sum += renewed - bound[k];
      bound[k] = renewed;
      largest = std::max(largest, renewed);
    }
  }
  count.temperature = gas.temperature(kEnd);
  return count;
}

/// Seconds of the fastest of 5 calls of `pass`.
template <class Pass>
double fastest_of_5(Pass pass) {
  double best = 1e300;
  for (int k = 0; k < 5; ++k) {
    const auto start = std::chrono::steady_clock::now();
    pass();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

/// --costs: ns per particle of the renewal pass, per selection draw, and per limit-kernel pair.
void time_costs(std::size_t n, double kappa) {
  using Records = granmc::perf::PackedFloatLayout;  // v and, in aux, the last-update time
  Records records(n);
  granmc::perf::SplitMix64 random{7};
  for (std::size_t k = 0; k < n; ++k)
    records.r[k].aux = static_cast<float>(0.001 * granmc::perf::initial_value(random));
  granmc::AlignedBuffer<float> bound(n);
  const double noise = 2.0 * kBeta, epoch_end = 0.002;
  float largest = 0.0F;
  const double renew = fastest_of_5([&] {
    float top = 0.0F;
    for (std::size_t k = 0; k < n; ++k) {
      const auto& r = records.r[k];
      const double far = std::sqrt(double{r.v[0]} * r.v[0] + double{r.v[1]} * r.v[1] + double{r.v[2]} * r.v[2]);
      bound[k] =
          static_cast<float>(far + kappa * std::sqrt(noise * (epoch_end - r.aux))) * (1.0F + 0x1p-22F);  // rounded up
      top = std::max(top, bound[k]);
    }
    largest = top;
  });
  constexpr std::size_t draws = 10'000'000, ahead = 32;
  std::uint64_t accepted = 0;
  const double select = fastest_of_5([&] {
    granmc::perf::SplitMix64 gen{11};
    std::uint64_t ring[ahead];
    __extension__ using uint128 = unsigned __int128;
    auto index = [&] { return static_cast<std::uint64_t>((static_cast<uint128>(gen.next()) * n) >> 64); };
    for (auto& slot : ring) __builtin_prefetch(&bound[slot = index()], 0, 3);
    for (std::size_t d = 0; d < draws; ++d) {
      std::uint64_t& slot = ring[d % ahead];
      const float threshold = static_cast<float>(gen.next() >> 40) * 0x1p-24F * largest;
      accepted += threshold < bound[slot] ? 1 : 0;
      __builtin_prefetch(&bound[slot = index()], 0, 3);
    }
  });
  constexpr std::uint64_t pairs = 10'000'000;
  const double limit = fastest_of_5([&] {
    granmc::perf::SplitMix64 gen{0x5EED};
    granmc::perf::run_pairs_prefetched(records, gen, pairs);
  });
  std::printf("# n = %zu, kappa = %g: ns per particle of the renewal pass, per selection draw, per limit pair\n", n,
              kappa);
  std::printf(
      "renewal %.2f  selection %.2f  limit_pair %.2f  (acceptance of the draws on these synthetic records %.3f)\n",
      1e9 * renew / n, 1e9 * select / draws, 1e9 * limit / pairs, static_cast<double>(accepted) / (5.0 * draws));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Candidates of paper 001's Example 8 with its majorant and with per-particle bounds (a study)"};
  std::size_t particles = 100'000, replicas = 2;
  double kappa = 7.0, epoch = 0.001;
  std::uint64_t seed = 100;
  app.add_option("--particles", particles, "particles per replica")
      ->check(CLI::Range(std::size_t{2}, std::size_t{1} << 32));
  app.add_option("--replicas", replicas, "replicas, seeds seed, seed + 1, ...")->check(CLI::PositiveNumber);
  app.add_option("--kappa", kappa, "margin of a particle's bound, in standard deviations of its Brownian increment")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--epoch", epoch, "time between recomputations of all bounds")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the first replica");
  bool costs = false;
  app.add_flag("--costs", costs, "time the renewal pass, a selection draw and a limit-kernel pair instead");
  CLI11_PARSE(app, argc, argv);
  if (costs) {
    time_costs(particles, kappa);
    return 0;
  }

  std::printf("# Example 8, n = %zu, kappa = %g, epoch = %g\n", particles, kappa, epoch);
  std::printf("%-8s %-10s %12s %12s %10s %10s %9s %12s %10s %8s %9s\n", "replica", "majorant", "candidates",
              "collisions", "acceptance", "violations", "T(0.25)", "selection/c", "above_own", "epochs", "ratio");
  for (std::size_t r = 0; r < replicas; ++r) {
    Gas first(particles, seed + r), second(particles, seed + r);  // the same initial state
    const Count paper = paper_majorant(first), local = particle_majorants(second, kappa, epoch);
    std::printf("%-8zu %-10s %12.5g %12.5g %10.4f %10.0f %9.4f\n", r, "paper", paper.candidates, paper.collisions,
                paper.collisions / paper.candidates, paper.violations, paper.temperature);
    std::printf("%-8zu %-10s %12.5g %12.5g %10.4f %10.0f %9.4f %12.3f %10.0f %8.0f %9.3f\n", r, "particle",
                local.candidates, local.collisions, local.collisions / local.candidates, local.violations,
                local.temperature, local.selection_draws / local.candidates, local.above_own_bound, local.epochs,
                paper.candidates / local.candidates);
  }
}
