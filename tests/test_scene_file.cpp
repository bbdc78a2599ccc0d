// The scene reader (io/scene_file.cpp): valid scenes give the right values and defaults; every bad input
// is refused with one message "<path>: <key>: <what is wrong>; <what is allowed>".
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "io/scene_file.hpp"

using namespace granmc;

namespace {

const std::string kPath = "scenes/test_scene.toml";

// Building blocks for inline scenes.
const std::string kRun = "[run]\nt_end = 1.0\ndt = 0.01\n";
const std::string kSpecies = "[[species]]\nparticles = 1000\n";
const std::string kGas = kRun + kSpecies;

/// The message of the SceneError that parse_scene throws for `text`, or "" (and a test failure).
std::string error_of(std::string_view text, const std::string& path = kPath) {
  try {
    parse_scene(text, path);
  } catch (const SceneError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw a non-SceneError: " << e.what();
    return {};
  }
  ADD_FAILURE() << "accepted a bad scene:\n" << text;
  return {};
}

/// Asserts that `text` is refused with a message that starts "<path>: <key>: " and contains `detail`.
void expect_rejected(std::string_view text, const std::string& key, std::string_view detail = {}) {
  SCOPED_TRACE(std::string("scene:\n") + std::string(text));
  const std::string msg = error_of(text);
  const std::string prefix = kPath + ": " + key + ": ";
  EXPECT_EQ(msg.substr(0, prefix.size()), prefix) << "message: " << msg;
  if (!detail.empty()) {
    EXPECT_NE(msg.find(detail), std::string::npos) << "message: " << msg;
  }
  EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
}

/// A fresh file under the test temp dir with the given bytes.
std::string temp_file(const std::string& name, std::string_view bytes) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "granmc_test_scene_file";
  std::filesystem::create_directories(dir);
  const auto p = dir / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return p.string();
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Valid scenes.

TEST(SceneFile, FullGasSceneParsesWithTheRightValues) {
  const std::string text = R"(# every key of a gas scene
[run]
method = "dsmc"
seed = 9223372036854775807
replicas = 4
t_end = 5            # an integer where a float is expected
dt = 1e-3
samples = 50
dt_scaling = "thermal"
sample_spacing = "log"
storage = "float"
checkpoint_every = 0.5

[[species]]
name = "big"
mass = 2.5
diameter = 1.5
density = 0.3
particles = 3000

[[species]]
name = "small"
mass = 1
diameter = 1
density = 0.1
particles = 1000

[collision]
kernel = "vhs"
lambda = 0.5
rate = 0
restitution = [[0.9, 0.8], [0.8, 0.7]]
packing_fraction = 0.58250364  # pi (0.3 x 1.5^3 + 0.1 x 1^3) / 6: consistent with the species, as shear requires

[thermostat]
kind = "gaussian"
zeta = 0.75

[shear]
rate = -0.5

[relaxation]
enabled = true

[initial]
temperature = 2.0
zero_momentum = false

[output]
histogram = { shells = 64, radius = 8.5, speed = "velocity" }
)";
  const Scene s = parse_scene(text, kPath);
  EXPECT_EQ(s.run.method, Method::dsmc);
  EXPECT_EQ(s.run.seed, 9223372036854775807ull);
  EXPECT_EQ(s.run.replicas, 4);
  EXPECT_EQ(s.run.t_end, 5.0);
  EXPECT_EQ(s.run.dt, 1e-3);
  EXPECT_EQ(s.run.samples, 50);
  EXPECT_EQ(s.run.dt_scaling, DtScaling::thermal);
  EXPECT_EQ(s.run.sample_spacing, SampleSpacing::log);
  EXPECT_EQ(s.run.storage, Storage::single_precision);
  EXPECT_EQ(s.run.checkpoint_every, 0.5);
  ASSERT_EQ(s.species.size(), 2u);
  EXPECT_EQ(s.species[0].name, "big");
  EXPECT_EQ(s.species[0].mass, 2.5);
  EXPECT_EQ(s.species[0].diameter, 1.5);
  EXPECT_EQ(s.species[0].density, 0.3);
  EXPECT_EQ(s.species[0].particles, 3000);
  EXPECT_EQ(s.species[1].name, "small");
  EXPECT_EQ(s.species[1].mass, 1.0);
  EXPECT_EQ(s.species[1].particles, 1000);
  EXPECT_EQ(total_particles(s), 4000);
  EXPECT_EQ(s.collision.kernel, CollisionKernel::vhs);
  EXPECT_EQ(s.collision.lambda, 0.5);
  EXPECT_EQ(s.collision.rate, 0.0);
  EXPECT_EQ(s.collision.restitution[0][0], 0.9);
  EXPECT_EQ(s.collision.restitution[0][1], 0.8);
  EXPECT_EQ(s.collision.restitution[1][0], 0.8);
  EXPECT_EQ(s.collision.restitution[1][1], 0.7);
  EXPECT_EQ(s.collision.packing_fraction, 0.58250364);
  EXPECT_EQ(s.thermostat.kind, ThermostatKind::gaussian);
  EXPECT_FALSE(s.thermostat.zeta_is_cooling_rate);
  EXPECT_EQ(s.thermostat.zeta, 0.75);
  EXPECT_EQ(s.shear_rate, -0.5);
  EXPECT_TRUE(s.relaxation);
  EXPECT_EQ(s.initial_temperature, 2.0);
  EXPECT_FALSE(s.initial_zero_momentum);
  EXPECT_FALSE(s.intruder.has_value());
  EXPECT_EQ(s.histogram.shells, 64);
  EXPECT_EQ(s.histogram.radius, 8.5);
  EXPECT_EQ(s.histogram.speed, HistogramSpeed::velocity);
  EXPECT_EQ(s.source_path, kPath);
  EXPECT_EQ(s.source_text, text);
}

TEST(SceneFile, DefaultsAreApplied) {
  const Scene s = parse_scene(kGas, kPath);
  EXPECT_EQ(s.run.method, Method::dsmc);
  EXPECT_EQ(s.run.seed, 1u);
  EXPECT_EQ(s.run.replicas, 1);
  EXPECT_EQ(s.run.t_end, 1.0);
  EXPECT_EQ(s.run.dt, 0.01);
  EXPECT_EQ(s.run.samples, 100);
  EXPECT_EQ(s.run.dt_scaling, DtScaling::fixed);
  EXPECT_EQ(s.run.sample_spacing, SampleSpacing::linear);
  EXPECT_EQ(s.run.storage, Storage::double_precision);
  EXPECT_EQ(s.run.checkpoint_every, 10.0);
  ASSERT_EQ(s.species.size(), 1u);
  EXPECT_EQ(s.species[0].name, "a");
  EXPECT_EQ(s.species[0].mass, 1.0);
  EXPECT_EQ(s.species[0].diameter, 1.0);
  EXPECT_EQ(s.species[0].density, 1.0);
  EXPECT_EQ(s.species[0].particles, 1000);
  EXPECT_EQ(s.collision.kernel, CollisionKernel::hard_sphere);
  EXPECT_EQ(s.collision.lambda, 1.0);
  EXPECT_EQ(s.collision.rate, 0.0);
  for (const auto& row : s.collision.restitution)
    for (const double a : row) EXPECT_EQ(a, 1.0);
  EXPECT_EQ(s.collision.packing_fraction, 0.0);
  EXPECT_EQ(s.thermostat.kind, ThermostatKind::none);
  EXPECT_TRUE(s.thermostat.zeta_is_cooling_rate);
  EXPECT_EQ(s.thermostat.beta, 0.0);
  EXPECT_EQ(s.shear_rate, 0.0);
  EXPECT_FALSE(s.relaxation);
  EXPECT_EQ(s.initial_temperature, 1.0);
  EXPECT_TRUE(s.initial_zero_momentum);
  EXPECT_FALSE(s.intruder.has_value());
  EXPECT_EQ(s.histogram.shells, 128);
  EXPECT_EQ(s.histogram.radius, 16.0);
  EXPECT_FALSE(s.histogram.speed.has_value()) << "absent: the method's default";
}

TEST(SceneFile, DefaultSpeciesNamesFollowTheIndex) {
  const Scene s = parse_scene(kRun + kSpecies + kSpecies, kPath);
  ASSERT_EQ(s.species.size(), 2u);
  EXPECT_EQ(s.species[0].name, "a");
  EXPECT_EQ(s.species[1].name, "b");
}

TEST(SceneFile, ScalarRestitutionFillsTheMatrix) {
  const Scene s = parse_scene(kGas + "[collision]\nrestitution = 0.8\n", kPath);
  for (const auto& row : s.collision.restitution)
    for (const double a : row) EXPECT_EQ(a, 0.8);
  const Scene one = parse_scene(kGas + "[collision]\nrestitution = 1\n", kPath);  // integer accepted
  EXPECT_EQ(one.collision.restitution[1][1], 1.0);
}

TEST(SceneFile, MaxwellKernelHasLambdaZero) {
  const Scene s = parse_scene(kGas + "[collision]\nkernel = \"maxwell\"\n", kPath);
  EXPECT_EQ(s.collision.kernel, CollisionKernel::maxwell);
  EXPECT_EQ(s.collision.lambda, 0.0);
}

TEST(SceneFile, EventAndWhiteNoiseScene) {
  const Scene s = parse_scene(R"([run]
method = "event"
t_end = 2.0
[[species]]
particles = 500
[collision]
kernel = "vhs"
lambda = 0
rate = 1.5
[thermostat]
kind = "white-noise"
beta = 0.5
)",
                              kPath);
  EXPECT_EQ(s.run.method, Method::event);
  EXPECT_EQ(s.run.dt, 0.0);
  EXPECT_EQ(s.collision.rate, 1.5);
  EXPECT_EQ(s.collision.lambda, 0.0);
  EXPECT_EQ(s.thermostat.kind, ThermostatKind::white_noise);
  EXPECT_EQ(s.thermostat.beta, 0.5);
}

TEST(SceneFile, WeightsTable) {
  const std::string event =
      "[run]\nmethod = \"event\"\nt_end = 2.0\n" + kSpecies + "[collision]\nkernel = \"maxwell\"\nrate = 1.0\n";
  EXPECT_FALSE(parse_scene(event, kPath).weights.has_value());
  const Scene defaults = parse_scene(event + "[weights]\nscheme = \"swpm\"\n", kPath);
  ASSERT_TRUE(defaults.weights.has_value());
  EXPECT_EQ(defaults.weights->particles_per_shell, 128);
  EXPECT_EQ(defaults.weights->growth, 2.0);
  const Scene s = parse_scene(event + "[weights]\nscheme = \"swpm\"\nparticles_per_shell = 64\ngrowth = 1.5\n", kPath);
  EXPECT_EQ(s.weights->particles_per_shell, 64);
  EXPECT_EQ(s.weights->growth, 1.5);
  expect_rejected(event + "[weights]\nparticles_per_shell = 64\n", "weights.scheme", "missing required key");
  expect_rejected(event + "[weights]\nscheme = \"swp\"\n", "weights.scheme", "did you mean \"swpm\"?");
  expect_rejected(kGas + "[weights]\nscheme = \"swpm\"\n", "weights.scheme", "needs run.method = \"event\"");
  expect_rejected(event + "[weights]\nscheme = \"swpm\"\nparticles_per_shell = 3\n", "weights.particles_per_shell",
                  "outside [4, 2147483647]");
  expect_rejected(event + "[weights]\nscheme = \"swpm\"\ngrowth = 1.0\n", "weights.growth", "not a finite number > 1");
  expect_rejected(event + "[weights]\nscheme = \"swpm\"\nsplit = 2\n", "weights.split", "allowed keys in [weights]");
}

TEST(SceneFile, GillespieIntruderScene) {
  const Scene s = parse_scene(R"([run]
method = "gillespie"
t_end = 100
[intruder]
dimension = 2
mass = 3.0
restitution = 0.5
bath = "power-law"
bath_a = 2
bath_density = 0.5
length = 1.5
inertia = 0.25
)",
                              kPath);
  EXPECT_EQ(s.run.method, Method::gillespie);
  EXPECT_TRUE(s.species.empty());
  ASSERT_TRUE(s.intruder.has_value());
  EXPECT_EQ(s.intruder->dimension, 2);
  EXPECT_EQ(s.intruder->mass, 3.0);
  EXPECT_EQ(s.intruder->restitution, 0.5);
  EXPECT_EQ(s.intruder->bath, BathKind::power_law);
  EXPECT_EQ(s.intruder->bath_a, 2.0);
  EXPECT_EQ(s.intruder->bath_density, 0.5);
  EXPECT_EQ(s.intruder->length, 1.5);
  EXPECT_EQ(s.intruder->inertia, 0.25);

  const Scene d = parse_scene(kRun + "[intruder]\n", kPath);  // the intruder's DSMC alternative, defaults
  EXPECT_EQ(d.run.method, Method::dsmc);
  EXPECT_TRUE(d.species.empty());
  ASSERT_TRUE(d.intruder.has_value());
  EXPECT_EQ(d.intruder->dimension, 1);
  EXPECT_EQ(d.intruder->mass, 1.0);
  EXPECT_EQ(d.intruder->restitution, 1.0);
  EXPECT_EQ(d.intruder->bath, BathKind::gaussian);
  EXPECT_EQ(d.intruder->bath_a, 1.0);
  EXPECT_EQ(d.intruder->bath_density, 1.0);
  EXPECT_EQ(d.intruder->length, 1.0);
  EXPECT_EQ(d.intruder->inertia, 0.0);
}

TEST(SceneFile, ParticleRatioWithinOnePercentIsAccepted) {
  const Scene s = parse_scene(kRun + R"([[species]]
density = 2
particles = 2000
[[species]]
density = 1
particles = 1009
)",
                              kPath);
  EXPECT_EQ(s.species[1].particles, 1009);
}

TEST(SceneFile, LoadSceneReadsAFile) {
  const std::string path = temp_file("valid.toml", kGas);
  const Scene s = load_scene(path);
  EXPECT_EQ(s.source_path, path);
  EXPECT_EQ(s.source_text, kGas);
  EXPECT_EQ(s.species.at(0).particles, 1000);
}

// ---------------------------------------------------------------------------------------------
// Unknown keys, in every table.

TEST(SceneFile, UnknownKeyInRun) {
  expect_rejected("[run]\nt_end = 1.0\ndt = 0.01\nfrobnicate = 3\n" + kSpecies, "run.frobnicate",
                  "unknown key; allowed keys in [run]: method, seed, replicas, t_end, dt, samples, dt_scaling, "
                  "sample_spacing, storage, checkpoint_every");
  expect_rejected("[run]\nt_end = 1.0\ndt = 0.01\ntend = 3\n" + kSpecies, "run.tend", "did you mean t_end?");
  expect_rejected("[run]\nt_end = 1.0\ndt = 0.01\nkernel = \"vhs\"\n" + kSpecies, "run.kernel",
                  "it belongs in [collision]");
}

TEST(SceneFile, UnknownKeyInEveryTable) {
  expect_rejected(kRun + "[[species]]\nparticles = 10\ncolour = \"red\"\n", "species[0].colour",
                  "allowed keys in [[species]]");
  expect_rejected(kRun + kSpecies + "[[species]]\nparticles = 1000\nmas = 2\n", "species[1].mas", "did you mean mass?");
  expect_rejected(kGas + "[collision]\nalpha = 0.9\n", "collision.alpha", "allowed keys in [collision]");
  expect_rejected(kGas + "[thermostat]\ntemperature = 1\n", "thermostat.temperature", "it belongs in [initial]");
  expect_rejected(kGas + "[shear]\nrte = 1\n", "shear.rte", "did you mean rate?");
  expect_rejected(kGas + "[relaxation]\non = true\n", "relaxation.on", "allowed keys in [relaxation]: enabled");
  expect_rejected(kGas + "[initial]\ntemp = 1\n", "initial.temp", "allowed keys in [initial]: temperature");
  expect_rejected(kRun + "[intruder]\nradius = 1\n", "intruder.radius", "allowed keys in [intruder]");
  expect_rejected(kGas + "[output]\nhdf5 = \"x.h5\"\n", "output.hdf5", "allowed keys in [output]: histogram");
  expect_rejected(kGas + "[output]\nhistogram = { shells = 10, bins = 3 }\n", "output.histogram.bins",
                  "allowed keys in output.histogram: shells, radius, speed");
}

TEST(SceneFile, UnknownTopLevelTableOrKey) {
  expect_rejected(kGas + "[frobnicate]\nx = 1\n", "frobnicate",
                  "unknown key; allowed top-level tables: [run], [[species]], [collision]");
  expect_rejected(kGas + "[colision]\nkernel = \"vhs\"\n", "colision", "did you mean collision?");
  expect_rejected("t_end = 1.0\n" + kGas, "t_end", "it belongs in [run]");
}

// ---------------------------------------------------------------------------------------------
// Missing required keys and tables.

TEST(SceneFile, MissingRequiredKeys) {
  expect_rejected("[run]\ndt = 0.01\n" + kSpecies, "run.t_end", "missing required key");
  expect_rejected(kSpecies, "run.t_end", "missing required key");  // no [run] at all
  expect_rejected("[run]\nt_end = 1.0\n" + kSpecies, "run.dt", "missing required key for method \"dsmc\"");
  expect_rejected(kRun + "[[species]]\nmass = 1\n", "species[0].particles", "missing required key");
}

TEST(SceneFile, MissingSpeciesForGasMethods) {
  expect_rejected(kRun, "species", "missing required [[species]]");
  expect_rejected("[run]\nmethod = \"event\"\nt_end = 1\n", "species", "missing required [[species]]");
  expect_rejected("species = []\n" + kRun, "species", "needs 1 or 2 species");
}

TEST(SceneFile, MethodAndTablesMustMatch) {
  const std::string gillespie = "[run]\nmethod = \"gillespie\"\nt_end = 1\n";
  expect_rejected(gillespie, "intruder", "missing required table for method \"gillespie\"");
  expect_rejected(gillespie + kSpecies + "[intruder]\n", "species", "not allowed with method \"gillespie\"");
  expect_rejected("[run]\nmethod = \"event\"\nt_end = 1\n" + kSpecies + "[intruder]\n", "intruder",
                  "not allowed with method \"event\"");
  expect_rejected(kGas + "[intruder]\nmass = 2\n", "intruder", "not allowed together with [[species]]");
}

TEST(SceneFile, MoreThanTwoSpecies) { expect_rejected(kRun + kSpecies + kSpecies + kSpecies, "species", "at most 2"); }

// ---------------------------------------------------------------------------------------------
// Wrong types.

TEST(SceneFile, WrongTypes) {
  expect_rejected("[run]\nt_end = \"5\"\ndt = 0.01\n" + kSpecies, "run.t_end", "got a string (\"5\"); expected");
  expect_rejected("[run]\nmethod = 1\nt_end = 1\ndt = 0.1\n" + kSpecies, "run.method", "got an integer (1)");
  expect_rejected("[run]\nt_end = 1\ndt = true\n" + kSpecies, "run.dt", "got a boolean (true)");
  expect_rejected(kRun + "[[species]]\nparticles = \"100\"\n", "species[0].particles", "expected an integer");
  expect_rejected(kRun + "[[species]]\nname = 3\nparticles = 100\n", "species[0].name", "expected a non-empty string");
  expect_rejected(kRun + "[[species]]\nparticles = 100\nmass = [1, 2]\n", "species[0].mass", "got an array");
  expect_rejected(kGas + "[collision]\nrestitution = \"high\"\n", "collision.restitution",
                  "expected a number in [0, 1] or a symmetric 2x2 array");
  expect_rejected(kGas + "[collision]\nkernel = 2\n", "collision.kernel", "expected a string");
  expect_rejected(kGas + "[thermostat]\nzeta = true\n", "thermostat.zeta",
                  "expected a finite number or \"cooling-rate\"");
  expect_rejected(kGas + "[relaxation]\nenabled = 1\n", "relaxation.enabled", "expected a boolean");
  expect_rejected(kGas + "[shear]\nrate = 1979-05-27\n", "shear.rate", "got a date");
  expect_rejected(kGas + "[output]\nhistogram = 5\n", "output.histogram", "expected an inline table");
  expect_rejected(kGas + "[output]\nhistogram = { radius = \"big\" }\n", "output.histogram.radius", "got a string");
  expect_rejected("run = 5\n" + kSpecies, "run", "expected a table [run]");
  expect_rejected(kRun + "[species]\nparticles = 100\n", "species", "write [[species]]");
  expect_rejected("species = [1, 2]\n" + kRun, "species[0]", "expected a table");
  expect_rejected(kRun + "[intruder]\ndimension = \"2\"\n", "intruder.dimension", "got a string");
}

TEST(SceneFile, IntegersWhereFloatsButNotFloatsWhereIntegers) {
  EXPECT_EQ(parse_scene("[run]\nt_end = 5\ndt = 1\n" + kSpecies, kPath).run.t_end, 5.0);
  expect_rejected(kRun + "[[species]]\nparticles = 1.5\n", "species[0].particles",
                  "got a float (1.5); expected an integer");
  expect_rejected(kRun + "[[species]]\nparticles = 1e3\n", "species[0].particles", "(write 1000, without");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nreplicas = 2.0\n" + kSpecies, "run.replicas", "got a float (2)");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nseed = 1.0\n" + kSpecies, "run.seed", "got a float");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nsamples = 10.5\n" + kSpecies, "run.samples", "got a float");
  expect_rejected(kGas + "[output]\nhistogram = { shells = 12.5 }\n", "output.histogram.shells", "got a float");
  expect_rejected(kRun + "[intruder]\ndimension = 2.0\n", "intruder.dimension", "got a float");
}

// ---------------------------------------------------------------------------------------------
// Values out of range.

TEST(SceneFile, TimeStep) {
  expect_rejected("[run]\nt_end = 1\ndt = 0\n" + kSpecies, "run.dt", "method \"dsmc\" needs a time step");
  expect_rejected("[run]\nt_end = 1\ndt = -0.1\n" + kSpecies, "run.dt", "-0.1 is negative");
  expect_rejected("[run]\nt_end = 1\ndt = 2\n" + kSpecies, "run.dt", "larger than run.t_end");
  expect_rejected("[run]\nt_end = 1\ndt = nan\n" + kSpecies, "run.dt", "nan is not a number");
  expect_rejected("[run]\nt_end = 1\ndt = inf\n" + kSpecies, "run.dt", "inf is not finite");
}

TEST(SceneFile, EndTime) {
  expect_rejected("[run]\nt_end = 0\ndt = 0.1\n" + kSpecies, "run.t_end", "0 is not > 0");
  expect_rejected("[run]\nt_end = -1.0\ndt = 0.1\n" + kSpecies, "run.t_end", "-1 is not > 0");
  expect_rejected("[run]\nt_end = inf\ndt = 0.1\n" + kSpecies, "run.t_end", "inf is not finite");
  expect_rejected("[run]\nt_end = nan\ndt = 0.1\n" + kSpecies, "run.t_end", "nan is not a number");
}

TEST(SceneFile, Restitution) {
  expect_rejected(kGas + "[collision]\nrestitution = 1.5\n", "collision.restitution", "1.5 is outside [0, 1]");
  EXPECT_EQ(error_of(kGas + "[collision]\nrestitution = 1.5\n"),
            kPath + ": collision.restitution: 1.5 is outside [0, 1]");
  expect_rejected(kGas + "[collision]\nrestitution = -0.1\n", "collision.restitution", "-0.1 is outside [0, 1]");
  expect_rejected(kGas + "[collision]\nrestitution = nan\n", "collision.restitution", "nan is not a number");
  expect_rejected(kGas + "[collision]\nrestitution = [[1, 1.5], [1.5, 1]]\n", "collision.restitution[0][1]",
                  "1.5 is outside [0, 1]");
  expect_rejected(kGas + "[collision]\nrestitution = [[1, 0.9], [0.9, nan]]\n", "collision.restitution[1][1]",
                  "nan is not a number");
  expect_rejected(kGas + "[collision]\nrestitution = [[1, 0.9], [0.8, 1]]\n", "collision.restitution",
                  "not symmetric (a12 = 0.9, a21 = 0.8)");
  expect_rejected(kGas + "[collision]\nrestitution = [0.9, 0.9]\n", "collision.restitution[0]",
                  "expected an array of 2 numbers");
  expect_rejected(kGas + "[collision]\nrestitution = [[1, 1], [1, 1], [1, 1]]\n", "collision.restitution",
                  "array of 3 elements");
  expect_rejected(kGas + "[collision]\nrestitution = [[1, 1, 1], [1, 1, 1]]\n", "collision.restitution[0]",
                  "array of 3 elements");
  expect_rejected(kGas + "[collision]\nrestitution = [[1, \"x\"], [1, 1]]\n", "collision.restitution[0][1]",
                  "got a string");
}

TEST(SceneFile, SpeciesValues) {
  expect_rejected(kRun + "[[species]]\nparticles = 10\nmass = 0\n", "species[0].mass", "0 is not > 0");
  expect_rejected(kRun + "[[species]]\nparticles = 10\nmass = -1\n", "species[0].mass", "-1 is not > 0");
  expect_rejected(kRun + "[[species]]\nparticles = 10\nmass = inf\n", "species[0].mass", "inf is not finite");
  expect_rejected(kRun + "[[species]]\nparticles = 10\ndiameter = 0.0\n", "species[0].diameter", "0 is not > 0");
  expect_rejected(kRun + "[[species]]\nparticles = 10\ndensity = -2\n", "species[0].density", "-2 is not > 0");
  expect_rejected(kRun + "[[species]]\nparticles = 10\ndensity = nan\n", "species[0].density", "nan");
  expect_rejected(kRun + "[[species]]\nparticles = 0\n", "species[0].particles", "0 is not > 0");
  expect_rejected(kRun + "[[species]]\nparticles = -5\n", "species[0].particles", "-5 is not > 0");
  expect_rejected(kRun + kSpecies + "[[species]]\nparticles = 1000\nmass = 0\n", "species[1].mass", "0 is not > 0");
}

TEST(SceneFile, SpeciesNames) {
  expect_rejected(kRun + "[[species]]\nname = \"\"\nparticles = 10\n", "species[0].name", "empty name");
  expect_rejected(kRun + "[[species]]\nname = \"x\"\nparticles = 10\n[[species]]\nname = \"x\"\nparticles = 10\n",
                  "species[1].name", "\"x\" is already the name of species[0]");
  expect_rejected(kRun + "[[species]]\nname = \"b\"\nparticles = 10\n[[species]]\nparticles = 10\n", "species[1].name",
                  "default names");
  expect_rejected(kRun + "[[species]]\nname = \"a/b\"\nparticles = 10\n", "species[0].name", "contains '/'");
}

TEST(SceneFile, ParticleRatioMustMatchDensityRatio) {
  expect_rejected(kRun + "[[species]]\ndensity = 1\nparticles = 1000\n[[species]]\ndensity = 1\nparticles = 500\n",
                  "species[1].particles", "e.g. species[1].particles = 1000");
  expect_rejected(kRun + "[[species]]\ndensity = 2\nparticles = 2000\n[[species]]\ndensity = 1\nparticles = 1011\n",
                  "species[1].particles", "by more than 1%");
}

TEST(SceneFile, RunCounts) {
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nreplicas = 0\n" + kSpecies, "run.replicas", "0 is outside [1, ");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nreplicas = -3\n" + kSpecies, "run.replicas", "-3 is outside");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nreplicas = 10000000000\n" + kSpecies, "run.replicas",
                  "outside [1, 2147483647]");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nsamples = 0\n" + kSpecies, "run.samples", "0 is outside [1, ");
}

TEST(SceneFile, Seed) {
  EXPECT_EQ(parse_scene("[run]\nt_end = 1\ndt = 0.1\nseed = 0\n" + kSpecies, kPath).run.seed, 0u);
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nseed = -1\n" + kSpecies, "run.seed",
                  "-1 is outside [0, 9223372036854775807]");
  const std::string msg = error_of("[run]\nt_end = 1\ndt = 0.1\nseed = 18446744073709551615\n" + kSpecies);
  EXPECT_EQ(msg.rfind(kPath + ": line 4, column", 0), 0u) << msg;
  EXPECT_NE(msg.find("signed 64-bit"), std::string::npos) << msg;
  EXPECT_NE(msg.find("run.seed"), std::string::npos) << msg;
}

TEST(SceneFile, InitialTemperature) {
  for (const char* t : {"inf", "-inf", "nan", "0", "0.0", "-1", "-0.5"}) {
    expect_rejected(kGas + "[initial]\ntemperature = " + t + "\n", "initial.temperature",
                    "expected a finite number > 0");
  }
}

TEST(SceneFile, UnknownChoiceStrings) {
  expect_rejected("[run]\nmethod = \"pic\"\nt_end = 1\n" + kSpecies, "run.method",
                  "\"pic\" is not a known value; allowed: \"dsmc\" | \"event\" | \"gillespie\"");
  expect_rejected("[run]\nmethod = \"DSMC\"\nt_end = 1\n" + kSpecies, "run.method", "did you mean \"dsmc\"?");
  expect_rejected(kGas + "[collision]\nkernel = \"hard_sphere\"\n", "collision.kernel",
                  "did you mean \"hard-sphere\"?");
  expect_rejected(kGas + "[collision]\nkernel = \"lennard-jones\"\n", "collision.kernel",
                  "allowed: \"hard-sphere\" | \"maxwell\" | \"vhs\"");
  expect_rejected(kGas + "[thermostat]\nkind = \"nose-hoover\"\n", "thermostat.kind",
                  "allowed: \"none\" | \"gaussian\" | \"white-noise\"");
  expect_rejected(kRun + "[intruder]\nbath = \"uniform\"\n", "intruder.bath", "allowed: \"gaussian\" | \"power-law\"");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\ndt_scaling = \"adaptive\"\n" + kSpecies, "run.dt_scaling",
                  "allowed: \"fixed\" | \"thermal\"");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nsample_spacing = \"geometric\"\n" + kSpecies, "run.sample_spacing",
                  "allowed: \"linear\" | \"log\"");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\nstorage = \"half\"\n" + kSpecies, "run.storage",
                  "allowed: \"double\" | \"float\"");
  expect_rejected("[run]\nt_end = 1\ndt = 0.1\ncheckpoint_every = -1\n" + kSpecies, "run.checkpoint_every", ">= 0");
  expect_rejected(kGas + "[thermostat]\nkind = \"gaussian\"\nzeta = \"auto\"\n", "thermostat.zeta",
                  "expected a finite number or \"cooling-rate\"");
}

TEST(SceneFile, CollisionValues) {
  expect_rejected(kGas + "[collision]\nkernel = \"vhs\"\nlambda = 1.5\n", "collision.lambda", "1.5 is outside [0, 1]");
  expect_rejected(kGas + "[collision]\nkernel = \"vhs\"\nlambda = -0.5\n", "collision.lambda", "outside [0, 1]");
  expect_rejected(kGas + "[collision]\nlambda = 0.5\n", "collision.lambda", "contradicts kernel = \"hard-sphere\"");
  expect_rejected(kGas + "[collision]\nkernel = \"maxwell\"\nlambda = 1\n", "collision.lambda",
                  "contradicts kernel = \"maxwell\"");
  expect_rejected(kGas + "[collision]\npacking_fraction = 1.0\n", "collision.packing_fraction", "1 is outside [0, 1)");
  expect_rejected(kGas + "[collision]\npacking_fraction = -0.1\n", "collision.packing_fraction", "outside [0, 1)");
  expect_rejected(kGas + "[collision]\npacking_fraction = nan\n", "collision.packing_fraction", "nan");
  expect_rejected(kGas + "[collision]\nrate = -1\n", "collision.rate", "-1 is negative");
  expect_rejected(kRun + kSpecies + kSpecies + "[collision]\nrate = 1\n", "collision.rate", "one-species Gamba form");
}

TEST(SceneFile, ThermostatValues) {
  expect_rejected(kGas + "[thermostat]\nkind = \"white-noise\"\nbeta = -0.5\n", "thermostat.beta", "-0.5 is negative");
  expect_rejected(kGas + "[thermostat]\nkind = \"white-noise\"\n", "thermostat.beta",
                  "needs a diffusion coefficient beta > 0");
  expect_rejected(kGas + "[thermostat]\nbeta = 0.5\n", "thermostat.beta", "applies only to kind = \"white-noise\"");
  expect_rejected(kGas + "[thermostat]\nzeta = 0.5\n", "thermostat.zeta", "applies only to kind = \"gaussian\"");
  expect_rejected(kGas + "[thermostat]\nkind = \"gaussian\"\nzeta = inf\n", "thermostat.zeta", "inf is not finite");
  expect_rejected(kGas + "[relaxation]\nenabled = true\n", "relaxation.enabled",
                  "needs thermostat.kind = \"gaussian\"");
  expect_rejected(kGas + "[relaxation]\na2 = 0.1\n", "relaxation.a2", "applies only with enabled = true");
  expect_rejected(kGas + "[thermostat]\nkind = \"gaussian\"\n[relaxation]\nenabled = true\na2 = 0.7\n", "relaxation.a2",
                  "must be in [-0.5, 0.5]");
}

TEST(SceneFile, ShearAndOutputValues) {
  expect_rejected(kGas + "[shear]\nrate = nan\n", "shear.rate", "nan is not finite");
  expect_rejected(kGas + "[collision]\npacking_fraction = 0.3\n[shear]\nrate = 0.5\n", "shear.rate",
                  "sum_i pi n_i sigma_i^3 / 6 = phi");
  // Disks: the packing fraction of the plane, pi n sigma^2 / 4, so density 1 at phi = pi / 4 passes.
  const std::string disks = "[run]\nt_end = 1.0\ndt = 0.01\ndimension = 2\n" + kSpecies;
  expect_rejected(disks + "[collision]\npacking_fraction = 0.3\n[shear]\nrate = 0.5\n", "shear.rate",
                  "sum_i pi n_i sigma_i^2 / 4 = phi (now 0.785398)");
  EXPECT_EQ(parse_scene(disks + "[collision]\npacking_fraction = 0.7853981633974483\n[shear]\nrate = 0.5\n", kPath)
                .shear_rate,
            0.5);
  expect_rejected(kGas + "[output]\nhistogram = { shells = 0 }\n", "output.histogram.shells", "0 is outside [1, ");
  expect_rejected(kGas + "[output]\nhistogram = { radius = 0 }\n", "output.histogram.radius", "0 is not > 0");
  expect_rejected(kGas + "[output]\nhistogram = { speed = \"v0\" }\n", "output.histogram.speed",
                  "\"scaled\" | \"velocity\"");
}

TEST(SceneFile, RunAdditions) {
  expect_rejected("[run]\nmethod = \"event\"\nt_end = 1\nsample_spacing = \"log\"\n" + kSpecies, "run.dt",
                  "missing; sample_spacing = \"log\" needs 0 < dt < t_end");
  expect_rejected("[run]\nt_end = 1\ndt = 1\nsample_spacing = \"log\"\n" + kSpecies, "run.dt", "needs 0 < dt < t_end");
  expect_rejected("[run]\nmethod = \"event\"\nt_end = 1\ndt_scaling = \"thermal\"\n" + kSpecies, "run.dt_scaling",
                  "only method \"dsmc\"");
  const Scene s =
      parse_scene("[run]\nmethod = \"event\"\nt_end = 10\ndt = 0.01\nsample_spacing = \"log\"\n" + kSpecies, kPath);
  EXPECT_EQ(s.run.sample_spacing, SampleSpacing::log);
  EXPECT_EQ(s.run.dt, 0.01);
}

TEST(SceneFile, IntruderValues) {
  const std::string gillespie = "[run]\nmethod = \"gillespie\"\nt_end = 1\n[intruder]\n";
  expect_rejected(gillespie + "dimension = 3\n", "intruder.dimension", "expected 1 (point intruder on a line) or 2");
  expect_rejected(gillespie + "dimension = 0\n", "intruder.dimension", "0 is not allowed");
  expect_rejected(gillespie + "mass = 0\n", "intruder.mass", "0 is not > 0");
  expect_rejected(gillespie + "restitution = 1.01\n", "intruder.restitution", "1.01 is outside [0, 1]");
  expect_rejected(gillespie + "restitution = nan\n", "intruder.restitution", "nan");
  expect_rejected(gillespie + "bath_a = 0\n", "intruder.bath_a", "0 is not > 0");
  expect_rejected(gillespie + "bath_density = -1\n", "intruder.bath_density", "-1 is not > 0");
  expect_rejected(gillespie + "length = 0\n", "intruder.length", "0 is not > 0");
  expect_rejected(gillespie + "inertia = -1\n", "intruder.inertia", "-1 is negative");
  expect_rejected(gillespie + "inertia = inf\n", "intruder.inertia", "inf is not finite");
  expect_rejected("intruder = 3\n[run]\nmethod = \"gillespie\"\nt_end = 1\n", "intruder",
                  "expected a table [intruder]");
}

// ---------------------------------------------------------------------------------------------
// The file as a whole.

TEST(SceneFile, BrokenTomlReportsLineAndColumn) {
  const std::string msg = error_of("[run]\nt_end = 1.0\n[collision\nkernel = \"vhs\"\n");
  EXPECT_EQ(msg.rfind(kPath + ": line 3, column ", 0), 0u) << msg;
  EXPECT_NE(msg.find("invalid TOML"), std::string::npos) << msg;
  const std::string dup = error_of(kGas + "[run]\nseed = 2\n");
  EXPECT_EQ(dup.rfind(kPath + ": line ", 0), 0u) << dup;
  const std::string str = error_of("[run]\nt_end = \"1.0\n");
  EXPECT_EQ(str.rfind(kPath + ": line 2, column ", 0), 0u) << str;
}

TEST(SceneFile, EmptyAndBinaryText) {
  EXPECT_EQ(error_of("").rfind(kPath + ": the file is empty", 0), 0u);
  EXPECT_EQ(error_of(" \n\t\r\n").rfind(kPath + ": the file is empty", 0), 0u);
  const std::string nul = error_of(std::string_view("[run]\nt_end = 1\0\0", 18));
  EXPECT_EQ(nul.rfind(kPath + ": binary file (NUL byte at line 2, column 10)", 0), 0u) << nul;
  const std::string utf8 = error_of("[run]\nt_end = 1 # caf\xe9\n");
  EXPECT_EQ(utf8.rfind(kPath + ": not UTF-8 text (invalid byte 0xe9 at line 2, column 16)", 0), 0u) << utf8;
  EXPECT_NE(error_of("x = \"\xc0\xaf\"").find("not UTF-8 text"), std::string::npos);      // overlong
  EXPECT_NE(error_of("x = \"\xed\xa0\x80\"").find("not UTF-8 text"), std::string::npos);  // surrogate
  // Valid multi-byte UTF-8 in names and comments is fine.
  EXPECT_EQ(parse_scene(kRun + "[[species]] # Teilchen \xc3\xa4\nname = \"\xce\xb1\"\nparticles = 10\n", kPath)
                .species[0]
                .name,
            "\xce\xb1");
}

TEST(SceneFile, LoadSceneMissingEmptyBinaryFiles) {
  const auto expect_load_error = [](const std::string& path, std::string_view detail) {
    try {
      load_scene(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
      EXPECT_NE(msg.find(detail), std::string::npos) << msg;
    }
  };
  const auto dir = std::filesystem::path(::testing::TempDir()) / "granmc_test_scene_file";
  std::filesystem::create_directories(dir);
  expect_load_error((dir / "does_not_exist.toml").string(), "no such file");
  expect_load_error(dir.string(), "is a directory");
  expect_load_error(temp_file("empty.toml", ""), "the file is empty");
  expect_load_error(temp_file("binary.toml", std::string_view("\x7f"
                                                              "ELF\x02\x01\x01\0\0\0",
                                                              10)),
                    "binary file");
  expect_load_error(temp_file("latin1.toml", "[run]\nt_end = 1 # \xb5s\n"), "not UTF-8 text");
  expect_load_error(temp_file("bad_value.toml", kGas + "[collision]\nrestitution = 2\n"),
                    "collision.restitution: 2 is outside [0, 1]");
}

TEST(SceneFile, OddKeysStayOnOneLine) {
  expect_rejected(kGas + "[collision]\n\"two\\nlines\" = 1\n", "collision.\"two\\u000alines\"", "unknown key");
  expect_rejected("\"with space\" = 1\n" + kGas, "\"with space\"", "unknown key");
}

TEST(SceneFile, RoughParticles) {
  const Scene smooth = parse_scene(kGas, kPath);
  EXPECT_EQ(smooth.collision.tangential_restitution, -1.0);
  EXPECT_FALSE(rough(smooth.collision));
  EXPECT_EQ(smooth.collision.reduced_inertia, 0.4);  // a uniform sphere
  const Scene s = parse_scene(kGas + "[collision]\ntangential_restitution = 0.5\nreduced_inertia = 0.25\n", kPath);
  EXPECT_TRUE(rough(s.collision));
  EXPECT_EQ(s.collision.tangential_restitution, 0.5);
  EXPECT_EQ(s.collision.reduced_inertia, 0.25);
  const Scene disks = parse_scene("[run]\nt_end = 1.0\ndt = 0.01\ndimension = 2\n" + kSpecies, kPath);
  EXPECT_EQ(disks.collision.reduced_inertia, 0.5);  // a uniform disk
  expect_rejected(kGas + "[collision]\ntangential_restitution = 1.5\n", "collision.tangential_restitution",
                  "outside [-1, 1]");
  expect_rejected(kGas + "[collision]\nreduced_inertia = 0\n", "collision.reduced_inertia", "outside (0, 1]");
  expect_rejected(kGas + "[collision]\nreduced_inertia = \"big\"\n", "collision.reduced_inertia", "(0, 1]");
  // The splitting thermostat: a share of white noise on the spins of rough particles only.
  const std::string noise = "[thermostat]\nkind = \"white-noise\"\nbeta = 1.0\n";
  const Scene split =
      parse_scene(kGas + "[collision]\ntangential_restitution = 0.0\n" + noise + "rotational_share = 0.25\n", kPath);
  EXPECT_EQ(split.thermostat.rotational_share, 0.25);
  EXPECT_EQ(s.thermostat.rotational_share, 0.0);
  expect_rejected(kGas + noise + "rotational_share = 0.25\n", "thermostat.rotational_share", "rough particles");
  expect_rejected(kGas + "[collision]\ntangential_restitution = 0.0\n" + noise + "rotational_share = 1.5\n",
                  "thermostat.rotational_share", "outside [0, 1]");
}

TEST(SceneFile, GasDimension) {
  EXPECT_EQ(parse_scene(kGas, kPath).run.dimension, 3);
  EXPECT_EQ(parse_scene("[run]\nt_end = 1.0\ndt = 0.01\ndimension = 2\n" + kSpecies, kPath).run.dimension, 2);
  expect_rejected("[run]\nt_end = 1.0\ndt = 0.01\ndimension = 4\n" + kSpecies, "run.dimension", "not 2 or 3");
  expect_rejected("[run]\nt_end = 1.0\ndt = 0.01\ndimension = 2.0\n" + kSpecies, "run.dimension", "2 or 3");
  expect_rejected(R"([run]
method = "gillespie"
t_end = 100
dimension = 2
[intruder]
dimension = 1
mass = 1.0
restitution = 0.5
bath = "gaussian"
bath_a = 1.0
bath_density = 1.0
)",
                  "run.dimension", "[intruder] dimension");
}
