// Checkpoints and restart (io/checkpoint.hpp, drivers/run_checkpoints.hpp): the file round trip and its
// refusals, and `granmc run` interrupted by SIGINT or killed with SIGKILL, then resumed, writing the files of
// an uninterrupted run.
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

Checkpoint small_checkpoint() {
  Checkpoint c;
  c.build = "0.1.0+0123456789ab";
  c.scene_text = "[run]\nreplicas = 3\n";
  c.seed = 7;
  c.replicas = 3;
  ReplicaSeries a, b;
  a.temperature = {1.0, 0.5, 0.25};
  a.collisions = {0.0, 10.0, 20.0};
  b.temperature = {1.0, 0.6, 0.3};
  b.intruder = IntruderSeries{};
  b.intruder->velocity = {0.1, -0.2};
  c.finished.emplace(0, a);
  c.finished.emplace(2, b);
  ReplicaInFlight f;
  f.series.temperature = {1.0, 0.7};
  f.samples_taken = 2;
  f.initial_majorant = {3.5};
  f.dsmc.velocities = {{0.1, 0.2, 0.3, -0.4, -0.5, -0.6}, {1.5, 2.5, 3.5}};
  f.dsmc.step = 41, f.dsmc.time = 0.41, f.dsmc.omega_max = {3.75}, f.dsmc.carried = {0.25};
  f.dsmc.total.collisions = 99, f.dsmc.pair_totals = {f.dsmc.total}, f.dsmc.transfer_integral.xy = -0.125;
  c.in_flight.emplace(1, f);
  return c;
}

class Checkpoints : public granmc_test::GranmcDirectory {
 protected:
  Checkpoints() : GranmcDirectory("granmc_checkpoint_") {}

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

TEST(CheckpointFile, RoundTripKeepsTheIdentityAndEveryReplica) {
  const fs::path path = fs::path(::testing::TempDir()) / "granmc_checkpoint_round_trip";
  const Checkpoint c = small_checkpoint();
  write_checkpoint(path.string(), c);
  const Checkpoint back = read_checkpoint(path.string());
  EXPECT_EQ(back.build, c.build);
  EXPECT_EQ(back.scene_text, c.scene_text);
  EXPECT_EQ(back.seed, 7u);
  EXPECT_EQ(back.replicas, 3u);
  ASSERT_EQ(back.finished.size(), 2u);
  EXPECT_EQ(back.finished.at(0).temperature, c.finished.at(0).temperature);
  EXPECT_EQ(back.finished.at(2).intruder->velocity, c.finished.at(2).intruder->velocity);
  ASSERT_EQ(back.in_flight.size(), 1u);
  const ReplicaInFlight &f = back.in_flight.at(1), &g = c.in_flight.at(1);
  EXPECT_EQ(f.series.temperature, g.series.temperature);
  EXPECT_EQ(f.samples_taken, 2u);
  EXPECT_EQ(f.initial_majorant, g.initial_majorant);
  EXPECT_EQ(f.dsmc.velocities, g.dsmc.velocities);
  EXPECT_EQ(f.dsmc.step, 41u);
  EXPECT_EQ(f.dsmc.omega_max, g.dsmc.omega_max);
  EXPECT_EQ(f.dsmc.carried, g.dsmc.carried);
  EXPECT_EQ(f.dsmc.total.collisions, 99u);
  EXPECT_EQ(f.dsmc.pair_totals.size(), 1u);
  EXPECT_EQ(f.dsmc.transfer_integral.xy, -0.125);
  EXPECT_EQ(checkpoint_mismatch(back, c.build, c.scene_text, 7, 3), "");
  EXPECT_NE(checkpoint_mismatch(back, "0.1.0+ffffffffffff", c.scene_text, 7, 3).find("written by granmc"),
            std::string::npos);
  EXPECT_NE(checkpoint_mismatch(back, c.build, "[run]\n", 7, 3).find("another scene"), std::string::npos);
  EXPECT_NE(checkpoint_mismatch(back, c.build, c.scene_text, 8, 3).find("seed 7"), std::string::npos);
  EXPECT_NE(checkpoint_mismatch(back, c.build, c.scene_text, 7, 4).find("3 replicas"), std::string::npos);
  fs::remove(path);
}

TEST(CheckpointFile, BadFilesAreRefusedSayingWhy) {
  const fs::path path = fs::path(::testing::TempDir()) / "granmc_checkpoint_bad";
  write_checkpoint(path.string(), small_checkpoint());
  const std::string good = slurp(path);
  auto refusal = [&](const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    try {
      read_checkpoint(path.string());
    } catch (const CheckpointError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal("[run]\nseed = 1\n").find("is not a granmc checkpoint"), std::string::npos);
  EXPECT_NE(refusal(good.substr(0, 40)).find("corrupt"), std::string::npos);
  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;
  EXPECT_NE(refusal(flipped).find("checksum"), std::string::npos);
  std::string other_version = good;
  other_version[std::string("granmc checkpoint\n").size()] = 9;  // the format version's low byte
  EXPECT_NE(refusal(other_version).find("checkpoint format 9"), std::string::npos);
  fs::remove(path);
  EXPECT_NE(refusal("").find("is not a granmc checkpoint"), std::string::npos);
  fs::remove(path);
}

TEST(CheckpointFile, AFailedWriteLeavesThePreviousCheckpoint) {
  const fs::path path = fs::path(::testing::TempDir()) / "granmc_checkpoint_failed_write";
  write_checkpoint(path.string(), small_checkpoint());
  const std::string before = slurp(path);
  // The temporary name is taken by a directory, so the write fails as on a full disk: before the rename.
  const fs::path blocker = path.string() + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  fs::create_directory(blocker);
  Checkpoint other = small_checkpoint();
  other.seed = 8;
  try {
    write_checkpoint(path.string(), other);
    ADD_FAILURE() << "the write did not fail";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the previous checkpoint, if any, is intact"), std::string::npos) << e.what();
  }
  EXPECT_EQ(slurp(path), before);
  EXPECT_EQ(read_checkpoint(path.string()).seed, 7u);
  fs::remove(blocker);
  fs::remove(path);
}

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

  // On one thread where the interrupted run had two: each replica is the same on any thread count.
  const Outcome resumed =
      granmc("run s.toml --out part.h5 --summary part.json --resume part.h5.checkpoint --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
  EXPECT_NE(resumed.stdout_text.find(std::to_string(kept) + " of 8 replicas from part.h5.checkpoint, " +
                                     std::to_string(in_flight) + " more going on"),
            std::string::npos)
      << resumed.stdout_text;
  EXPECT_FALSE(exists("part.h5.checkpoint"));  // the files replace it
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
const std::string weighted_scene = event_scene;  // with [weights] and 20 000 particles, below
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
  std::string weighted = weighted_scene;
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
  // One large system (the time-stepped scheme): SIGINT keeps its state at its next sample time, and the
  // resumed run goes on from there to the files of an uninterrupted run.
  write("one.toml",
        "[run]\nseed = 3\nreplicas = 1\nt_end = 20.0\ndt = 0.01\nsamples = 20\n[[species]]\n"
        "particles = 400000\n[collision]\nrestitution = 0.8\n");
  const Outcome full = granmc("run one.toml --out full.h5 --summary full.json --quiet");
  ASSERT_EQ(full.status, 0) << full.stderr_text;
  const pid_t pid = start("run one.toml --out part.h5 --summary part.json --checkpoint-every 0");
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
  EXPECT_LT(stopped.samples_taken, 21u);
  EXPECT_EQ(stopped.series.temperature.size(), stopped.samples_taken);
  const Outcome resumed = granmc("run one.toml --out part.h5 --summary part.json --resume part.h5.checkpoint");
  ASSERT_EQ(resumed.status, 0) << resumed.stderr_text;
  EXPECT_NE(resumed.stdout_text.find("0 of 1 replicas from part.h5.checkpoint, 1 more going on"), std::string::npos)
      << resumed.stdout_text;
  EXPECT_EQ(numbers("part.json"), numbers("full.json"));
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

}  // namespace
}  // namespace granmc
