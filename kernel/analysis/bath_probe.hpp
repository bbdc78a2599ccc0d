#pragma once
// The bath of a Gillespie intruder as the intruder sees it (002 Figs. 1-2): the collision fluxes phi_+(v1),
// phi_-(v1) = phi_+(-v1) and the law g_+(v; v1) of the velocity of a bath particle that hits the right side
// (002 eqs. 14, 19-20), sampled by the bath's own rejection scheme (collide/bath_*.hpp), the code the
// intruder runs. For `granmc bath`.
#include <cstdint>
#include <utility>
#include <vector>

#include "kernel/core/philox_stream.hpp"
#include "kernel/core/rng_ids.hpp"

namespace granmc {

struct BathProbePoint {
  double v1 = 0.0;
  double flux_right = 0.0;      // phi_+(v1)
  double flux_left = 0.0;       // phi_-(v1) = phi_+(-v1)
  std::uint64_t attempts = 0;   // rejection attempts for `samples` accepted draws
  std::vector<double> density;  // histogram of the draws from g_+ on the edges, per unit velocity
  std::uint64_t outside = 0;    // draws below the first edge or above the last
};

/// For each v1: the fluxes, and `samples` draws from g_+(v; v1) binned on `edges` (increasing). The draws use
/// the stream (seed, replica 0), block (intruder_event, 0, draw, attempt), so a probe is reproducible.
template <class Bath>
std::vector<BathProbePoint> probe_bath(const Bath& bath, const std::vector<double>& v1s, std::uint64_t samples,
                                       const std::vector<double>& edges, std::uint64_t seed) {
  const RandomStream rng(seed, 0);
  std::vector<BathProbePoint> out;
  const std::size_t bins = edges.size() - 1;
  for (double v1 : v1s) {
    BathProbePoint p;
    p.v1 = v1;
    p.flux_right = bath.flux_right(v1);
    p.flux_left = bath.flux_right(-v1);
    std::vector<std::uint64_t> counts(bins, 0);
    for (std::uint64_t s = 0; s < samples; ++s) {
      double v = 0.0;
      for (std::uint64_t k = 0;; ++k) {
        ++p.attempts;
        if (bath.try_sample_right(v1, rng.block(RngPurpose::intruder_event, 0, s, k), v)) break;
      }
      if (v < edges.front() || v >= edges.back()) {
        ++p.outside;
        continue;
      }
      std::size_t lo = 0, hi = bins;  // edges[lo] <= v < edges[hi]
      while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        (v < edges[mid] ? hi : lo) = mid;
      }
      ++counts[lo];
    }
    for (std::size_t b = 0; b < bins; ++b)
      p.density.push_back(static_cast<double>(counts[b]) / (static_cast<double>(samples) * (edges[b + 1] - edges[b])));
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace granmc
