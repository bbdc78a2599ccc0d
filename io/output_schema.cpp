#include "io/output_schema.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <utility>

#include "granmc/version.hpp"
#include "io/build_id.hpp"

namespace granmc {

namespace {

using Value = std::optional<RecordValue>;
using K = RecordKind;

constexpr const char* units_text =
    "k_B = 1; temperature in energy units; time in the scene's time unit; velocities in sqrt(energy/mass)";
constexpr const char* ci_text =
    "replica mean and its confidence half-width lambda_p sqrt(Var/R), lambda_p = 3.2 "
    "(001 eq. 31)";

/// Row r is what `pick` gives for replica r: the dataset [R x n] (or [R x n x width] for vectors of width
/// values, flattened by `flat`).
template <class Pick>
ReplicaRows<double> rows(const RunResult& result, Pick pick) {
  ReplicaRows<double> out;
  std::size_t n = 0;
  for (const ReplicaSeries& s : result.replicas) {
    const std::vector<double>& v = pick(s);
    n = v.size();
    out.values.insert(out.values.end(), v.begin(), v.end());
  }
  out.dims = {result.replicas.size(), n};
  return out;
}

/// One value per replica: the dataset [R].
template <class T, class Pick>
ReplicaRows<T> per_replica(const RunResult& result, Pick pick) {
  ReplicaRows<T> out;
  for (const ReplicaSeries& s : result.replicas) out.values.push_back(pick(s));
  out.dims = {result.replicas.size()};
  return out;
}

bool gas(const RunOutput& o) { return !o.report.momentum_relative.mean.empty(); }

/// The optional parts of the report a record can belong to (nothing when the run has no such part).
const IntruderReport* intruder(const RunOutput& o) { return o.report.intruder ? &*o.report.intruder : nullptr; }
const NeedleReport* needle(const RunOutput& o) {
  return o.report.intruder && o.report.intruder->needle ? &*o.report.intruder->needle : nullptr;
}
const ViscosityReport* viscosity(const RunOutput& o) { return o.report.viscosity ? &*o.report.viscosity : nullptr; }

template <class T>
constexpr bool is_optional = false;
template <class T>
constexpr bool is_optional<std::optional<T>> = true;

/// The accessor of `member` of the part `part` gives, or of nothing when the run has no such part (or the
/// member is an empty optional).
template <class Part, class T>
std::function<Value(const RunOutput&, std::size_t)> member_of(const Part* (*part)(const RunOutput&), T Part::*member) {
  return [part, member](const RunOutput& o, std::size_t) -> Value {
    const Part* p = part(o);
    if (p == nullptr) return {};
    if constexpr (is_optional<T>) {
      if (!(p->*member)) return {};
      return *(p->*member);
    } else {
      return p->*member;
    }
  };
}

std::vector<OutputRecord> declare() {
  std::vector<OutputRecord> r;
  auto add = [&](std::string path, RecordKind kind, InSummary summary, std::string units, std::string meaning,
                 std::function<Value(const RunOutput&, std::size_t)> value) {
    r.push_back({std::move(path), kind, summary, std::move(units), std::move(meaning), std::move(value)});
  };
  // In the summary too, in the HDF5 file only, or in the summary at its sample times only.
  const InSummary S = InSummary::yes, H = InSummary::no, ST = InSummary::sample_times;

  // The run as a whole.
  add("format_version", K::text, S, "", "version of this format, major.minor (docs/formats/output-format.md)",
      [](const RunOutput&, std::size_t) { return output_format_version(); });
  add("scene", K::text, S, "", "the scene file's path as given to granmc",
      [](const RunOutput& o, std::size_t) { return o.scene.source_path; });
  add("scene_text", K::text, H, "", "the scene file's text",
      [](const RunOutput& o, std::size_t) { return o.scene.source_text; });
  add("seed", K::count, S, "", "run.seed", [](const RunOutput& o, std::size_t) { return o.scene.run.seed; });
  add("replicas", K::count, S, "", "independent replicas R",
      [](const RunOutput& o, std::size_t) { return std::uint64_t{o.result.replicas.size()}; });
  add("method", K::text, S, "", "run.method: dsmc, event or gillespie",
      [](const RunOutput& o, std::size_t) { return o.report.method; });
  add("version", K::text, S, "", "granmc's version",
      [](const RunOutput&, std::size_t) { return std::string(granmc::version); });
  add("build", K::text, S, "",
      "the build that wrote the file: version+commit (12 hex digits, -dirty when tracked files differed from it), "
      "as granmc --version prints it",
      [](const RunOutput&, std::size_t) { return std::string(build_id()); });
  add("units", K::text, S, "", "the units of every record",
      [](const RunOutput&, std::size_t) { return std::string(units_text); });
  add("wall_seconds", K::number, S, "s", "wall-clock time of the run",
      [](const RunOutput& o, std::size_t) { return o.report.wall_seconds; });
  add("threads", K::count, S, "", "OpenMP threads (of rank 0 over MPI)",
      [](const RunOutput& o, std::size_t) { return static_cast<std::uint64_t>(o.result.threads); });
  add("threads_per_replica", K::count, S, "",
      "of the threads, each replica's own: the concurrent rounds of the time-stepped scheme's collision stage or "
      "the event scheme's candidates (docs/user-guide/parallel-runs.md)",
      [](const RunOutput& o, std::size_t) { return static_cast<std::uint64_t>(o.result.threads_per_replica); });
  // The concurrent rounds' counts (observe/gas_series.hpp), present when the replicas had threads inside them.
  const auto round_count = [](std::uint64_t CollisionRoundCounts::*count) {
    return [count](const RunOutput& o, std::size_t) -> Value {
      if (o.result.threads_per_replica < 2) return {};
      return o.result.rounds.*count;
    };
  };
  add("collision_rounds", K::count, S, "",
      "time-stepped or event scheme with threads inside a replica: rounds of candidates run on several threads, all "
      "replicas (of rank 0 over MPI)",
      round_count(&CollisionRoundCounts::rounds));
  add("collision_rounds_deferred", K::count, S, "",
      "candidates those rounds deferred to the round's end (a particle that an earlier thread's chunk names) and "
      "replayed in order",
      round_count(&CollisionRoundCounts::deferred));
  add("collision_rounds_in_order", K::count, S, "",
      "rounds run again in order on one thread because a candidate raised the majorant",
      round_count(&CollisionRoundCounts::in_order));
  add("ranks", K::count, S, "", "MPI ranks (1 without MPI)",
      [](const RunOutput& o, std::size_t) { return static_cast<std::uint64_t>(o.result.ranks); });
  add("particles", K::count, S, "", "simulated particles per replica, all species",
      [](const RunOutput& o, std::size_t) { return static_cast<std::uint64_t>(total_particles(o.scene)); });
  add("dimension", K::count, S, "",
      "a gas's dimension d, run.dimension: 3 hard spheres, 2 hard disks (temperatures m <V^2> / d, cumulants of "
      "d dimensions); absent for an intruder",
      [](const RunOutput& o, std::size_t) -> Value {
        if (o.scene.intruder) return {};
        return static_cast<std::uint64_t>(o.scene.run.dimension);
      });
  add("collisions", K::count, S, "", "accepted collisions, all replicas",
      [](const RunOutput& o, std::size_t) { return o.report.collisions; });
  add("candidates", K::count, S, "", "candidate pairs tested, all replicas",
      [](const RunOutput& o, std::size_t) { return o.report.candidates; });
  add("majorant_updates", K::count, S, "", "raises of the collision majorant, all replicas",
      [](const RunOutput& o, std::size_t) { return o.report.majorant_updates; });
  add("majorant_violations", K::count, S, "",
      "event scheme: candidates above the majorant U_max their waiting time was drawn with, all replicas (0: the "
      "thinning was exact)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (o.scene.run.method != Method::event) return {};
        return o.report.majorant_violations;
      });
  add("rescales", K::count, S, "", "velocity rescalings in long cooling runs, all replicas",
      [](const RunOutput& o, std::size_t) { return o.report.rescales; });
  add("energy_residual_max", K::number, S, "",
      "time-stepped gas: the largest |E_tracked / E_summed - 1| over replicas and samples, the steps' energy "
      "bookkeeping against a direct sum (rounding only)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!o.report.energy_residual) return {};
        return *o.report.energy_residual;
      });
  add("times", K::numbers, ST, "time", "sample times t_k",
      [](const RunOutput& o, std::size_t) { return o.result.times; });
  add("summary_stride", K::count, S, "",
      "the JSON summary's records over the sample times hold every summary_stride-th sample time from the first, "
      "and the last: at most " +
          std::to_string(summary_sample_times_max) + " (1 when the run has no more); the HDF5 file holds every one",
      [](const RunOutput& o, std::size_t) {
        return static_cast<std::uint64_t>(summary_stride(o.result.times.size()));
      });

  // Series over the sample times, with their rows per replica.
  auto series_with_rows = [&](const std::string& path, const std::string& units, const std::string& what,
                              std::function<const MeanCISeries*(const RunOutput&)> stats,
                              std::function<const std::vector<double>&(const ReplicaSeries&)> pick) {
    add(path, K::series, ST, units, what + " at the sample times; " + ci_text,
        [stats](const RunOutput& o, std::size_t) -> Value {
          const MeanCISeries* s = stats(o);
          if (s == nullptr) return {};
          return *s;
        });
    add(path + "/replicas", K::rows, H, units, what + " of each replica (rows) at each sample time (columns)",
        [stats, pick](const RunOutput& o, std::size_t) -> Value {
          if (stats(o) == nullptr) return {};
          return rows(o.result, pick);
        });
  };
  series_with_rows(
      "temperature", "energy", "mixture temperature T = sum_i x_i T_i",
      [](const RunOutput& o) { return &o.report.temperature; },
      [](const ReplicaSeries& s) -> const auto& { return s.temperature; });
  add("temperature_last_half", K::mean_ci, S, "energy",
      "the mixture temperature over the last half of the samples (a steady state's T): per-replica time average, "
      "then " +
          std::string(ci_text),
      [](const RunOutput& o, std::size_t) -> Value { return o.report.temperature_last_half; });
  series_with_rows(
      "log_temperature", "", "ln T of the mixture temperature (finite where T underflows)",
      [](const RunOutput& o) { return &o.report.log_temperature; },
      [](const ReplicaSeries& s) -> const auto& { return s.log_temperature; });
  add("temperature_uncentred", K::series, ST, "energy",
      "the mixture temperature without removing the bulk velocity, T + (sum_i x_i m_i) |V|^2 / 3 with V = P / M "
      "(momentum/replicas): 001's T = (1/3) int |v|^2 f (eq. 35), which the paper evaluates on a sample whose "
      "mean is not removed (step 1.2; initial.zero_momentum = false), at the sample times (gas); " +
          std::string(ci_text),
      [](const RunOutput& o, std::size_t) -> Value {
        if (!gas(o)) return {};
        return o.report.temperature_uncentred;
      });
  series_with_rows(
      "momentum_relative", "", "|P| / sqrt(M 2 E_kin), the centre-of-mass speed over the rms speed (gas)",
      [](const RunOutput& o) { return gas(o) ? &o.report.momentum_relative : nullptr; },
      [](const ReplicaSeries& s) -> const auto& { return s.momentum_relative; });
  add("momentum/replicas", K::rows, H, "mass sqrt(energy/mass)",
      "total momentum P = sum_i m_i sum_k V_k (x, y, z) of each replica at each sample time (gas)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!gas(o)) return {};
        ReplicaRows<double> out;
        for (const ReplicaSeries& s : o.result.replicas)
          for (const Vec3& p : s.momentum) out.values.insert(out.values.end(), {p.x, p.y, p.z});
        out.dims = {o.result.replicas.size(), o.result.times.size(), 3};
        return out;
      });
  add("collisions/replicas", K::rows, H, "",
      "cumulative accepted collisions since t = 0 of each replica (rows) at each sample time (columns), a count "
      "stored as double (exact below 2^53)",
      [](const RunOutput& o, std::size_t) {
        return rows(
            o.result, [](const ReplicaSeries& s) -> const auto& { return s.collisions; });
      });
  add("speed_shell_edges", K::numbers, S, "",
      "edges of the scaled-speed shells v* = |V|/v0 of the speed distributions, v0 = sqrt(2 T / m_hat) with m_hat "
      "= m1 m2/(m1 + m2) for two species (000 eq. 7), m for one; with output.histogram.speed = \"velocity\" (the "
      "event scheme's default, 001 eq. 37) |V| in velocity units",
      [](const RunOutput& o, std::size_t) { return o.report.speed_shell_edges; });

  // Species.
  add("species", K::group, H, "", "per-species records, one group per species; attribute index gives the scene order",
      [](const RunOutput& o, std::size_t) -> Value {
        if (o.report.species.empty()) return {};
        return std::monostate{};
      });
  add("species/{species}", K::group, H, "", "one species: attributes name, index, particles, mass",
      [](const RunOutput&, std::size_t) { return std::monostate{}; });
  add("species/{species}/name", K::text, S, "", "the species' name in the scene",
      [](const RunOutput& o, std::size_t i) { return o.report.species[i].name; });
  add("species/{species}/index", K::count, S, "", "position in the scene's [[species]]",
      [](const RunOutput&, std::size_t i) { return std::uint64_t{i}; });
  add("species/{species}/particles", K::count, S, "", "simulated particles N_i per replica",
      [](const RunOutput& o, std::size_t i) -> Value {
        if (i >= o.scene.species.size()) return {};
        return static_cast<std::uint64_t>(o.scene.species[i].particles);
      });
  add("species/{species}/mass", K::number, S, "mass", "m_i", [](const RunOutput& o, std::size_t i) -> Value {
    if (i >= o.scene.species.size()) return {};
    return o.scene.species[i].mass;
  });
  auto species_series = [&](const std::string& leaf, const std::string& units, const std::string& what,
                            MeanCISeries SpeciesReport::*stats, std::vector<double> SpeciesSeries::*member) {
    add("species/{species}/" + leaf, K::series, ST, units, what + " at the sample times; " + ci_text,
        [stats](const RunOutput& o, std::size_t i) { return o.report.species[i].*stats; });
    add("species/{species}/" + leaf + "/replicas", K::rows, H, units,
        what + " of each replica (rows) at each sample time (columns)", [member](const RunOutput& o, std::size_t i) {
          return rows(
              o.result, [&](const ReplicaSeries& s) -> const auto& { return s.species[i].*member; });
        });
  };
  species_series("temperature", "energy", "partial temperature T_i = m_i <V^2>/3", &SpeciesReport::temperature,
                 &SpeciesSeries::temperature);
  species_series("a2", "", "kurtosis cumulant a2 = (3/5) <V^4>/<V^2>^2 - 1", &SpeciesReport::a2, &SpeciesSeries::a2);
  add("species/{species}/a2_last_half", K::mean_ci, S, "",
      "a2 over the last half of the samples: per-replica time average, then " + std::string(ci_text),
      [](const RunOutput& o, std::size_t i) { return o.report.species[i].a2_last_half; });
  species_series("a3", "", "third Sonine coefficient a3 = 1 + 3 a2 - (9/35) <V^6>/<V^2>^3", &SpeciesReport::a3,
                 &SpeciesSeries::a3);
  add("species/{species}/a3_last_half", K::mean_ci, S, "",
      "a3 over the last half of the samples: per-replica time average, then " + std::string(ci_text),
      [](const RunOutput& o, std::size_t i) { return o.report.species[i].a3_last_half; });
  add("species/{species}/speed_distribution", K::series, S, "per d^3 v*",
      "distribution of the scaled speed over the last half of the samples, per shell of speed_shell_edges (000 eqs. "
      "7, 19; with output.histogram.speed = \"velocity\" |V| in velocity units, per d^3 V, 001 eq. 37; with "
      "weighted particles the weight "
      "in each shell); " +
          std::string(ci_text),
      [](const RunOutput& o, std::size_t i) -> Value {
        if (o.report.species[i].speed_distribution.mean.empty()) return {};
        return o.report.species[i].speed_distribution;
      });
  add("species/{species}/speed_distribution/counts", K::rows, H, "",
      "particles counted in each shell (columns), summed over the histogram samples, per replica (rows); with "
      "weighted particles their weight in units of 1/N of the total",
      [](const RunOutput& o, std::size_t i) -> Value {
        if (o.report.species[i].speed_distribution.mean.empty()) return {};
        return rows(
            o.result, [&](const ReplicaSeries& s) -> const auto& { return s.species[i].speed_counts; });
      });
  // Rough particles (collide/rough_rule.hpp): spins, only where the scene has them.
  auto rough_series = [&](const std::string& leaf, const std::string& units, const std::string& what,
                          MeanCISeries SpeciesReport::*stats, std::vector<double> SpeciesSeries::*member) {
    add("species/{species}/" + leaf, K::series, ST, units, what + " at the sample times (rough particles); " + ci_text,
        [stats](const RunOutput& o, std::size_t i) -> Value {
          if ((o.report.species[i].*stats).mean.empty()) return {};
          return o.report.species[i].*stats;
        });
    add("species/{species}/" + leaf + "/replicas", K::rows, H, units,
        what + " of each replica (rows) at each sample time (columns), rough particles",
        [stats, member](const RunOutput& o, std::size_t i) -> Value {
          if ((o.report.species[i].*stats).mean.empty()) return {};
          return rows(
              o.result, [&](const ReplicaSeries& s) -> const auto& { return s.species[i].*member; });
        });
  };
  auto rough_last_half = [&](const std::string& leaf, const std::string& what,
                             std::optional<MeanCI> SpeciesReport::*stats) {
    add("species/{species}/" + leaf, K::mean_ci, S, "",
        what + " over the last half of the samples (rough particles): per-replica time average, then " +
            std::string(ci_text),
        [stats](const RunOutput& o, std::size_t i) -> Value {
          if (!(o.report.species[i].*stats)) return {};
          return *(o.report.species[i].*stats);
        });
  };
  rough_series("rotational_temperature", "energy",
               "rotational temperature T_rot,i = I_i <omega^2> / d_r (d_r = 3 for spheres, 1 for disks)",
               &SpeciesReport::rotational_temperature, &SpeciesSeries::rotational_temperature);
  rough_last_half("rotational_ratio", "theta = T_rot,i / T_i", &SpeciesReport::rotational_ratio);
  rough_series("a02", "", "the spins' kurtosis cumulant a02 = d_r/(d_r + 2) <omega^4>/<omega^2>^2 - 1",
               &SpeciesReport::a02, &SpeciesSeries::a02);
  rough_last_half("a02_last_half", "a02", &SpeciesReport::a02_last_half);
  rough_series("a11", "", "the correlation a11 = <V^2 omega^2> / (<V^2> <omega^2>) - 1 of translation and rotation",
               &SpeciesReport::a11, &SpeciesSeries::a11);
  rough_last_half("a11_last_half", "a11", &SpeciesReport::a11_last_half);
  add("temperature_ratio", K::mean_ci, S, "",
      "T_1/T_2 over the last half of the samples (two species): per-replica time average, then " + std::string(ci_text),
      [](const RunOutput& o, std::size_t) -> Value {
        if (!o.report.temperature_ratio) return {};
        return *o.report.temperature_ratio;
      });

  // Counters per replica.
  add("counters", K::group, H, "", "per-replica counters of the run",
      [](const RunOutput&, std::size_t) { return std::monostate{}; });
  add("counters/candidates", K::count_rows, H, "", "candidate pairs tested by each replica",
      [](const RunOutput& o, std::size_t) {
        return per_replica<std::uint64_t>(o.result, [](const ReplicaSeries& s) { return s.candidates; });
      });
  add("counters/histogram_samples", K::count_rows, H, "",
      "samples added to the speed histograms by each replica (the last half of the run)",
      [](const RunOutput& o, std::size_t) {
        return per_replica<std::uint64_t>(o.result, [](const ReplicaSeries& s) { return s.histogram_samples; });
      });
  add("counters/pair_collisions", K::count_rows, H, "",
      "accepted collisions of each replica (rows) per ordered species pair (i, j) (columns, index i * species + j), "
      "whole run",
      [](const RunOutput& o, std::size_t) -> Value {
        ReplicaRows<std::uint64_t> out;
        for (const ReplicaSeries& s : o.result.replicas)
          out.values.insert(out.values.end(), s.pair_collisions.begin(), s.pair_collisions.end());
        if (out.values.empty()) return {};
        out.dims = {o.result.replicas.size(), out.values.size() / o.result.replicas.size()};
        return out;
      });
  add("counters/majorant_updates", K::count_rows, H, "", "times each replica raised its collision majorant",
      [](const RunOutput& o, std::size_t) {
        return per_replica<std::uint64_t>(o.result, [](const ReplicaSeries& s) { return s.majorant_updates; });
      });
  add("counters/majorant_violations", K::count_rows, H, "",
      "event scheme: candidates whose relative speed exceeded the majorant U_max their waiting time was drawn "
      "with, per replica (0 means the thinning was exact)",
      [](const RunOutput& o, std::size_t) {
        return per_replica<std::uint64_t>(o.result, [](const ReplicaSeries& s) { return s.majorant_violations; });
      });
  add("counters/rescales", K::count_rows, H, "", "velocity rescalings of each replica in long cooling runs",
      [](const RunOutput& o, std::size_t) {
        return per_replica<std::uint64_t>(o.result, [](const ReplicaSeries& s) { return s.rescales; });
      });
  add("counters/energy_residual", K::rows, H, "",
      "largest |E_tracked / E_summed - 1| over the sample times per replica: the steps' energy bookkeeping against "
      "a direct sum over the particles (time-stepped gas; rounding only)",
      [](const RunOutput& o, std::size_t) -> Value {
        for (const ReplicaSeries& s : o.result.replicas)
          if (!s.energy_residual) return {};
        return per_replica<double>(o.result, [](const ReplicaSeries& s) { return *s.energy_residual; });
      });
  add("counters/momentum_removed_relative", K::rows, H, "",
      "sum over rescalings of the removed centre-of-mass momentum |P| / sqrt(M 2 E_kin) per replica",
      [](const RunOutput& o, std::size_t) {
        return per_replica<double>(o.result, [](const ReplicaSeries& s) { return s.momentum_removed_relative; });
      });

  // The tail exponent (analysis/tail_fit.hpp).
  add("tail", K::group, H, "",
      "the high-velocity tail of one species' f: ln f = c + gamma ln v - a v^b fitted per replica (001 eqs. 19-21)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!o.report.tail) return {};
        return std::monostate{};
      });
  add("tail/exponent", K::mean_ci, S, "",
      "b of f ~ v^gamma exp(-a v^b) fitted to the replica-mean density from where it falls below 10^-3 of its "
      "maximum to the last shell every replica has weight in; ci: lambda_p (001 eq. 31) times the jackknife "
      "standard error over the replicas",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!o.report.tail) return {};
        return o.report.tail->exponent;
      });
  add("tail/fit_range", K::numbers, S, "velocity", "the fit window's speeds [from, to] (shell edges)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!o.report.tail) return {};
        return std::vector<double>{o.report.tail->speed_from, o.report.tail->speed_to};
      });
  add("tail/profile", K::rows, H, "",
      "b against the window's inner edge: rows (from, to, b, ci) for windows from where the mean density falls "
      "below 10^-1, 10^-2, ... of its maximum to the last shell every replica has weight in; where b levels off "
      "the window has left the pre-asymptotic region",
      [](const RunOutput& o, std::size_t) -> Value {
        if (o.report.tail_profile.empty()) return {};
        ReplicaRows<double> out;
        for (const TailWindow& w : o.report.tail_profile)
          out.values.insert(out.values.end(), {w.speed_from, w.speed_to, w.exponent.mean, w.exponent.ci});
        out.dims = {o.report.tail_profile.size(), 4};
        return out;
      });

  // Weighted particles (schemes/swpm_scheme.hpp, schemes/weight_control.hpp).
  const auto weighted = [](const RunOutput& o) { return o.result.replicas.front().weighted.has_value(); };
  const auto weighted_total = [weighted](std::uint64_t WeightedSeries::*member) {
    return [weighted, member](const RunOutput& o, std::size_t) -> Value {
      if (!weighted(o)) return {};
      std::uint64_t total = 0;
      for (const ReplicaSeries& s : o.result.replicas) total += (*s.weighted).*member;
      return total;
    };
  };
  add("weights", K::group, H, "", "weighted particles ([weights], SWPM): the particle count and the weight control",
      [weighted](const RunOutput& o, std::size_t) -> Value {
        if (!weighted(o)) return {};
        return std::monostate{};
      });
  add("weights/particles", K::rows, H, "",
      "particles of each replica (rows) at each sample (columns), after the weight control",
      [weighted](const RunOutput& o, std::size_t) -> Value {
        if (!weighted(o)) return {};
        return rows(
            o.result, [](const ReplicaSeries& s) -> const auto& { return s.weighted->particles; });
      });
  add("weights/particles_max", K::number, S, "", "the most particles of any replica at a sample",
      [weighted](const RunOutput& o, std::size_t) -> Value {
        if (!weighted(o)) return {};
        double most = 0.0;
        for (const ReplicaSeries& s : o.result.replicas)
          for (double n : s.weighted->particles) most = std::max(most, n);
        return most;
      });
  add("weights/transfers", K::count, S, "", "collisions of unequal weights (each adds a particle), all replicas",
      weighted_total(&WeightedSeries::transfers));
  add("weights/controls", K::count, S, "", "whole-system weight controls, all replicas",
      weighted_total(&WeightedSeries::controls));
  add("weights/split_copies", K::count, S, "", "particles added by splitting, all replicas",
      weighted_total(&WeightedSeries::split_copies));
  add("weights/reductions", K::count, S, "", "groups replaced by two particles, all replicas",
      weighted_total(&WeightedSeries::reductions));
  add("weights/reduced", K::count, S, "", "particles removed by the reductions, all replicas",
      weighted_total(&WeightedSeries::reduced));
  add("weights/conservation_residual_max", K::number, S, "",
      "largest relative change of mass, momentum (over sqrt(W 2 E)) or energy at a weight control, all replicas",
      [weighted](const RunOutput& o, std::size_t) -> Value {
        if (!weighted(o)) return {};
        double most = 0.0;
        for (const ReplicaSeries& s : o.result.replicas) most = std::max(most, s.weighted->conservation_residual);
        return most;
      });

  // The intruder (002).
  add("intruder", K::group, H, "", "the Gillespie intruder or needle (002) in its bath",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!intruder(o)) return {};
        return std::monostate{};
      });
  add("intruder/temperature_ratio", K::mean_ci, S, "",
      "T/T_B over the last half of the samples, T = M <v1^2> per degree of freedom (the needle's translational "
      "temperature): per-replica time average, then " +
          std::string(ci_text),
      member_of(intruder, &IntruderReport::temperature_ratio));
  add("intruder/temperature_ratio_time_average", K::mean_ci, S, "",
      "Gillespie intruder and needle: T/T_B with <|v1|^2> the exact time average over the same window (v1 is "
      "constant between events; absent with one sample, an empty window), per replica, then " +
          std::string(ci_text),
      member_of(intruder, &IntruderReport::temperature_ratio_time_average));
  add("intruder/bath_temperature", K::number, S, "energy", "T_B = m <v^2> of the bath (m = 1)",
      member_of(intruder, &IntruderReport::bath_temperature));
  add("intruder/events", K::count, S, "", "collisions of the intruder, all replicas",
      member_of(intruder, &IntruderReport::events));
  add("intruder/temperature_ratio_exact", K::number, S, "",
      "exact stationary T/T_B where it is known (002 eq. 22; alpha for the power law with M = alpha)",
      member_of(intruder, &IntruderReport::temperature_ratio_exact));
  add("intruder/speed_shell_edges", K::numbers, S, "velocity", "edges of the |v1| shells",
      member_of(intruder, &IntruderReport::speed_shell_edges));
  add("intruder/speed_distribution", K::series, S, "1/velocity",
      "density of |v1| per unit speed over the last half of the samples, per shell; " + std::string(ci_text),
      member_of(intruder, &IntruderReport::speed_distribution));
  add("intruder/speed_distribution/counts", K::rows, H, "",
      "samples of |v1| counted in each shell (columns), per replica (rows)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!intruder(o)) return {};
        return rows(
            o.result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->speed_counts; });
      });
  add("intruder/velocity", K::rows, H, "velocity",
      "intruder velocity v1 (the needle's v1_x) of each replica (rows) at each sample (columns)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!intruder(o)) return {};
        return rows(
            o.result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->velocity; });
      });
  add("intruder/R", K::mean_ci, S, "",
      "needle: R = <v^2 w^2> / (<v^2> <w^2>) over the last half of the samples (002 eq. 34), per replica, then " +
          std::string(ci_text),
      member_of(needle, &NeedleReport::correlation));
  add("intruder/rotational_temperature_ratio", K::mean_ci, S, "",
      "needle: T_rot/T_B, T_rot = I <omega^2>, over the last half of the samples; " + std::string(ci_text),
      member_of(needle, &NeedleReport::rotational_temperature_ratio));
  add("intruder/rotational_temperature_ratio_time_average", K::mean_ci, S, "",
      "needle: T_rot/T_B with <omega^2> the exact time average over the same window (absent with one sample), "
      "per replica, then " +
          std::string(ci_text),
      member_of(needle, &NeedleReport::rotational_temperature_ratio_time_average));
  add("intruder/R_time_average", K::mean_ci, S, "",
      "needle: R (002 eq. 34) from the exact time averages over the same window (absent with one sample), per "
      "replica, then " +
          std::string(ci_text),
      member_of(needle, &NeedleReport::correlation_time_average));
  add("intruder/newton_iterations", K::count, S, "", "needle: Newton steps for the event times (002 eq. 28)",
      member_of(needle, &NeedleReport::newton_iterations));
  add("intruder/bisection_fallbacks", K::count, S, "", "needle: bisection steps taken instead of a Newton step",
      member_of(needle, &NeedleReport::bisection_fallbacks));
  add("intruder/velocity_y", K::rows, H, "velocity", "needle: v1_y of each replica (rows) at each sample (columns)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!needle(o)) return {};
        return rows(
            o.result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->velocity_y; });
      });
  add("intruder/angular_velocity", K::rows, H, "1/time",
      "needle: angular velocity omega of each replica (rows) at each sample (columns)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!needle(o)) return {};
        return rows(
            o.result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->angular_velocity; });
      });
  add("intruder/angular_shell_edges", K::numbers, S, "1/time", "needle: edges of the |omega| shells",
      member_of(needle, &NeedleReport::angular_shell_edges));
  add("intruder/angular_distribution", K::series, S, "time",
      "needle: density of |omega| per unit angular speed over the last half of the samples, per shell; " +
          std::string(ci_text),
      member_of(needle, &NeedleReport::angular_distribution));
  add("intruder/angular_distribution/counts", K::rows, H, "",
      "needle: samples of |omega| counted in each shell (columns), per replica (rows)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!needle(o)) return {};
        return rows(
            o.result, [](const ReplicaSeries& s) -> const auto& { return s.intruder->angular_counts; });
      });

  // Uniform shear flow (000 secs. 2-3, 003).
  add("viscosity", K::group, H, "",
      "uniform shear flow (000 secs. 2-3): eta* = nu eta / (n T) = -(P_xy / n T) / a*, window values over t >= "
      "window_start",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!viscosity(o)) return {};
        return std::monostate{};
      });
  auto window = [&](const std::string& leaf, const std::string& units, const std::string& what,
                    std::function<std::optional<MeanCI>(const ViscosityReport&)> pick) {
    add("viscosity/" + leaf, K::mean_ci, S, units, what + "; " + ci_text,
        [pick](const RunOutput& o, std::size_t) -> Value {
          if (!viscosity(o)) return {};
          const std::optional<MeanCI> m = pick(*viscosity(o));
          if (!m) return {};
          return *m;
        });
  };
  window("eta", "viscosity", "shear viscosity -P_xy / a in scene units at the final temperature, over the window",
         [](const ViscosityReport& v) { return v.eta_scene_units; });
  window("eta_kinetic", "viscosity", "its kinetic part -P^k_xy / a in scene units, over the window",
         [](const ViscosityReport& v) { return v.eta_kinetic_scene_units; });
  window("eta_star", "", "reduced viscosity eta* over the window: per-replica time average, then the replica mean",
         [](const ViscosityReport& v) { return v.eta; });
  window("eta_kinetic_star", "", "kinetic part eta^k* over the window",
         [](const ViscosityReport& v) { return v.eta_kinetic; });
  window("eta_over_eta0", "",
         "one species: eta / eta0, eta0 = (5/16 sigma^2) sqrt(m T / pi) (disks (1 / (2 sigma)) sqrt(m T / pi)), over "
         "the window",
         [](const ViscosityReport& v) { return v.eta_over_eta0; });
  window("eta_kinetic_over_eta0", "", "one species: eta^k / eta0 over the window",
         [](const ViscosityReport& v) { return v.eta_kinetic_over_eta0; });
  window("drift", "", "the plateau test: eta* over the second half of the window minus over the first half",
         [](const ViscosityReport& v) { return v.drift; });
  add("viscosity/steady", K::flag, S, "", "|drift| within its confidence half-width: the Navier-Stokes plateau",
      member_of(viscosity, &ViscosityReport::steady));
  add("viscosity/window_start", K::number, S, "time", "first sample time of the window (the last half of the run)",
      member_of(viscosity, &ViscosityReport::window_start));
  add("viscosity/reduced_shear_rate_range", K::numbers, S, "", "smallest and largest a* (replica means) in the window",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!viscosity(o)) return {};
        return std::vector<double>{viscosity(o)->reduced_shear_rate_min, viscosity(o)->reduced_shear_rate_max};
      });
  auto shear_series = [&](const std::string& leaf, const std::string& what, MeanCISeries ViscosityReport::*member) {
    add("viscosity/" + leaf, K::series, ST, "", what + " at the sample times; " + ci_text,
        [member](const RunOutput& o, std::size_t) -> Value {
          if (!viscosity(o)) return {};
          return viscosity(o)->*member;
        });
  };
  shear_series("reduced_shear_rate", "a* = a / nu, nu = sqrt(pi) n sigma_12^2 v0 (disks (sqrt(pi) / 2) n sigma_12 v0)",
               &ViscosityReport::reduced_shear_rate);
  shear_series("pressure_xy", "P_xy / (n T), kinetic + collisional", &ViscosityReport::pressure_xy);
  shear_series("pressure_kinetic_xy", "P^k_xy / (n T) (000 eq. 17)", &ViscosityReport::pressure_kinetic_xy);
  shear_series("eta_star_series", "eta* = -P_xy / (n T a*) (undefined at t = 0: null)", &ViscosityReport::eta_star);
  shear_series("eta_kinetic_star_series", "eta^k* = -P^k_xy / (n T a*)", &ViscosityReport::eta_kinetic_star);
  for (const bool kinetic : {true, false}) {
    add(kinetic ? "viscosity/pressure_kinetic" : "viscosity/pressure_collisional", K::rows, H, "",
        std::string(kinetic ? "kinetic" : "collisional") +
            " pressure tensor over n T of each replica at each sample (xx, yy, zz, xy, xz, yz); " +
            (kinetic ? "at the sample (000 eq. 17)" : "averaged since the previous sample (000 eq. 18)"),
        [kinetic](const RunOutput& o, std::size_t) -> Value {
          if (!viscosity(o)) return {};
          ReplicaRows<double> out;
          for (const ReplicaSeries& s : o.result.replicas)
            for (const SymTensor& t : kinetic ? s.shear->pressure_kinetic : s.shear->pressure_collisional)
              out.values.insert(out.values.end(), {t.xx, t.yy, t.zz, t.xy, t.xz, t.yz});
          out.dims = {o.result.replicas.size(), o.result.times.size(), 6};
          return out;
        });
  }

  // Theory beside the results: the monodisperse hard-sphere cooling state (docs/methods/physics.md).
  using Prediction = theory::CoolingStatePrediction;
  add("theory", K::group, H, "",
      "monodisperse hard-sphere homogeneous cooling state: Haff's law, first- and second-Sonine a2 "
      "(docs/methods/physics.md)",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!o.report.theory) return {};
        return std::monostate{};
      });
  auto prediction = [&](const std::string& leaf, const std::string& units, const std::string& what,
                        double Prediction::*member) {
    add("theory/" + leaf, K::number, S, units, what, [member](const RunOutput& o, std::size_t) -> Value {
      if (!o.report.theory) return {};
      return (*o.report.theory).*member;
    });
  };
  prediction("alpha", "", "restitution alpha", &Prediction::alpha);
  prediction("chi", "", "Enskog pair correlation at contact chi (1 in the Boltzmann limit)", &Prediction::chi);
  prediction("a2", "", "first-Sonine a2 of the cooling state", &Prediction::a2);
  prediction("a2_model_error", "", "model error of the first-Sonine a2 (docs/methods/physics.md)",
             &Prediction::a2_model_error);
  prediction("a2_second_sonine", "", "second-Sonine a2", &Prediction::a2_second_sonine);
  prediction("a3_second_sonine", "", "second-Sonine a3", &Prediction::a3_second_sonine);
  prediction("cooling_rate0", "1/time", "cooling rate zeta0 at t = 0 (second Sonine)", &Prediction::cooling_rate0);
  prediction("cooling_rate0_first_sonine", "1/time", "zeta0 with the first-Sonine a2",
             &Prediction::cooling_rate0_first_sonine);
  prediction("cooling_rate0_maxwell", "1/time", "zeta0 of a Maxwellian (a2 = 0)", &Prediction::cooling_rate0_maxwell);
  prediction("cooling_rate_model_error", "", "relative model error of zeta0 (docs/methods/physics.md)",
             &Prediction::cooling_rate_model_error);
  prediction("collision_frequency0", "1/time", "collision frequency at t = 0", &Prediction::collision_frequency0);
  add("theory/haff_temperature", K::numbers, ST, "energy",
      "Haff's law T(t) = T0 / (1 + zeta0 t / 2)^2 at the sample times, zeta0 = cooling_rate0",
      [](const RunOutput& o, std::size_t) -> Value {
        if (!o.report.theory) return {};
        return o.report.theory->temperature;
      });
  return r;
}

const char* kind_name(RecordKind kind) {
  switch (kind) {
    case K::text:
      return "text (attribute)";
    case K::number:
      return "number (attribute)";
    case K::count:
      return "count (attribute)";
    case K::flag:
      return "flag (attribute)";
    case K::numbers:
      return "numbers [K]";
    case K::mean_ci:
      return "mean, ci (attributes)";
    case K::series:
      return "mean [K], ci [K]";
    case K::rows:
      return "rows [R x ...]";
    case K::count_rows:
      return "counts [R x ...]";
    case K::group:
      return "group";
  }
  return "";
}

const char* summary_column(InSummary in) {
  switch (in) {
    case InSummary::no:
      return "";
    case InSummary::yes:
      return "yes";
    case InSummary::sample_times:
      return "sampled";
  }
  return "";
}

}  // namespace

std::size_t summary_stride(std::size_t sample_times) {
  const std::size_t intervals = sample_times > 0 ? sample_times - 1 : 0;
  const std::size_t kept = summary_sample_times_max - 1;
  return std::max<std::size_t>(1, (intervals + kept - 1) / kept);
}

std::vector<std::size_t> summary_sample_indices(std::size_t sample_times) {
  std::vector<std::size_t> out;
  const std::size_t stride = summary_stride(sample_times);
  for (std::size_t k = 0; k < sample_times; k += stride) out.push_back(k);
  if (sample_times > 0 && out.back() != sample_times - 1) out.push_back(sample_times - 1);
  return out;
}

std::string output_format_version() {
  return std::to_string(output_format_major) + "." + std::to_string(output_format_minor);
}

const std::vector<OutputRecord>& output_records() {
  static const std::vector<OutputRecord> records = declare();
  return records;
}

const std::vector<std::string>& machine_records() {
  static const std::vector<std::string> paths = {"build",
                                                 "wall_seconds",
                                                 "threads",
                                                 "threads_per_replica",
                                                 "collision_rounds",
                                                 "collision_rounds_deferred",
                                                 "collision_rounds_in_order",
                                                 "ranks"};
  return paths;
}

std::string species_group_name(const std::string& name, std::size_t index) {
  if (name.empty() || name == "." || name == "..") return "species_" + std::to_string(index);
  std::string g = name;
  for (char& c : g)
    if (c == '/') c = '_';
  return g;
}

std::string output_format_page() {
  std::string page =
      "# Output format " + output_format_version() +
      "\n\n"
      "Generated by `granmc output-format` from io/output_schema.cpp, the one declaration of every record; "
      "`make output-format-page` rewrites this page and the test suite checks that it is current.\n\n"
      "`granmc run SCENE --out FILE.h5 --summary FILE.json` writes every record below that the run has to the "
      "HDF5 file, and those marked *yes* under *summary* also to the JSON summary, under the same name: a path `a/b` "
      "is the "
      "HDF5 object `/a/b` and the JSON key `[\"a\"][\"b\"]`; `{species}` stands for each species in turn (the "
      "group `/species/<name>/` in HDF5, the entry of the array `species` in JSON). In HDF5, text, numbers, "
      "counts and flags are attributes of their parent group (the root for a top-level record), a `mean, ci` "
      "record is a group with the attributes `mean` and `ci`, a series is a group with the datasets `mean` and "
      "`ci`, and rows are datasets with one row per replica (R replicas, S sample times, K shells). Every "
      "dataset and group carries a `description` attribute with the meaning below. JSON has no NaN: a number "
      "that is not finite is `null`. A record marked *sampled* is over the sample times: the summary holds it at "
      "no more than " +
      std::to_string(summary_sample_times_max) +
      " of them (every `summary_stride`-th from the first, and the last), so that the summary of a long run "
      "stays small; the HDF5 file holds every sample time.\n\n"
      "The major version changes when a record is renamed, moved or given another meaning, and readers refuse a "
      "major version they do not know; a minor version only adds records. Units: " +
      std::string(units_text) + ".\n\n| record | kind | summary | units | meaning |\n|---|---|---|---|---|\n";
  for (const OutputRecord& r : output_records()) {
    page += "| `" + r.path + "` | " + kind_name(r.kind) + " | " + summary_column(r.summary) + " | " + r.units + " | " +
            r.meaning + " |\n";
  }
  return page;
}

}  // namespace granmc
