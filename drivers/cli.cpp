#include "drivers/cli.hpp"

#include <omp.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "drivers/run_checkpoints.hpp"
#include "drivers/run_job.hpp"
#include "drivers/sweep.hpp"
#include "granmc/version.hpp"
#include "io/build_id.hpp"
#include "io/explain_rates.hpp"
#include "io/output_schema.hpp"
#include "io/scene_file.hpp"
#include "io/theory_json.hpp"
#include "kernel/analysis/bath_probe.hpp"
#include "kernel/schemes/rank_wave_backend.hpp"
#include "kernel/schemes/replica_runner.hpp"
#include "kernel/setup/explain.hpp"
#include "kernel/setup/run_plan.hpp"

namespace granmc {

namespace {

/// "10^k" for a power of ten n.
std::string power_of_ten(std::uint64_t n) {
  return "10^" + std::to_string(std::lround(std::log10(static_cast<double>(n))));
}

struct RunArgs {
  std::string scene;
  std::string out;
  std::string summary;
  int threads = 0;
  int threads_per_replica = 0;  // 0: by the replicas' size (share_threads)
  std::optional<std::uint64_t> seed;
  bool quiet = false;
  bool explain = false;
  std::string spread = "replicas";
  std::string resume;                      // a checkpoint to continue from (drivers/run_checkpoints.hpp)
  std::optional<double> checkpoint_every;  // minutes (0: at every sample); unset: the scene's run.checkpoint_every
  bool no_checkpoints = false;
};

std::string default_output(const std::string& scene_path) {
  return std::filesystem::path(scene_path).stem().string() + ".h5";
}

/// The checkpoints line of --explain (drivers/run_checkpoints.hpp): where, how often, and what a replica in
/// flight adds to each one.
void explain_checkpoints(const Scene& scene, const RunPlan& plan, const RunArgs& args, const PlanExplanation& what) {
  if (plan.spread == Spread::particles || args.no_checkpoints) {
    std::printf("checkpoints  none (%s)\n", args.no_checkpoints ? "--no-checkpoints" : "one replica over the ranks");
    return;
  }
  std::string out = checkpoint_path(args.out.empty() ? default_output(args.scene) : args.out);
  if (const Place at = place(); at.size > 1) out += ".K-of-" + std::to_string(at.size) + " (one file per rank)";
  const double every = args.checkpoint_every.value_or(scene.run.checkpoint_every);
  char when[64];
  if (every == 0.0)
    std::snprintf(when, sizeof when, "at every sample");
  else
    std::snprintf(when, sizeof when, "every %g min", every);
  if (!what.gas) {
    std::printf(
        "checkpoints  %s and on SIGINT or SIGTERM to %s: the finished replicas (an intruder replica is "
        "kept whole only)\n",
        when, out.c_str());
    return;
  }
  // A replica in flight: 24 bytes per particle, 52 for weighted particles (their count at the start).
  const double per_particle = scene.weights ? 52.0 : 24.0;
  std::printf(
      "checkpoints  %s and on SIGINT or SIGTERM to %s: the finished replicas, and each replica in flight "
      "at its latest sample (%.1f MB each)\n",
      when, out.c_str(), per_particle * static_cast<double>(total_particles(scene)) / 1e6);
}

int explain_command(const Scene& full_scene, const RunPlan& plan, const RunArgs& args) {
  const Place at = place();
  if (at.rank != 0) return exit_ok;
  const int threads = args.threads > 0 ? args.threads : omp_get_max_threads();
  Scene rank_share = full_scene;  // over several ranks: rank 0's replicas (the others run as many or one fewer)
  rank_share.run.replicas = own_replicas(full_scene.run.replicas, at);
  const Scene& scene = at.size > 1 && plan.spread == Spread::replicas ? rank_share : full_scene;
  const PlanExplanation what = explain_plan(plan, scene, threads, args.threads_per_replica);
  std::printf("scene        %s\n", args.scene.c_str());
  std::printf("kernel       %s\n", what.instantiation.c_str());
  for (const std::string& e : what.effects) std::printf("effect       %s\n", e.c_str());
  std::string absent;
  for (const std::string& a : what.absent) absent += (absent.empty() ? "" : ", ") + a;
  if (!absent.empty()) std::printf("not compiled %s (the scene does not name them)\n", absent.c_str());
  if (plan.spread == Spread::particles) {  // docs/user-guide/parallel-runs.md, "One system over several ranks"
    const double n = static_cast<double>(total_particles(full_scene));
    std::printf(
        "spread       every replica is one system over %d rank(s), the replicas one after another on one "
        "thread per rank; per rank %.1f MB of particles and at most %.0f MB of candidate list; it takes "
        "2-3x the time of one process for each replica (docs/user-guide/parallel-runs.md)\n",
        at.size, n * static_cast<double>(what.bytes_per_particle) / at.size / 1e6,
        static_cast<double>(spread_segment * spread_candidate_bytes) / 1e6);
    return exit_ok;
  }
  if (at.size > 1)
    std::printf(
        "ranks        %d MPI ranks, replica r on rank r mod %d; rank 0 runs %d of the %d replicas, "
        "memory and work below are rank 0's\n",
        at.size, at.size, scene.run.replicas, full_scene.run.replicas);
  explain_checkpoints(full_scene, plan, args, what);
  if (!what.gas) {
    std::printf("work         about %.3g collision events (one intruder per replica)\n", what.events);
    return exit_ok;
  }
  std::printf("memory       %.1f MB of particles (%d replicas at once, %zu bytes per particle)\n",
              static_cast<double>(what.particle_bytes) / 1e6, what.replicas_in_flight, what.bytes_per_particle);
  if (what.threads_per_replica > 1)
    std::printf(
        "threads      %d replica(s) at a time, each on %d threads: the candidates in concurrent rounds, the "
        "same bits as on one; faster for replicas of millions of particles, slower for small ones "
        "(docs/user-guide/parallel-runs.md)\n",
        what.replicas_in_flight, what.threads_per_replica);
  else if (threads > what.replicas_in_flight && what.threads_inside && args.threads_per_replica == 0)
    std::printf(
        "threads      %d replica(s) at a time, one thread each; %d thread(s) idle (by default threads go "
        "inside replicas of at least %s particles, where the rounds are faster than one thread; "
        "--threads-per-replica puts them inside smaller ones, docs/user-guide/parallel-runs.md)\n",
        what.replicas_in_flight, threads - what.replicas_in_flight, power_of_ten(what.least_particles_inside).c_str());
  else if (threads > what.replicas_in_flight)
    std::printf("threads      %d replica(s) at a time, one thread each; %d thread(s) idle%s\n", what.replicas_in_flight,
                threads - what.replicas_in_flight,
                what.threads_inside
                    ? " (--threads-per-replica puts them inside the replicas, docs/user-guide/parallel-runs.md)"
                    : " (this scheme runs a replica on one thread)");
  else
    std::printf("threads      %d replicas at a time, one thread each\n", what.replicas_in_flight);
  // Threads inside a replica shorten it by a factor that depends on its size and the machine
  // (docs/developer-guide/scaling.md): the time is the replicas' on one thread each, and says so.
  const double rate = measured_candidates_per_second(what.rate_class);
  const double seconds = what.candidates / (rate * what.replicas_in_flight);
  std::printf("work         %s%.3g candidate pairs, about %.0f s ", what.candidates_upper_bound ? "at most " : "",
              what.candidates, seconds);
  if (what.threads_per_replica > 1)
    std::printf(
        "with one thread per replica at %.2g candidates/s per thread (%s, drivers/explain_rates.toml); the %d "
        "threads inside each replica shorten that by a factor that depends on its size and the machine "
        "(docs/developer-guide/scaling.md)\n",
        rate, what.rate_class.c_str(), what.threads_per_replica);
  else
    std::printf("on %d threads at %.2g candidates/s per thread (%s, drivers/explain_rates.toml)\n", threads, rate,
                what.rate_class.c_str());
  return exit_ok;
}

/// A scene and the plan that runs it.
struct CheckedScene {
  Scene scene;
  RunPlan plan;
};

/// Loads a scene and makes its plan; on a bad scene, or one granmc cannot run as asked, sets `message` and
/// returns nothing.
std::optional<CheckedScene> load_checked_scene(const std::string& path, std::optional<std::uint64_t> seed,
                                               Spread spread, std::string& message) {
  try {
    Scene scene = load_scene(path);
    if (seed) scene.run.seed = *seed;
    RunPlan plan = make_plan(scene, spread);
    return CheckedScene{std::move(scene), std::move(plan)};
  } catch (const SceneError& e) {
    message = std::string("granmc: ") + e.what() + "\n";
  } catch (const PlanRefusal& e) {
    message = "granmc: " + path + ": " + e.what() + "\n";
  }
  return std::nullopt;
}

/// Loads a scene and makes its plan; on a bad scene prints one message and returns nothing. With MPI every
/// rank reads the scene and all go on only if all could (all_ranks_ok): a rank that stopped here would leave
/// the others waiting in the gather.
std::optional<CheckedScene> checked_scene(const std::string& path, std::optional<std::uint64_t> seed,
                                          Spread spread = Spread::replicas) {
  std::string message;
  std::optional<CheckedScene> scene = load_checked_scene(path, seed, spread, message);
  if (!all_ranks_ok(scene.has_value(), message)) return std::nullopt;
  return scene;
}

int run_command(const RunArgs& args) {
  const std::optional<CheckedScene> loaded =
      checked_scene(args.scene, args.seed, args.spread == "particles" ? Spread::particles : Spread::replicas);
  if (!loaded) return exit_bad_input;
  const Scene& scene = loaded->scene;
  if (args.explain) return explain_command(scene, loaded->plan, args);
  const std::string out = args.out.empty() ? default_output(args.scene) : args.out;

  const Place at = place();
  // Checkpoints (drivers/run_checkpoints.hpp), on every rank for its own replicas; none for one replica spread
  // over the ranks. An earlier run's checkpoint beside the output is never overwritten unasked: it is resumed
  // (--resume) or deleted by the user. Every rank decides alike (all_ranks_ok), so none waits alone.
  const bool checkpointable = loaded->plan.spread != Spread::particles;
  const CheckpointSettings settings{checkpointable && !args.no_checkpoints,
                                    args.checkpoint_every.value_or(scene.run.checkpoint_every), args.resume};
  std::optional<RunCheckpoints> checkpoints;
  if (!all_ranks_ok(args.resume.empty() || checkpointable,
                    "granmc: --resume: a run with one replica spread over the ranks (run.spread = \"particles\") "
                    "has no checkpoints\n"))
    return exit_bad_input;
  if (checkpointable) {
    const std::string earlier = checkpoint_path(out);
    if (!all_ranks_ok(!(settings.enabled && args.resume.empty() && !checkpoint_files(earlier).empty()),
                      "granmc: " + earlier +
                          " is the checkpoint of an earlier run of this output: continue it with "
                          "--resume " +
                          earlier + ", or delete it (and " + earlier + ".K-of-R) to start afresh\n"))
      return exit_bad_input;
    std::string refusal;
    try {
      checkpoints.emplace(scene, out, settings, at.rank, at.size);
    } catch (const CheckpointError& e) {
      refusal = "granmc: " + std::string(e.what()) + "\n";
    }
    if (!all_ranks_ok(refusal.empty(), refusal)) return exit_bad_input;
    if (checkpoints->restored_all() + checkpoints->restored_in_flight_all() > 0 && !args.quiet && at.rank == 0)
      std::printf("granmc: %zu of %d replicas from %s, %zu more going on from where they stopped\n",
                  checkpoints->restored_all(), scene.run.replicas, args.resume.c_str(),
                  checkpoints->restored_in_flight_all());
  }
  try {
    const JobResult done = run_job(scene, loaded->plan, {out, args.summary}, args.threads, args.quiet,
                                   args.threads_per_replica, checkpoints ? &*checkpoints : nullptr);
    if (at.rank != 0) return exit_ok;  // rank 0 alone reports
    if (!args.quiet && at.size == 1) {
      std::printf("granmc %s: %s, %d replicas, %.1f s on %d threads -> %s%s%s\n", version, args.scene.c_str(),
                  scene.run.replicas, done.wall_seconds, done.threads, out.c_str(), args.summary.empty() ? "" : ", ",
                  args.summary.c_str());
    } else if (!args.quiet) {
      std::printf("granmc %s: %s, %d replicas, %.1f s on %d MPI ranks (rank 0: %d threads) -> %s%s%s\n", version,
                  args.scene.c_str(), scene.run.replicas, done.wall_seconds, at.size, done.threads, out.c_str(),
                  args.summary.empty() ? "" : ", ", args.summary.c_str());
    }
    return exit_ok;
  } catch (const RunInterrupted&) {
    try {
      const std::string& file = checkpoints->write_now();
      if (at.size == 1)
        std::cerr << "granmc: interrupted; " << checkpoints->finished() << " of " << scene.run.replicas
                  << " replicas finished and " << checkpoints->in_flight() << " stopped at a sample time are kept in "
                  << file << "; continue with: granmc run " << args.scene << " --resume " << file
                  << " (and the same --out, --summary and --seed)\n";
      else if (at.rank == 0)
        std::cerr << "granmc: interrupted; each rank keeps its finished replicas and those stopped at a sample time "
                     "in "
                  << checkpoint_path(out) << ".K-of-" << at.size
                  << "; continue on any number of ranks with: granmc run " << args.scene << " --resume "
                  << checkpoint_path(out) << " (and the same --out, --summary and --seed)\n";
    } catch (const std::exception& e) {
      std::cerr << "granmc: interrupted, and " << e.what() << "\n";
    }
    return exit_interrupted;
  } catch (const std::exception& e) {
    return run_failure(e);
  }
}

int theory_command(const std::string& path) {
  // The scene alone, without its plan: the theory of a scene that granmc cannot run yet (a gas in d = 2) too.
  std::string message;
  std::optional<Scene> scene;
  try {
    scene = load_scene(path);
  } catch (const SceneError& e) {
    message = std::string("granmc: ") + e.what() + "\n";
  }
  if (!all_ranks_ok(scene.has_value(), message)) return exit_bad_input;
  if (place().rank != 0) return exit_ok;
  std::cout << scene_theory_json(*scene).dump(2) << "\n";
  return exit_ok;
}

struct BathArgs {
  std::string scene;
  std::vector<double> v1{-2.0, -1.0, 0.0, 1.0, 2.0};
  std::uint64_t samples = 100000;
  std::vector<double> range{-4.0, 4.0};
  int bins = 80;
};

/// `granmc bath`: the fluxes and the sampled g_+ of an intruder scene's bath (kernel/analysis/bath_probe.hpp),
/// as JSON.
int bath_command(const BathArgs& args) {
  const std::optional<CheckedScene> checked = checked_scene(args.scene, std::nullopt);
  if (!checked) return exit_bad_input;
  if (place().rank != 0) return exit_ok;
  if (!(args.range[1] > args.range[0])) {
    std::fprintf(stderr, "granmc bath: --range LO HI needs LO < HI (got %g %g)\n", args.range[0], args.range[1]);
    return exit_bad_input;
  }
  std::vector<double> edges;
  for (int b = 0; b <= args.bins; ++b) edges.push_back(args.range[0] + (args.range[1] - args.range[0]) * b / args.bins);
  auto probe = [&](const auto& bath) {
    nlohmann::json points = nlohmann::json::array();
    for (const BathProbePoint& p : probe_bath(bath, args.v1, args.samples, edges, checked->scene.run.seed))
      points.push_back({{"v1", p.v1},
                        {"flux_right", p.flux_right},
                        {"flux_left", p.flux_left},
                        {"acceptance", static_cast<double>(args.samples) / static_cast<double>(p.attempts)},
                        {"g_right_density", p.density},
                        {"g_right_outside", p.outside}});
    return nlohmann::json{
        {"bath", bath.name},       {"a", bath.a},    {"density", bath.rho}, {"temperature", bath.temperature()},
        {"samples", args.samples}, {"edges", edges}, {"points", points}};
  };
  const auto bath_of = [](const SchemeChoice& s) -> std::optional<BathChoice> {
    if (const auto* p = std::get_if<IntruderLinePlan>(&s)) return p->bath;
    if (const auto* p = std::get_if<IntruderDsmcPlan>(&s)) return p->bath;
    if (const auto* p = std::get_if<NeedlePlan>(&s)) return p->bath;
    return std::nullopt;
  };
  const std::optional<BathChoice> bath = bath_of(checked->plan.scheme);
  if (!bath) {
    std::fprintf(stderr, "granmc bath: %s has no [intruder] table, so no bath to probe\n", args.scene.c_str());
    return exit_bad_input;
  }
  std::cout << std::visit(probe, *bath).dump(1) << "\n";
  return exit_ok;
}

}  // namespace

int cli_main(int argc, char** argv) {
  CLI::App app{"granmc: direct-simulation Monte Carlo for granular gases (Boltzmann and Enskog equations)"};
  app.set_version_flag("--version", "granmc " + std::string(build_id()));
  app.require_subcommand(1);

  RunArgs run;
  CLI::App* run_cmd = app.add_subcommand("run", "Run a scene and write its results (HDF5, optional JSON summary)");
  run_cmd->add_option("scene", run.scene, "Scene file (TOML, see docs/formats/scenes.md)")->required();
  run_cmd->add_option("--out", run.out, "HDF5 output file (default: <scene name>.h5 in the current directory)");
  run_cmd->add_option("--summary", run.summary,
                      "Also write the JSON summary (docs/formats/output-format.md) to this file");
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (default: all cores)")->check(CLI::Range(1, 4096));
  run_cmd
      ->add_option("--threads-per-replica", run.threads_per_replica,
                   "At most this many threads inside one replica, for threads the replicas leave over (time-stepped "
                   "and event schemes: the candidates in concurrent rounds, the same bits; default: all of them, "
                   "for replicas of at least " +
                       power_of_ten(stepped_rounds_inside.least_particles) + " particles (time-stepped) or " +
                       power_of_ten(event_rounds_inside.least_particles) +
                       " (event), else 1: docs/user-guide/parallel-runs.md)")
      ->check(CLI::Range(1, 4096));
  run_cmd->add_option("--seed", run.seed, "Override the scene's run.seed");
  run_cmd->add_flag("--quiet", run.quiet, "No progress line and no closing message");
  run_cmd
      ->add_option("--spread", run.spread,
                   "What the MPI ranks share: \"replicas\" (default: each rank runs its replicas) or \"particles\" "
                   "(each replica is one system spread over all ranks, for systems larger than one machine; "
                   "docs/user-guide/parallel-runs.md)")
      ->check(CLI::IsMember({"replicas", "particles"}));
  run_cmd->add_option(
      "--resume", run.resume,
      "Continue the run of this scene that a checkpoint (OUT.checkpoint) holds: only the replicas it "
      "lacks run, and the files are those of an uninterrupted run (docs/formats/scenes.md, \"Checkpoints\")");
  run_cmd
      ->add_option("--checkpoint-every", run.checkpoint_every,
                   "Minutes between checkpoints (OUT.checkpoint: the finished replicas, and the gas schemes' ones in "
                   "flight; 0: at every sample; "
                   "default: the scene's run.checkpoint_every, 10); one is also written on SIGINT or SIGTERM, and "
                   "the run stops with status 3")
      ->check(CLI::NonNegativeNumber);
  run_cmd->add_flag("--no-checkpoints", run.no_checkpoints,
                    "No checkpoints, and SIGINT or SIGTERM end the run at once with nothing kept");
  run_cmd->add_flag("--explain", run.explain,
                    "Print the kernel, the effects, the memory and a cost estimate, and run nothing");

  SweepArgs sweep;
  CLI::App* sweep_cmd =
      app.add_subcommand("sweep",
                         "Run the scenes of a sweep file one after another: one HDF5 file and JSON summary each, and "
                         "index.json; a rerun skips the scenes already done");
  sweep_cmd->add_option("sweep", sweep.sweep, "Sweep file (TOML, see docs/formats/scenes.md, \"Sweep files\")")
      ->required();
  sweep_cmd->add_option("--out-dir", sweep.out_dir,
                        "Directory of the outputs and index.json (default: <sweep name>/ in the current directory)");
  sweep_cmd->add_option("--threads", sweep.threads, "OpenMP threads (default: all cores)")->check(CLI::Range(1, 4096));
  sweep_cmd
      ->add_option("--threads-per-replica", sweep.threads_per_replica,
                   "As for granmc run: at most this many threads inside one replica (default: by the replicas' "
                   "size, docs/user-guide/parallel-runs.md)")
      ->check(CLI::Range(1, 4096));
  sweep_cmd->add_flag("--quiet", sweep.quiet, "No progress lines, no notes on skipped scenes, no closing message");
  sweep_cmd->add_flag("--keep-other-builds", sweep.keep_other_builds,
                      "Keep the files of scenes done by another build of granmc (index.json says which); by default "
                      "they run again");

  CLI::App* format_cmd = app.add_subcommand(
      "output-format",
      "Print the format of the HDF5 file and the JSON summary (Markdown, docs/formats/output-format.md)");

  std::string theory_scene;
  CLI::App* theory_cmd = app.add_subcommand("theory", "Print the theory predictions that apply to a scene (JSON)");
  theory_cmd->add_option("scene", theory_scene, "Scene file (TOML)")->required();

  BathArgs bath;
  CLI::App* bath_cmd = app.add_subcommand(
      "bath", "Print the collision fluxes and the sampled law g_+ of an intruder scene's bath (JSON, 002 Figs. 1-2)");
  bath_cmd->add_option("scene", bath.scene, "Scene file with an [intruder] table (TOML)")->required();
  bath_cmd->add_option("--v1", bath.v1, "Intruder velocities (default: -2 -1 0 1 2)");
  bath_cmd->add_option("--samples", bath.samples, "Draws from g_+ at each v1 (default 100000)")
      ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1} << 40));
  bath_cmd->add_option("--range", bath.range, "Histogram range of the bath velocity (default: -4 4)")->expected(2);
  bath_cmd->add_option("--bins", bath.bins, "Histogram bins (default 80)")->check(CLI::Range(1, 1000000));

  // Help, version and parse errors: printed by rank 0 only (every rank parses the same arguments).
  std::ostream quiet(nullptr);
  const bool root = place().rank == 0;
  std::ostream& out = root ? std::cout : quiet;
  std::ostream& err = root ? std::cerr : quiet;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    app.exit(e, out, err);
    return exit_bad_input;
  }
  if (*run_cmd) return run_command(run);
  if (*sweep_cmd) return sweep_command(sweep);
  if (*bath_cmd) return bath_command(bath);
  if (*format_cmd) {
    if (place().rank == 0) std::cout << output_format_page();
    return exit_ok;
  }
  return theory_command(theory_scene);
}

}  // namespace granmc
