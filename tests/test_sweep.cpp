// `granmc sweep` (docs/formats/scenes.md "Sweep files", docs/user-guide/parallel-runs.md "Sweeps"): a grid writes one
// HDF5 file and summary per scene and an index, with the numbers `granmc run` writes for the same scene; a sweep killed
// mid-scene leaves nothing under the unfinished scene's names, and its rerun skips the finished scene
// (files untouched), removes stale temporary files and completes the rest; an edited base reruns; a bad
// sweep file exits 2 with one message and writes nothing. (A sweep interrupted by SIGINT: tests/test_checkpoint.cpp.)
#include <fcntl.h>
#include <hdf5.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/output_schema.hpp"
#include "tests/granmc_process.hpp"

namespace fs = std::filesystem;
using granmc_test::Outcome;
using granmc_test::slurp;

namespace {

const std::string base_scene = R"([run]
t_end = 0.5
dt = 0.01
samples = 5
replicas = 2
[[species]]
particles = 500
[collision]
restitution = 0.9
)";

class Sweep : public granmc_test::GranmcDirectory {
 protected:
  Sweep() : GranmcDirectory("granmc_sweep_") {}

  /// The names of the files in `sub` of the test directory.
  std::set<std::string> files(const std::string& sub) const {
    std::set<std::string> names;
    if (fs::exists(dir_ / sub))
      for (const auto& e : fs::directory_iterator(dir_ / sub)) names.insert(e.path().filename().string());
    return names;
  }

  nlohmann::json json(const std::string& name) const { return nlohmann::json::parse(slurp(dir_ / name)); }
};

/// `text` with `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

std::string with(const std::string& from, const std::string& to) { return replaced(base_scene, from, to); }

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// The bytes of a dataset of an HDF5 file (native doubles).
std::vector<double> dataset(const fs::path& file, const char* name) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  const hid_t set = H5Dopen2(f, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(set);
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(f);
  return values;
}

/// A summary without what differs between two runs of the same scene: the time, the threads and the
/// scene's name.
nlohmann::json numbers(nlohmann::json summary) {
  for (const std::string& key : granmc::machine_records()) summary.erase(key);
  summary.erase("scene");
  return summary;
}

}  // namespace

TEST_F(Sweep, GridWritesEveryScenesFilesAndAnIndexWithTheNumbersOfRun) {
  write("base.toml", base_scene);
  write("alpha.toml", "base = \"base.toml\"\n[grid]\n\"collision.restitution\" = [0.5, 0.7]\nrun.seed = [1, 2]\n");
  const Outcome o = granmc("sweep alpha.toml --threads 2");
  ASSERT_EQ(o.status, 0) << o.stderr_text;

  const std::vector<std::string> names = {"restitution0.5_seed1", "restitution0.5_seed2", "restitution0.7_seed1",
                                          "restitution0.7_seed2"};
  std::set<std::string> expected = {"index.json"};
  for (const auto& n : names) expected.insert({n + ".h5", n + ".json"});
  EXPECT_EQ(files("alpha"), expected);

  const nlohmann::json index = json("alpha/index.json");
  ASSERT_EQ(index["scenes"].size(), names.size()) << index.dump(2);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const nlohmann::json& s = index["scenes"][k];
    EXPECT_EQ(s["name"], names[k]);
    EXPECT_EQ(s["hdf5"], names[k] + ".h5");
    EXPECT_EQ(s["summary"], names[k] + ".json");
    EXPECT_EQ(s["status"], "done");
    EXPECT_EQ(s["values"]["collision.restitution"], k < 2 ? 0.5 : 0.7);
    EXPECT_EQ(s["values"]["run.seed"], k % 2 + 1);
    EXPECT_EQ(s["scene_hash"].get<std::string>().rfind("fnv1a64:", 0), 0u) << s;
  }
  EXPECT_EQ(index["base"], "base.toml");
  for (std::size_t k = 1; k <= names.size(); ++k)
    EXPECT_EQ(count(o.stdout_text, "scene " + std::to_string(k) + " of 4 (" + names[k - 1] + ") done in "), 1u)
        << o.stdout_text;
  EXPECT_EQ(count(o.stdout_text, "s left"), 4u) << o.stdout_text;

  // The same scene by hand, run by `granmc run` on one thread: the same numbers to the last bit.
  write("by_hand.toml", replaced(with("[run]", "[run]\nseed = 2"), "restitution = 0.9", "restitution = 0.7"));
  ASSERT_EQ(granmc("run by_hand.toml --quiet --threads 1 --out by_hand.h5 --summary by_hand.json").status, 0);
  EXPECT_EQ(numbers(json("alpha/restitution0.7_seed2.json")).dump(), numbers(json("by_hand.json")).dump());
  EXPECT_EQ(json("alpha/restitution0.7_seed2.json")["scene"],
            "base.toml with collision.restitution = 0.7, run.seed = 2");
  for (const char* set : {"/temperature/replicas", "/species/a/a2/replicas", "/collisions/replicas"})
    EXPECT_EQ(dataset(dir_ / "alpha/restitution0.7_seed2.h5", set), dataset(dir_ / "by_hand.h5", set)) << set;
}

TEST_F(Sweep, KilledSweepLeavesNoPartialFileAndItsRerunSkipsTheFinishedScene) {
  write("base.toml", base_scene);
  // The second scene is long enough (about 1 s) to be killed while it runs.
  write("list.toml",
        "base = \"base.toml\"\n"
        "[[scenes]]\nrun.seed = 1\n"
        "[[scenes]]\nrun.seed = 2\n\"species[0].particles\" = 100000\n"
        "[[scenes]]\nrun.seed = 3\n");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    if (chdir(dir_.c_str()) != 0 || null < 0) _exit(127);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    execl(GRANMC_EXECUTABLE, GRANMC_EXECUTABLE, "sweep", "list.toml", "--out-dir", "out", "--threads", "1",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait for the index to record the first scene as done: written after its two files, it is the last
  // thing the sweep does before it starts the second scene.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool first_done = false;
  while (!first_done && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    const nlohmann::json index = nlohmann::json::parse(slurp(dir_ / "out/index.json"), nullptr, false);
    first_done = index.is_object() && index["scenes"][0]["status"] == "done";
  }
  kill(pid, SIGKILL);
  int raw = 0;
  waitpid(pid, &raw, 0);
  ASSERT_TRUE(first_done) << "the first scene never finished";
  ASSERT_TRUE(WIFSIGNALED(raw)) << "the sweep ended before it could be killed in its second scene";

  EXPECT_EQ(files("out"), (std::set<std::string>{"index.json", "seed1.h5", "seed1.json"}));
  const nlohmann::json killed = json("out/index.json");
  EXPECT_EQ(killed["scenes"][1]["name"], "seed2_particles100000");
  EXPECT_EQ(killed["scenes"][1]["status"], "pending");
  EXPECT_EQ(killed["scenes"][2]["status"], "pending");

  const std::string first_h5 = slurp(dir_ / "out/seed1.h5"), first_json = slurp(dir_ / "out/seed1.json");
  const auto first_time = fs::last_write_time(dir_ / "out/seed1.h5");
  write("out/seed2_particles100000.h5.tmp-999999", "what a killed writer left");
  write("out/index.json.tmp-999998", "{");
  write("out/keep.tmp-1", "not an output of this sweep");

  const Outcome o = granmc("sweep list.toml --out-dir out --threads 1");
  ASSERT_EQ(o.status, 0) << o.stderr_text;
  EXPECT_NE(o.stdout_text.find("scene 1 of 3 (seed1) skipped"), std::string::npos) << o.stdout_text;
  EXPECT_NE(o.stdout_text.find("removed out/seed2_particles100000.h5.tmp-999999"), std::string::npos) << o.stdout_text;
  EXPECT_NE(o.stdout_text.find("removed out/index.json.tmp-999998"), std::string::npos) << o.stdout_text;
  EXPECT_NE(o.stdout_text.find("(2 run, 1 skipped)"), std::string::npos) << o.stdout_text;
  EXPECT_EQ(slurp(dir_ / "out/seed1.h5"), first_h5);
  EXPECT_EQ(slurp(dir_ / "out/seed1.json"), first_json);
  EXPECT_EQ(fs::last_write_time(dir_ / "out/seed1.h5"), first_time);
  EXPECT_EQ(files("out"),
            (std::set<std::string>{"index.json", "keep.tmp-1", "seed1.h5", "seed1.json", "seed2_particles100000.h5",
                                   "seed2_particles100000.json", "seed3.h5", "seed3.json"}));
  const nlohmann::json index = json("out/index.json");  // alive through the loop
  for (const auto& s : index["scenes"]) EXPECT_EQ(s["status"], "done") << s;
}

TEST_F(Sweep, RerunSkipsWhatIsDoneAndRunsWhatChanged) {
  write("base.toml", base_scene);
  write("alpha.toml", "base = \"base.toml\"\n[grid]\n\"collision.restitution\" = [0.6, 0.8]\n");
  ASSERT_EQ(granmc("sweep alpha.toml --quiet").status, 0);
  const std::string hash = json("alpha/index.json")["scenes"][0]["scene_hash"];

  const Outcome again = granmc("sweep alpha.toml");
  ASSERT_EQ(again.status, 0) << again.stderr_text;
  EXPECT_EQ(count(again.stdout_text, "skipped: done by an earlier run"), 2u) << again.stdout_text;
  EXPECT_NE(again.stdout_text.find("(0 run, 2 skipped)"), std::string::npos) << again.stdout_text;

  // A third value: only its scene runs.
  write("alpha.toml", "base = \"base.toml\"\n[grid]\n\"collision.restitution\" = [0.6, 0.8, 1.0]\n");
  const Outcome more = granmc("sweep alpha.toml");
  ASSERT_EQ(more.status, 0) << more.stderr_text;
  EXPECT_NE(more.stdout_text.find("scene 3 of 3 (restitution1.0) done"), std::string::npos) << more.stdout_text;
  EXPECT_NE(more.stdout_text.find("(1 run, 2 skipped)"), std::string::npos) << more.stdout_text;

  // An edited base changes every scene: all run again, under new hashes.
  write("base.toml", with("samples = 5", "samples = 4"));
  const Outcome edited = granmc("sweep alpha.toml");
  ASSERT_EQ(edited.status, 0) << edited.stderr_text;
  EXPECT_NE(edited.stdout_text.find("(3 run, 0 skipped)"), std::string::npos) << edited.stdout_text;
  EXPECT_NE(json("alpha/index.json")["scenes"][0]["scene_hash"], hash);
  EXPECT_EQ(json("alpha/restitution0.6.json")["times"].size(), 5u);
}

TEST_F(Sweep, ScenesMadeByAnotherBuildRunAgainUnlessKept) {
  // index.json records the build that made each scene's files (io/build_id.hpp); a scene done by
  // another build runs again, or is kept with --keep-other-builds, each with a line saying which.
  write("base.toml", base_scene);
  write("alpha.toml", "base = \"base.toml\"\n[grid]\n\"collision.restitution\" = [0.6, 0.8]\n");
  ASSERT_EQ(granmc("sweep alpha.toml --quiet").status, 0);
  nlohmann::json index = json("alpha/index.json");
  const std::string this_build = index["build"];
  EXPECT_EQ(index["scenes"][0]["build"], this_build);
  EXPECT_EQ(index["scenes"][1]["build"], this_build);
  // The first scene as another build left it, the second as an index from before build ids.
  index["scenes"][0]["build"] = "0.0.1+000000000000";
  index["scenes"][1].erase("build");
  write("alpha/index.json", index.dump());

  const Outcome kept = granmc("sweep alpha.toml --keep-other-builds");
  ASSERT_EQ(kept.status, 0) << kept.stderr_text;
  EXPECT_NE(kept.stdout_text.find("scene 1 of 2 (restitution0.6) kept: made by build 0.0.1+000000000000, not this "
                                  "one (" +
                                  this_build + ")"),
            std::string::npos)
      << kept.stdout_text;
  EXPECT_NE(kept.stdout_text.find("scene 2 of 2 (restitution0.8) kept: made by build (not recorded)"),
            std::string::npos)
      << kept.stdout_text;
  EXPECT_NE(kept.stdout_text.find("(0 run, 2 skipped)"), std::string::npos) << kept.stdout_text;
  EXPECT_EQ(json("alpha/index.json")["scenes"][0]["build"], "0.0.1+000000000000");  // still says who made them

  const Outcome rerun = granmc("sweep alpha.toml");
  ASSERT_EQ(rerun.status, 0) << rerun.stderr_text;
  EXPECT_NE(rerun.stdout_text.find("scene 1 of 2 (restitution0.6) runs again: its files were made by build "
                                   "0.0.1+000000000000, this is " +
                                   this_build),
            std::string::npos)
      << rerun.stdout_text;
  EXPECT_NE(rerun.stdout_text.find("(2 run, 0 skipped)"), std::string::npos) << rerun.stdout_text;
  const nlohmann::json after = json("alpha/index.json");  // alive through the loop
  for (const auto& scene : after["scenes"]) EXPECT_EQ(scene["build"], this_build) << scene;
}

// Like a bad scene: exit 2 before any work, one line naming the sweep file and what is wrong, no output.
TEST_F(Sweep, BadSweepFilesExitTwoWithOneMessageAndNoOutput) {
  write("base.toml", base_scene);
  write("event.toml", with("[run]", "[run]\nmethod = \"event\""));
  struct Case {
    std::string name, text, says;
  };
  const std::string grid = "base = \"base.toml\"\n[grid]\n";
  const std::vector<Case> cases = {
      {"broken", "base = \n", "invalid TOML"},
      {"unknown_key", grid + "frobnicate = [1]\n", "frobnicate: unknown key"},
      {"top_level_key", "bases = \"base.toml\"\n" + grid.substr(grid.find('[')) + "\"run.seed\" = [1]\n",
       "bases: unknown key"},
      {"no_base", "[grid]\n\"run.seed\" = [1]\n", "base: missing"},
      {"missing_base", "base = \"nowhere.toml\"\n[grid]\n\"run.seed\" = [1]\n", "nowhere.toml: cannot open"},
      {"no_values", "base = \"base.toml\"\n", "missing [grid] or [[scenes]]"},
      {"both", grid + "\"run.seed\" = [1]\n[[scenes]]\n\"run.seed\" = 2\n", "give one of them"},
      {"not_a_list", grid + "\"run.seed\" = 1\n", "grid.run.seed: expected a non-empty list"},
      {"empty_list", grid + "\"run.seed\" = []\n", "grid.run.seed: expected a non-empty list"},
      {"bad_key", grid + "\"collision..restitution\" = [0.5]\n", "not a scene key"},
      {"no_such_species", grid + "\"species[1].mass\" = [2.0]\n", "has 1 [[species]] table"},
      {"not_a_table", grid + "\"run.t_end.x\" = [2.0]\n", "run.t_end is a value in the base scene"},
      {"bad_value", grid + "\"collision.restitution\" = [0.5, 1.5]\n",
       "collision.restitution = 1.5: collision.restitution: 1.5"},
      {"unknown_scene_key", grid + "\"collision.restitutio\" = [0.5]\n", "did you mean restitution"},
      {"same_names", grid + "\"collision.restitution\" = [0.5, 0.5]\n", "would both write restitution0.5.h5"},
      {"unsupported", "base = \"event.toml\"\n[grid]\n\"run.seed\" = [1]\n", "supported:"},
  };
  for (const Case& c : cases) {
    write(c.name + ".toml", c.text);
    const Outcome o = granmc("sweep " + c.name + ".toml --out-dir out");
    EXPECT_EQ(o.status, 2) << c.name << ": " << o.stderr_text;
    EXPECT_EQ(o.stderr_text.rfind("granmc: " + c.name + ".toml: ", 0), 0u) << c.name << ": " << o.stderr_text;
    EXPECT_NE(o.stderr_text.find(c.says), std::string::npos) << c.name << ": " << o.stderr_text;
    EXPECT_EQ(count(o.stderr_text, "\n"), 1u) << c.name << ": " << o.stderr_text;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << c.name;
  }
  const Outcome missing = granmc("sweep no_such_sweep.toml");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.stderr_text.find("no_such_sweep.toml: cannot open the sweep file"), std::string::npos)
      << missing.stderr_text;
}
