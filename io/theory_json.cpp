#include "io/theory_json.hpp"

#include <cmath>
#include <stdexcept>

#include "kernel/collide/enskog_chi.hpp"
#include "kernel/schemes/sample_times.hpp"
#include "kernel/theory/intruder.hpp"
#include "kernel/theory/mixture_viscosity.hpp"
#include "kernel/theory/rough.hpp"
#include "kernel/theory/scene_theory.hpp"
#include "kernel/theory/sonine.hpp"
#include "kernel/theory/sonine_hcs.hpp"
#include "kernel/theory/steady_shear.hpp"
#include "kernel/theory/viscosity.hpp"
#include "kernel/theory/white_noise.hpp"

namespace granmc {

nlohmann::json cooling_state_json(const theory::CoolingStatePrediction& p) {
  return {{"alpha", p.alpha},
          {"chi", p.chi},
          {"a2", p.a2},
          {"a2_model_error", p.a2_model_error},
          {"a2_second_sonine", p.a2_second_sonine},
          {"a3_second_sonine", p.a3_second_sonine},
          {"cooling_rate0", p.cooling_rate0},
          {"cooling_rate0_first_sonine", p.cooling_rate0_first_sonine},
          {"cooling_rate0_maxwell", p.cooling_rate0_maxwell},
          {"cooling_rate_model_error", p.cooling_rate_model_error},
          {"collision_frequency0", p.collision_frequency0},
          {"haff_temperature", p.temperature}};
}

namespace {

/// Haff's law and the Sonine a2 of the monodisperse hard-sphere cooling state.
void add_cooling_state(const Scene& scene, const std::vector<double>& times, nlohmann::json& j,
                       nlohmann::json& applies) {
  if (const auto hcs = theory::cooling_state(scene, times)) {
    applies.push_back(scene.run.dimension == 2
                          ? "homogeneous cooling state, monodisperse hard disks: Haff's law, Sonine "
                            "a2 (docs/methods/derivations/sonine-hcs.md, \"Hard disks\")"
                          : "homogeneous cooling state, monodisperse hard spheres: Haff's law, "
                            "Sonine a2 (docs/methods/physics.md)");
    j["times"] = times;
    j["cooling_state"] = cooling_state_json(*hcs);
  }
}

/// The Sonine a2 and a3 of the scaled cooling state (HCS, or HSS with the Gaussian thermostat).
void add_scaled_state(const Scene& scene, const std::vector<double>& /*times*/, nlohmann::json& j,
                      nlohmann::json& applies) {
  if (const auto s = theory::scaled_state(scene)) {
    applies.push_back("scaled homogeneous cooling state (HCS, or HSS with the Gaussian thermostat): Sonine a2, a3");
    j["scaled_state"] = {{"a2", s->a2},
                         {"a2_model_error", s->a2_model_error},
                         {"a2_second_sonine", s->a2_second_sonine},
                         {"a3_second_sonine", s->a3_second_sonine}};
  }
}

/// The temperature ratio and a2_i of a binary mixture.
void add_mixture(const Scene& scene, const std::vector<double>& /*times*/, nlohmann::json& j, nlohmann::json& applies) {
  const auto m = theory::mixture_state(scene);
  if (!m) return;
  applies.push_back(std::string("binary mixture") + (scene.run.dimension == 2 ? " of disks" : "") +
                    ", HCS or HSS: temperature ratio and a2_i (docs/methods/derivations/mixture-hcs.md)");
  j["mixture"] = {{"temperature_ratio_maxwell", m->temperature_ratio_maxwell},
                  {"temperature_ratio_sonine", m->first_sonine.gamma},
                  {"a2_sonine", {m->first_sonine.a2[0], m->first_sonine.a2[1]}}};
}

/// The intruder's bath and its exact T/T_B where known (002 eq. 22).
void add_intruder(const Scene& scene, const std::vector<double>& /*times*/, nlohmann::json& j,
                  nlohmann::json& applies) {
  if (scene.intruder) {
    const IntruderConfig& in = *scene.intruder;
    // 002 eq. (22), the Gaussian-bath result, also as the reference line of 002 Fig. 4 for other baths.
    j["intruder"] = {{"bath", in.bath == BathKind::gaussian ? "gaussian" : "power-law"},
                     {"bath_temperature", theory::bath_temperature(in)},
                     {"temperature_ratio_gaussian_bath", theory::gaussian_bath_temperature_ratio(in)}};
    if (const auto exact = theory::intruder_temperature_ratio(*scene.intruder)) {
      applies.push_back("1D intruder: exact stationary T/T_B (002 eq. 22, or alpha for the power law with M = alpha)");
      j["intruder"]["temperature_ratio_exact"] = *exact;
    }
  }
}

/// The white-noise a2 of hard cores, first Sonine (van Noije and Ernst), and the linear second-Sonine a2 and
/// a3 (theory/sonine_hcs.hpp), whose shift from the first is the first's model error.
void add_white_noise_sonine(double alpha, int d, nlohmann::json& w) {
  const theory::SecondSonine second = theory::second_sonine_linear(alpha, theory::SonineState::white_noise, d);
  w["a2"] = theory::white_noise_a2(alpha, d);
  w["a2_model_error"] = theory::white_noise_a2_model_error(alpha, d);
  w["a2_second_sonine"] = second.a2;
  w["a3_second_sonine"] = second.a3;
}

/// The kernel form of 001, spheres or disks: Maxwell's exact temperature relaxation, the white-noise steady
/// state (Maxwell's exact a2, hard cores' first- and second-Sonine a2) and tails; the white-noise steady state
/// of hard spheres or disks in 000's form (Sonine a2, temperature, tails).
void add_kernel_form(const Scene& scene, const std::vector<double>& times, nlohmann::json& j, nlohmann::json& applies) {
  const int d = scene.run.dimension;
  if (scene.species.size() == 1 && scene.collision.rate > 0.0) {  // the kernel form of 001
    const double alpha = scene.collision.restitution[0][0], rate = scene.collision.rate;
    const double beta = scene.thermostat.kind == ThermostatKind::white_noise ? scene.thermostat.beta : 0.0;
    const double lambda = scene.collision.lambda;
    j["times"] = times;
    if (lambda == 0.0) {
      applies.push_back(
          "Maxwell pseudomolecules: exact temperature relaxation (001 eqs. 16-17; |S^(d-1)| rate (1 - alpha^2) / 4 "
          "in d dimensions), and (1 - 1/n) times it for the n-particle system (docs/methods/physics.md)");
      const double n = static_cast<double>(scene.species[0].particles);
      std::vector<double> exact, particles, uncentred;
      for (double t : times) {
        exact.push_back(theory::maxwell_temperature(t, scene.initial_temperature, beta, rate, alpha, d));
        particles.push_back(
            theory::maxwell_temperature_particles(t, scene.initial_temperature, beta, rate, alpha, n, d));
        uncentred.push_back(theory::maxwell_temperature_uncentred(
            t, scene.initial_temperature, beta, rate, alpha, n, scene.species[0].mass, scene.initial_zero_momentum, d));
      }
      j["maxwell_relaxation"] = {{"rate", theory::maxwell_relaxation_rate(rate, alpha, d)},
                                 {"temperature", exact},
                                 {"temperature_particles", particles},
                                 {"temperature_uncentred_particles", uncentred}};
    }
    if (beta > 0.0) {
      applies.push_back(
          "white-noise heated steady state: temperature from the energy balance (001 eq. 15), "
          "tail exponent b = 1 + lambda/2 (001 eqs. 19-21), a2 exact for Maxwell pseudomolecules, first-Sonine "
          "for VHS, and first- and second-Sonine for hard cores");
      nlohmann::json w = {
          {"tail_exponent", theory::tail_exponent(lambda)},
          {"steady_temperature_maxwellian", theory::white_noise_steady_temperature(lambda, rate, alpha, beta, 0.0, d)}};
      if (lambda == 0.0) w["a2"] = theory::maxwell_white_noise_a2(alpha, d);
      if (lambda == 1.0) add_white_noise_sonine(alpha, d, w);
      if (lambda > 0.0 && lambda < 1.0) {  // VHS: first and second Sonine of the isotropic kernels
        const theory::SecondSonine second = theory::isotropic_white_noise_second_sonine(alpha, lambda, d);
        w["a2"] = theory::isotropic_white_noise_a2(alpha, lambda, d);
        w["a2_model_error"] = std::fabs(second.a2 - w["a2"].get<double>());
        w["a2_second_sonine"] = second.a2;
        w["a3_second_sonine"] = second.a3;
      }
      if (lambda > 0.0)
        w["steady_temperature_first_sonine"] =
            theory::white_noise_steady_temperature(lambda, rate, alpha, beta, w["a2"].get<double>(), d);
      j["white_noise"] = w;
    }
    if (scene.thermostat.kind == ThermostatKind::none && lambda > 0.0) {
      applies.push_back(
          "freely cooling state: tail exponent b = lambda of f ~ exp(-a c^b) in the scaled speed (van Noije and "
          "Ernst 1998 for hard spheres)");
      j["free_cooling"] = {{"tail_exponent", theory::free_cooling_tail_exponent(lambda)}};
    }
  } else if (scene.thermostat.kind == ThermostatKind::white_noise && scene.species.size() == 1 &&
             scene.collision.kernel == CollisionKernel::hard_sphere) {
    applies.push_back(std::string("white-noise heated steady state, monodisperse ") +
                      (d == 2 ? "hard disks" : "hard spheres") +
                      ": first- and second-Sonine a2 (and a3), steady temperature from the energy balance, "
                      "tail exponent b = 3/2 of "
                      "f ~ exp(-a c^b) (van Noije and Ernst 1998, any d)");
    const SpeciesConfig& sp = scene.species[0];
    const double alpha = scene.collision.restitution[0][0], phi = scene.collision.packing_fraction;
    const double chi = phi > 0.0 ? (d == 2 ? enskog_chi_disks(phi) : enskog_chi(phi, {1.0}, {sp.diameter}, 0, 0)) : 1.0;
    const double a2 = theory::white_noise_a2(alpha, d), beta = scene.thermostat.beta;
    auto temperature = [&](double a) {
      return theory::white_noise_temperature(alpha, sp.density, sp.diameter, sp.mass, chi, beta, a, d);
    };
    nlohmann::json w = {{"steady_temperature_maxwellian", temperature(0.0)},
                        {"steady_temperature_first_sonine", temperature(a2)},
                        {"tail_exponent", 1.5}};
    add_white_noise_sonine(alpha, d, w);
    j["white_noise"] = w;
  }
}

/// The Enskog pair correlation at contact chi_ij (000 eq. 3; disks collide/enskog_chi.hpp).
void add_enskog_chi(const Scene& scene, const std::vector<double>& /*times*/, nlohmann::json& j,
                    nlohmann::json& applies) {
  const double phi = scene.collision.packing_fraction;
  if (!(phi > 0.0) || scene.species.empty()) return;
  if (scene.species.size() == 1 && scene.run.dimension == 2) {
    applies.push_back("Enskog pair correlation at contact chi of hard disks, Henderson (Mol. Phys. 30 (1975) 971)");
    j["henderson_chi"] = enskog_chi_disks(phi);
    return;
  }
  const double n = total_density(scene);
  std::vector<double> x, sigma;
  for (const auto& s : scene.species) {
    x.push_back(s.density / n);
    sigma.push_back(s.diameter);
  }
  const bool disks = scene.run.dimension == 2;
  nlohmann::json chi = nlohmann::json::array();
  for (std::size_t a = 0; a < x.size(); ++a) {
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t b = 0; b < x.size(); ++b) {
      const int i = static_cast<int>(a), k = static_cast<int>(b);
      row.push_back(disks ? enskog_chi_disks(phi, x, sigma, i, k) : enskog_chi(phi, x, sigma, i, k));
    }
    chi.push_back(row);
  }
  if (disks) {
    applies.push_back("Enskog pair correlation at contact chi_ij of a hard-disk mixture (Jenkins and Mancini 1987)");
    j["jenkins_mancini_chi"] = chi;
  } else {
    applies.push_back("Enskog pair correlation at contact chi_ij, Carnahan-Starling (000 eq. 3)");
    j["carnahan_starling_chi"] = chi;
  }
}

/// The first-Sonine Navier-Stokes shear viscosity of a uniform shear flow of hard spheres or disks (one species;
/// mixtures of spheres), dilute or Enskog.
void add_viscosity(const Scene& scene, const std::vector<double>& /*times*/, nlohmann::json& j,
                   nlohmann::json& applies) {
  const bool hard_cores = scene.shear_rate != 0.0 && scene.collision.kernel == CollisionKernel::hard_sphere &&
                          !scene.species.empty() && !rough(scene.collision);
  const int d = scene.run.dimension;
  if (hard_cores) {
    // The reference state whose Navier-Stokes viscosity the run measures: the HSS of 000 (Gaussian thermostat
    // compensating the cooling), or the HCS with 003's relaxation term (theory/viscosity.hpp).
    const bool hcs = scene.relaxation;
    const auto reference = hcs ? theory::ViscosityReference::cooling : theory::ViscosityReference::gaussian_thermostat;
    const double phi = scene.collision.packing_fraction, alpha = scene.collision.restitution[0][0];
    nlohmann::json v = {{"reference", hcs ? "cooling state (003)" : "Gaussian-thermostat steady state (000)"}};
    if (scene.species.size() == 1) {
      auto block = [&](theory::ViscosityReference r) {
        const theory::ShearViscosity s = theory::shear_viscosity(alpha, phi, r, d);
        return nlohmann::json{{"eta_over_eta0", s.total},
                              {"eta_kinetic_over_eta0", s.kinetic},
                              {"eta_star", theory::reduced_viscosity_one_species(s.total, d)},
                              {"eta_kinetic_star", theory::reduced_viscosity_one_species(s.kinetic, d)}};
      };
      v["first_sonine"] = block(reference);
      if (hcs)  // the f^(0) of the relaxation term: first-Sonine a2 by default; the second-Sonine HCS for scale
        v["relaxation_f0"] = {{"a2", scene.relaxation_a2.value_or(theory::hcs_a2(alpha, d))},
                              {"hcs_a2_first_sonine", theory::hcs_a2(alpha, d)},
                              {"hcs_a2_second_sonine", theory::hcs_second_sonine(alpha, d).a2}};
      v["first_sonine_cooling_state"] = block(theory::ViscosityReference::cooling);
      v["first_sonine_gaussian_thermostat"] = block(theory::ViscosityReference::gaussian_thermostat);
      // The elastic dilute gas: the converged Sonine series gives 1.016 eta0 for spheres (003: the first Sonine
      // value is 1.6 % low), 1.022 eta0 for disks (Garcia-Rojo, Luding and Brey, PRE 74, 061305 (2006)).
      v["elastic_dilute_eta_over_eta0"] = d == 2 ? 1.022 : 1.016;
    } else if (const auto& r = scene.collision.restitution; d == 3 && r[0][1] == alpha && r[1][1] == alpha) {
      const SpeciesConfig &a = scene.species[0], &b = scene.species[1];
      const theory::MixtureViscosityRatios m = theory::mixture_viscosity_from_ratios(
          a.mass / b.mass, a.diameter / b.diameter, a.density / b.density, alpha, phi, reference);
      v["first_sonine"] = {
          {"eta_over_eta_elastic", m.over_elastic}, {"eta_kinetic_star", m.kinetic_star}, {"eta_star", m.star}};
    }
    if (d == 2 && !v.contains("first_sonine")) return;  // disk mixtures: no viscosity theory
    applies.push_back(d == 2 ? "uniform shear flow, hard disks: first-Sonine Navier-Stokes shear viscosity in d = 2, "
                               "dilute or Enskog (docs/methods/derivations/viscosity.md, \"Disks\")"
                             : "uniform shear flow, hard spheres: first-Sonine Navier-Stokes shear viscosity (003; "
                               "mixtures docs/methods/derivations/viscosity.md)");
    j["viscosity"] = v;
  }
}

/// The steady uniform shear flow without a thermostat (000 sec. 5): a dilute inelastic gas of one species of
/// hard spheres, Grad's solution (theory/steady_shear.hpp).
void add_steady_shear(const Scene& scene, const std::vector<double>& /*times*/, nlohmann::json& j,
                      nlohmann::json& applies) {
  if (scene.run.method != Method::dsmc || scene.shear_rate == 0.0 || scene.species.size() != 1 ||
      scene.collision.kernel != CollisionKernel::hard_sphere || scene.collision.packing_fraction > 0.0 ||
      scene.thermostat.kind != ThermostatKind::none || scene.relaxation || scene.collision.restitution[0][0] >= 1.0)
    return;
  const SpeciesConfig& sp = scene.species[0];
  const theory::SteadyShearFlow s = theory::steady_shear_grad(scene.collision.restitution[0][0], scene.run.dimension);
  j["steady_shear"] = {{"approximation", "Grad 13-moment (Santos, Garzo and Dufty, PRE 69, 061303, 2004)"},
                       {"reduced_shear_rate", s.shear_rate_star},
                       {"shear_rate_over_nu0", s.shear_rate_nu0},
                       {"eta_star", s.eta_star},
                       {"eta_over_eta0", s.eta_over_eta0},
                       {"pressure_xx_over_p", s.pressure_xx},
                       {"pressure_yy_over_p", s.pressure_yy},
                       {"pressure_xy_over_p", s.pressure_xy},
                       {"temperature", theory::steady_shear_temperature(s, std::fabs(scene.shear_rate), sp.density,
                                                                        sp.diameter, sp.mass)}};
  applies.push_back(scene.run.dimension == 2
                        ? "steady uniform shear flow without thermostat, dilute hard disks: Grad's solution in d = 2"
                        : "steady uniform shear flow without thermostat, dilute hard spheres: Grad's solution (000 "
                          "sec. 5)");
}

/// Rough hard spheres or disks, one or two species: theta = T_r / T and the cooling rate of the cooling state,
/// or theta under white noise; for two species theta of each and T_1 / T_2 (docs/methods/derivations/rough-hcs.md).
void add_rough(const Scene& scene, const std::vector<double>& /*times*/, nlohmann::json& j, nlohmann::json& applies) {
  if (scene.collision.kernel != CollisionKernel::hard_sphere || scene.shear_rate != 0.0) return;
  const CollisionConfig& c = scene.collision;
  const int d = scene.run.dimension;
  const double alpha = c.restitution[0][0], beta = c.tangential_restitution, kappa = c.reduced_inertia;
  const bool mixture = scene.species.size() == 2;
  nlohmann::json r = {{"beta", beta}, {"kappa", kappa}};
  if (!mixture) {
    r["alpha"] = alpha;
    r["tangential_factor"] = theory::rough_tangential_factor(beta, kappa);
  }
  const std::string particles = std::string(mixture ? "binary mixture of " : "monodisperse ") +
                                (d == 2 ? "rough hard disks" : "rough hard spheres");
  const theory::RoughMixture m{mixture ? theory::mixture_parameters(scene) : theory::MixtureParameters{}, beta, kappa};
  auto species_values = [](const theory::RoughMixtureState& s) {
    return nlohmann::json::array({s.theta[0], s.theta[1]});
  };
  if (scene.thermostat.kind != ThermostatKind::white_noise) {
    // The Gaussian thermostat scales translation and spins alike, so its steady state is the cooling state's
    // in scaled variables (docs/methods/physics.md, "Rough particles").
    if (mixture) {
      try {
        const theory::RoughMixtureState s = theory::rough_mixture_hcs(m);
        r["theta_hcs"] = species_values(s);
        r["temperature_ratio_hcs"] = s.temperature_ratio;
      } catch (const std::runtime_error& e) {  // near beta = -1 (theory/rough.hpp)
        r["note"] = e.what();
      }
    } else {
      const double theta = theory::rough_hcs_theta(alpha, beta, kappa, d);
      r["theta_hcs"] = theta;
      r["cooling_rate_over_nu_hcs"] = theory::rough_cooling_rates(alpha, beta, kappa, theta, d).translation;
    }
    const std::string what = mixture
                                 ? "T_rot / T_tr of each species and T_1 / T_2 (docs/methods/derivations/rough-hcs.md)"
                                 : "T_rot / T_tr and the cooling rate (Huthmann and Zippelius 1997; "
                                   "docs/methods/derivations/rough-hcs.md)";
    applies.push_back("homogeneous cooling state (or its scaled state under the Gaussian thermostat), " + particles +
                      ", Maxwellian approximation: " + what);
  } else {
    const double share = scene.thermostat.rotational_share;
    r["rotational_share"] = share;
    if (mixture) {
      try {
        const theory::RoughMixtureState s = theory::rough_mixture_white_noise(m, share);
        r["theta_white_noise"] = species_values(s);
        r["temperature_ratio_white_noise"] = s.temperature_ratio;
      } catch (const std::runtime_error& e) {
        r["note"] = e.what();
      }
    } else {
      r["theta_white_noise"] = theory::rough_split_noise_theta(alpha, beta, kappa, share, d);
    }
    applies.push_back(
        std::string(share > 0.0 ? "white noise split between translation and rotation" : "white noise on translation") +
        ", " + particles + ", Maxwellian approximation: the steady T_rot / T_tr" +
        (mixture ? " of each species and T_1 / T_2" : "") + " (docs/methods/derivations/rough-hcs.md)");
  }
  j["rough"] = r;
}

}  // namespace

nlohmann::json scene_theory_json(const Scene& scene) {
  nlohmann::json j;
  j["scene"] = scene.source_path;
  if (!scene.intruder) j["dimension"] = scene.run.dimension;
  nlohmann::json applies = nlohmann::json::array();
  const std::vector<double> times = sample_times(scene.run);
  using Add = void (*)(const Scene&, const std::vector<double>&, nlohmann::json&, nlohmann::json&);
  // Rough particles have their own theory; the smooth gas's predictions do not apply to them.
  const std::vector<Add> smooth = {add_cooling_state, add_scaled_state, add_mixture,   add_intruder,
                                   add_kernel_form,   add_enskog_chi,   add_viscosity, add_steady_shear};
  const std::vector<Add> rough_particles = {add_rough, add_enskog_chi};
  for (Add add : !scene.intruder && rough(scene.collision) ? rough_particles : smooth) add(scene, times, j, applies);
  j["applies"] = applies;
  return j;
}

}  // namespace granmc
