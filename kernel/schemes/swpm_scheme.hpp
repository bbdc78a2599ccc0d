#pragma once
// The stochastic weighted particle method (SWPM; Rjasanow and Wagner, J. Comput. Phys. 124 (1996) 243; Math.
// Comput. Modelling 33 (2001) 907) for the uniformly heated or freely cooling inelastic Boltzmann equation of
// 001 (df/dt - beta Lap_v f = gamma Q_alpha(f), 001 eq. 1, B = rate |u|^lambda), time-step free as 001 sec. 4,
// one replica of one species, spheres or disks: the tails of f resolved to densities far below 1/N (001 Remark
// 10). The derivation, with the inelastic weight transfer: docs/methods/derivations/swpm-inelastic.md.
//
// The particles (schemes/weighted_particles.hpp) represent nu = sum_k w_k delta(v - v_k), total weight 1.
// A pair {i, j} collides at the rate 4 pi rate max(w_i, w_j) |v_i - v_j|^lambda; then the lighter partner,
// l, takes its post-collision velocity (001 eq. 4) whole, and the heavier, h, keeps weight w_h - w_l at v_h
// and gives weight w_l to a new particle at its post-collision velocity (the weight transfer gamma = min(w_i,
// w_j), kappa = 0 of Rjasanow and Wagner). Equal weights collide as in the event scheme, and so does a pair
// of disks (Kernel::dimension = 2: the plane z = 0, 2 pi for 4 pi, xi in the plane, the collision of
// collide/rate_form_scattering.hpp). Candidates come at the majorant rate
//   pi_hat = 4 pi rate U_max^lambda W_hat (n - 1),   W_hat = sum over weight classes of n_e 2^e,
// an ordered pair is i by weight class (weighted_particles.hpp) and j uniform among the n - 1 others, and it
// is real with probability (w_i / 2^e) (max(w_i, w_j) / (w_i + w_j)) (|v_i - v_j| / U_max)^lambda: the
// two orders of a pair together give the rate above. As in the event scheme (schemes/event_scheme.hpp),
// both partners are first brought to the candidate time by Brownian motion (001 eq. 23), U_max bounds
// |v_i - v_j| by 2 max |v_k - V| and is raised when a touched particle exceeds it, and at every sample time
// all particles are brought to that time. White noise moves each particle independently and leaves its
// weight as it is.
//
// After a candidate, each particle it touched is split if it is heavier than its shell's target, and when
// the particle count has grown by weights.growth, every particle is brought to the present and the weight
// control (schemes/weight_control.hpp) runs; it also runs at every sample time. The control's shells are the
// histogram's (output.histogram, in its unit: velocity or v0(t), observe/speed_histogram.hpp).
//
// A freely cooling gas (thermostat "none") is rescaled, as the time-stepped scheme's (schemes/dsmc.hpp),
// whenever all particles are current and its stored temperature has left [1/1.25, 1.25]: the weighted mean
// velocity is removed and the velocities are scaled to unit stored temperature, the scale moving into log u
// and the rates following it. The measure's shape is unchanged; its speeds stay far from underflow however
// long the gas cools.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "kernel/collide/collision_kernel.hpp"
#include "kernel/collide/pair_coefficients.hpp"
#include "kernel/collide/rate_form_scattering.hpp"
#include "kernel/core/batch_variates.hpp"
#include "kernel/core/philox_stream.hpp"
#include "kernel/core/sampling.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/core/velocity_scale.hpp"
#include "kernel/observe/speed_histogram.hpp"
#include "kernel/schemes/event_tallies.hpp"
#include "kernel/schemes/initial_state.hpp"
#include "kernel/schemes/replica_in_flight.hpp"
#include "kernel/schemes/weight_control.hpp"
#include "kernel/schemes/weighted_particles.hpp"

namespace granmc {

template <EventKernel Kernel>
class SwpmScheme {
  static constexpr int dimension = Kernel::dimension;

 public:
  /// From the scene's initial Maxwellian: the N = species.particles velocities of the equal-weight start
  /// (the same draws as the event scheme's), each of weight 1 / N, then the weight control at t = 0.
  SwpmScheme(const Scene& scene, std::uint64_t replica, Kernel kernel)
      : SwpmScheme(scene, replica, kernel, maxwellian_state<double>(scene, RandomStream(scene.run.seed, replica))) {}

  /// From a given equal-weight start (one species, state.time = 0).
  SwpmScheme(const Scene& scene, std::uint64_t replica, Kernel kernel, const GasState& start)
      : scene_(scene),
        kernel_(kernel),
        rng_(scene.run.seed, replica),
        alpha_(scene.collision.restitution[0][0]),
        pair_(pair_coefficients(scene).at(0)),
        scale_(start.scale),
        control_(static_cast<std::size_t>(scene.histogram.shells), 1.0, scene.weights->particles_per_shell,
                 scene.weights->growth) {
    const SpeciesStore& store = start.species.at(0);
    if (store.size() < 2) throw std::invalid_argument("the weighted scheme needs at least two particles");
    const double w = 1.0 / static_cast<double>(store.size());
    for (std::size_t k = 0; k < store.size(); ++k) particles_.add(store.velocity(k), 0.0, w);
    set_scale(scale_);
    control_now(0.0);
  }

  [[nodiscard]] const WeightedParticles& particles() const noexcept { return particles_; }
  [[nodiscard]] const SwpmTally& tally() const noexcept { return tally_; }
  [[nodiscard]] const WeightControlTally& control_tally() const noexcept { return control_.tally(); }
  /// The stored velocity unit, u = sqrt(T(0)) in scene units.
  [[nodiscard]] const VelocityScale& scale() const noexcept { return scale_; }
  [[nodiscard]] double time() const noexcept { return time_; }
  /// Rescalings of a freely cooling gas so far.
  [[nodiscard]] std::uint64_t rescales() const noexcept { return rescales_; }

  /// The state at a sample time (after advance_to), for a checkpoint (schemes/replica_in_flight.hpp).
  [[nodiscard]] SwpmSnapshot snapshot() const {
    return {particles_, control_, scale_, rescales_, time_, draws_, syncs_, tally_};
  }

  /// Puts the replica back in the state `s` of a replica of the same scene at a sample time: there U_max was
  /// reset from the particles, and the noise and rate follow from the stored unit.
  void restore(const SwpmSnapshot& s) {
    particles_ = s.particles, control_ = s.control;
    set_scale(s.scale);
    rescales_ = s.rescales, time_ = s.time, draws_ = s.draws, syncs_ = s.syncs, tally_ = s.tally;
    reset_majorant();
  }

  /// Processes every candidate before t, brings all particles to t and runs the weight control.
  void advance_to(double t) {
    for (;;) {
      const RandomBlock first = draw(0);
      const double rate = candidate_rate();
      const double next = time_ - std::log(uniform_open(first[0])) / rate;
      if (!(next < t)) break;  // memoryless: the draw is discarded and the process restarts at t
      time_ = next;
      candidate(first);
      ++draws_;
      if (control_.due(particles_.size())) synchronise(time_);
    }
    ++draws_;
    if (!(draws_ < RandomStream::counter_limit)) throw std::runtime_error("weighted scheme: random counter exhausted");
    time_ = t;
    synchronise(t);
  }

 private:
  [[nodiscard]] RandomBlock draw(std::uint64_t block) const noexcept {
    return rng_.block(RngPurpose::swpm_candidate, 0, draws_, block);
  }

  /// pi_hat = |S^(d-1)| rate U_max^lambda W_hat (n - 1).
  [[nodiscard]] double candidate_rate() const noexcept {
    return candidate_prefactor_ * particles_.weight_bound() * static_cast<double>(particles_.size() - 1);
  }

  /// 001 eq. (23) for particle k up to the present: v += sqrt(2 beta s) xi.
  void brownian_update(std::size_t k, const Vec3& xi) noexcept {
    const double s = time_ - particles_.last_update(k);
    particles_.set_last_update(k, time_);
    if (s > 0.0) particles_.set_velocity(k, particles_.velocity(k) + std::sqrt(noise_ * s) * xi);
  }

  /// One candidate at time_, with the blocks (swpm_candidate, 0, draws_, 0..4): block 0 the waiting time
  /// (used by advance_to), the class share and the member of i; block 1 j and the acceptance uniform;
  /// block 2 the direction e; blocks 3-4 the six normals of the two Brownian increments (disks: the z
  /// normals unused).
  void candidate(const RandomBlock& b0) {
    ++tally_.candidates;
    const RandomBlock b1 = draw(1), b2 = draw(2);
    double bound = 0.0;
    const std::size_t i = particles_.pick(uniform_open52(b0[1], b0[2]), particles_.weight_bound(), b0[3], b1[0], bound);
    std::size_t j = uniform_index(b1[1], b1[2], particles_.size() - 1);
    j += j >= i ? 1 : 0;
    if (noise_ != 0.0) {
      const RandomBlock b3 = draw(3), b4 = draw(4);
      double z[6];
      standard_normal_pair(uniform_open(b3[0]), uniform_open(b3[1]), z[0], z[1]);
      standard_normal_pair(uniform_open(b3[2]), uniform_open(b3[3]), z[2], z[3]);
      standard_normal_pair(uniform_open(b4[0]), uniform_open(b4[1]), z[4], z[5]);
      brownian_update(i, in_plane({z[0], z[1], z[2]}));
      brownian_update(j, in_plane({z[3], z[4], z[5]}));
    }
    Vec3 vi = particles_.velocity(i), vj = particles_.velocity(j);
    const double wi = particles_.weight(i), wj = particles_.weight(j);
    double accept = (wi / bound) * (std::max(wi, wj) / (wi + wj));
    if constexpr (!Kernel::constant_rate) {
      const double drawn_with = majorant_;
      raise_majorant(vi, vj);
      const double ratio = norm(vi - vj) / drawn_with;
      if (ratio > 1.0)
        ++tally_.majorant_violations;  // collides as if at the bound (schemes/event_scheme.hpp)
      else
        accept *= std::pow(ratio, kernel_.lambda);
    }
    if (!(uniform_open(b1[3]) < accept)) {
      split_if_heavy(i);
      split_if_heavy(j);
      return;
    }
    rate_form_scattering<Kernel>(vi, vj, scattering_variate<Kernel>(uniform_open(b2[0]), uniform_open(b2[1])), alpha_,
                                 pair_);  // 001 eq. (4)
    ++tally_.collisions;
    if (wi == wj) {
      particles_.set_velocity(i, vi);
      particles_.set_velocity(j, vj);
    } else {
      // The weight transfer: the lighter partner l moves whole; the heavier h keeps w_h - w_l at v_h and
      // a new particle of weight w_l takes h's post-collision velocity.
      const bool i_heavier = wi > wj;
      const std::size_t h = i_heavier ? i : j, l = i_heavier ? j : i;
      particles_.set_velocity(l, i_heavier ? vj : vi);
      particles_.set_weight(h, std::fabs(wi - wj));
      const std::size_t born = particles_.add(i_heavier ? vi : vj, time_, std::min(wi, wj));
      ++tally_.transfers;
      split_if_heavy(born);
    }
    if constexpr (!Kernel::constant_rate) raise_majorant(vi, vj);
    split_if_heavy(i);
    split_if_heavy(j);
  }

  /// A Brownian increment's normals, without the z component for disks.
  [[nodiscard]] static Vec3 in_plane(const Vec3& xi) noexcept { return dimension == 2 ? Vec3{xi.x, xi.y, 0.0} : xi; }

  void split_if_heavy(std::size_t k) {
    control_.count_split(split_particle(particles_, k, control_.copies(particles_.weight(k), particles_.velocity(k))));
  }

  /// Every particle to time t (001 Remark 2), normals from (swpm_sync, 0, syncs_, k); then the control.
  void synchronise(double t) {
    if (noise_ != 0.0)
      for_each_particle_normal<64>(rng_, RngPurpose::swpm_sync, 0, syncs_, 0, particles_.size(),
                                   [&](std::size_t k, const Vec3& xi) { brownian_update(k, in_plane(xi)); });
    ++syncs_;
    control_now(t);
  }

  /// With every particle current: the rescaling of a cooling gas, the weight control in the histogram's
  /// shells, and the majorant of the new system.
  void control_now(double t) {
    const WeightedParticles::Totals totals = particles_.totals();
    const Vec3 mean = (1.0 / totals.weight) * totals.momentum;
    // theta = m <|c - V|^2> / d of the measure (stored units)
    const double theta = scene_.species[0].mass * (totals.twice_energy / totals.weight - norm2(mean)) / dimension;
    const bool cools_freely = scene_.thermostat.kind == ThermostatKind::none;
    if (cools_freely && (theta > rescale_factor || theta < 1.0 / rescale_factor)) {
      const double s = 1.0 / std::sqrt(theta);
      for (std::size_t k = 0; k < particles_.size(); ++k)
        particles_.set_velocity(k, s * (particles_.velocity(k) - mean));
      VelocityScale scale = scale_;
      scale.log_u -= std::log(s);
      set_scale(scale);
      ++rescales_;
      control_.set_width(shell_width(1.0));
    } else {
      control_.set_width(shell_width(theta));
    }
    control_.control(particles_, t);
    reset_majorant();
  }

  /// The stored unit and what follows it: 2 beta / u^2 and |S^(d-1)| rate u^lambda (4 pi; disks 2 pi).
  void set_scale(const VelocityScale& scale) noexcept {
    scale_ = scale;
    const double u = scale_.u();
    noise_ = 2.0 * scene_.thermostat.beta / (u * u);  // 2 beta in stored units per unit time
    // |S^(d-1)| rate (u U_max)^lambda per unit weight (U_max in stored units)
    rate_prefactor_ = unit_sphere_area(dimension) * scene_.collision.rate * std::pow(u, kernel_.lambda);
  }

  /// The histogram's shell width in stored units, at stored temperature theta.
  [[nodiscard]] double shell_width(double theta) const noexcept {
    return scene_.histogram.radius / static_cast<double>(scene_.histogram.shells) *
           histogram_speed_unit(scene_, scale_, theta);
  }

  /// U_max := max(U_max, 2 |v_i - V|, 2 |v_j - V|) (001 steps 2.7, 2.10).
  void raise_majorant(const Vec3& vi, const Vec3& vj) noexcept {
    const double bound = 2.0 * std::sqrt(std::max(norm2(vi - reference_), norm2(vj - reference_)));
    if (!(bound > majorant_)) return;
    set_majorant(bound);
    ++tally_.majorant_updates;
  }

  /// V := the weighted bulk velocity, U_max := 2 max_k |v_k - V|, with every particle current.
  void reset_majorant() noexcept {
    if constexpr (Kernel::constant_rate) {
      candidate_prefactor_ = rate_prefactor_;
    } else {
      const WeightedParticles::Totals totals = particles_.totals();
      reference_ = (1.0 / totals.weight) * totals.momentum;
      double max2 = 0.0;
      for (std::size_t k = 0; k < particles_.size(); ++k)
        max2 = std::max(max2, norm2(particles_.velocity(k) - reference_));
      set_majorant(2.0 * std::sqrt(max2));
    }
  }
  void set_majorant(double value) noexcept {
    majorant_ = value;
    candidate_prefactor_ = rate_prefactor_ * std::pow(value, kernel_.lambda);
  }

  Scene scene_;  // a copy: the scheme may outlive the scene it was built from
  Kernel kernel_;
  RandomStream rng_;
  double alpha_;
  PairCoefficients pair_;  // hard disks: 000's rule for two unit masses
  VelocityScale scale_;    // the stored unit: u = sqrt(T(0)), then moved by rescalings
  std::uint64_t rescales_ = 0;
  WeightControl control_;
  WeightedParticles particles_;
  double time_ = 0.0;
  double noise_ = 0.0;                // 2 beta / u^2
  double rate_prefactor_ = 0.0;       // |S^(d-1)| rate u^lambda
  double candidate_prefactor_ = 0.0;  // |S^(d-1)| rate (u U_max)^lambda
  double majorant_ = 0.0;             // U_max, stored units
  Vec3 reference_;                    // V of the majorant, stored units
  std::uint64_t draws_ = 0;           // candidate draws so far (the random counter)
  std::uint64_t syncs_ = 0;           // updates of every particle so far
  SwpmTally tally_;
};

}  // namespace granmc
