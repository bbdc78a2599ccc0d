// What a pair-dependent majorant would buy the time-stepped DSMC of hard spheres (a study, not granmc's
// scheme). An elastic hard-sphere gas (the scaling scenes of docs/developer-guide/scaling.md) from a Maxwellian at T =
// 1, in granmc's packed records (x, y, z, aux), runs the same steps two ways, one candidate after the other:
//
//  - the paper's majorant (000 sec. 3), as granmc's collision stage: C = c N (N - 1) / 2 U candidates per
//    step, k and l uniform, real with probability |v_k - v_l| / U, U raised when exceeded; U starts at
//    2 max |v - V|, so it follows the fastest particle;
//  - pair bounds: |v_k - v_l| <= s_k + s_l with s = |v - V| (V the conserved mean velocity), so the sum
//    of the pairs' bounds is (N - 1) S, S = sum_k s_k: C = c (N - 1) S candidates per step, k drawn in
//    proportion to s_k (a uniform index accepted with probability s_k / s_max: "selection draws", each a
//    read of a random record), l uniform, real with probability |v_k - v_l| / (s_k + s_l). S and s_max
//    are kept up to date at every collision (s_max raised only). The number of candidates is set at the
//    step's start, as the paper's is.
//
// Both draw their indices a ring of `ahead` draws before their use and prefetch the records then (the
// selection draws too), and both collide with the same rule (isotropic scattering, 001 eq. 4, alpha = 1),
// so the difference is the majorant and its selection. c is set so that a step has about 0.05 N
// collisions (nu dt = 0.1). Output per n: candidates and selection draws per collision, the collisions
// per step and per particle (the same law: equal within noise), and ns per collision (wall time of
// `steps` steps, the fastest of `passes` runs; std::chrono, indicative only on a shared host).
// docs/developer-guide/performance.md ("A pair-dependent majorant for the time-stepped scheme") has the table and the
// commands; `pair_bound_study --help` lists the options.
#include <algorithm>
#include <bit>
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
using granmc::perf::SplitMix64;

template <class Real>
struct alignas(4 * sizeof(Real)) Record {
  Real v[3];
  Real aux;
  [[nodiscard]] Vec3 velocity() const noexcept { return {double{v[0]}, double{v[1]}, double{v[2]}}; }
  void set(const Vec3& w) noexcept {
    v[0] = static_cast<Real>(w.x), v[1] = static_cast<Real>(w.y), v[2] = static_cast<Real>(w.z);
  }
};

struct Count {
  double candidates = 0, collisions = 0, selection_draws = 0, raises = 0, seconds = 0, temperature = 0;
};

double uniform01(SplitMix64& gen) noexcept { return static_cast<double>(gen.next() >> 11) * 0x1p-53; }
std::uint64_t index_below(SplitMix64& gen, std::uint64_t n) noexcept {
  __extension__ using uint128 = unsigned __int128;
  return static_cast<std::uint64_t>((static_cast<uint128>(gen.next()) * n) >> 64);
}
/// A selection draw from one 64-bit word: the index from its high 32 bits (n < 2^32; bias below 2^-32 x n,
/// immaterial for a study), the uniform from its low 32.
std::uint64_t index_of_word(std::uint64_t word, std::uint64_t n) noexcept { return ((word >> 32) * n) >> 32; }
double uniform_of_word(std::uint64_t word) noexcept { return static_cast<double>(word & 0xFFFFFFFFu) * 0x1p-32; }
/// A unit vector uniform on the sphere (cos theta and phi uniform).
Vec3 unit_vector(SplitMix64& gen) noexcept {
  const double cos_theta = 2.0 * uniform01(gen) - 1.0, phi = 2.0 * std::numbers::pi * uniform01(gen);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}
/// Candidates of a step: the integer part of `mean`, plus one with the probability of its fraction.
std::uint64_t candidates_of(double mean, SplitMix64& gen) noexcept {
  const double whole = std::floor(mean);
  return static_cast<std::uint64_t>(whole) + (uniform01(gen) < mean - whole ? 1u : 0u);
}

template <class Real>
class Gas {
 public:
  Gas(std::size_t n, std::uint64_t seed) : r_(n) {
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal;
    for (std::size_t k = 0; k < n; ++k) r_[k].set({normal(random), normal(random), normal(random)}), r_[k].aux = 0;
    Vec3 sum;
    for (std::size_t k = 0; k < n; ++k) sum += r_[k].velocity();
    mean_ = (1.0 / static_cast<double>(n)) * sum;
  }
  [[nodiscard]] std::size_t size() const noexcept { return r_.size(); }
  Record<Real>& operator[](std::size_t k) noexcept { return r_[k]; }
  [[nodiscard]] double far(const Vec3& v) const noexcept { return granmc::norm(v - mean_); }
  [[nodiscard]] double far2(const Vec3& v) const noexcept { return granmc::norm2(v - mean_); }
  [[nodiscard]] double temperature() const noexcept {
    double sum = 0.0;
    for (std::size_t k = 0; k < size(); ++k) sum += granmc::norm2(r_[k].velocity() - mean_);
    return sum / (3.0 * static_cast<double>(size()));
  }

 private:
  granmc::AlignedBuffer<Record<Real>> r_;
  Vec3 mean_;
};

constexpr std::size_t kAhead = 32;

/// The paper's majorant, `steps` steps with rate constant c.
template <class Real>
Count paper_majorant(Gas<Real>& gas, double c, int steps, std::uint64_t seed) {
  Count count;
  const std::size_t n = gas.size();
  double majorant = 0.0;
  for (std::size_t k = 0; k < n; ++k) majorant = std::max(majorant, 2.0 * gas.far(gas[k].velocity()));
  SplitMix64 gen{seed}, pairs{seed ^ 0xA5A5A5A5u};
  std::uint64_t ring_k[kAhead], ring_l[kAhead];
  auto draw = [&](std::size_t slot) {
    const std::uint64_t k = index_below(pairs, n), l_other = index_below(pairs, n - 1);
    ring_k[slot] = k, ring_l[slot] = l_other + (l_other >= k ? 1 : 0);
    __builtin_prefetch(&gas[ring_k[slot]], 1, 3);
    __builtin_prefetch(&gas[ring_l[slot]], 1, 3);
  };
  for (std::size_t s = 0; s < kAhead; ++s) draw(s);
  std::uint64_t next = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < steps; ++step) {
    const std::uint64_t m =
        candidates_of(0.5 * c * static_cast<double>(n) * static_cast<double>(n - 1) * majorant, gen);
    for (std::uint64_t i = 0; i < m; ++i, ++next) {
      const std::size_t slot = next % kAhead;
      auto& rk = gas[ring_k[slot]];
      auto& rl = gas[ring_l[slot]];
      draw(slot);
      Vec3 vk = rk.velocity(), vl = rl.velocity();
      const double g = granmc::norm(vk - vl);
      if (g > majorant) {
        majorant = g;
        ++count.raises;
      } else if (uniform01(gen) * majorant >= g) {
        continue;
      }
      granmc::isotropic_scattering(vk, vl, unit_vector(gen), 1.0);
      rk.set(vk), rl.set(vl);
      ++count.collisions;
    }
    count.candidates += static_cast<double>(m);
  }
  count.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  count.temperature = gas.temperature();
  return count;
}

/// Whether the try (k, u) selects k: u s_max < s_k, tested on squares (the square root for the accepted k only).
template <class Real>
bool selects(Gas<Real>& gas, std::uint64_t k, double u, double largest) noexcept {
  const double threshold = u * largest;
  return threshold * threshold < gas.far2(gas[k].velocity());
}

/// A selection try from one 64-bit word of `tries`, its record prefetched.
template <class Real>
void draw_try(Gas<Real>& gas, SplitMix64& tries, std::uint64_t& k, double& u) {
  const std::uint64_t word = tries.next();
  k = index_of_word(word, gas.size());
  u = uniform_of_word(word);
  __builtin_prefetch(&gas[k], 1, 3);
}

/// k in proportion to s_k by rejection, one try after the other, each drawn a ring of kAhead tries before
/// its turn.
template <class Real>
class PlainSelection {
 public:
  PlainSelection(Gas<Real>& gas, SplitMix64& tries, const double& largest, Count& count)
      : gas_(gas), tries_(tries), largest_(largest), count_(count) {
    for (std::size_t s = 0; s < kAhead; ++s) draw_try(gas_, tries_, k_[s], u_[s]);
  }
  std::uint64_t next() {
    for (;;) {
      const std::size_t slot = next_++ % kAhead;
      const std::uint64_t k = k_[slot];
      const double u = u_[slot];
      draw_try(gas_, tries_, k_[slot], u_[slot]);
      ++count_.selection_draws;
      if (selects(gas_, k, u, largest_)) return k;
    }
  }
  void touched(std::uint64_t, std::uint64_t, bool) noexcept {}

 private:
  Gas<Real>& gas_;
  SplitMix64& tries_;
  const double& largest_;
  Count& count_;
  std::uint64_t k_[kAhead], next_ = 0;
  double u_[kAhead];
};

/// The same tries screened a block at a time: a block's 16 tries are tested together, branch-free, when its
/// first try's turn comes, and a try whose particle a later collision of the block's time touched (or every
/// try left, when s_max rose) is tested again at its turn. So every try is decided on the velocities of its
/// turn, the same bits as PlainSelection.
template <class Real>
class ScreenedSelection {
 public:
  ScreenedSelection(Gas<Real>& gas, SplitMix64& tries, const double& largest, Count& count)
      : gas_(gas), tries_(tries), largest_(largest), count_(count) {
    for (Block& b : ring_) fill(b);
    accepted_ = evaluate(ring_[0]);
  }
  std::uint64_t next() {
    for (;;) {
      if (position_ == kBlock) {
        fill(ring_[current_ % kBlocksAhead]);  // the tries kBlocksAhead blocks later
        ++current_, position_ = 0, stale_ = 0;
        accepted_ = evaluate(ring_[current_ % kBlocksAhead]);
      }
      const std::uint32_t rest = (accepted_ | stale_) >> position_;
      if (rest == 0) {
        count_.selection_draws += kBlock - position_;
        position_ = kBlock;
        continue;
      }
      const unsigned t = position_ + static_cast<unsigned>(std::countr_zero(rest));
      count_.selection_draws += t - position_ + 1;
      position_ = t + 1;
      const Block& b = ring_[current_ % kBlocksAhead];
      if (((stale_ >> t) & 1u) != 0 && !selects(gas_, b.k[t], b.u[t], largest_)) continue;
      return b.k[t];
    }
  }
  /// After a collision of k and l: their tries left in the block are tested again at their turn, and every
  /// try left when s_max rose.
  void touched(std::uint64_t k, std::uint64_t l, bool raised) noexcept {
    const Block& b = ring_[current_ % kBlocksAhead];
    for (unsigned i = 0; i < kBlock; ++i) stale_ |= static_cast<std::uint32_t>((b.k[i] == k) | (b.k[i] == l)) << i;
    if (raised) stale_ = ~0u;
  }

 private:
  static constexpr unsigned kBlock = 16, kBlocksAhead = 4;
  struct Block {
    std::uint64_t k[kBlock];
    double u[kBlock];
  };
  void fill(Block& b) {
    for (unsigned i = 0; i < kBlock; ++i) draw_try(gas_, tries_, b.k[i], b.u[i]);
  }
  std::uint32_t evaluate(const Block& b) const {
    std::uint32_t mask = 0;
    for (unsigned i = 0; i < kBlock; ++i)
      mask |= static_cast<std::uint32_t>(selects(gas_, b.k[i], b.u[i], largest_)) << i;
    return mask;
  }

  Gas<Real>& gas_;
  SplitMix64& tries_;
  const double& largest_;
  Count& count_;
  Block ring_[kBlocksAhead];
  std::uint64_t current_ = 0;
  unsigned position_ = 0;
  std::uint32_t accepted_ = 0, stale_ = 0;
};

/// The pair bounds s_k + s_l, `steps` steps with rate constant c, k chosen by `Selection`.
template <template <class> class Selection, class Real>
Count pair_bounds(Gas<Real>& gas, double c, int steps, std::uint64_t seed) {
  Count count;
  const std::size_t n = gas.size();
  double sum = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double s = gas.far(gas[k].velocity());
    sum += s, largest = std::max(largest, s);
  }
  SplitMix64 gen{seed}, tries{seed ^ 0x5A5A5A5Au}, partners{seed ^ 0xC3C3C3C3u};
  Selection<Real> selection(gas, tries, largest, count);
  std::uint64_t ring_l[kAhead];
  auto draw_partner = [&](std::size_t slot) {
    ring_l[slot] = index_below(partners, n - 1);  // mapped past k at use
    __builtin_prefetch(&gas[ring_l[slot]], 1, 3);
  };
  for (std::size_t s = 0; s < kAhead; ++s) draw_partner(s);
  std::uint64_t next = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int step = 0; step < steps; ++step) {
    const std::uint64_t m = candidates_of(c * static_cast<double>(n - 1) * sum, gen);
    for (std::uint64_t i = 0; i < m; ++i, ++next) {
      const std::uint64_t k = selection.next();  // k in proportion to s_k
      Vec3 vk = gas[k].velocity();
      const double sk = gas.far(vk);
      const std::size_t slot = next % kAhead;
      const std::uint64_t l = ring_l[slot] + (ring_l[slot] >= k ? 1 : 0);
      draw_partner(slot);
      auto& rk = gas[k];
      auto& rl = gas[l];
      Vec3 vl = rl.velocity();
      const double sl = gas.far(vl), g = granmc::norm(vk - vl);
      if (uniform01(gen) * (sk + sl) >= g) continue;
      granmc::isotropic_scattering(vk, vl, unit_vector(gen), 1.0);
      rk.set(vk), rl.set(vl);
      const double sk_new = gas.far(vk), sl_new = gas.far(vl);
      sum += (sk_new - sk) + (sl_new - sl);
      // A branch, rarely taken, not a max: the next selection then waits on this collision only when s_max rises.
      const bool raised = sk_new > largest || sl_new > largest;
      if (raised) largest = std::max({largest, sk_new, sl_new});
      selection.touched(k, l, raised);
      ++count.collisions;
    }
    count.candidates += static_cast<double>(m);
  }
  count.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  count.temperature = gas.temperature();
  return count;
}

template <class Real>
void study(std::size_t n, int steps, int passes, std::uint64_t seed) {
  // c with about 0.05 N collisions per step: c N (N - 1) / 2 <|g|> = 0.05 N, <|g|> = 4 / sqrt(pi) at T = 1.
  const double mean_relative_speed = 4.0 / std::sqrt(std::numbers::pi);
  const double c = 0.1 / (static_cast<double>(n - 1) * mean_relative_speed);
  Count best_paper, best_pair, best_screened;
  best_paper.seconds = best_pair.seconds = best_screened.seconds = 1e300;
  for (int p = 0; p < passes; ++p) {
    Gas<Real> first(n, seed), second(n, seed), third(n, seed);  // the same initial state
    const Count a = paper_majorant(first, c, steps, seed + 1 + p);
    const Count b = pair_bounds<PlainSelection>(second, c, steps, seed + 1 + p);
    const Count d = pair_bounds<ScreenedSelection>(third, c, steps, seed + 1 + p);
    if (b.collisions != d.collisions || b.temperature != d.temperature || b.selection_draws != d.selection_draws)
      std::printf("# n = %zu: the screened selection differs from the plain one\n", n);
    if (a.seconds < best_paper.seconds) best_paper = a;
    if (b.seconds < best_pair.seconds) best_pair = b;
    if (d.seconds < best_screened.seconds) best_screened = d;
  }
  const double per_step = static_cast<double>(steps) * static_cast<double>(n);
  auto line = [&](const char* name, const Count& k) {
    std::printf("%-9zu %-6s %-7s %10.4f %10.3f %11.3f %12.5f %9.5f %8.0f %9.2f\n", n,
                sizeof(Real) == 4 ? "float" : "double", name, k.collisions / k.candidates, k.candidates / k.collisions,
                k.selection_draws / k.candidates, k.collisions / per_step, k.temperature, k.raises,
                1e9 * k.seconds / k.collisions);
  };
  line("paper", best_paper);
  line("pair", best_pair);
  line("screened", best_screened);
  const auto per = [](const Count& k) { return k.seconds / k.collisions; };
  std::printf("# n = %zu: ns per collision, paper / pair = %.2f, paper / screened = %.2f\n", n,
              per(best_paper) / per(best_pair), per(best_paper) / per(best_screened));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Time-stepped hard spheres with the paper's majorant and with pair bounds s_k + s_l (a study)"};
  std::vector<std::size_t> particles{100'000, 1'000'000, 10'000'000};
  int steps = 20, passes = 3;
  std::uint64_t seed = 7;
  bool single = false;
  app.add_option("--particles", particles, "particle counts")->check(CLI::Range(std::size_t{2}, std::size_t{1} << 32));
  app.add_option("--steps", steps, "steps of nu dt = 0.1 per run")->check(CLI::PositiveNumber);
  app.add_option("--passes", passes, "runs of each way per n; the fastest is kept")->check(CLI::PositiveNumber);
  app.add_option("--seed", seed, "seed of the initial state");
  app.add_flag("--float", single, "16-byte float records (granmc's run.storage = \"float\") instead of 32-byte double");
  CLI11_PARSE(app, argc, argv);
  std::printf("%-9s %-6s %-7s %10s %10s %11s %12s %9s %8s %9s\n", "n", "record", "majorant", "acceptance", "cand/coll",
              "selection/c", "coll/step/n", "T", "raises", "ns/coll");
  for (const std::size_t n : particles) {
    if (single)
      study<float>(n, steps, passes, seed);
    else
      study<double>(n, steps, passes, seed);
  }
}
