#include "drivers/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "drivers/cli.hpp"
#include "drivers/run_checkpoints.hpp"
#include "drivers/run_job.hpp"
#include "granmc/version.hpp"
#include "io/build_id.hpp"
#include "io/fnv1a.hpp"
#include "io/summary_json.hpp"
#include "io/sweep_file.hpp"
#include "kernel/setup/run_plan.hpp"
#ifdef GRANMC_HAVE_MPI
#include "drivers/mpi_replicas.hpp"
#endif

namespace granmc {

namespace {

namespace fs = std::filesystem;

constexpr const char* index_name = "index.json";

/// FNV-1a, 64 bits, of the scene text (io/fnv1a.hpp): enough to notice an edited scene.
std::string scene_hash(const std::string& text) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "fnv1a64:%016llx", static_cast<unsigned long long>(fnv1a64(text)));
  return buf;
}

/// Reads the sweep and makes its scenes; on a bad sweep or scene sets `message` and returns nothing.
std::optional<Sweep> load_checked_sweep(const std::string& path, std::string& message) {
  try {
    Sweep sweep = load_sweep(path);
    for (const SweepScene& s : sweep.scenes) {
      if (const std::string why = plan_refusal(s.scene); !why.empty()) {
        message = "granmc: " + path + ": " + s.scene.source_path + ": " + why + "\n";
        return std::nullopt;
      }
    }
    return sweep;
  } catch (const SweepError& e) {
    message = std::string("granmc: ") + e.what() + "\n";
    return std::nullopt;
  }
}

/// What an earlier run's index.json says of a scene.
struct EarlierRecord {
  std::string status, scene_hash;
  std::string build;  // empty when the index predates build ids
};

/// What an earlier run's index.json says of each scene, by name. Nothing when there is no readable index
/// (every scene then runs).
std::map<std::string, EarlierRecord> earlier_records(const fs::path& index) {
  std::map<std::string, EarlierRecord> records;
  std::ifstream in(index);
  if (!in) return records;
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object() || !j.contains("scenes") || !j["scenes"].is_array()) return records;
  for (const auto& s : j["scenes"]) {
    const auto text = [&s](const char* key) {
      return s.is_object() && s.contains(key) && s[key].is_string() ? s[key].get<std::string>() : std::string();
    };
    if (!text("name").empty()) records[text("name")] = {text("status"), text("scene_hash"), text("build")};
  }
  return records;
}

/// Removes the temporary files (FILE.tmp-PID, io/hdf5_output.hpp, io/summary_json.hpp) that a killed run
/// left of `files` in `dir`; returns their names.
std::vector<std::string> remove_stale_temporaries(const fs::path& dir, const std::set<std::string>& files) {
  std::vector<std::string> removed;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    const std::size_t at = name.rfind(".tmp-");
    if (at == std::string::npos || !files.contains(name.substr(0, at))) continue;
    const std::string pid = name.substr(at + 5);
    if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
    fs::remove(entry.path());
    removed.push_back(name);
  }
  return removed;
}

std::string hdf5_name(const SweepScene& s) { return s.name + ".h5"; }
std::string summary_name(const SweepScene& s) { return s.name + ".json"; }

/// Runs one scene of the sweep as `granmc run` would, writing its two files into `dir`. In one process the
/// scene keeps checkpoints as `granmc run` does (drivers/run_checkpoints.hpp), and an interrupted sweep resumes
/// inside the interrupted scene: from NAME.h5.checkpoint when it belongs to this scene and build, else afresh
/// (saying why). Returns false when a signal interrupted the scene (its checkpoint written and named).
bool run_sweep_scene(const SweepScene& s, const fs::path& dir, const SweepArgs& args, bool one_process) {
  const std::string hdf5 = (dir / hdf5_name(s)).string();
  const JobOutputs outputs{hdf5, (dir / summary_name(s)).string()};
  if (!one_process) {
    run_job(s.scene, make_plan(s.scene), outputs, args.threads, args.quiet, args.threads_per_replica);
    return true;
  }
  const std::string earlier = checkpoint_path(hdf5);
  std::optional<RunCheckpoints> checkpoints;
  if (fs::exists(earlier)) {
    try {
      checkpoints.emplace(s.scene, hdf5, CheckpointSettings{true, s.scene.run.checkpoint_every, earlier});
      if (!args.quiet)
        std::printf("granmc sweep: %s resumes from %s (%zu of %d replicas, %zu more in flight)\n", s.name.c_str(),
                    earlier.c_str(), checkpoints->restored(), s.scene.run.replicas, checkpoints->restored_in_flight());
    } catch (const CheckpointError& e) {
      if (!args.quiet) std::printf("granmc sweep: %s runs afresh: %s\n", s.name.c_str(), e.what());
      fs::remove(earlier);
    }
  }
  if (!checkpoints) checkpoints.emplace(s.scene, hdf5, CheckpointSettings{true, s.scene.run.checkpoint_every, ""});
  std::fflush(stdout);
  try {
    run_job(s.scene, make_plan(s.scene), outputs, args.threads, args.quiet, args.threads_per_replica, &*checkpoints);
    return true;
  } catch (const RunInterrupted&) {
    const std::string& file = checkpoints->write_now();
    std::cerr << "granmc sweep: interrupted in " << s.name << "; " << checkpoints->finished() << " of "
              << s.scene.run.replicas << " replicas finished and " << checkpoints->in_flight()
              << " stopped at a sample time are kept in " << file << "; run the same sweep again to continue\n";
    return false;
  }
}

/// The index: per scene its status, scene hash and the build that made its files (this one for a scene
/// not done yet).
nlohmann::json index_json(const std::string& sweep_path, const Sweep& sweep, const std::vector<std::string>& hashes,
                          const std::vector<std::string>& builds, const std::vector<bool>& done) {
  nlohmann::json scenes = nlohmann::json::array();
  for (std::size_t k = 0; k < sweep.scenes.size(); ++k) {
    const SweepScene& s = sweep.scenes[k];
    scenes.push_back({{"name", s.name},
                      {"values", s.values},
                      {"hdf5", hdf5_name(s)},
                      {"summary", summary_name(s)},
                      {"status", done[k] ? "done" : "pending"},
                      {"scene_hash", hashes[k]},
                      {"build", done[k] ? builds[k] : std::string(build_id())}});
  }
  return {{"sweep", sweep_path},
          {"base", sweep.base_path},
          {"version", version},
          {"build", build_id()},
          {"scenes", scenes}};
}

#ifdef GRANMC_HAVE_MPI
/// The scenes not done, whole scenes on `groups` groups of consecutive ranks (each scene's replicas over
/// its group, as `granmc run` spreads them): in round r, group g runs the (r groups + g)-th scene left.
/// After each round every rank learns which scenes are done, and world rank 0 rewrites the index.
void run_in_groups(const SweepArgs& args, const Sweep& sweep, const fs::path& dir,
                   const std::vector<std::string>& hashes, const std::vector<std::string>& builds,
                   std::vector<bool>& done, int groups, bool world_root) {
  std::vector<std::size_t> todo;
  for (std::size_t k = 0; k < done.size(); ++k)
    if (!done[k]) todo.push_back(k);
  const mpi::RankGroups scope(groups);
  const Place in_group = place();
  for (std::size_t first = 0; first < todo.size(); first += static_cast<std::size_t>(groups)) {
    std::vector<int> finished(done.size(), 0);
    if (const std::size_t at = first + static_cast<std::size_t>(scope.group()); at < todo.size()) {
      const std::size_t k = todo[at];
      const SweepScene& s = sweep.scenes[k];
      const auto start = std::chrono::steady_clock::now();
      run_sweep_scene(s, dir, args, false);
      finished[k] = 1;
      if (in_group.rank == 0 && !args.quiet) {
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("granmc sweep: scene %zu of %zu (%s) done in %.1f s by rank group %d of %d (%d ranks)\n", k + 1,
                    done.size(), s.name.c_str(), seconds, scope.group() + 1, groups, in_group.size);
        std::fflush(stdout);
      }
    }
    mpi::world_max(finished);
    for (std::size_t k = 0; k < done.size(); ++k)
      if (finished[k] != 0) done[k] = true;
    if (world_root) write_summary((dir / index_name).string(), index_json(args.sweep, sweep, hashes, builds, done));
  }
}
#endif

std::string plural(std::size_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

}  // namespace

int sweep_command(const SweepArgs& args) {
  // Every rank reads the sweep and all go on only if all could: a rank that stopped here would leave the
  // others waiting in the first scene's gather.
  std::string message;
  const std::optional<Sweep> loaded = load_checked_sweep(args.sweep, message);
  if (!all_ranks_ok(loaded.has_value(), message)) return exit_bad_input;
  const Sweep& sweep = *loaded;
  const std::size_t count = sweep.scenes.size();

  const Place at = place();
  const bool talk = at.rank == 0 && !args.quiet;
  const fs::path dir = args.out_dir.empty() ? fs::path(args.sweep).stem() : fs::path(args.out_dir);
  std::vector<std::string> hashes;
  for (const SweepScene& s : sweep.scenes) hashes.push_back(scene_hash(s.scene.source_text));
  std::vector<std::string> builds(count, build_id());  // the build that made each scene's files

  try {
    // Rank 0 alone looks at what an earlier run left (it alone writes); every rank learns which scenes are
    // done, so that all run the same scenes in the same order.
    std::vector<bool> done(count, false);
    if (at.rank == 0) {
      fs::create_directories(dir);
      std::set<std::string> files = {index_name};
      for (const SweepScene& s : sweep.scenes)
        files.insert({hdf5_name(s), summary_name(s), checkpoint_path(hdf5_name(s))});
      for (const std::string& name : remove_stale_temporaries(dir, files))
        if (talk) std::printf("granmc sweep: removed %s, left by an interrupted run\n", (dir / name).c_str());
      const auto records = earlier_records(dir / index_name);
      for (std::size_t k = 0; k < count; ++k) {
        const SweepScene& s = sweep.scenes[k];
        const auto record = records.find(s.name);
        const bool same_scene_done = record != records.end() && record->second.status == "done" &&
                                     record->second.scene_hash == hashes[k] && fs::exists(dir / hdf5_name(s)) &&
                                     fs::exists(dir / summary_name(s));
        if (!same_scene_done) continue;
        const std::string& made_by = record->second.build;
        if (made_by == build_id() || args.keep_other_builds) {
          done[k] = true;
          builds[k] = made_by;
          if (talk && made_by == build_id())
            std::printf("granmc sweep: scene %zu of %zu (%s) skipped: done by an earlier run with the same scene\n",
                        k + 1, count, s.name.c_str());
          else if (talk)
            std::printf(
                "granmc sweep: scene %zu of %zu (%s) kept: made by build %s, not this one (%s), kept as "
                "--keep-other-builds asks\n",
                k + 1, count, s.name.c_str(), made_by.empty() ? "(not recorded)" : made_by.c_str(), build_id());
        } else if (talk) {
          std::printf(
              "granmc sweep: scene %zu of %zu (%s) runs again: its files were made by build %s, this is %s "
              "(--keep-other-builds keeps them)\n",
              k + 1, count, s.name.c_str(), made_by.empty() ? "(not recorded)" : made_by.c_str(), build_id());
        }
      }
      write_summary((dir / index_name).string(), index_json(args.sweep, sweep, hashes, builds, done));
      std::fflush(stdout);
    }
    for (std::size_t k = 0; k < count; ++k) done[k] = rank0_value(done[k]);

    const auto sweep_start = std::chrono::steady_clock::now();
    std::size_t to_run = 0;
    for (std::size_t k = 0; k < count; ++k) to_run += done[k] ? 0 : 1;
    std::size_t ran = 0;
    double spent = 0.0;
    // More ranks than the largest scene has replicas would leave ranks idle: then whole scenes go to groups
    // of ranks (docs/user-guide/parallel-runs.md, "Over MPI ranks").
    int most_replicas = 1;
    for (std::size_t k = 0; k < count; ++k)
      if (!done[k]) most_replicas = std::max(most_replicas, sweep.scenes[k].scene.run.replicas);
    const int groups = static_cast<int>(std::min<std::size_t>(
        std::max<std::size_t>(to_run, 1), static_cast<std::size_t>(std::max(1, at.size / most_replicas))));
#ifdef GRANMC_HAVE_MPI
    if (groups > 1) run_in_groups(args, sweep, dir, hashes, builds, done, groups, at.rank == 0);
#endif
    for (std::size_t k = 0; k < count; ++k) {
      if (done[k]) continue;
      const SweepScene& s = sweep.scenes[k];
      const auto start = std::chrono::steady_clock::now();
      if (!run_sweep_scene(s, dir, args, at.size == 1)) return exit_interrupted;
      done[k] = true;
      if (at.rank != 0) continue;
      write_summary((dir / index_name).string(), index_json(args.sweep, sweep, hashes, builds, done));
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      spent += seconds;
      ++ran;
      if (talk) {
        // The scenes left are assumed to cost what those run so far did on average.
        std::printf("granmc sweep: scene %zu of %zu (%s) done in %.1f s, about %.0f s left\n", k + 1, count,
                    s.name.c_str(), seconds, spent / static_cast<double>(ran) * static_cast<double>(to_run - ran));
        std::fflush(stdout);
      }
    }
    if (talk) {
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep_start).count();
      std::string where = at.size == 1 ? "" : " on " + std::to_string(at.size) + " MPI ranks";
      if (groups > 1) where += " in " + std::to_string(groups) + " groups";
      std::printf("granmc %s: %s, %s (%zu run, %zu skipped) in %.1f s%s -> %s\n", version, args.sweep.c_str(),
                  plural(count, "scene").c_str(), to_run, count - to_run, wall, where.c_str(),
                  (dir / index_name).c_str());
    }
    return exit_ok;
  } catch (const std::exception& e) {
    return run_failure(e);
  }
}

}  // namespace granmc
