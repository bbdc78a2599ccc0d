// Replicas over MPI ranks (GRANMC_MPI=ON, docs/developer-guide/scaling.md): the byte round trip of every ReplicaSeries
// field, and `mpirun -np R granmc run` against one process on 1 and 2 threads for small scenes (cooling,
// shear with the Gaussian thermostat, the 1D intruder): every dataset and attribute of the HDF5 file
// bit-identical (wall_seconds and threads aside), the JSON summaries equal, nothing written by the other
// ranks, and one message from a bad scene. The test launches mpirun itself; CTest sets
// OMPI_ALLOW_RUN_AS_ROOT(_CONFIRM) for it (tests/CMakeLists.txt), as OpenMPI refuses root without them.
#include <hdf5.h>
#include <signal.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "drivers/mpi_replicas.hpp"
#include "io/output_schema.hpp"
#include "tests/granmc_process.hpp"

namespace granmc {
namespace {

namespace fs = std::filesystem;
using granmc_test::Outcome;
using granmc_test::slurp;

// --- granmc under mpirun against one process ---

class MpiRun : public granmc_test::GranmcDirectory {
 protected:
  MpiRun() : GranmcDirectory("granmc_mpi_") {}

  static std::string mpirun(int ranks) {
    return std::string("'" GRANMC_MPIEXEC "' -np ") + std::to_string(ranks) + " --oversubscribe";
  }

  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }

  struct Way {
    std::string name, prefix, threads;
    int ranks;  // recorded as "ranks" in the summary
  };
  /// One process on 1 and 2 threads (granmc started without mpirun: MPI's singleton, one rank), mpirun with 2
  /// ranks, and up to `most_ranks`: 2 ranks of 2 threads and 3 ranks (5 replicas: 2, 2, 1) from 3, 6 ranks (rank 5
  /// runs no replica) from 6. Ranks beyond the cores wait in each exchange of a system spread over them until the
  /// scheduler runs the rank they need, so on a busy host a spread run over 6 ranks of 2 cores can take 20 times
  /// its idle time: one spread test runs them.
  static std::vector<Way> ways(int most_ranks) {
    std::vector<Way> w{{"one process, 1 thread", "", "1", 1},
                       {"one process, 2 threads", "", "2", 1},
                       {"mpirun -np 2, 1 thread", mpirun(2), "1", 2}};
    if (most_ranks >= 3)
      w.insert(w.end(),
               {{"mpirun -np 2, 2 threads", mpirun(2), "2", 2}, {"mpirun -np 3, 1 thread", mpirun(3), "1", 3}});
    if (most_ranks >= 6) w.push_back({"mpirun -np 6 (a rank without replicas), 1 thread", mpirun(6), "1", 6});
    return w;
  }

  /// Runs scene.toml once per way (with `options` added to each command) into its own outputs, and checks
  /// them all against the first.
  void expect_identical_runs(const std::vector<Way>& ways, const std::vector<std::string>& must_have,
                             const std::string& options = "") {
    std::vector<std::string> outputs;
    for (std::size_t k = 0; k < ways.size(); ++k) {
      const Way& w = ways[k];
      const std::string stem = "run" + std::to_string(k);
      const Outcome o = granmc(
          "run scene.toml --seed 77 --out " + stem + ".h5 --summary " + stem + ".json --threads " + w.threads + options,
          w.prefix);
      ASSERT_EQ(o.status, 0) << w.name << "\n" << o.stdout_text << o.stderr_text;
      EXPECT_EQ(std::count(o.stdout_text.begin(), o.stdout_text.end(), '\n'), 1) << w.name << ": one closing line\n"
                                                                                 << o.stdout_text;
      EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / (stem + ".json")))["ranks"], w.ranks) << w.name;
      outputs.push_back(stem);
    }
    std::vector<std::string> expected_files{"scene.toml"};
    for (const std::string& s : outputs) expected_files.insert(expected_files.end(), {s + ".h5", s + ".json"});
    std::sort(expected_files.begin(), expected_files.end());
    EXPECT_EQ(files(), expected_files) << "only rank 0 writes, and only its two files";

    const auto reference = read_h5((dir_ / (outputs[0] + ".h5")).string());
    for (const std::string& name : must_have) EXPECT_TRUE(reference.contains(name)) << name;
    const nlohmann::json reference_summary = summary(outputs[0]);
    for (std::size_t k = 1; k < outputs.size(); ++k) {
      SCOPED_TRACE(ways[k].name);
      const auto other = read_h5((dir_ / (outputs[k] + ".h5")).string());
      EXPECT_EQ(other.size(), reference.size());
      for (const auto& [name, bytes] : reference) {
        const auto it = other.find(name);
        ASSERT_NE(it, other.end()) << name;
        EXPECT_TRUE(it->second == bytes) << name << " differs";
      }
      EXPECT_EQ(summary(outputs[k]), reference_summary);
    }
  }

  /// Two sweep directories hold the same index (every scene done) and, scene by scene, bit-identical HDF5
  /// files and equal summaries; `other` holds nothing else.
  void expect_same_sweep(const std::string& reference, const std::string& other, std::size_t scenes) {
    const nlohmann::json index = nlohmann::json::parse(slurp(dir_ / reference / "index.json"));
    EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / other / "index.json")), index);
    ASSERT_EQ(index["scenes"].size(), scenes);
    std::vector<std::string> expected{"index.json"};
    for (const auto& scene : index["scenes"]) {
      const std::string name = scene["name"];
      SCOPED_TRACE(name);
      EXPECT_EQ(scene["status"], "done");
      expected.insert(expected.end(), {name + ".h5", name + ".json"});
      const auto a = read_h5((dir_ / reference / (name + ".h5")).string());
      const auto b = read_h5((dir_ / other / (name + ".h5")).string());
      EXPECT_FALSE(a.empty());
      EXPECT_TRUE(a == b) << "the HDF5 files differ";
      EXPECT_EQ(summary(other + "/" + name), summary(reference + "/" + name));
    }
    std::vector<std::string> written;
    for (const auto& e : fs::directory_iterator(dir_ / other)) written.push_back(e.path().filename().string());
    std::sort(written.begin(), written.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(written, expected) << "only the sweep's files, written once";
  }

  /// The JSON summary without what may differ between runs of the same seed.
  nlohmann::json summary(const std::string& stem) const {
    nlohmann::json j = nlohmann::json::parse(slurp(dir_ / (stem + ".json")));
    for (const std::string& key : machine_records()) j.erase(key);
    return j;
  }

  /// Every dataset ("path") and attribute ("path@name") of an HDF5 file as its bytes in native layout
  /// (variable-length strings as their text); the root's machine records (machine_records()) left out.
  static std::map<std::string, std::vector<char>> read_h5(const std::string& path) {
    std::map<std::string, std::vector<char>> items;
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_GE(file, 0) << path;
    if (file < 0) return items;
    struct Visit {
      hid_t file;
      std::map<std::string, std::vector<char>>* items;
    } visit{file, &items};
    H5Ovisit(
        file, H5_INDEX_NAME, H5_ITER_INC,
        [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
          auto& v = *static_cast<Visit*>(data);
          std::string object = "/";  // appended, not "/" + name: GCC 12 warns (-Wrestrict) on that, falsely
          if (std::string_view(name) != ".") object += name;
          const hid_t obj = H5Oopen(v.file, object.c_str(), H5P_DEFAULT);
          if (info->type == H5O_TYPE_DATASET) (*v.items)[object] = read_dataset(obj);
          struct Attrs {
            std::string object;
            std::map<std::string, std::vector<char>>* items;
          } attrs{object, v.items};
          H5Aiterate2(
              obj, H5_INDEX_NAME, H5_ITER_INC, nullptr,
              [](hid_t loc, const char* attr_name, const H5A_info_t*, void* d) -> herr_t {
                auto& a = *static_cast<Attrs*>(d);
                const std::string n(attr_name);
                const auto& machine = machine_records();
                if (a.object == "/" && std::find(machine.begin(), machine.end(), n) != machine.end()) return 0;
                const hid_t attr = H5Aopen(loc, attr_name, H5P_DEFAULT);
                (*a.items)[a.object + "@" + n] = read_attribute(attr);
                H5Aclose(attr);
                return 0;
              },
              &attrs);
          H5Oclose(obj);
          return 0;
        },
        &visit);
    H5Fclose(file);
    return items;
  }

  static std::vector<char> read_dataset(hid_t set) {
    const hid_t type = H5Dget_type(set);
    const hid_t native = H5Tget_native_type(type, H5T_DIR_ASCEND);
    const hid_t space = H5Dget_space(set);
    const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    std::vector<char> bytes;
    if (H5Tis_variable_str(type) > 0) {
      std::vector<char*> text(n);
      EXPECT_GE(H5Dread(set, native, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()), 0);
      for (char* t : text) bytes.insert(bytes.end(), t, t + std::strlen(t) + 1);
      H5Dvlen_reclaim(native, space, H5P_DEFAULT, text.data());
    } else {
      bytes.resize(n * H5Tget_size(native));
      EXPECT_GE(H5Dread(set, native, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()), 0);
    }
    H5Sclose(space);
    H5Tclose(native);
    H5Tclose(type);
    return bytes;
  }

  static std::vector<char> read_attribute(hid_t attr) {
    const hid_t type = H5Aget_type(attr);
    const hid_t native = H5Tget_native_type(type, H5T_DIR_ASCEND);
    const hid_t space = H5Aget_space(attr);
    const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
    std::vector<char> bytes;
    if (H5Tis_variable_str(type) > 0) {
      std::vector<char*> text(n);
      EXPECT_GE(H5Aread(attr, native, text.data()), 0);
      for (char* t : text) bytes.insert(bytes.end(), t, t + std::strlen(t) + 1);
      H5Dvlen_reclaim(native, space, H5P_DEFAULT, text.data());
    } else {
      bytes.resize(n * H5Tget_size(native));
      EXPECT_GE(H5Aread(attr, native, bytes.data()), 0);
    }
    H5Sclose(space);
    H5Tclose(native);
    H5Tclose(type);
    return bytes;
  }
};

/// `text` with each (from, to) replaced once; throws if a `from` does not occur.
std::string edited(std::string text, std::initializer_list<std::pair<std::string, std::string>> edits) {
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw std::invalid_argument("edited: no \"" + from + "\" in the scene");
    text.replace(at, from.size(), to);
  }
  return text;
}

/// A monodisperse hard-sphere cooling state: 5 replicas of 2000 particles, t_end 1, dt 0.01, 10 samples.
const std::string cooling_scene = R"([run]
method = "dsmc"
seed = 1
replicas = 5
t_end = 1.0
dt = 0.01
samples = 10
[[species]]
particles = 2000
[collision]
kernel = "hard-sphere"
restitution = 0.8
)";

TEST_F(MpiRun, CoolingStateIsBitIdenticalOverRanksAndThreads) {
  write("scene.toml", cooling_scene);
  expect_identical_runs(ways(6), {"/temperature/replicas", "/log_temperature/replicas", "/momentum/replicas",
                                  "/collisions/replicas", "/counters/candidates", "/temperature/mean@description"});
}

TEST_F(MpiRun, ShearWithGaussianThermostatIsBitIdentical) {
  write("scene.toml", cooling_scene + "[thermostat]\nkind = \"gaussian\"\n[shear]\nrate = 0.5\n");
  expect_identical_runs(ways(6), {"/temperature/replicas", "/viscosity/pressure_kinetic",
                                  "/viscosity/pressure_collisional", "/viscosity/eta_star_series/mean"});
}

/// One system over the ranks (--spread particles, schemes/rank_wave_backend.hpp): 20000 particles are 5 chunks of
/// 4096, so 2 and 3 ranks split them unevenly and 6 ranks leave one rank without particles. 2 replicas of 100 steps.
std::string spread_scene() {
  return edited(cooling_scene, {{"replicas = 5", "replicas = 2"},
                                {"particles = 2000", "particles = 20000"},
                                {"restitution = 0.8", "restitution = 0.7"}}) +
         "[output]\nhistogram = { shells = 16, radius = 4.0 }\n";
}

TEST_F(MpiRun, OneSystemOverRanksIsBitIdentical) {
  write("scene.toml", spread_scene());
  expect_identical_runs(ways(6),
                        {"/temperature/replicas", "/species/a/speed_distribution/counts", "/counters/candidates"},
                        " --spread particles");
}

TEST_F(MpiRun, OneSystemOverRanksWithGaussianThermostatIsBitIdentical) {
  write("scene.toml", spread_scene() + "[thermostat]\nkind = \"gaussian\"\n");
  expect_identical_runs(ways(2), {"/temperature/replicas"}, " --spread particles");
}

TEST_F(MpiRun, OneSystemOverRanksWithWhiteNoiseIsBitIdentical) {
  write("scene.toml", spread_scene() + "[thermostat]\nkind = \"white-noise\"\nbeta = 1.0\n");
  expect_identical_runs(ways(3), {"/temperature/replicas"}, " --spread particles");
}

TEST_F(MpiRun, OneSystemOfDisksOverRanksIsBitIdentical) {
  write("scene.toml", edited(spread_scene(), {{"seed = 1", "seed = 1\ndimension = 2"}}) +
                          "[thermostat]\nkind = \"white-noise\"\nbeta = 1.0\n");
  expect_identical_runs(ways(3), {"/temperature/replicas", "/species/a/speed_distribution/counts"},
                        " --spread particles");
}

TEST_F(MpiRun, OneSystemOfRoughParticlesOverRanksIsBitIdentical) {
  // Rough spheres (beta = 0) under white noise with half its power on the spins: the spins of partners held
  // elsewhere travel with their velocities, the kicks of the spins are drawn per global index.
  write("scene.toml",
        edited(spread_scene(), {{"restitution = 0.7", "restitution = 0.7\ntangential_restitution = 0.0"}}) +
            "[thermostat]\nkind = \"white-noise\"\nbeta = 1.0\nrotational_share = 0.5\n");
  expect_identical_runs(ways(3),
                        {"/temperature/replicas", "/species/a/rotational_temperature/replicas",
                         "/species/a/a11/replicas", "/species/a/speed_distribution/counts"},
                        " --spread particles");
}

TEST_F(MpiRun, IntruderIsBitIdentical) {
  write("scene.toml", R"([run]
method = "gillespie"
seed = 3
replicas = 5
t_end = 500.0
samples = 50
[intruder]
dimension = 1
mass = 1.0
restitution = 0.5
bath = "gaussian"
bath_a = 1.0
bath_density = 1.0
[output]
histogram = { shells = 20, radius = 5.0 }
)");
  expect_identical_runs(ways(2),
                        {"/temperature/replicas", "/intruder/velocity", "/intruder/speed_distribution/counts"});
}

/// Weighted particles (schemes/swpm_scheme.hpp) in a freely cooling hard-sphere gas, rescaled as it cools:
/// replicas over ranks carry the weighted records too.
TEST_F(MpiRun, WeightedParticlesAreBitIdentical) {
  write("scene.toml", R"([run]
method = "event"
seed = 5
replicas = 3
t_end = 20.0
dt = 0.5
samples = 6
sample_spacing = "log"
[[species]]
particles = 500
[collision]
kernel = "hard-sphere"
rate = 1.0
restitution = 0.5
[output]
histogram = { shells = 24, radius = 12.0, speed = "scaled" }
[weights]
scheme = "swpm"
particles_per_shell = 8
)");
  expect_identical_runs(ways(2), {"/temperature/replicas", "/species/a/speed_distribution/counts", "/weights/particles",
                                  "/weights@reductions", "/counters/rescales"});
}

/// `granmc sweep` under mpirun (docs/user-guide/parallel-runs.md, "Over MPI ranks"): the same index and, scene by
/// scene, the same files as one process; only rank 0 writes; a rerun skips every scene.
TEST_F(MpiRun, SweepOverRanksMatchesOneProcessAndResumes) {
  write("base.toml", cooling_scene);
  write("alpha.toml", "base = \"base.toml\"\n[grid]\n\"collision.restitution\" = [0.6, 0.8]\nrun.seed = [1, 2]\n");
  const Outcome one = granmc("sweep alpha.toml --out-dir one --threads 1 --quiet");
  ASSERT_EQ(one.status, 0) << one.stdout_text << one.stderr_text;
  const Outcome two = granmc("sweep alpha.toml --out-dir two --threads 1", mpirun(2));
  ASSERT_EQ(two.status, 0) << two.stdout_text << two.stderr_text;
  EXPECT_EQ(std::count(two.stdout_text.begin(), two.stdout_text.end(), '\n'), 5) << "4 scene lines and 1 closing line, "
                                                                                    "from rank 0 alone:\n"
                                                                                 << two.stdout_text;
  expect_same_sweep("one", "two", 4);
  const Outcome again = granmc("sweep alpha.toml --out-dir two --threads 1", mpirun(2));
  ASSERT_EQ(again.status, 0) << again.stderr_text;
  std::size_t skipped = 0;
  for (std::size_t at = again.stdout_text.find("skipped:"); at != std::string::npos;
       at = again.stdout_text.find("skipped:", at + 1))
    ++skipped;
  EXPECT_EQ(skipped, 4u) << again.stdout_text;
}

/// More ranks than a scene has replicas: 4 ranks and scenes of 2 replicas make 2 groups of 2 ranks, each
/// running whole scenes (docs/user-guide/parallel-runs.md); the files are those of one process.
TEST_F(MpiRun, SweepGivesWholeScenesToGroupsOfRanks) {
  write("base.toml", edited(cooling_scene, {{"replicas = 5", "replicas = 2"}}));
  write("alpha.toml", "base = \"base.toml\"\n[grid]\n\"collision.restitution\" = [0.5, 0.6, 0.8]\nrun.seed = [1, 2]\n");
  const Outcome one = granmc("sweep alpha.toml --out-dir one --threads 1 --quiet");
  ASSERT_EQ(one.status, 0) << one.stdout_text << one.stderr_text;
  const Outcome four = granmc("sweep alpha.toml --out-dir four --threads 1", mpirun(4));
  ASSERT_EQ(four.status, 0) << four.stdout_text << four.stderr_text;
  EXPECT_NE(four.stdout_text.find("on 4 MPI ranks in 2 groups"), std::string::npos) << four.stdout_text;
  EXPECT_NE(four.stdout_text.find("by rank group 2 of 2 (2 ranks)"), std::string::npos) << four.stdout_text;
  EXPECT_EQ(std::count(four.stdout_text.begin(), four.stdout_text.end(), '\n'), 7) << "6 scene lines, 1 closing line\n"
                                                                                   << four.stdout_text;
  expect_same_sweep("one", "four", 6);
}

TEST_F(MpiRun, BadSceneStopsEveryRankWithOneMessage) {
  write("scene.toml", cooling_scene + "[shear]\nrate = \"fast\"\n");
  const Outcome o = granmc("run scene.toml --out bad.h5", mpirun(2));
  EXPECT_EQ(o.status, 2) << o.stdout_text << o.stderr_text;
  const std::string first_line = o.stderr_text.substr(0, o.stderr_text.find('\n'));
  EXPECT_NE(first_line.find("scene.toml"), std::string::npos) << o.stderr_text;
  EXPECT_EQ(o.stderr_text.find(first_line, first_line.size()), std::string::npos) << "printed twice:\n"
                                                                                  << o.stderr_text;
  EXPECT_EQ(files(), std::vector<std::string>{"scene.toml"});
}

/// Checkpoints over ranks (drivers/run_checkpoints.hpp): a run on 2 ranks stopped by SIGINT to mpirun keeps
/// each rank's replicas in its own file; resumed on 3 ranks it is stopped again; resumed in one process it
/// writes the files of the uninterrupted run. 5 replicas of about a second each: on 2 ranks rank 1 has 2 to
/// rank 0's 3 and may wait for rank 0, its replicas kept in its file.
TEST_F(MpiRun, CheckpointsResumeOnAnyNumberOfRanks) {
  write("s.toml", R"([run]
seed = 5
replicas = 5
t_end = 40.0
dt = 0.01
samples = 40
[[species]]
particles = 200000
[collision]
restitution = 0.8
)");
  const Outcome full = granmc("run s.toml --out full.h5 --summary full.json --quiet --threads 1");
  ASSERT_EQ(full.status, 0) << full.stderr_text;
  const auto interrupt = [&](const std::string& resume, int ranks) {
    const pid_t pid =
        start("run s.toml --out p.h5 --summary p.json --threads 1 --checkpoint-every 0" + resume, mpirun(ranks));
    const std::string last = "p.h5.checkpoint." + std::to_string(ranks - 1) + "-of-" + std::to_string(ranks);
    for (int k = 0; k < 6000 && !exists(last) && slurp(dir_ / "rc.txt").empty(); ++k) sleep_ms(5);
    sleep_ms(300);
    ::kill(pid, SIGINT);  // mpirun sends SIGTERM to every rank
    return wait_exit();
  };
  if (interrupt("", 2) == 0) GTEST_SKIP() << "the run ended before the signal";
  EXPECT_NE(slurp(dir_ / "err.txt").find("--resume p.h5.checkpoint"), std::string::npos) << slurp(dir_ / "err.txt");
  EXPECT_TRUE(exists("p.h5.checkpoint.0-of-2"));
  EXPECT_TRUE(exists("p.h5.checkpoint.1-of-2"));
  EXPECT_FALSE(exists("p.h5"));

  // A plain rerun on any rank count does not overwrite them.
  const Outcome again = granmc("run s.toml --out p.h5 --summary p.json", mpirun(3));
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.stderr_text.find("--resume p.h5.checkpoint"), std::string::npos) << again.stderr_text;

  if (interrupt(" --resume p.h5.checkpoint", 3) == 0) GTEST_SKIP() << "the resumed run ended before the signal";
  EXPECT_TRUE(exists("p.h5.checkpoint.2-of-3"));
  const Outcome resumed = granmc("run s.toml --out p.h5 --summary p.json --threads 2 --resume p.h5.checkpoint");
  ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
  for (const std::string& name : files()) EXPECT_EQ(name.find("p.h5.checkpoint"), std::string::npos) << name;
  EXPECT_EQ(summary("p"), summary("full"));
  const auto reference = read_h5((dir_ / "full.h5").string()), other = read_h5((dir_ / "p.h5").string());
  EXPECT_EQ(other.size(), reference.size());
  for (const auto& [name, bytes] : reference) {
    const auto it = other.find(name);
    ASSERT_NE(it, other.end()) << name;
    EXPECT_TRUE(it->second == bytes) << name << " differs";
  }
}

TEST_F(MpiRun, TheoryAndExplainPrintOnce) {
  write("scene.toml", cooling_scene);
  const Outcome theory = granmc("theory scene.toml", mpirun(2));
  ASSERT_EQ(theory.status, 0) << theory.stderr_text;
  EXPECT_TRUE(nlohmann::json::accept(theory.stdout_text)) << theory.stdout_text;
  const Outcome explain = granmc("run scene.toml --explain", mpirun(2));
  ASSERT_EQ(explain.status, 0) << explain.stderr_text;
  const std::string kernel_line = "kernel       dsmc<";
  const auto first = explain.stdout_text.find(kernel_line);
  EXPECT_NE(first, std::string::npos) << explain.stdout_text;
  EXPECT_EQ(explain.stdout_text.find(kernel_line, first + 1), std::string::npos) << explain.stdout_text;
  EXPECT_NE(explain.stdout_text.find("ranks        2 MPI ranks"), std::string::npos) << explain.stdout_text;
  EXPECT_NE(explain.stdout_text.find("rank 0 runs 3 of the 5 replicas"), std::string::npos) << explain.stdout_text;
  EXPECT_EQ(files(), std::vector<std::string>{"scene.toml"});
}

}  // namespace
}  // namespace granmc
