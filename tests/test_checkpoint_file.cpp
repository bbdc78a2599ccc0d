// The checkpoint file (io/checkpoint.hpp): the round trip of finished replicas and replicas in flight, the
// refusals of foreign, truncated, corrupt and other-format files, and a failed write that keeps the previous
// checkpoint.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "io/checkpoint.hpp"
#include "tests/granmc_process.hpp"

namespace granmc {
namespace {

namespace fs = std::filesystem;
using granmc_test::slurp;

Checkpoint small_checkpoint() {
  Checkpoint c;
  c.build = "0.1.0+0123456789ab";
  c.scene_text = "[run]\nreplicas = 4\n";
  c.seed = 7;
  c.replicas = 4;
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
  DsmcSnapshot& d = f.state.emplace<DsmcSnapshot>();
  d.velocities = {{0.1, 0.2, 0.3, -0.4, -0.5, -0.6}, {1.5, 2.5, 3.5}};
  d.spins = {{0.0, 0.0, 0.75, 0.0, 0.0, -0.125}, {0.5, -1.5, 2.0}};  // rough particles
  d.step = 41, d.time = 0.41, d.omega_max = {3.75}, d.carried = {0.25};
  d.total.collisions = 99, d.pair_totals = {d.total}, d.transfer_integral.xy = -0.125;
  c.in_flight.emplace(1, f);
  // An event-scheme replica in flight too (a checkpoint holds one scheme's; the file does not care).
  ReplicaInFlight e;
  e.series.temperature = {1.0};
  e.samples_taken = 1;
  EventSnapshot& event = e.state.emplace<EventSnapshot>();
  event.velocities = {0.5, -0.25, 0.125};
  event.time = 0.75, event.draws = 1234567, event.syncs = 3, event.tally.majorant_violations = 2;
  c.in_flight.emplace(3, e);
  return c;
}

TEST(CheckpointFile, RoundTripKeepsTheIdentityAndEveryReplica) {
  const fs::path path = fs::path(::testing::TempDir()) / "granmc_checkpoint_round_trip";
  const Checkpoint c = small_checkpoint();
  write_checkpoint(path.string(), c);
  const Checkpoint back = read_checkpoint(path.string());
  EXPECT_EQ(back.build, c.build);
  EXPECT_EQ(back.scene_text, c.scene_text);
  EXPECT_EQ(back.seed, 7u);
  EXPECT_EQ(back.replicas, 4u);
  ASSERT_EQ(back.finished.size(), 2u);
  EXPECT_EQ(back.finished.at(0).temperature, c.finished.at(0).temperature);
  EXPECT_EQ(back.finished.at(2).intruder->velocity, c.finished.at(2).intruder->velocity);
  ASSERT_EQ(back.in_flight.size(), 2u);
  const ReplicaInFlight &f = back.in_flight.at(1), &g = c.in_flight.at(1);
  EXPECT_EQ(f.series.temperature, g.series.temperature);
  EXPECT_EQ(f.samples_taken, 2u);
  EXPECT_EQ(f.initial_majorant, g.initial_majorant);
  const DsmcSnapshot &d = std::get<DsmcSnapshot>(f.state), &dg = std::get<DsmcSnapshot>(g.state);
  EXPECT_EQ(d.velocities, dg.velocities);
  EXPECT_EQ(d.spins, dg.spins);
  EXPECT_EQ(d.step, 41u);
  EXPECT_EQ(d.omega_max, dg.omega_max);
  EXPECT_EQ(d.carried, dg.carried);
  EXPECT_EQ(d.total.collisions, 99u);
  EXPECT_EQ(d.pair_totals.size(), 1u);
  EXPECT_EQ(d.transfer_integral.xy, -0.125);
  const EventSnapshot& e = std::get<EventSnapshot>(back.in_flight.at(3).state);
  EXPECT_EQ(e.velocities, std::get<EventSnapshot>(c.in_flight.at(3).state).velocities);
  EXPECT_EQ(e.time, 0.75);
  EXPECT_EQ(e.draws, 1234567u);
  EXPECT_EQ(e.syncs, 3u);
  EXPECT_EQ(e.tally.majorant_violations, 2u);
  EXPECT_EQ(checkpoint_mismatch(back, c.build, c.scene_text, 7, 4), "");
  EXPECT_NE(checkpoint_mismatch(back, "0.1.0+ffffffffffff", c.scene_text, 7, 4).find("written by granmc"),
            std::string::npos);
  EXPECT_NE(checkpoint_mismatch(back, c.build, "[run]\n", 7, 4).find("another scene"), std::string::npos);
  EXPECT_NE(checkpoint_mismatch(back, c.build, c.scene_text, 8, 4).find("seed 7"), std::string::npos);
  EXPECT_NE(checkpoint_mismatch(back, c.build, c.scene_text, 7, 5).find("4 replicas"), std::string::npos);
  fs::remove(path);
}

/// The files of the ranks of one run, merged in either order: each replica at its furthest state.
TEST(CheckpointFile, MergeKeepsEachReplicaAtItsFurthestState) {
  const Checkpoint base = small_checkpoint();  // 0 and 2 finished, 1 in flight at sample 2, 3 at sample 1
  Checkpoint further;                          // 1 further on, 2 in flight (stale: finished in `base`)
  further.in_flight.emplace(1, base.in_flight.at(1));
  further.in_flight.at(1).samples_taken = 3;
  further.in_flight.emplace(2, base.in_flight.at(1));
  Checkpoint done;  // 1 finished
  done.finished.emplace(1, base.finished.at(0));
  for (const bool base_first : {true, false}) {
    Checkpoint a = base_first ? base : further, b = base_first ? further : base;
    merge_checkpoint(a, std::move(b));
    EXPECT_EQ(a.finished.size(), 2u);
    ASSERT_EQ(a.in_flight.size(), 2u);
    EXPECT_EQ(a.in_flight.at(1).samples_taken, 3u) << base_first;
    merge_checkpoint(a, Checkpoint(done));
    EXPECT_EQ(a.finished.size(), 3u);
    EXPECT_EQ(a.in_flight.size(), 1u);  // 3
    Checkpoint c = done;
    merge_checkpoint(c, Checkpoint(further));
    EXPECT_EQ(c.in_flight.size(), 1u);  // 2 in flight; 1 stays finished
    EXPECT_TRUE(c.in_flight.contains(2));
  }
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

}  // namespace
}  // namespace granmc
