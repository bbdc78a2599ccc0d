#pragma once
// The high-velocity tail exponent b of f ~ C v^gamma exp(-a v^b) (001 eqs. 19-21 give b; gamma is the
// pre-asymptotic prefactor), from the speed distribution per replica: on a window of shells,
//   ln f_k = c + gamma ln v_k - a v_k^b,
// least squares over (c, gamma, a) for each b, and the b of least misfit (a grid of step 0.005 on [0.2, 3],
// then a finer one of step 1e-4 around the best; NaN when the least misfit is at an end of the grid). f_k is
// the replica mean of the density per unit velocity volume at the shell centre v_k: a fit per replica would
// carry the bias of a nonlinear fit to noisy data. Its confidence half-width is lambda_p (001 eq. 31) times
// the jackknife standard error over the replicas (the fits with one replica left out). Carrying gamma lets
// the window sit where weighted particles resolve f, far out, without the bias of 001 eq. (38), which
// assumes gamma = 0 and reads the prefactor as a change of b.
#include <cstddef>
#include <optional>
#include <vector>

#include "kernel/analysis/replica_statistics.hpp"

namespace granmc {

struct TailWindow {
  std::size_t first = 0, last = 0;          // shells [first, last], 0-based
  double speed_from = 0.0, speed_to = 0.0;  // their outer edges: edges[first], edges[last + 1]
  MeanCI exponent;                          // b of the replica-mean density, with its jackknife CI
};

/// The fit of b on shells [first, last] (at least 4), densities[r][k] the density of replica r in shell k.
TailWindow fit_tail_window(const std::vector<double>& edges, const std::vector<std::vector<double>>& densities,
                           std::size_t first, std::size_t last);

/// The shells every replica has weight in, counted from the innermost: [0, reach).
std::size_t tail_reach(const std::vector<std::vector<double>>& densities) noexcept;

/// Where the tail begins: the replica-mean density below this fraction of its maximum.
inline constexpr double tail_density_fraction = 1e-3;
/// The fewest shells a window may have.
inline constexpr std::size_t tail_min_shells = 8;

/// The headline fit: from the first shell where the mean density is below 10^-3 of its maximum to the end of
/// the shells every replica has weight in; none when that leaves fewer than 8 shells. A window over a large
/// factor in speed tells gamma ln v and a v^b apart: on a factor 2 they are nearly collinear and b's CI
/// grows tenfold (001 Example 7 with weighted particles: +-0.14 on [20, 80], +-0.05 on [10, 80]).
std::optional<TailWindow> fit_tail(const std::vector<double>& edges, const std::vector<std::vector<double>>& densities);

/// b against the window's inner edge: windows from where the mean density falls below 10^-1, 10^-2, ...
/// of its maximum to the end of the reach, while 8 shells and a factor 2 in speed remain. Where b levels
/// off as the inner edge moves out, the window has left the pre-asymptotic region (the CI grows as the
/// window narrows).
std::vector<TailWindow> tail_exponent_profile(const std::vector<double>& edges,
                                              const std::vector<std::vector<double>>& densities);

}  // namespace granmc
