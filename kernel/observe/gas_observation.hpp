#pragma once
// Observes a gas replica at a sample time: partial and mixture temperatures, a2, total momentum.
#include <vector>

#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"
#include "kernel/observe/moments.hpp"
#include "kernel/schemes/gas_state.hpp"

namespace granmc {

/// The moments of every species of `state` about `centre` (stored units), in species order.
template <class Real>
std::vector<SpeciesMoments> gas_moments(const BasicGasState<Real>& state, const Vec3& centre = {});

/// Mass-weighted sums over all species in stored units, used to observe and to rescale.
struct GasTotals {
  double mass = 0.0;          // sum_i m_i N_i
  double twice_energy = 0.0;  // sum_i m_i sum_k |c_k|^2
  Vec3 momentum;              // sum_i m_i sum_k c_k
};
/// (The moments must be about the origin.)
GasTotals gas_totals(const Scene& scene, const std::vector<SpeciesMoments>& moments) noexcept;

/// What record_observation returns: the totals about the origin and the mixture temperature in stored units.
struct Observed {
  GasTotals totals;
  double theta_mixture = 0.0;  // sum_i x_i m_i <|c - flow|^2> / d
};

/// Appends the temperatures, cumulants and momentum of one observation to `series`, from the moments of
/// every species about the origin and about the flow velocity (the part of observe_gas that needs no
/// particle; a system spread over ranks sums its moments first, schemes/rank_wave_backend.hpp).
Observed record_observation(const Scene& scene, const VelocityScale& scale,
                            const std::vector<SpeciesMoments>& about_origin,
                            const std::vector<SpeciesMoments>& about_flow, ReplicaSeries& series);

/// Appends the rotational temperature and spin cumulants of species i of rough particles to its series, from
/// its spin moments about the flow velocity and <|c - flow|^2> of the same particles: with s = (sigma / 2) omega
/// and I = kappa m sigma^2 / 4, T_rot = I <omega^2> / d_r = kappa m <s^2> / d_r.
void record_spin_observation(const Scene& scene, const VelocityScale& scale, std::size_t i, const SpinMoments& m,
                             double mean_c2, SpeciesSeries& s);

/// Appends one observation of `state` to `series` (series.species must have one entry per species); with
/// `histogram`, also adds the scaled speeds to each species' speed_counts. Returns the totals it summed
/// (stored units), for checks the caller makes on the same state.
template <class Real>
GasTotals observe_gas(const Scene& scene, const BasicGasState<Real>& state, ReplicaSeries& series, bool histogram);

}  // namespace granmc
