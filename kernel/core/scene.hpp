#pragma once
// Scene: what to simulate, as a plain, validated, immutable value. io/scene_file.cpp builds it from a
// TOML file (the scene contract, docs/formats/scenes.md) and is the only place that checks
// it; everything downstream may assume the invariants stated beside each member.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace granmc {

enum class Method { dsmc, event, gillespie };
enum class CollisionKernel { hard_sphere, maxwell, vhs };
enum class ThermostatKind { none, gaussian, white_noise };
enum class BathKind { gaussian, power_law };
/// How the time step follows the state: fixed, or a fixed fraction of the mean free time, i.e.
/// dt_k = dt * u(0) / u(t_k) with u the current thermal velocity scale (000 sec. 3: "the value of
/// dt must be conveniently updated"), so a cooling run costs the same per decade of temperature.
enum class DtScaling { fixed, thermal };
/// Where the observations fall: t_k = k t_end / samples, or geometrically from dt to t_end.
enum class SampleSpacing { linear, log };
/// The scalar of the stored particle velocities (docs/formats/scenes.md, run.storage; core/species_store.hpp).
enum class Storage { double_precision, single_precision };

/// The scene-file spelling of a method ("dsmc", "event", "gillespie").
constexpr const char* method_name(Method m) noexcept {
  switch (m) {
    case Method::dsmc:
      return "dsmc";
    case Method::event:
      return "event";
    case Method::gillespie:
      return "gillespie";
  }
  return "unknown";
}

struct RunConfig {
  Method method = Method::dsmc;
  std::uint64_t seed = 1;
  int replicas = 1;    // > 0
  double t_end = 0.0;  // > 0, scene time units
  double dt = 0.0;     // > 0 for dsmc (initial step when dt_scaling = thermal)
  int samples = 100;   // > 0; observations at samples + 1 times including t = 0
  DtScaling dt_scaling = DtScaling::fixed;
  SampleSpacing sample_spacing = SampleSpacing::linear;
  Storage storage = Storage::double_precision;
  double checkpoint_every = 10.0;  // >= 0, minutes between checkpoints of `granmc run` (0: at every sample)
  int dimension = 3;               // of a gas: 3 hard spheres, 2 hard disks
};

struct SpeciesConfig {
  std::string name;
  double mass = 1.0;           // > 0
  double diameter = 1.0;       // > 0, sigma_i
  double density = 1.0;        // > 0, number density n_i
  std::int64_t particles = 0;  // > 0, simulated particles N_i (N_1/N_2 = n_1/n_2 to 1%)
};

struct CollisionConfig {
  CollisionKernel kernel = CollisionKernel::hard_sphere;
  double lambda = 1.0;                                                         // VHS exponent in [0, 1]
  double rate = 0.0;                                                           // >= 0; Gamba form (001) when > 0
  std::array<std::array<double, 2>, 2> restitution{{{1.0, 1.0}, {1.0, 1.0}}};  // alpha_ij in [0, 1], symmetric
  double packing_fraction = 0.0;         // in [0, 1); > 0 switches on Enskog chi_ij (000 eq. 3)
  double tangential_restitution = -1.0;  // beta in [-1, 1]; -1: smooth particles, > -1: rough
  double reduced_inertia = 0.4;          // kappa = 4 I / (m sigma^2) in (0, 1]; default 2/5 (1/2 for disks)
};

/// Whether the scene's particles are rough (collision.tangential_restitution > -1).
inline bool rough(const CollisionConfig& c) noexcept { return c.tangential_restitution > -1.0; }

struct ThermostatConfig {
  ThermostatKind kind = ThermostatKind::none;
  bool zeta_is_cooling_rate = true;  // gaussian: compensate the instantaneous cooling rate
  double zeta = 0.0;                 // gaussian with a fixed rate (1/time)
  double beta = 0.0;                 // white noise: dv = sqrt(2 beta) dW, >= 0
  double rotational_share = 0.0;     // white noise on rough particles: the fraction of the injected power that
                                     // kicks the spins, in [0, 1] (effects/white_noise.hpp)
};

struct IntruderConfig {
  int dimension = 1;         // 1 or 2
  double mass = 1.0;         // > 0, M (bath particle mass 1)
  double restitution = 1.0;  // in [0, 1]
  BathKind bath = BathKind::gaussian;
  double bath_a = 1.0;        // > 0
  double bath_density = 1.0;  // > 0
  double length = 1.0;        // > 0, needle length L
  double inertia = 0.0;       // >= 0; 0 means M L^2 / 12
};

/// What the speed histogram's shells measure: the scaled speed v* = |V| / v0(t) (observe/speed_histogram.hpp)
/// or |V| in the scene's velocity units.
enum class HistogramSpeed { scaled, velocity };

struct HistogramConfig {
  int shells = 128;                     // > 0
  double radius = 16.0;                 // > 0
  std::optional<HistogramSpeed> speed;  // absent: scaled for method "dsmc", velocity for "event"
};

/// Weighted particles for the tails (001 Remark 10; schemes/swpm_scheme.hpp): present when the scene has a
/// [weights] table (scheme = "swpm", the stochastic weighted particle method of Rjasanow and Wagner).
struct WeightsConfig {
  int particles_per_shell = 128;  // >= 4; M: the weight control's target count in every histogram shell
  double growth = 2.0;            // > 1; the control also runs when the count reaches growth x its count after
                                  // the last control
};

struct Scene {
  RunConfig run;
  std::vector<SpeciesConfig> species;  // 1 or 2 for gas scenes, empty for an intruder scene
  CollisionConfig collision;
  ThermostatConfig thermostat;
  double shear_rate = 0.0;              // a of u_x = a y (000 sec. 2)
  bool relaxation = false;              // BGK-like relaxation to the HCS (003)
  std::optional<double> relaxation_a2;  // a2 of its f^(0); default the first-Sonine HCS a2 (c0 / 2 of 003)
  double initial_temperature = 1.0;     // > 0, finite
  bool initial_zero_momentum = true;    // remove each species' sample mean; false keeps it (001 step 1.2)
  std::optional<IntruderConfig> intruder;
  HistogramConfig histogram;
  std::optional<WeightsConfig> weights;

  std::string source_path;  // where the scene came from (for messages and output)
  std::string source_text;  // the file's text, stored with the results
};

/// The needle's moment of inertia: the scene's, or M L^2 / 12 (a uniform rod) when it is 0.
inline double needle_inertia(const IntruderConfig& in) noexcept {
  return in.inertia > 0.0 ? in.inertia : in.mass * in.length * in.length / 12.0;
}

/// Total simulated particles over all species.
inline std::int64_t total_particles(const Scene& s) {
  std::int64_t n = 0;
  for (const auto& sp : s.species) n += sp.particles;
  return n;
}

/// The species' masses m_i, in scene order.
inline std::vector<double> species_masses(const Scene& s) {
  std::vector<double> masses;
  for (const auto& sp : s.species) masses.push_back(sp.mass);
  return masses;
}

/// Total number density n = sum_i n_i.
inline double total_density(const Scene& s) {
  double n = 0.0;
  for (const auto& sp : s.species) n += sp.density;
  return n;
}

}  // namespace granmc
