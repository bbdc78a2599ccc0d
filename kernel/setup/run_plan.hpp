#pragma once
// The run plan: a validated Scene -> what runs, as types (docs/developer-guide/architecture.md). make_plan is
// the one function that branches on the scene's kinds (method, kernel, thermostat, shear, bath, storage);
// the support check with its reason, the instantiation name, `--explain` with its cost estimate
// (setup/explain.hpp) and the dispatch (setup/run_scene.hpp) all read the plan. The plan holds the
// evaluators themselves, built from the scene's parameters (collide/, effects/), so the dispatch only
// visits it.
//
// A time-stepped plan is the product of five choices: the kernel, the shear effects, the thermostat
// effects, the storage precision and the collision backend. Not every product is supported:
// stepped_refusal and spread_refusal say which are not, at compile time, so the dispatch instantiates only the
// supported ones and make_plan refuses the others with the same reason. Adding a collision kernel is one
// evaluator file in collide/ and one alternative in KernelChoice, with its line in stepped_kernel and
// event_plan (run_plan.cpp; docs/developer-guide/architecture.md, "Adding things").
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>

#include "kernel/collide/bath_gaussian.hpp"
#include "kernel/collide/bath_power_law.hpp"
#include "kernel/collide/enskog_shear_shift.hpp"
#include "kernel/collide/hard_sphere.hpp"
#include "kernel/collide/maxwell_pseudomolecules.hpp"
#include "kernel/collide/variable_hard_spheres.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/effects/bgk_relaxation.hpp"
#include "kernel/effects/gaussian_thermostat.hpp"
#include "kernel/effects/lagrangian_shear.hpp"
#include "kernel/effects/white_noise.hpp"

namespace granmc {

/// A scene granmc cannot run, or cannot run the way it was asked: what() says why and what is supported.
struct PlanRefusal : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// The scalar of the stored velocities as a type (run.storage; core/species_store.hpp).
template <class Real>
struct StoredAs {
  using type = Real;
};
using StorageChoice = std::variant<StoredAs<double>, StoredAs<float>>;

/// Effects in the order they act within a phase (schemes/dsmc.hpp runs each phase's list in this order).
template <class... Effects>
struct EffectList {
  std::tuple<Effects...> effects;
  static constexpr bool empty = sizeof...(Effects) == 0;
  template <class E>
  static constexpr bool has = (std::is_same_v<E, Effects> || ...);
};

/// The collision kernels, one per physical law and dimension (collide/collision_kernel.hpp): of the event
/// scheme and the weighted particles, and of the time-stepped scheme, which also has rough particles.
using EventKernelChoice =
    std::variant<HardSphere, MaxwellPseudomolecules, VariableHardSpheres, HardDisk, MaxwellDisks, VariableHardDisks>;
using KernelChoice = std::variant<HardSphere, HardDisk, RoughHardSphere, RoughHardDisk, MaxwellPseudomolecules,
                                  VariableHardSpheres, MaxwellDisks, VariableHardDisks>;
/// Uniform shear flow: none, the inertial force (Boltzmann), or with the Enskog shift of the contact velocity.
using ShearChoice =
    std::variant<EffectList<>, EffectList<LagrangianShear>, EffectList<LagrangianShear, EnskogShearShift>>;
/// What acts on the gas after the collisions: nothing, the Gaussian thermostat (with 003's relaxation term), or
/// white noise.
using ThermostatChoice = std::variant<EffectList<>, EffectList<GaussianThermostat>,
                                      EffectList<GaussianThermostat, BgkRelaxation>, EffectList<WhiteNoise>>;

/// The collision backends of the time stepper: the batched stage of one process, or the rank waves of one
/// system spread over MPI ranks (`--spread particles`, schemes/rank_wave_backend.hpp).
struct BatchedStage {};
struct RankWaveStage {};
using BackendChoice = std::variant<BatchedStage, RankWaveStage>;

/// The relaxation term's refusal, for a kernel or a scene outside 003's case.
inline constexpr const char* relaxation_refusal =
    "the [relaxation] term other than for one species of smooth hard spheres or disks with zeta = \"cooling-rate\" "
    "(003)";

/// Why the time-stepped scheme cannot combine these choices (completing "cannot run ... yet"), or nullptr.
/// The one list of what it cannot combine: make_plan refuses with it, and the dispatch compiles only the
/// products for which it and spread_refusal are nullptr.
template <class Kernel, class Shear, class Thermostat>
constexpr const char* stepped_refusal() noexcept {
  if constexpr (rough_kernel<Kernel> && Shear::template has<EnskogShearShift>)
    return "a [shear] rate with rough particles (collision.tangential_restitution > -1) and a packing_fraction "
           "(the Enskog shift of the contact velocity)";
  else if constexpr (!Shear::empty && !std::is_same_v<Kernel, HardCore<Kernel::dimension, rough_kernel<Kernel>>>)
    return "a [shear] rate with kernel = \"maxwell\" or \"vhs\"";
  else if constexpr (!Shear::empty && Thermostat::template has<WhiteNoise>)
    return "a [shear] rate with the white-noise thermostat";
  else if constexpr (Thermostat::template has<BgkRelaxation> && !std::is_same_v<Kernel, HardCore<Kernel::dimension>>)
    return relaxation_refusal;
  else
    return nullptr;
}

/// Why the rank-wave backend cannot run these choices (completing "is not implemented for ..."), or nullptr.
template <class Kernel, class Shear, class Thermostat, class Storage, class Backend>
constexpr const char* spread_refusal() noexcept {
  if constexpr (!std::is_same_v<Backend, RankWaveStage>)
    return nullptr;
  else if constexpr (!Shear::empty)
    return "a [shear] rate";
  else if constexpr (Thermostat::template has<BgkRelaxation>)
    return "the [relaxation] term";
  else if constexpr (!std::is_same_v<Storage, StoredAs<double>>)
    return "run.storage = \"float\"";
  else
    return nullptr;
}

/// Whether the dispatch compiles this product of time-stepped choices.
template <class Kernel, class Shear, class Thermostat, class Storage, class Backend>
inline constexpr bool stepped_supported = stepped_refusal<Kernel, Shear, Thermostat>() ==
                                          nullptr&& spread_refusal<Kernel, Shear, Thermostat, Storage, Backend>() ==
                                          nullptr;

/// Time-stepped ESMC/DSMC of a gas (000 sec. 3; 001's time-stepped counterpart; 003).
struct SteppedPlan {
  KernelChoice kernel;
  ShearChoice shear;
  ThermostatChoice thermostat;
  StorageChoice storage;
  BackendChoice backend;
};

/// The time-step-free white-noise scheme (001 sec. 4).
struct EventPlan {
  EventKernelChoice kernel;
  StorageChoice storage;
  bool white_noise = false;  // beta > 0 acts by lazy Brownian updates (001 eq. 23)
};

/// Weighted particles for the tails (SWPM, schemes/swpm_scheme.hpp; 001 Remark 10): the event scheme's
/// gas, double storage.
struct WeightedPlan {
  EventKernelChoice kernel;
  bool white_noise = false;  // beta > 0 acts by lazy Brownian updates (001 eq. 23)
};

/// The bath of an intruder (002 eqs. 18, 23).
using BathChoice = std::variant<GaussianBath, PowerLawBath>;

/// The Gillespie intruder on a line (002 sec. 3.1).
struct IntruderLinePlan {
  BathChoice bath;
};

/// The Gillespie needle in the plane (002 sec. 3.2).
struct NeedlePlan {
  BathChoice bath;
};

/// The time-stepped DSMC alternative for the intruder on a line (002 sec. 4).
struct IntruderDsmcPlan {
  BathChoice bath;
};

using SchemeChoice = std::variant<SteppedPlan, EventPlan, WeightedPlan, IntruderLinePlan, NeedlePlan, IntruderDsmcPlan>;

/// How the particles of a replica are placed: in one process, or one system over all MPI ranks.
enum class Spread { replicas, particles };

struct RunPlan {
  SchemeChoice scheme;
  Spread spread = Spread::replicas;
};

/// The plan for `scene` (validated by io/scene_file). Throws PlanRefusal, with the reason and what is
/// supported, when granmc cannot run the scene, or cannot spread it over ranks with Spread::particles.
RunPlan make_plan(const Scene& scene, Spread spread = Spread::replicas);

/// Empty if make_plan(scene, spread) succeeds, otherwise its reason.
std::string plan_refusal(const Scene& scene, Spread spread = Spread::replicas);

}  // namespace granmc
