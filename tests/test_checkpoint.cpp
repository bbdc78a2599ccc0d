// Checkpoints and restart (drivers/run_checkpoints.hpp): `granmc run` and `granmc sweep` interrupted by SIGINT
// or killed with SIGKILL, then resumed, writing the files of an uninterrupted run. Runs of a second or more
// each, so the sanitizer builds leave this suite out (heavy); the file format's tests are
// tests/test_checkpoint_file.cpp.
#include <signal.h>
#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/checkpoint.hpp"
#include "io/output_schema.hpp"
#include "tests/granmc_process.hpp"

namespace granmc {
namespace {

namespace fs = std::filesystem;
using granmc_test::Outcome;
using granmc_test::slurp;

class Checkpoints : public granmc_test::GranmcDirectory {
 protected:
  Checkpoints() : GranmcDirectory("granmc_checkpoint_") {}

  nlohmann::json json(const std::string& name) const { return nlohmann::json::parse(slurp(dir_ / name)); }
  /// A summary without the records that describe the machine or the build.
  nlohmann::json numbers(const std::string& name) const {
    nlohmann::json j = nlohmann::json::parse(slurp(dir_ / name));
    for (const std::string& key : machine_records()) j.erase(key);
    return j;
  }
};

// Eight replicas of a cooling gas, each about a third of a second on this machine (1.5 s in all on 2 cores).
const std::string scene = R"([run]
seed = 5
replicas = 8
t_end = 10.0
dt = 0.01
samples = 10
[[species]]
particles = 200000
[collision]
restitution = 0.8
)";

TEST_F(Checkpoints, InterruptedRunResumesToTheFilesOfAnUninterruptedOne) {
  write("s.toml", scene);
  const Outcome full = granmc("run s.toml --out full.h5 --summary full.json --quiet");
  ASSERT_EQ(full.status, 0) << full.stderr_text;

  // Stop it with SIGINT once a replica has been checkpointed.
  const pid_t pid = start("run s.toml --out part.h5 --summary part.json --checkpoint-every 0");
  for (int k = 0; k < 6000 && !exists("part.h5.checkpoint") && slurp(dir_ / "rc.txt").empty(); ++k) sleep_ms(5);
  ::kill(pid, SIGINT);
  const int status = wait_exit();
  if (status == 0) GTEST_SKIP() << "the run ended before the signal";
  ASSERT_EQ(status, 3) << slurp(dir_ / "err.txt");
  EXPECT_NE(slurp(dir_ / "err.txt").find("--resume part.h5.checkpoint"), std::string::npos) << slurp(dir_ / "err.txt");
  EXPECT_FALSE(exists("part.h5"));
  EXPECT_FALSE(exists("part.json"));
  ASSERT_TRUE(exists("part.h5.checkpoint"));
  const Checkpoint left = read_checkpoint((dir_ / "part.h5.checkpoint").string());
  const std::size_t kept = left.finished.size(), in_flight = left.in_flight.size();
  EXPECT_GE(kept + in_flight, 1u);
  EXPECT_LT(kept, 8u);

  // A plain rerun does not overwrite the checkpoint; a resume with another seed is refused.
  const Outcome again = granmc("run s.toml --out part.h5 --summary part.json");
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.stderr_text.find("--resume part.h5.checkpoint"), std::string::npos) << again.stderr_text;
  const Outcome other_seed = granmc("run s.toml --out part.h5 --resume part.h5.checkpoint --seed 6");
  EXPECT_EQ(other_seed.status, 2);
  EXPECT_NE(other_seed.stderr_text.find("seed 5"), std::string::npos) << other_seed.stderr_text;

  // A rank's file of the same run (here a copy) is read with it, and a name that only looks like one is not.
  fs::copy_file(dir_ / "part.h5.checkpoint", dir_ / "part.h5.checkpoint.1-of-2");
  write("part.h5.checkpoint.x-of-2", "not a checkpoint");
  // On one thread where the interrupted run had two: each replica is the same on any thread count.
  const Outcome resumed =
      granmc("run s.toml --out part.h5 --summary part.json --resume part.h5.checkpoint --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
  EXPECT_NE(resumed.stdout_text.find(std::to_string(kept) + " of 8 replicas from part.h5.checkpoint, " +
                                     std::to_string(in_flight) + " more going on"),
            std::string::npos)
      << resumed.stdout_text;
  EXPECT_FALSE(exists("part.h5.checkpoint"));  // the files replace it, and its ranks' files
  EXPECT_FALSE(exists("part.h5.checkpoint.1-of-2"));
  EXPECT_TRUE(exists("part.h5.checkpoint.x-of-2"));
  EXPECT_EQ(numbers("part.json"), numbers("full.json"));
}

// The other schemes (each about a second on 2 cores): the event scheme under white noise, the same with
// weighted particles, and the Gillespie intruder. Each interrupted once a replica is kept, then resumed.
const std::string event_scene = R"([run]
method = "event"
seed = 7
replicas = 8
t_end = 8.0
samples = 4
[[species]]
particles = 100000
[collision]
kernel = "maxwell"
rate = 1.2732395447351628
restitution = 0.1
[thermostat]
kind = "white-noise"
beta = 30.0
[output]
histogram = { shells = 64, radius = 40.0 }
)";
const std::string intruder_scene = R"([run]
method = "gillespie"
seed = 7
replicas = 8
t_end = 2000000.0
samples = 2000
[intruder]
dimension = 1
mass = 1.0
restitution = 0.5
bath = "gaussian"
bath_a = 1.0
bath_density = 1.0
[output]
histogram = { shells = 100, radius = 5.0 }
)";

TEST_F(Checkpoints, EverySchemeResumesToTheFilesOfAnUninterruptedRun) {
  std::string weighted = event_scene;  // with [weights], 20 000 particles and a shorter run
  weighted.replace(weighted.find("t_end = 8.0"), 11, "t_end = 0.6");
  weighted.replace(weighted.find("particles = 100000"), 18, "particles = 20000");
  weighted += "[weights]\nscheme = \"swpm\"\nparticles_per_shell = 128\n";
  int interrupted = 0;
  for (const auto& [name, text] :
       {std::pair{"event", event_scene}, std::pair{"weighted", weighted}, std::pair{"intruder", intruder_scene}}) {
    SCOPED_TRACE(name);
    const std::string n = name;
    write(n + ".toml", text);
    const Outcome full = granmc("run " + n + ".toml --out " + n + "_full.h5 --summary " + n + "_full.json --quiet");
    ASSERT_EQ(full.status, 0) << full.stderr_text;
    const std::string out = " --out " + n + ".h5 --summary " + n + ".json";
    const pid_t pid = start("run " + n + ".toml" + out + " --checkpoint-every 0");
    for (int k = 0; k < 6000 && !exists(n + ".h5.checkpoint") && slurp(dir_ / "rc.txt").empty(); ++k) sleep_ms(5);
    ::kill(pid, SIGINT);
    const int status = wait_exit();
    if (status == 3) {
      ++interrupted;
      const Outcome resumed = granmc("run " + n + ".toml" + out + " --resume " + n + ".h5.checkpoint --quiet");
      ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
    } else {
      ASSERT_EQ(status, 0) << slurp(dir_ / "err.txt");  // it ended before the signal
    }
    EXPECT_EQ(numbers(n + ".json"), numbers(n + "_full.json"));
  }
  EXPECT_GE(interrupted, 2);
}

TEST_F(Checkpoints, OneReplicaStopsAtASampleAndGoesOn) {
  // One large system, time-stepped, time-step-free and weighted: SIGINT keeps its state at its next sample
  // time, and the resumed run goes on from there to the files of an uninterrupted run.
  std::string event = event_scene;  // one replica of 400 000 particles, about 2 s
  event.replace(event.find("replicas = 8"), 12, "replicas = 1");
  event.replace(event.find("particles = 100000"), 18, "particles = 400000");
  event.replace(event.find("t_end = 8.0"), 11, "t_end = 16.0");
  event.replace(event.find("samples = 4"), 11, "samples = 16");
  const std::string dsmc =
      "[run]\nseed = 3\nreplicas = 1\nt_end = 20.0\ndt = 0.01\nsamples = 20\n[[species]]\n"
      "particles = 400000\n[collision]\nrestitution = 0.8\n";
  std::string weighted = event_scene;  // one replica of 20 000 weighted particles, about a second
  weighted.replace(weighted.find("replicas = 8"), 12, "replicas = 1");
  weighted.replace(weighted.find("particles = 100000"), 18, "particles = 20000");
  weighted.replace(weighted.find("t_end = 8.0"), 11, "t_end = 4.8");
  weighted.replace(weighted.find("samples = 4"), 11, "samples = 16");
  weighted += "[weights]\nscheme = \"swpm\"\nparticles_per_shell = 128\n";
  for (const auto& [name, text] :
       {std::pair{"dsmc", dsmc}, std::pair{"event", event}, std::pair{"weighted", weighted}}) {
    SCOPED_TRACE(name);
    const std::string n = name;
    write(n + ".toml", text);
    const Outcome full = granmc("run " + n + ".toml --out full.h5 --summary full.json --quiet");
    ASSERT_EQ(full.status, 0) << full.stderr_text;
    const pid_t pid = start("run " + n + ".toml --out part.h5 --summary part.json --checkpoint-every 0");
    for (int k = 0; k < 6000 && !exists("part.h5.checkpoint") && slurp(dir_ / "rc.txt").empty(); ++k) sleep_ms(5);
    ::kill(pid, SIGINT);
    const int status = wait_exit();
    if (status == 0) GTEST_SKIP() << "the run ended before the signal";
    ASSERT_EQ(status, 3) << slurp(dir_ / "err.txt");
    const Checkpoint left = read_checkpoint((dir_ / "part.h5.checkpoint").string());
    EXPECT_EQ(left.finished.size(), 0u);
    ASSERT_EQ(left.in_flight.size(), 1u);
    const ReplicaInFlight& stopped = left.in_flight.at(0);
    EXPECT_GE(stopped.samples_taken, 1u);
    EXPECT_LT(stopped.samples_taken, 17u);
    EXPECT_EQ(stopped.series.temperature.size(), stopped.samples_taken);
    const Outcome resumed = granmc("run " + n + ".toml --out part.h5 --summary part.json --resume part.h5.checkpoint");
    ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
    EXPECT_NE(resumed.stdout_text.find("0 of 1 replicas from part.h5.checkpoint, 1 more going on"), std::string::npos)
        << resumed.stdout_text;
    EXPECT_EQ(numbers("part.json"), numbers("full.json"));
  }
}

TEST_F(Checkpoints, KilledAtRandomAndResumedEachTimeGivesTheSameFiles) {
  // kill -9 at random moments (the checkpoint may be half written: its temporary name), resuming each time,
  // until a run finishes; then the summary is the uninterrupted run's.
  write("s.toml", scene);
  const Outcome full = granmc("run s.toml --out full.h5 --summary full.json --quiet");
  ASSERT_EQ(full.status, 0) << full.stderr_text;
  // With --checkpoint-every 0 a checkpoint is written at every sample (the replicas in flight: 4.8 MB each),
  // which makes the run several times slower than without; the last attempt runs to the end.
  std::mt19937 random(2024);
  constexpr int attempts = 30;
  int kills = 0;
  for (int attempt = 0; attempt < attempts; ++attempt) {
    const std::string resume = exists("part.h5.checkpoint") ? " --resume part.h5.checkpoint" : "";
    const pid_t pid = start("run s.toml --out part.h5 --summary part.json --quiet --checkpoint-every 0" + resume);
    if (attempt + 1 < attempts) {
      sleep_ms(std::uniform_int_distribution<int>(200, 1000)(random));
      ::kill(pid, SIGKILL);
    }
    const int status = wait_exit();
    if (status == 0) break;
    ASSERT_EQ(status, 128 + SIGKILL) << slurp(dir_ / "err.txt");
    ++kills;
  }
  std::printf("[ measured ] %d kills before the run finished\n", kills);
  EXPECT_GE(kills, 2);  // the run takes several times the longest wait
  ASSERT_TRUE(exists("part.json"));
  EXPECT_EQ(numbers("part.json"), numbers("full.json"));
}

TEST_F(Checkpoints, InterruptedSweepResumesInsideTheInterruptedScene) {
  // Two scenes of 8 replicas, about a second each on 2 cores; SIGINT during the second keeps its finished
  // replicas in its checkpoint, and the rerun continues from it: the files are those of an uninterrupted sweep.
  write("base.toml",
        "[run]\nt_end = 0.5\ndt = 0.01\nsamples = 5\nreplicas = 8\n[[species]]\nparticles = 200000\n"
        "[collision]\nrestitution = 0.9\n");
  write("alpha.toml", "base = \"base.toml\"\n[grid]\n\"collision.restitution\" = [0.6, 0.8]\n\"run.t_end\" = [8.0]\n");
  ASSERT_EQ(granmc("sweep alpha.toml --out-dir whole --quiet").status, 0);

  const pid_t pid = start("sweep alpha.toml --out-dir cut");
  for (int k = 0;
       k < 12000 && slurp(dir_ / "out.txt").find("scene 1 of 2") == std::string::npos && slurp(dir_ / "rc.txt").empty();
       ++k)
    sleep_ms(5);
  sleep_ms(400);  // into the second scene
  ::kill(pid, SIGINT);
  const int status = wait_exit();
  if (status == 0) GTEST_SKIP() << "the sweep ended before the signal";
  ASSERT_EQ(status, 3) << slurp(dir_ / "err.txt");
  const std::string second = "restitution0.8_t_end8.0";
  EXPECT_NE(slurp(dir_ / "err.txt").find("interrupted in " + second), std::string::npos) << slurp(dir_ / "err.txt");
  EXPECT_TRUE(exists("cut/" + second + ".h5.checkpoint"));
  EXPECT_EQ(json("cut/index.json")["scenes"][1]["status"], "pending");

  const Outcome resumed = granmc("sweep alpha.toml --out-dir cut");
  ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
  EXPECT_NE(resumed.stdout_text.find(second + " resumes from cut/" + second + ".h5.checkpoint"), std::string::npos)
      << resumed.stdout_text;
  EXPECT_FALSE(exists("cut/" + second + ".h5.checkpoint"));
  for (const std::string name : {"restitution0.6_t_end8.0.json", "restitution0.8_t_end8.0.json"})
    EXPECT_EQ(numbers("cut/" + name), numbers("whole/" + name)) << name;
}

}  // namespace
}  // namespace granmc
