#include "io/summary_json.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "granmc/version.hpp"
#include "io/theory_json.hpp"

namespace granmc {
namespace {

/// A number, or null when it is not finite (JSON has no NaN or infinity).
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json numbers(const std::vector<double>& xs) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : xs) a.push_back(number(x));
  return a;
}

nlohmann::json mean_ci(const MeanCISeries& s) { return {{"mean", numbers(s.mean)}, {"ci", numbers(s.ci)}}; }
nlohmann::json mean_ci(const MeanCI& m) { return {{"mean", number(m.mean)}, {"ci", number(m.ci)}}; }

}  // namespace

nlohmann::json summary_json(const Scene& scene, const RunResult& result, const RunReport& report) {
  nlohmann::json j;
  j["scene"] = scene.source_path;
  j["seed"] = scene.run.seed;
  j["replicas"] = result.replicas.size();
  j["method"] = report.method;
  j["wall_seconds"] = number(report.wall_seconds);
  j["collisions"] = report.collisions;
  j["candidates"] = report.candidates;
  j["majorant_updates"] = report.majorant_updates;
  if (report.method == "event") j["majorant_violations"] = report.majorant_violations;
  j["rescales"] = report.rescales;
  if (report.energy_residual) j["energy_residual_max"] = number(*report.energy_residual);
  j["threads"] = result.threads;
  j["ranks"] = result.ranks;
  j["version"] = granmc::version;
  j["times"] = numbers(result.times);
  j["temperature"] = mean_ci(report.temperature);
  j["log_temperature"] = mean_ci(report.log_temperature);
  if (report.momentum_relative.size() > 0) j["momentum_relative"] = mean_ci(report.momentum_relative);
  if (report.intruder) {
    const IntruderReport& in = *report.intruder;
    j["intruder"] = {{"temperature_ratio", mean_ci(in.temperature_ratio)},
                     {"bath_temperature", number(in.bath_temperature)},
                     {"events", in.events},
                     {"speed_shell_edges", numbers(in.speed_shell_edges)},
                     {"speed_distribution", mean_ci(in.speed_distribution)}};
    if (in.temperature_ratio_exact) j["intruder"]["temperature_ratio_exact"] = number(*in.temperature_ratio_exact);
    if (in.needle) {
      const NeedleReport& n = *in.needle;
      j["intruder"]["R"] = mean_ci(n.correlation);
      j["intruder"]["rotational_temperature_ratio"] = mean_ci(n.rotational_temperature_ratio);
      j["intruder"]["angular_shell_edges"] = numbers(n.angular_shell_edges);
      j["intruder"]["angular_distribution"] = mean_ci(n.angular_distribution);
      j["intruder"]["newton_iterations"] = n.newton_iterations;
      j["intruder"]["bisection_fallbacks"] = n.bisection_fallbacks;
    }
  }
  nlohmann::json species = nlohmann::json::array();
  for (const SpeciesReport& sp : report.species)
    species.push_back({{"name", sp.name},
                       {"temperature", mean_ci(sp.temperature)},
                       {"a2", mean_ci(sp.a2)},
                       {"a2_last_half", mean_ci(sp.a2_last_half)},
                       {"a3", mean_ci(sp.a3)},
                       {"a3_last_half", mean_ci(sp.a3_last_half)},
                       {"speed_distribution", mean_ci(sp.speed_distribution)}});
  j["species"] = std::move(species);
  j["speed_shell_edges"] = numbers(report.speed_shell_edges);
  if (report.temperature_ratio) j["temperature_ratio"] = mean_ci(*report.temperature_ratio);
  if (report.viscosity) {
    const ViscosityReport& v = *report.viscosity;
    nlohmann::json& out = j["viscosity"];
    out = {{"eta", mean_ci(v.eta_scene_units)},
           {"eta_kinetic", mean_ci(v.eta_kinetic_scene_units)},
           {"eta_star", mean_ci(v.eta)},
           {"eta_kinetic_star", mean_ci(v.eta_kinetic)},
           {"window_start", number(v.window_start)},
           {"reduced_shear_rate_range", numbers({v.reduced_shear_rate_min, v.reduced_shear_rate_max})},
           {"drift", mean_ci(v.drift)},
           {"steady", v.steady},
           {"reduced_shear_rate", mean_ci(v.reduced_shear_rate)},
           {"pressure_xy", mean_ci(v.pressure_xy)},
           {"eta_star_series", mean_ci(v.eta_star)}};
    if (v.eta_over_eta0) {
      out["eta_over_eta0"] = mean_ci(*v.eta_over_eta0);
      out["eta_kinetic_over_eta0"] = mean_ci(*v.eta_kinetic_over_eta0);
    }
  }
  if (report.theory) {
    j["theory"] = cooling_state_json(*report.theory);
  }
  return j;
}

void write_summary(const std::string& path, const nlohmann::json& summary) {
  const std::string temporary = path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  auto fail = [&](const std::string& what) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write summary '" + path + "': " + what + " (" + reason + ")");
  };
  {
    std::ofstream out(temporary, std::ios::out | std::ios::trunc);
    if (!out) fail("cannot create '" + temporary + "'");
    // error_handler::replace: an invalid UTF-8 byte in a name (e.g. the scene path) becomes U+FFFD, not a throw.
    out << summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
    out.close();
    if (!out) fail("cannot write '" + temporary + "'");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) fail("cannot rename '" + temporary + "' to it");
}

}  // namespace granmc
