#pragma once
// Time-stepped ESMC/DSMC for a spatially homogeneous gas (000 sec. 3), one replica: the one time stepper.
//
// A step of length dt runs the free-flight effects the scene named, then the collision stage for every
// ordered species pair (i, j) with 1/2 N_i omega_max^(ij) dt candidates (the fractional part carried to
// the next step), then the post-collision effects; an around_collisions effect (the shear map) acts half
// before and half after the collision stage, the second half fused with the next step's first in one pass
// (settled before every observation). `Kernel` is the collision-rate evaluator
// (collide/), `Effects` the evaluator structs of effects/ (effects/step_context.hpp says what they
// look like); an effect the scene does not name is not in the pack and costs nothing. `Backend` holds the
// particles, the collision stage and the sums over particles: the batched stage of one process
// (schemes/batched_backend.hpp) or the rank waves of one system spread over MPI ranks
// (schemes/rank_wave_backend.hpp). One file, setup/run_plan.cpp, chooses the instantiation.
//
// Long cooling runs never underflow: the stored velocities are rescaled to unit temperature (and the
// centre-of-mass velocity removed) whenever the stored energy has drifted by a factor
// `rescale_factor` (core/velocity_scale.hpp), with the scale kept as log u.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/collide/enskog_shear_shift.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/ranks.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/core/sym_tensor.hpp"
#include "kernel/core/velocity_scale.hpp"
#include "kernel/effects/lagrangian_shear.hpp"
#include "kernel/effects/step_context.hpp"
#include "kernel/observe/gas_observation.hpp"
#include "kernel/schemes/batched_backend.hpp"
#include "kernel/schemes/collision_stage.hpp"
#include "kernel/schemes/gas_state.hpp"
#include "kernel/schemes/replica_in_flight.hpp"

namespace granmc {

namespace detail {
/// The in_collision evaluator of the pack (at most one), or NoCollisionShift.
template <class... Effects>
struct collision_shift {
  using type = NoCollisionShift;
};
template <class First, class... Rest>
struct collision_shift<First, Rest...> {
  using type =
      std::conditional_t<First::phase == StepPhase::in_collision, First, typename collision_shift<Rest...>::type>;
};
}  // namespace detail

/// Real is the storage precision of the velocities (run.storage; core/species_store.hpp).
template <class Backend, class Real, SteppedKernel Kernel, StepEffect... Effects>
class BasicDsmc {
  using Shift = typename detail::collision_shift<Effects...>::type;
  // Degrees of freedom per particle: T = m <c^2> / d (3 spheres, 2 disks).
  static constexpr double dimension = Kernel::dimension;
  // Rough particles spin (collide/rough_rule.hpp); the tracked energy is the translational one.
  static constexpr bool rough = rough_kernel<Kernel>;

 public:
  /// Uniform shear flow (effects/lagrangian_shear.hpp) is in the pack: the pressure tensor is observed.
  static constexpr bool sheared = (std::is_same_v<Effects, LagrangianShear> || ...);

  /// A replica held in one process (BatchedBackend), with the scene's kernel.
  BasicDsmc(const Scene& scene, std::uint64_t replica, Effects... effects)
      : BasicDsmc(scene, replica, Backend(scene), Kernel::from_scene(scene), effects...) {}

  /// A replica spread over `ranks` (RankWaveBackend), with the scene's kernel.
  BasicDsmc(const Scene& scene, std::uint64_t replica, const Ranks& ranks, Effects... effects)
      : BasicDsmc(scene, replica, Backend(scene, ranks), Kernel::from_scene(scene), effects...) {}

  /// The backend and the kernel given (the run plan's, setup/run_stepped.hpp).
  BasicDsmc(const Scene& scene, std::uint64_t replica, Backend backend, Kernel kernel, Effects... effects)
      : scene_(scene),
        rng_(scene.run.seed, replica),
        kernel_(kernel),
        pairs_(pair_coefficients(scene)),
        effects_(effects...),
        backend_(std::move(backend)),
        state_(backend_.template initial_state<Real>(scene, rng_)) {
    for (const SpeciesConfig& s : scene.species) total_particles_ += static_cast<double>(s.particles);
    rescale();  // unit stored temperature from the start; not counted as a rescaling during the run
    rescales_ = 0;
    momentum_removed_ = 0.0;
    log_temperature0_ = log_temperature();
    // Initial majorant: for hard spheres 4 pi sigma_ij^2 n_j chi_ij (max_k |c_k| + max_l |c_l|), a bound
    // on omega_kl at t = 0, or a quarter of it, a bound on its mean over sigma-hat, in the form of the
    // acceptance the collision stage uses (majorant_bound); afterwards it grows when exceeded (000 sec. 3).
    std::vector<double> max_speed;
    for (const BasicSpeciesStore<Real>& s : state_.species) max_speed.push_back(std::sqrt(backend_.largest_speed2(s)));
    for (const PairCoefficients& p : pairs_) {
      omega_max_.push_back(majorant_bound<Shift>(kernel_, p, max_speed[p.i] + max_speed[p.j]));
      carried_.push_back(0.0);
      pair_totals_.emplace_back();
      step_tallies_.emplace_back();
      candidates_.push_back(0);
    }
  }

  [[nodiscard]] const BasicGasState<Real>& state() const noexcept { return state_; }
  [[nodiscard]] const Backend& backend() const noexcept { return backend_; }
  [[nodiscard]] const CollisionTally& tally() const noexcept { return total_; }
  /// Totals per ordered species pair, in the order of pair_coefficients(scene).
  [[nodiscard]] const std::vector<CollisionTally>& pair_tallies() const noexcept { return pair_totals_; }
  [[nodiscard]] std::uint64_t rescales() const noexcept { return rescales_; }
  [[nodiscard]] double momentum_removed_relative() const noexcept { return momentum_removed_; }
  [[nodiscard]] const std::vector<double>& omega_max() const noexcept { return omega_max_; }
  /// The energy bookkeeping of the steps, sum_i m_i sum_k |c_k|^2 in stored units (not summed over particles).
  [[nodiscard]] double tracked_twice_energy() const noexcept { return twice_energy_; }

  /// The collisional transfer part of the pressure tensor over nT (000 eq. 18, n/(N dt) per collision of
  /// the sum of J sigma_ij sigma-hat sigma-hat; docs/methods/physics.md derives the factor), averaged over the time
  /// since the last call; zero without an Enskog shift. Resets the average.
  SymTensor take_collisional_pressure() noexcept {
    const double span = state_.time - transfer_since_;
    const SymTensor mean = span > 0.0 ? (1.0 / span) * transfer_integral_ : SymTensor{};
    transfer_integral_ = {};
    transfer_since_ = state_.time;
    return mean;
  }

  /// Steps until the time reaches t; the last step is shortened to land on t exactly. On return the state
  /// is the state at t: the half step an around_collisions effect still owes is applied.
  void advance_to(double t) {
    while (state_.time < t) {
      const double dt = std::min(step_length(), t - state_.time);
      step(dt);
      state_.time = state_.time + dt >= t ? t : state_.time + dt;
    }
    run_around_collisions(owed_);
    owed_ = 0.0;
  }

  /// The state at a sample time (after advance_to), for a checkpoint (schemes/replica_in_flight.hpp).
  [[nodiscard]] DsmcSnapshot snapshot() const {
    DsmcSnapshot s;
    for (const BasicSpeciesStore<Real>& store : state_.species) {
      std::vector<double>& v = s.velocities.emplace_back();
      v.reserve(3 * store.size());
      for (std::size_t k = 0; k < store.size(); ++k) {
        const Vec3 c = store.velocity(k);
        v.insert(v.end(), {c.x, c.y, c.z});
      }
      if constexpr (rough) {
        std::vector<double>& w = s.spins.emplace_back();
        w.reserve(3 * store.size());
        for (std::size_t k = 0; k < store.size(); ++k) {
          const Vec3 c = store.spin(k);
          w.insert(w.end(), {c.x, c.y, c.z});
        }
      }
    }
    s.log_u = state_.scale.log_u, s.time = state_.time, s.step = state_.step;
    s.omega_max = omega_max_, s.carried = carried_, s.total = total_, s.pair_totals = pair_totals_;
    s.twice_energy = twice_energy_, s.reference_twice_energy = reference_twice_energy_;
    s.log_temperature0 = log_temperature0_, s.momentum_removed = momentum_removed_, s.rescales = rescales_;
    s.transfer_integral = transfer_integral_, s.transfer_since = transfer_since_;
    return s;
  }

  /// Puts the replica back in the state `s` of a replica of the same scene (a stored velocity read back from
  /// its double is the same Real).
  void restore(const DsmcSnapshot& s) {
    if (s.velocities.size() != state_.species.size() || s.omega_max.size() != omega_max_.size())
      throw std::runtime_error("a snapshot of another scene");
    for (std::size_t i = 0; i < state_.species.size(); ++i) {
      BasicSpeciesStore<Real>& store = state_.species[i];
      const std::vector<double>& v = s.velocities[i];
      if (v.size() != 3 * store.size()) throw std::runtime_error("a snapshot of another scene");
      for (std::size_t k = 0; k < store.size(); ++k) store.set_velocity(k, {v[3 * k], v[3 * k + 1], v[3 * k + 2]});
      if constexpr (rough) {
        if (s.spins.size() != state_.species.size() || s.spins[i].size() != v.size())
          throw std::runtime_error("a snapshot of another scene");
        const std::vector<double>& w = s.spins[i];
        for (std::size_t k = 0; k < store.size(); ++k) store.set_spin(k, {w[3 * k], w[3 * k + 1], w[3 * k + 2]});
      }
    }
    state_.scale.log_u = s.log_u, state_.time = s.time, state_.step = s.step;
    omega_max_ = s.omega_max, carried_ = s.carried, total_ = s.total, pair_totals_ = s.pair_totals;
    twice_energy_ = s.twice_energy, reference_twice_energy_ = s.reference_twice_energy;
    log_temperature0_ = s.log_temperature0, momentum_removed_ = s.momentum_removed, rescales_ = s.rescales;
    transfer_integral_ = s.transfer_integral, transfer_since_ = s.transfer_since;
    owed_ = 0.0;
  }

  /// Appends the observation of the present state to `series` (with `histogram`, its speeds to the speed
  /// histograms); returns the totals the backend summed.
  GasTotals observe(ReplicaSeries& series, bool histogram) const {
    return backend_.observe(scene_, state_, series, histogram);
  }

 private:
  double log_temperature() const noexcept {
    return state_.scale.log_temperature(twice_energy_ / (dimension * total_particles_));
  }

  /// The thermal time step follows the mean free time, dt ~ T^-1/2 (000 sec. 3). Under shear it never
  /// exceeds the scene's dt, so a dt (the inertial map per step) stays at most its initial value when the
  /// gas cools (000 sec. 3: dt small against the mean free time and 1/a).
  double step_length() const noexcept {
    if (scene_.run.dt_scaling == DtScaling::fixed) return scene_.run.dt;
    const double thermal = scene_.run.dt * std::exp(0.5 * (log_temperature0_ - log_temperature()));
    return sheared ? std::min(thermal, scene_.run.dt) : thermal;
  }

  void step(double dt) {
    run_phase<StepPhase::free_flight>({dt, twice_energy_, 0.0, &rng_});

    const double u_dt = std::exp(kernel_.lambda * state_.scale.log_u + std::log(dt));  // u^lambda dt
    for (std::size_t q = 0; q < pairs_.size(); ++q) {
      const PairCoefficients& p = pairs_[q];
      const double n_i = static_cast<double>(scene_.species[p.i].particles);
      if (p.i == p.j && n_i < 2.0) continue;  // no partner within a species of one particle
      // 1/2 N_i omega_max dt candidates (000 sec. 3), with N_i - 1 for a pair within one species: the
      // partner is drawn among the N_i - 1 others, so each of the N_i (N_i - 1) ordered pairs gets its
      // exact rate omega / N_i; the paper's N_i over-counts by N_i / (N_i - 1) (docs/methods/physics.md).
      const double partners = p.i == p.j ? n_i - 1.0 : n_i;
      const double wanted = 0.5 * partners * omega_max_[q] * u_dt + carried_[q];
      if (!(wanted < static_cast<double>(RandomStream::counter_limit / 8)))
        throw std::runtime_error("time step too large: " + std::to_string(wanted) +
                                 " collision candidates in one step; reduce run.dt");
      const double whole = std::floor(wanted);
      carried_[q] = wanted - whole;
      candidates_[q] = static_cast<std::uint64_t>(whole);
    }
    std::fill(step_tallies_.begin(), step_tallies_.end(), CollisionTally{});
    backend_.collide(state_, std::span<const PairCoefficients>(pairs_), std::span<double>(omega_max_),
                     std::span<const std::uint64_t>(candidates_), rng_, std::span<CollisionTally>(step_tallies_),
                     kernel_, step_shift());
    CollisionTally tally;
    for (std::size_t q = 0; q < pairs_.size(); ++q) {
      add(pair_totals_[q], step_tallies_[q]);
      add(tally, step_tallies_[q]);
    }
    if constexpr (Shift::active) {
      // This step's share of the time integral of P^c / (n T): n / N u sum / (n u^2 T_stored), with the
      // stored mixture temperature T_stored = twice_energy / dN before the collisions.
      transfer_integral_ += (dimension / (state_.scale.u() * twice_energy_)) * tally.transfer;
      twice_energy_ += tally.twice_energy_shear_work;
    }
    twice_energy_ -= tally.twice_energy_loss;
    run_phase<StepPhase::after_collisions>({dt, twice_energy_, tally.twice_energy_loss, &rng_});
    add(total_, tally);
    ++state_.step;
    if (twice_energy_ < reference_twice_energy_ / rescale_factor ||
        twice_energy_ > reference_twice_energy_ * rescale_factor)
      rescale();
  }

  /// The contact-velocity shift of this step in stored units (collide/enskog_shear_shift.hpp), or none.
  Shift step_shift() const noexcept {
    if constexpr (Shift::active)
      return std::get<Shift>(effects_).in_stored_units(state_.scale.u());
    else
      return {};
  }

  static void add(CollisionTally& to, const CollisionTally& from) noexcept {
    to.candidates += from.candidates;
    to.collisions += from.collisions;
    to.majorant_updates += from.majorant_updates;
    to.twice_energy_loss += from.twice_energy_loss;
    to.twice_energy_shear_work += from.twice_energy_shear_work;
    to.transfer += from.transfer;
  }

  /// Runs the effects of one phase in pack order, each seeing the stored energy its predecessors left.
  /// An around_collisions effect (Strang halves, effects/step_context.hpp) runs in the free_flight phase
  /// over the half step the previous step owes plus this step's first half, in one pass (one O(N) sweep
  /// per step instead of two): the two halves compose exactly (the shear map is linear with a.a = 0) and
  /// commute with the Gaussian thermostat's scaling. The after_collisions effects now act before the owed
  /// half instead of after it, which changes the step at O(dt^2) only: the thermostat's cooling-rate factor
  /// is measured across the collision stage alone, and the relaxation term replaces velocities before it.
  template <StepPhase phase>
  void run_phase(StepContext ctx) noexcept {
    auto run_one = [&](auto& effect) {
      constexpr StepPhase its = std::decay_t<decltype(effect)>::phase;
      if constexpr (its == phase) {
        twice_energy_ += backend_.apply(effect, state_, ctx);
        ctx.twice_energy = twice_energy_;
      } else if constexpr (its == StepPhase::around_collisions && phase == StepPhase::free_flight) {
        StepContext owed_and_half = ctx;
        owed_and_half.dt = owed_ + 0.5 * ctx.dt;
        twice_energy_ += backend_.apply(effect, state_, owed_and_half);
        ctx.twice_energy = twice_energy_;
      }
    };
    std::apply([&](auto&... effect) { (run_one(effect), ...); }, effects_);
    if constexpr (phase == StepPhase::after_collisions) owed_ = 0.5 * ctx.dt;
  }

  /// Applies the around_collisions effects over dt alone (the owed half step, before an observation).
  void run_around_collisions(double dt) noexcept {
    if (dt == 0.0) return;
    auto run_one = [&](auto& effect) {
      if constexpr (std::decay_t<decltype(effect)>::phase == StepPhase::around_collisions)
        twice_energy_ += backend_.apply(effect, state_, {dt, twice_energy_, 0.0, &rng_});
    };
    std::apply([&](auto&... effect) { (run_one(effect), ...); }, effects_);
  }

  /// Removes the centre-of-mass velocity and rescales the stored velocities to unit mean temperature,
  /// moving the scale into log u. omega_max stays in stored units: the majorant estimate follows the
  /// thermal speed, as the shape of the scaled distribution does.
  void rescale() noexcept {
    const GasTotals t = gas_totals(scene_, backend_.moments(state_));
    const Vec3 v_cm = (1.0 / t.mass) * t.momentum;
    momentum_removed_ += norm(t.momentum) / std::sqrt(t.mass * t.twice_energy);
    const double twice_energy = t.twice_energy - norm2(t.momentum) / t.mass;  // after removing v_cm
    const double s = std::sqrt(dimension * total_particles_ / twice_energy);
    for (BasicSpeciesStore<Real>& store : state_.species) {
      store.for_each_velocity([&](Vec3& c) { c = s * (c - v_cm); });
      store.for_each_spin([&](Vec3& w) { w = s * w; });  // rough particles: spins in the same unit
    }
    state_.scale.log_u -= std::log(s);
    twice_energy_ = reference_twice_energy_ = dimension * total_particles_;
    ++rescales_;
  }

  const Scene& scene_;
  RandomStream rng_;
  Kernel kernel_;
  std::vector<PairCoefficients> pairs_;
  std::tuple<Effects...> effects_;
  Backend backend_;
  BasicGasState<Real> state_;
  std::vector<double> omega_max_;          // per ordered pair, units of u
  std::vector<double> carried_;            // fractional candidates carried to the next step
  std::vector<std::uint64_t> candidates_;  // this step's candidates per pair
  CollisionTally total_;
  std::vector<CollisionTally> pair_totals_;
  std::vector<CollisionTally> step_tallies_;  // this step's, per pair
  double total_particles_ = 0.0;
  double twice_energy_ = 0.0;            // tracked sum_i m_i sum_k |c_k|^2
  double reference_twice_energy_ = 0.0;  // its value after the last rescaling
  double log_temperature0_ = 0.0;
  double momentum_removed_ = 0.0;
  std::uint64_t rescales_ = 0;
  SymTensor transfer_integral_;  // time integral of P^c / (n T) since transfer_since_
  double transfer_since_ = 0.0;
  double owed_ = 0.0;  // the half step the around_collisions effects owe since the last step (scene time)
};

/// One process, double storage, the default.
template <class Kernel, class... Effects>
using Dsmc = BasicDsmc<BatchedBackend, double, Kernel, Effects...>;

}  // namespace granmc
