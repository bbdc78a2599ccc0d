#pragma once
// Where the weighted particles put their resolution (docs/methods/derivations/swpm-inelastic.md, "Weight control"):
// every shell of the speed histogram (output.histogram) should hold about M = weights.particles_per_shell
// particles. Shell s gets the target weight W_s = m_s / M, m_s its weight at the last control; shells beyond
// the outermost populated one continue the targets geometrically. Two operations keep the particles near
// their targets, and neither changes the measure's mass, momentum or energy:
//  - splitting: a particle heavier than 2 W_s in shell s becomes k = round(w / W_s) (at most M) copies of
//    weight w / k at the same velocity: the same measure; the copies part with their next Brownian updates
//    and collisions. The scheme splits a particle whenever it touches it (schemes/swpm_scheme.hpp), and the
//    control splits every particle.
//  - reduction, only in a shell holding more than 2 M particles: its particles, ordered along the sphere
//    (a Morton curve of the octahedral map of their direction; for disks, z = 0, the map's diamond
//    |x| + |y| = 1, along each edge of which the key grows monotonically), are grouped in order until a group weighs
//    2 W_s; a group of three or more, of weight W, mean V and spread eps = sum w |v - V|^2 / W, becomes two
//    particles of weight W / 2 at V +- sqrt(eps) e (Rjasanow, Schreiber and Wagner, J. Comput. Phys. 145
//    (1998) 382): mass, momentum and energy are kept to rounding whatever the unit vector e. e is chosen
//    so that the pair also keeps the group's sum w |v|^4 (possible unless the group's speeds spread more
//    than its directions allow): without it, each reduction pulled speeds together and a2 of 001's Maxwell
//    gas at alpha = 1/2 came out 0.050 instead of 0.087 (docs/methods/derivations/swpm-inelastic.md). Shells at or
//    below 2 M particles, where the resolution is wanted, are never reduced.
// Particles at or beyond the histogram's radius are neither split nor reduced.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel/core/vec3.hpp"
#include "kernel/schemes/weighted_particles.hpp"

namespace granmc {

struct WeightControlTally {
  std::uint64_t controls = 0;      // whole-system controls
  std::uint64_t split_copies = 0;  // particles added by splitting
  std::uint64_t reductions = 0;    // groups replaced by two particles
  std::uint64_t reduced = 0;       // particles removed by the reductions
  double residual = 0.0;           // largest relative change of mass, momentum or energy at a control
};

class WeightControl {
 public:
  /// `shells` shells of width `width` (stored velocity units) from speed 0; M particles per shell.
  WeightControl(std::size_t shells, double width, int per_shell, double growth);
  WeightControl() = default;  // to be assigned or read into

  /// The shell of a stored velocity, or shells() at or beyond the radius.
  [[nodiscard]] std::size_t shell_of(const Vec3& c) const noexcept;
  [[nodiscard]] std::size_t shells() const noexcept { return target_.size(); }
  /// Moves the shells to width `width` (stored units), as the histogram's unit moves in stored units.
  void set_width(double width) noexcept { per_speed_ = 1.0 / width; }

  /// How many copies a particle of weight w at c becomes: round(w / W_s) (at most M) when w > 2 W_s, else 1.
  [[nodiscard]] std::size_t copies(double w, const Vec3& c) const noexcept;

  /// Whether a system of `count` particles is due for a control (growth x the count after the last one).
  [[nodiscard]] bool due(std::size_t count) const noexcept { return count >= next_control_; }

  /// The whole-system control at time t, every particle current: new targets from the shell weights,
  /// splitting, then reduction of the overfull shells.
  void control(WeightedParticles& particles, double t);

  [[nodiscard]] const WeightControlTally& tally() const noexcept { return tally_; }
  /// Counts particles added by a split outside the control (the scheme's, when it touches a particle).
  void count_split(std::size_t added) noexcept { tally_.split_copies += added; }
  [[nodiscard]] const std::vector<double>& targets() const noexcept { return target_; }

  /// Every member, in one order (a checkpoint's packing walks it, io/replica_bytes.hpp).
  template <class Self, class Visit>
  static void visit_fields(Self& c, Visit&& visit) {
    visit("per_speed", c.per_speed_);
    visit("per_shell", c.per_shell_);
    visit("growth", c.growth_);
    visit("target", c.target_);
    visit("next_control", c.next_control_);
    visit("tally", c.tally_);
  }

 private:
  void set_targets(const WeightedParticles& particles);
  void split_all(WeightedParticles& particles);
  void reduce(WeightedParticles& particles, double t);

  double per_speed_ = 0.0;     // shells per stored speed unit
  std::size_t per_shell_ = 0;  // M
  double growth_ = 0.0;
  std::vector<double> target_;  // W_s
  std::size_t next_control_ = 0;
  WeightControlTally tally_;
};

/// Splits particle k into `copies` particles of weight w / copies at its velocity and update time (the
/// first keeps index k, the others are appended). Returns the number added.
std::size_t split_particle(WeightedParticles& particles, std::size_t k, std::size_t copies);

}  // namespace granmc
