#include "io/hdf5_output.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <stdexcept>
#include <vector>

#include "granmc/version.hpp"

namespace granmc {
namespace {

constexpr const char* units_text =
    "k_B = 1; temperature in energy units; time in the scene's time unit; velocities in sqrt(energy/mass)";

/// Thrown inside this file on an HDF5 failure; write_hdf5 turns it into std::runtime_error with the path.
struct Hdf5Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The innermost message of HDF5's error stack (e.g. "unable to open file: ... No such file or directory").
std::string hdf5_detail() {
  std::string detail;
  auto take_first = [](unsigned n, const H5E_error2_t* err, void* data) -> herr_t {
    if (n == 0 && err->desc != nullptr) *static_cast<std::string*>(data) = err->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, take_first, &detail);
  return detail;
}

[[noreturn]] void fail(const std::string& what) {
  const std::string detail = hdf5_detail();
  throw Hdf5Failure(detail.empty() ? what : what + " (" + detail + ")");
}

hid_t check(hid_t id, const std::string& what) {
  if (id < 0) fail(what);
  return id;
}

void check_status(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

/// Owns one HDF5 identifier and closes it with the matching H5?close.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) noexcept : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  [[nodiscard]] hid_t get() const noexcept { return id_; }
  /// Closes now and reports a failure (a file's close is where buffered writes can fail).
  void close(const std::string& what) {
    const hid_t id = id_;
    id_ = -1;
    check_status(close_(id), what);
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// Silences HDF5's own error printing for the lifetime of the object and restores it afterwards.
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// Writes objects into one open file, by absolute path, creating intermediate groups as needed.
class Writer {
 public:
  explicit Writer(hid_t file)
      : file_(file), lcpl_(check(H5Pcreate(H5P_LINK_CREATE), "cannot create a property list"), H5Pclose) {
    check_status(H5Pset_create_intermediate_group(lcpl_.get(), 1), "cannot set intermediate group creation");
  }

  void group(const std::string& path, const std::string& description) {
    Handle g(check(H5Gcreate2(file_, path.c_str(), lcpl_.get(), H5P_DEFAULT, H5P_DEFAULT),
                   "cannot create group '" + path + "'"),
             H5Gclose);
    string_attribute(g.get(), path, "description", description);
  }

  /// The one dataset writer: `data` holds prod(dims) values of `memory_type` in row-major order.
  void dataset(const std::string& path, hid_t memory_type, hid_t file_type, const void* data,
               const std::vector<hsize_t>& dims, const std::string& description) {
    Handle space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                       "cannot create dataspace for '" + path + "'"),
                 H5Sclose);
    Handle set(check(H5Dcreate2(file_, path.c_str(), file_type, space.get(), lcpl_.get(), H5P_DEFAULT, H5P_DEFAULT),
                     "cannot create dataset '" + path + "'"),
               H5Dclose);
    bool empty = false;
    for (hsize_t d : dims) empty = empty || d == 0;
    if (!empty)
      check_status(H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
                   "cannot write dataset '" + path + "'");
    string_attribute(set.get(), path, "description", description);
  }

  void doubles(const std::string& path, std::span<const double> values, const std::vector<hsize_t>& dims,
               const std::string& description) {
    dataset(path, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, values.data(), dims, description);
  }
  void doubles(const std::string& path, std::span<const double> values, const std::string& description) {
    doubles(path, values, {values.size()}, description);
  }
  void uint64s(const std::string& path, std::span<const std::uint64_t> values, const std::vector<hsize_t>& dims,
               const std::string& description) {
    dataset(path, H5T_NATIVE_UINT64, H5T_STD_U64LE, values.data(), dims, description);
  }
  void uint64s(const std::string& path, std::span<const std::uint64_t> values, const std::string& description) {
    uint64s(path, values, {values.size()}, description);
  }

  // Attributes of the object at `path` (a group or dataset; "/" is the root).
  void attribute(const std::string& path, const char* name, const std::string& value) {
    Handle object = open(path);
    string_attribute(object.get(), path, name, value);
  }
  void attribute(const std::string& path, const char* name, double value) {
    scalar_attribute(path, name, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE, &value);
  }
  void attribute(const std::string& path, const char* name, std::int64_t value) {
    scalar_attribute(path, name, H5T_NATIVE_INT64, H5T_STD_I64LE, &value);
  }
  void attribute(const std::string& path, const char* name, std::uint64_t value) {
    scalar_attribute(path, name, H5T_NATIVE_UINT64, H5T_STD_U64LE, &value);
  }

 private:
  Handle open(const std::string& path) {
    return Handle(check(H5Oopen(file_, path.c_str(), H5P_DEFAULT), "cannot open '" + path + "'"), H5Oclose);
  }

  void scalar_attribute(const std::string& path, const char* name, hid_t memory_type, hid_t file_type,
                        const void* value) {
    Handle object = open(path);
    const std::string what = "attribute '" + std::string(name) + "' of '" + path + "'";
    Handle space(check(H5Screate(H5S_SCALAR), "cannot create dataspace for " + what), H5Sclose);
    Handle attr(check(H5Acreate2(object.get(), name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                      "cannot create " + what),
                H5Aclose);
    check_status(H5Awrite(attr.get(), memory_type, value), "cannot write " + what);
  }

  /// A variable-length UTF-8 string attribute (h5py reads it as str).
  static void string_attribute(hid_t object, const std::string& path, const char* name, const std::string& value) {
    const std::string what = "attribute '" + std::string(name) + "' of '" + path + "'";
    Handle type(check(H5Tcopy(H5T_C_S1), "cannot create string type for " + what), H5Tclose);
    check_status(H5Tset_size(type.get(), H5T_VARIABLE), "cannot size string type for " + what);
    check_status(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot set UTF-8 for " + what);
    Handle space(check(H5Screate(H5S_SCALAR), "cannot create dataspace for " + what), H5Sclose);
    Handle attr(
        check(H5Acreate2(object, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), "cannot create " + what),
        H5Aclose);
    const char* text = value.c_str();
    check_status(H5Awrite(attr.get(), type.get(), &text), "cannot write " + what);
  }

  hid_t file_;
  Handle lcpl_;
};

/// Row r of the result is the replica r series that `pick` selects: an [R x S] row-major array.
template <class Pick>
std::vector<double> replica_rows(const RunResult& result, Pick pick) {
  std::vector<double> rows;
  for (const ReplicaSeries& s : result.replicas) {
    const std::vector<double>& v = pick(s);
    rows.insert(rows.end(), v.begin(), v.end());
  }
  return rows;
}

/// A group name for a species: HDF5 path separators are replaced, the scene name is kept as an attribute.
std::string species_group_name(const std::string& name, std::size_t index) {
  if (name.empty() || name == "." || name == "..") return "species_" + std::to_string(index);
  std::string g = name;
  for (char& c : g)
    if (c == '/') c = '_';
  return g;
}

/// /<path>/{mean,ci} [S] and /<path>/replicas [R x S] of the quantity `what`, measured in `units`.
void write_series(Writer& w, const std::string& path, const MeanCISeries& stats, const std::vector<double>& replicas,
                  std::size_t replica_count, const std::string& what, const std::string& units) {
  const hsize_t samples = stats.mean.size();
  w.group(path, what + " at the sample times");
  w.doubles(path + "/mean", stats.mean, "replica mean of " + what + " at each sample time (" + units + ")");
  w.doubles(path + "/ci", stats.ci,
            "confidence half-width of the replica mean of " + what + ": lambda_p sqrt(Var/R), lambda_p = 3.2 " +
                "(001 eq. 31) (" + units + ")");
  w.doubles(path + "/replicas", replicas, {replica_count, samples},
            what + " of each replica (rows) at each sample time (columns) (" + units + ")");
}

/// A shear run: /viscosity with the window results as attributes and the reduced series; the full reduced
/// pressure tensors per replica as [R x S x 6] (xx, yy, zz, xy, xz, yz).
void write_viscosity(Writer& w, const RunResult& result, const ViscosityReport& v) {
  const std::size_t replicas = result.replicas.size(), samples = result.times.size();
  w.group("/viscosity", "uniform shear flow (000 secs. 2-3): eta* = nu eta / (n T) = -(P_xy / n T) / a*, averaged "
                        "over the window t >= window_start; attributes *_mean, *_ci (lambda_p = 3.2)");
  auto stat = [&](const std::string& name, const MeanCI& m) {
    w.attribute("/viscosity", (name + "_mean").c_str(), m.mean);
    w.attribute("/viscosity", (name + "_ci").c_str(), m.ci);
  };
  stat("eta_star", v.eta);
  stat("eta_kinetic_star", v.eta_kinetic);
  stat("eta", v.eta_scene_units);
  stat("eta_kinetic", v.eta_kinetic_scene_units);
  if (v.eta_over_eta0) {
    stat("eta_over_eta0", *v.eta_over_eta0);
    stat("eta_kinetic_over_eta0", *v.eta_kinetic_over_eta0);
  }
  stat("drift", v.drift);
  w.attribute("/viscosity", "steady", static_cast<std::int64_t>(v.steady));
  w.attribute("/viscosity", "window_start", v.window_start);
  auto series = [&](const std::string& name, const MeanCISeries& m, const std::string& what) {
    w.doubles("/viscosity/" + name + "_mean", m.mean, "replica mean of " + what + " at each sample time");
    w.doubles("/viscosity/" + name + "_ci", m.ci, "confidence half-width of " + what);
  };
  series("reduced_shear_rate", v.reduced_shear_rate, "a* = a / nu, nu = sqrt(pi) n sigma_12^2 v0");
  series("pressure_xy", v.pressure_xy, "P_xy / (n T), kinetic + collisional");
  series("pressure_kinetic_xy", v.pressure_kinetic_xy, "P^k_xy / (n T) (000 eq. 17)");
  series("eta_star", v.eta_star, "eta* = -P_xy / (n T a*)");
  series("eta_kinetic_star", v.eta_kinetic_star, "eta^k* = -P^k_xy / (n T a*)");
  for (const char* part : {"kinetic", "collisional"}) {
    std::vector<double> rows;
    for (const ReplicaSeries& s : result.replicas)
      for (const SymTensor& t : part[0] == 'k' ? s.pressure_kinetic : s.pressure_collisional)
        rows.insert(rows.end(), {t.xx, t.yy, t.zz, t.xy, t.xz, t.yz});
    w.doubles(std::string("/viscosity/pressure_") + part, rows, {replicas, samples, 6},
              std::string(part) + " pressure tensor over n T of each replica at each sample (xx, yy, zz, xy, xz, yz); " +
                  (part[0] == 'k' ? "at the sample (000 eq. 17)" : "averaged since the previous sample (000 eq. 18)"));
  }
}

void write_intruder(Writer& w, const RunResult& result, const IntruderReport& in) {
  const std::size_t replicas = result.replicas.size();
  w.group("/intruder", "Gillespie intruder (002): attributes temperature_ratio_mean, temperature_ratio_ci (T/T_B, "
                       "T = M <v1^2> per degree of freedom, over the last half of the samples; the needle's "
                       "translational temperature; for the needle also R_*, rotational_temperature_ratio_*, "
                       "newton_iterations, bisection_fallbacks), bath_temperature, events, and "
                       "temperature_ratio_exact where it is known (002 eq. 22; power law with M = alpha)");
  w.attribute("/intruder", "temperature_ratio_mean", in.temperature_ratio.mean);
  w.attribute("/intruder", "temperature_ratio_ci", in.temperature_ratio.ci);
  w.attribute("/intruder", "bath_temperature", in.bath_temperature);
  w.attribute("/intruder", "events", static_cast<std::int64_t>(in.events));
  if (in.temperature_ratio_exact) w.attribute("/intruder", "temperature_ratio_exact", *in.temperature_ratio_exact);
  w.doubles("/intruder/velocity",
            replica_rows(result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->velocity; }),
            {replicas, result.times.size()}, "intruder velocity v1 of each replica (rows) at each sample (columns)");
  w.doubles("/intruder/speed_shell_edges", in.speed_shell_edges, "edges of the |v1| shells (velocity units)");
  w.doubles("/intruder/speed_distribution_mean", in.speed_distribution.mean,
            "replica mean of the density of |v1| per unit speed over the last half of the samples");
  w.doubles("/intruder/speed_distribution_ci", in.speed_distribution.ci,
            "confidence half-width of that mean, lambda_p = 3.2 (001 eq. 31)");
  w.doubles("/intruder/speed_counts",
            replica_rows(result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->speed_counts; }),
            {replicas, in.speed_distribution.mean.size()},
            "samples of |v1| counted in each shell (columns), per replica (rows)");
  if (in.needle) {
    const NeedleReport& n = *in.needle;
    w.attribute("/intruder", "R_mean", n.correlation.mean);
    w.attribute("/intruder", "R_ci", n.correlation.ci);
    w.attribute("/intruder", "rotational_temperature_ratio_mean", n.rotational_temperature_ratio.mean);
    w.attribute("/intruder", "rotational_temperature_ratio_ci", n.rotational_temperature_ratio.ci);
    w.attribute("/intruder", "newton_iterations", static_cast<std::int64_t>(n.newton_iterations));
    w.attribute("/intruder", "bisection_fallbacks", static_cast<std::int64_t>(n.bisection_fallbacks));
    w.doubles("/intruder/velocity_y",
              replica_rows(result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->velocity_y; }),
              {replicas, result.times.size()}, "needle: v1_y of each replica (rows) at each sample (columns); "
                                               "/intruder/velocity holds v1_x");
    w.doubles("/intruder/angular_velocity",
              replica_rows(result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->angular_velocity; }),
              {replicas, result.times.size()}, "needle: angular velocity omega (1/time) of each replica at each sample");
    w.doubles("/intruder/angular_shell_edges", n.angular_shell_edges, "edges of the |omega| shells (1/time)");
    w.doubles("/intruder/angular_distribution_mean", n.angular_distribution.mean,
              "replica mean of the density of |omega| per unit angular speed over the last half of the samples");
    w.doubles("/intruder/angular_distribution_ci", n.angular_distribution.ci,
              "confidence half-width of that mean, lambda_p = 3.2 (001 eq. 31)");
  }
}

void write_contents(hid_t file, const Scene& scene, const RunResult& result, const RunReport& report) {
  Writer w(file);
  const std::size_t replicas = result.replicas.size();
  const hsize_t samples = result.times.size();

  w.attribute("/", "scene", scene.source_text);
  w.attribute("/", "scene_path", scene.source_path);
  w.attribute("/", "seed", static_cast<std::uint64_t>(scene.run.seed));
  w.attribute("/", "replicas", static_cast<std::int64_t>(replicas));
  w.attribute("/", "method", report.method);
  w.attribute("/", "version", std::string(granmc::version));
  w.attribute("/", "units", std::string(units_text));
  w.attribute("/", "wall_seconds", report.wall_seconds);
  w.attribute("/", "threads", static_cast<std::int64_t>(result.threads));
  w.attribute("/", "ranks", static_cast<std::int64_t>(result.ranks));
  w.attribute("/", "particles", static_cast<std::int64_t>(total_particles(scene)));

  w.doubles("/times", result.times, "sample times t_k (scene time unit)");

  write_series(w, "/temperature", report.temperature,
               replica_rows(
                   result, [](const ReplicaSeries& s) -> const auto& { return s.temperature; }),
               replicas, "mixture temperature T = sum_i x_i T_i", "energy units");
  write_series(w, "/log_temperature", report.log_temperature,
               replica_rows(
                   result, [](const ReplicaSeries& s) -> const auto& { return s.log_temperature; }),
               replicas, "natural logarithm ln T of the mixture temperature", "T in energy units");

  w.group("/species", "per-species observables, one group per species; attribute index gives the scene order");
  for (std::size_t i = 0; i < report.species.size(); ++i) {
    const SpeciesReport& sp = report.species[i];
    const std::string path = "/species/" + species_group_name(sp.name, i);
    w.group(path, "species '" + sp.name + "'");
    w.attribute(path, "name", sp.name);
    w.attribute(path, "index", static_cast<std::int64_t>(i));
    if (i < scene.species.size()) {
      w.attribute(path, "particles", static_cast<std::int64_t>(scene.species[i].particles));
      w.attribute(path, "mass", scene.species[i].mass);
    }
    // a2 over the last half of the samples, per-replica time average then replica mean (as temperature_ratio).
    w.attribute(path, "a2_last_half_mean", sp.a2_last_half.mean);
    w.attribute(path, "a2_last_half_ci", sp.a2_last_half.ci);
    write_series(w, path + "/temperature", sp.temperature,
                 replica_rows(
                     result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].temperature; }),
                 replicas, "partial temperature T_i = m_i <V^2>/3 of species '" + sp.name + "'", "energy units");
    write_series(w, path + "/a2", sp.a2,
                 replica_rows(
                     result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].a2; }),
                 replicas, "kurtosis cumulant a2 = (3/5) <V^4>/<V^2>^2 - 1 of species '" + sp.name + "'",
                 "dimensionless");
    write_series(w, path + "/a3", sp.a3,
                 replica_rows(result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].a3; }),
                 replicas, "third Sonine coefficient a3 = 1 + 3 a2 - (9/35) <V^6>/<V^2>^3 of species '" + sp.name + "'",
                 "dimensionless");
    w.attribute(path, "a3_last_half_mean", sp.a3_last_half.mean);
    w.attribute(path, "a3_last_half_ci", sp.a3_last_half.ci);
    if (!sp.speed_distribution.mean.empty()) {
      const std::string d = path + "/speed_distribution";
      w.group(d, scene.run.method == Method::event
                     ? "distribution of the speed |V| (velocity units, 001 eq. 37) over the last half of the samples, "
                       "per shell of /speed_shell_edges; normalised per d^3 V"
                     : "distribution Phi_i(v*) of the scaled speed v* = |V|/v0 (000 eqs. 7, 19) over the last half of "
                       "the samples, per shell of /speed_shell_edges; normalised per d^3 v*");
      w.doubles(d + "/mean", sp.speed_distribution.mean, "replica mean of Phi_i(v*) in each shell (per d^3 v*)");
      w.doubles(d + "/ci", sp.speed_distribution.ci,
                "confidence half-width of the replica mean, lambda_p = 3.2 (001 eq. 31) (per d^3 v*)");
      w.doubles(d + "/counts",
                replica_rows(result, [i](const ReplicaSeries& s) -> const auto& { return s.species[i].speed_counts; }),
                {replicas, sp.speed_distribution.mean.size()},
                "particles counted in each shell (columns), summed over the histogram samples, per replica (rows)");
    }
  }

  if (report.intruder) write_intruder(w, result, *report.intruder);
  if (report.viscosity) write_viscosity(w, result, *report.viscosity);
  std::vector<double> momentum;
  for (const ReplicaSeries& s : result.replicas)
    for (const Vec3& p : s.momentum) momentum.insert(momentum.end(), {p.x, p.y, p.z});
  if (!momentum.empty()) {  // gas runs
    w.group("/momentum", "total momentum");
    w.doubles("/momentum/replicas", momentum, {replicas, samples, 3},
              "total momentum P = sum_i m_i sum_k V_k (x, y, z) of each replica at each sample time "
              "(mass times sqrt(energy/mass))");
    write_series(w, "/momentum_relative", report.momentum_relative,
                 replica_rows(
                     result, [](const ReplicaSeries& s) -> const auto& { return s.momentum_relative; }),
                 replicas, "relative momentum |P| / sqrt(M 2 E_kin), centre-of-mass speed over rms speed",
                 "dimensionless");
  }

  w.group("/collisions", "accepted collisions");
  w.doubles("/collisions/replicas",
            replica_rows(
                result, [](const ReplicaSeries& s) -> const auto& { return s.collisions; }),
            {replicas, samples},
            "cumulative accepted collisions since t = 0 of each replica (rows) at each sample time (columns), "
            "a count stored as double");

  std::vector<std::uint64_t> candidates, majorant_updates, majorant_violations, rescales;
  std::vector<double> momentum_removed;
  for (const ReplicaSeries& s : result.replicas) {
    candidates.push_back(s.candidates);
    majorant_updates.push_back(s.majorant_updates);
    majorant_violations.push_back(s.majorant_violations);
    rescales.push_back(s.rescales);
    momentum_removed.push_back(s.momentum_removed_relative);
  }
  w.group("/counters", "per-replica counters of the run");
  w.uint64s("/counters/candidates", candidates, "candidate pairs tested by each replica (count)");
  std::vector<std::uint64_t> histogram_samples;
  for (const ReplicaSeries& s : result.replicas) histogram_samples.push_back(s.histogram_samples);
  w.uint64s("/counters/histogram_samples", histogram_samples,
            "samples added to the speed histograms by each replica (the last half of the run) (count)");
  if (!report.speed_shell_edges.empty())
    w.doubles("/speed_shell_edges", report.speed_shell_edges,
              "edges of the scaled-speed shells v* = |V|/v0, v0 = sqrt(2 T / m_hat) with m_hat = m1 m2/(m1 + m2) "
              "for two species (000 eq. 7), m for one (dimensionless)");
  std::vector<std::uint64_t> pair_collisions;
  for (const ReplicaSeries& s : result.replicas)
    pair_collisions.insert(pair_collisions.end(), s.pair_collisions.begin(), s.pair_collisions.end());
  if (!pair_collisions.empty())
    w.uint64s("/counters/pair_collisions", pair_collisions, {replicas, pair_collisions.size() / replicas},
              "accepted collisions of each replica (rows) per ordered species pair (i, j) (columns, index "
              "i * species + j), whole run (count)");
  w.uint64s("/counters/majorant_updates", majorant_updates,
            "times each replica raised its collision majorant omega_max (count)");
  w.uint64s("/counters/majorant_violations", majorant_violations,
            "event scheme: candidates whose relative speed exceeded the majorant U_max their waiting time "
            "was drawn with, per replica (count; 0 means the thinning was exact)");
  w.uint64s("/counters/rescales", rescales, "velocity rescalings of each replica in long cooling runs (count)");
  std::vector<double> energy_residual;
  for (const ReplicaSeries& s : result.replicas)
    if (s.energy_residual) energy_residual.push_back(*s.energy_residual);
  if (energy_residual.size() == result.replicas.size() && !energy_residual.empty())
    w.doubles("/counters/energy_residual", energy_residual,
              "largest |E_tracked / E_summed - 1| over the sample times per replica: the steps' energy "
              "bookkeeping against a direct sum over the particles (dimensionless; rounding only)");
  w.doubles("/counters/momentum_removed_relative", momentum_removed,
            "sum over rescalings of the removed centre-of-mass momentum |P| / sqrt(M 2 E_kin) per replica "
            "(dimensionless)");

  if (report.temperature_ratio) {
    w.group("/temperature_ratio",
            "T_1/T_2 over the last half of the samples: per-replica time average, then replica mean "
            "(attributes mean and ci, dimensionless)");
    w.attribute("/temperature_ratio", "mean", report.temperature_ratio->mean);
    w.attribute("/temperature_ratio", "ci", report.temperature_ratio->ci);
  }

  if (report.theory) {
    const theory::CoolingStatePrediction& th = *report.theory;
    w.group("/theory", "monodisperse hard-sphere homogeneous cooling state: Haff's law, first- and second-Sonine "
                       "a2 (docs/physics.md)");
    w.attribute("/theory", "a2_sonine", th.a2);
    w.attribute("/theory", "a2_model_error", th.a2_model_error);
    w.attribute("/theory", "a2_second_sonine", th.a2_second_sonine);
    w.attribute("/theory", "a3_second_sonine", th.a3_second_sonine);
    w.attribute("/theory", "cooling_rate0", th.cooling_rate0);
    w.attribute("/theory", "cooling_rate0_first_sonine", th.cooling_rate0_first_sonine);
    w.attribute("/theory", "cooling_rate0_maxwell", th.cooling_rate0_maxwell);
    w.attribute("/theory", "cooling_rate_model_error", th.cooling_rate_model_error);
    w.attribute("/theory", "chi", th.chi);
    w.attribute("/theory", "alpha", th.alpha);
    w.attribute("/theory", "collision_frequency0", th.collision_frequency0);
    w.doubles("/theory/haff_temperature", th.temperature,
              "Haff's law T(t) = T0 / (1 + zeta0 t / 2)^2 with the second-Sonine cooling rate zeta0 = cooling_rate0, "
              "at the sample times (energy units)");
  }
}

}  // namespace

void write_hdf5(const std::string& path, const Scene& scene, const RunResult& result, const RunReport& report) {
  const std::string temporary = path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  const QuietHdf5 quiet;
  try {
    Handle file(check(H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), "cannot create the file"),
                H5Fclose);
    write_contents(file.get(), scene, result, report);
    file.close("cannot close the file");
  } catch (const Hdf5Failure& e) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write HDF5 output '" + path + "': " + e.what());
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write HDF5 output '" + path + "': cannot rename '" + temporary + "' to it (" +
                             reason + ")");
  }
}

}  // namespace granmc
