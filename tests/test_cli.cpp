// The command line: a bad scene or bad arguments exit with status 2 before any work, with one message
// on stderr naming the file and the key, and leave no output file; a good run exits 0 and writes both
// outputs atomically (docs/user-guide/command-line.md).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/output_schema.hpp"
#include "tests/granmc_process.hpp"

namespace fs = std::filesystem;
using granmc_test::Outcome;
using granmc_test::slurp;

namespace {

class Cli : public granmc_test::GranmcDirectory {
 protected:
  Cli() : GranmcDirectory("granmc_cli_") {}

  /// Files in the test directory other than the scenes we wrote.
  std::vector<std::string> outputs() const {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir_))
      if (e.path().extension() != ".toml") names.push_back(e.path().filename().string());
    return names;
  }
};

const std::string good_scene = R"([run]
t_end = 0.5
dt = 0.01
samples = 5
replicas = 2
[[species]]
particles = 500
[collision]
restitution = 0.9
)";

/// The good scene with one line replaced or added.
std::string with(const std::string& from, const std::string& to) {
  std::string s = good_scene;
  const auto at = s.find(from);
  if (at == std::string::npos) return s + to + "\n";
  return s.replace(at, from.size(), to);
}

}  // namespace

TEST_F(Cli, GoodRunWritesBothOutputsAndNothingElse) {
  write("good.toml", good_scene);
  const Outcome o = granmc("run good.toml --out out/r.h5 --summary out/r.json --threads 2");
  EXPECT_EQ(o.status, 0) << o.stderr_text;
  EXPECT_TRUE(fs::exists(dir_ / "out/r.h5"));
  EXPECT_TRUE(fs::exists(dir_ / "out/r.json"));
  for (const auto& name : outputs()) EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
}

TEST_F(Cli, OneAndTwoThreadsWriteTheSameNumbers) {
  write("good.toml", with("replicas = 2", "replicas = 3"));
  ASSERT_EQ(granmc("run good.toml --quiet --threads 1 --out one.h5 --summary one.json").status, 0);
  ASSERT_EQ(granmc("run good.toml --quiet --threads 2 --out two.h5 --summary two.json").status, 0);
  nlohmann::json one = nlohmann::json::parse(slurp(dir_ / "one.json"));
  nlohmann::json two = nlohmann::json::parse(slurp(dir_ / "two.json"));
  EXPECT_EQ(one["threads"], 1);
  EXPECT_EQ(two["threads"], 2);
  for (auto* j : {&one, &two})
    for (const std::string& key : granmc::machine_records()) j->erase(key);
  EXPECT_EQ(one.dump(), two.dump());  // the dump prints doubles exactly (round-trip precision)
}

TEST_F(Cli, ThreadsInsideOneReplicaWriteTheSameNumbers) {
  std::string scene = with("replicas = 2", "replicas = 1");
  scene = scene.replace(scene.find("particles = 500"), 15, "particles = 20000");
  write("one.toml", scene);
  ASSERT_EQ(granmc("run one.toml --quiet --threads 1 --out one.h5 --summary one.json").status, 0);
  ASSERT_EQ(granmc("run one.toml --quiet --threads 2 --out two.h5 --summary two.json").status, 0);
  ASSERT_EQ(granmc("run one.toml --quiet --threads 2 --threads-per-replica 2 --out in.h5 --summary in.json").status, 0);
  nlohmann::json one = nlohmann::json::parse(slurp(dir_ / "one.json"));
  nlohmann::json two = nlohmann::json::parse(slurp(dir_ / "two.json"));
  nlohmann::json in = nlohmann::json::parse(slurp(dir_ / "in.json"));
  EXPECT_EQ(two["threads_per_replica"], 1) << "a replica of 20000 particles keeps one thread unless asked";
  EXPECT_EQ(in["threads_per_replica"], 2);
  EXPECT_GT(in["collision_rounds"].get<std::uint64_t>(), 0u) << "the rounds ran, not only the in-order fallback";
  for (auto* j : {&one, &in})
    for (const std::string& key : granmc::machine_records()) j->erase(key);
  EXPECT_EQ(one.dump(), in.dump());
}

TEST_F(Cli, DefaultOutputIsNamedAfterTheScene) {
  write("good.toml", good_scene);
  EXPECT_EQ(granmc("run good.toml --quiet").status, 0);
  EXPECT_TRUE(fs::exists(dir_ / "good.h5"));
}

TEST_F(Cli, TheoryPrintsJsonForTheScene) {
  write("good.toml", good_scene);
  const Outcome o = granmc("theory good.toml");
  EXPECT_EQ(o.status, 0) << o.stderr_text;
  EXPECT_NE(o.stdout_text.find("\"cooling_state\""), std::string::npos);
  EXPECT_NE(o.stdout_text.find("\"a2_second_sonine\""), std::string::npos);
}

/// A gas of hard disks (run.dimension = 2): `granmc theory` gives its cooling state
/// (docs/methods/derivations/sonine-hcs.md, "Hard disks"), and `granmc run` refuses it, naming the key, with nothing
/// written.
TEST_F(Cli, HardDisksHaveTheirTheoryAndRun) {
  write("disks.toml", with("dt = 0.01", "dt = 0.01\ndimension = 2"));
  const Outcome o = granmc("theory disks.toml");
  ASSERT_EQ(o.status, 0) << o.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(o.stdout_text);
  EXPECT_EQ(j["dimension"], 2);
  const double alpha = 0.9;
  EXPECT_EQ(j["cooling_state"]["a2"].get<double>(),
            16.0 * (1.0 - alpha) * (1.0 - 2.0 * alpha * alpha) /
                (9.0 + 48.0 - alpha * (41.0 - 16.0) + 30.0 * (1.0 - alpha) * alpha * alpha));  // vNE, d = 2
  // nu = 2 sqrt(pi) n sigma sqrt(T / m) and zeta = nu (1 - alpha^2) / 2 (1 + 3 a2 / 16) for n = sigma = T = m = 1
  EXPECT_NEAR(j["cooling_state"]["collision_frequency0"].get<double>(), 2.0 * std::sqrt(std::numbers::pi), 1e-15);
  EXPECT_NEAR(j["cooling_state"]["cooling_rate0_maxwell"].get<double>(),
              std::sqrt(std::numbers::pi) * (1.0 - alpha * alpha), 1e-15);
  EXPECT_NE(o.stdout_text.find("hard disks"), std::string::npos);
  EXPECT_EQ(o.stdout_text.find("viscosity"), std::string::npos);
  const Outcome run = granmc("run disks.toml --summary disks.json --quiet");
  ASSERT_EQ(run.status, 0) << run.stderr_text;
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir_ / "disks.json"));
  EXPECT_EQ(summary["dimension"], 2);
  EXPECT_EQ(summary["theory"]["a2"], j["cooling_state"]["a2"]);
  const Outcome explain = granmc("run disks.toml --explain");
  EXPECT_NE(explain.stdout_text.find("hard-disk"), std::string::npos) << explain.stdout_text;
  // What the disks do not run yet is refused with the key named.
  write("disks_event.toml", with("dt = 0.01", "dt = 0.01\ndimension = 2\nmethod = \"event\""));
  const Outcome event = granmc("run disks_event.toml");
  EXPECT_EQ(event.status, 2);
  EXPECT_NE(event.stderr_text.find("run.dimension = 2"), std::string::npos) << event.stderr_text;
}

/// White noise on hard cores: `granmc theory` gives the first- and second-Sonine a2 (and a3) of the heated
/// state (docs/methods/derivations/sonine-hcs.md, "White noise"), the same for the hard disks of 000's form and of
/// 001's kernel form, with the first Sonine's model error their distance; and so for VHS.
TEST_F(Cli, WhiteNoiseHardCoresHaveTheirSecondSonine) {
  const std::string scenes = std::string(GRANMC_SOURCE_DIR) + "/drivers/scenes/white_noise/";
  const Outcome stepped = granmc("theory " + scenes + "disks.toml");
  const Outcome event = granmc("theory " + scenes + "event_disks_hard.toml");
  ASSERT_EQ(stepped.status, 0) << stepped.stderr_text;
  ASSERT_EQ(event.status, 0) << event.stderr_text;
  const nlohmann::json a = nlohmann::json::parse(stepped.stdout_text)["white_noise"];
  const nlohmann::json b = nlohmann::json::parse(event.stdout_text)["white_noise"];
  for (const char* key : {"a2", "a2_second_sonine", "a3_second_sonine", "a2_model_error"})
    EXPECT_EQ(a[key], b[key]) << key;
  const double first = a["a2"], second = a["a2_second_sonine"];
  EXPECT_EQ(a["a2_model_error"].get<double>(), std::fabs(second - first));
  EXPECT_NEAR(second, 0.03452, 5e-6);  // alpha = 1/2, d = 2: docs/methods/derivations/sonine-hcs.md's table
  EXPECT_NEAR(a["a3_second_sonine"].get<double>(), -0.00550, 5e-6);
  // VHS spheres (e uniform, lambda = 1/2): the isotropic kernels' second Sonine
  // (docs/methods/derivations/vhs-white-noise-a2.md)
  const Outcome vhs = granmc("theory " + scenes + "event_vhs.toml");
  ASSERT_EQ(vhs.status, 0) << vhs.stderr_text;
  const nlohmann::json v = nlohmann::json::parse(vhs.stdout_text)["white_noise"];
  EXPECT_NEAR(v["a2"].get<double>(), 64.0 / 1235.0, 1e-15);
  EXPECT_NEAR(v["a2_second_sonine"].get<double>(), 61435712.0 / 1209815701.0, 1e-15);
  EXPECT_EQ(v["a2_model_error"].get<double>(), std::fabs(v["a2_second_sonine"].get<double>() - v["a2"].get<double>()));
}

TEST_F(Cli, RoughParticlesHaveTheirTheoryAndRun) {
  write("rough.toml", good_scene + "tangential_restitution = 0.5\n");
  const Outcome o = granmc("theory rough.toml");
  ASSERT_EQ(o.status, 0) << o.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(o.stdout_text);
  EXPECT_GT(j["rough"]["theta_hcs"].get<double>(), 0.0);
  EXPECT_EQ(j["rough"]["kappa"], 0.4);
  EXPECT_FALSE(j.contains("cooling_state"));  // the smooth gas's Haff law does not apply
  const Outcome run = granmc("run rough.toml --summary rough.json --quiet");
  ASSERT_EQ(run.status, 0) << run.stderr_text;
  const nlohmann::json summary = nlohmann::json::parse(slurp(dir_ / "rough.json"));
  const nlohmann::json& species = summary["species"][0];
  EXPECT_GT(species["rotational_ratio"]["mean"].get<double>(), 0.0);
  EXPECT_TRUE(species.contains("a02_last_half") && species.contains("a11_last_half"));
  EXPECT_TRUE(species.contains("rotational_temperature"));
  const Outcome explain = granmc("run rough.toml --explain");
  EXPECT_NE(explain.stdout_text.find("rough-hard-sphere"), std::string::npos) << explain.stdout_text;
  EXPECT_NE(explain.stdout_text.find("64 bytes per particle"), std::string::npos) << explain.stdout_text;  // + spins
  // A smooth scene has none of the rough records.
  write("smooth.toml", good_scene);
  ASSERT_EQ(granmc("run smooth.toml --summary smooth.json --quiet").status, 0);
  EXPECT_FALSE(nlohmann::json::parse(slurp(dir_ / "smooth.json"))["species"][0].contains("rotational_ratio"));
  // A mixture of rough particles runs, with theta per species in its theory and its summary.
  write("rough_mixture.toml", good_scene + "tangential_restitution = 0.5\n" + R"(
[[species]]
name = "b"
particles = 500
mass = 2.0
)");
  const Outcome mixture_theory = granmc("theory rough_mixture.toml");
  ASSERT_EQ(mixture_theory.status, 0) << mixture_theory.stderr_text;
  const nlohmann::json m = nlohmann::json::parse(mixture_theory.stdout_text)["rough"];
  EXPECT_EQ(m["theta_hcs"].size(), 2u) << m;
  EXPECT_GT(m["temperature_ratio_hcs"].get<double>(), 0.0) << m;
  ASSERT_EQ(granmc("run rough_mixture.toml --summary rough_mixture.json --quiet").status, 0);
  const nlohmann::json mixture_summary = nlohmann::json::parse(slurp(dir_ / "rough_mixture.json"));
  for (const nlohmann::json& sp : mixture_summary["species"])
    EXPECT_GT(sp["rotational_ratio"]["mean"].get<double>(), 0.0);
  // What rough particles do not run yet is refused with the key named.
  write("rough_event.toml", with("t_end = 0.5", "t_end = 0.5\nmethod = \"event\"") + "tangential_restitution = 0.5\n");
  const Outcome event = granmc("run rough_event.toml");
  EXPECT_EQ(event.status, 2);
  EXPECT_NE(event.stderr_text.find("collision.tangential_restitution"), std::string::npos) << event.stderr_text;
}

TEST_F(Cli, BathPrintsTheIntrudersFluxesAndSampledLaw) {  // 002 Figs. 1-2 (drivers/plot_bath.py)
  write("bath.toml", R"([run]
method = "gillespie"
t_end = 1.0
samples = 1
[intruder]
bath = "gaussian"
bath_a = 2.0
bath_density = 1.5
)");
  const Outcome o = granmc("bath bath.toml --v1 0 1.5 --samples 20000 --range -3 0 --bins 30");
  ASSERT_EQ(o.status, 0) << o.stderr_text;
  const nlohmann::json j = nlohmann::json::parse(o.stdout_text);
  ASSERT_EQ(j["points"].size(), 2u);
  // phi_+(0) = rho / (2 sqrt(pi a)) (002 eq. 19); phi_-(v1) = phi_+(-v1).
  EXPECT_NEAR(j["points"][0]["flux_right"].get<double>(), 1.5 / (2.0 * std::sqrt(std::numbers::pi * 2.0)), 1e-12);
  EXPECT_DOUBLE_EQ(j["points"][0]["flux_left"].get<double>(), j["points"][0]["flux_right"].get<double>());
  // At v1 = 0 every draw is v <= 0, inside [-3, 0] but for the far tail: the density integrates to 1.
  double mass = 0.0;
  for (double d : j["points"][0]["g_right_density"]) mass += d * 0.1;
  EXPECT_NEAR(mass, 1.0, 1e-9 + static_cast<double>(j["points"][0]["g_right_outside"].get<int>()) / 20000.0);
  EXPECT_EQ(granmc("bath bath.toml --range 1 -1").status, 2);
  // A scene without an intruder has no bath: exit 2, saying so.
  write("gas.toml", good_scene);
  const Outcome none = granmc("bath gas.toml");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.stderr_text.find("no bath"), std::string::npos) << none.stderr_text;
}

TEST_F(Cli, ExplainPrintsThePlanAndRunsNothing) {
  write("heated.toml", good_scene + "[thermostat]\nkind = \"gaussian\"\n");
  const Outcome o = granmc("run heated.toml --explain");
  EXPECT_EQ(o.status, 0) << o.stderr_text;
  EXPECT_NE(o.stdout_text.find("dsmc<hard-sphere, gaussian-thermostat>"), std::string::npos) << o.stdout_text;
  EXPECT_NE(o.stdout_text.find("not compiled shear"), std::string::npos) << o.stdout_text;
  EXPECT_NE(o.stdout_text.find("memory"), std::string::npos) << o.stdout_text;
  EXPECT_NE(o.stdout_text.find("checkpoints  every 10 min and on SIGINT or SIGTERM to heated.h5.checkpoint"),
            std::string::npos)
      << o.stdout_text;
  EXPECT_NE(granmc("run heated.toml --explain --no-checkpoints").stdout_text.find("checkpoints  none"),
            std::string::npos);
  // Threads inside a replica: the time estimate is that of one thread per replica, and says so.
  write("one.toml", with("replicas = 2", "replicas = 1"));
  const Outcome inside = granmc("run one.toml --explain --threads 2 --threads-per-replica 2");
  EXPECT_NE(inside.stdout_text.find("1 replica(s) at a time, each on 2 threads"), std::string::npos)
      << inside.stdout_text;
  EXPECT_NE(inside.stdout_text.find("with one thread per replica"), std::string::npos) << inside.stdout_text;
  EXPECT_NE(granmc("run one.toml --explain --threads 1").stdout_text.find(" s on 1 threads at "), std::string::npos);
  EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, HelpExitsZero) {
  EXPECT_EQ(granmc("--help").status, 0);
  EXPECT_EQ(granmc("run --help").status, 0);
}

TEST_F(Cli, BadArgumentsExitTwo) {
  write("good.toml", good_scene);
  for (const std::string args : {"", "frobnicate", "run", "run good.toml --threads 0", "run good.toml --seed x",
                                 "run good.toml --no-such-flag", "run good.toml --spread atoms"}) {
    const Outcome o = granmc(args);
    EXPECT_EQ(o.status, 2) << "granmc " << args;
    EXPECT_FALSE(o.stderr_text.empty()) << "granmc " << args;
  }
  EXPECT_TRUE(outputs().empty());
}

// Every kind of bad scene: exit 2, one message naming the file and the key, no output file.
TEST_F(Cli, BadScenesExitTwoNamingFileAndKeyWithoutOutput) {
  struct Case {
    std::string name, text, key;
  };
  const std::vector<Case> cases = {
      {"unknown_key", with("samples = 5", "samples = 5\nfrobnicate = 1"), "run.frobnicate"},
      {"missing_t_end", with("t_end = 0.5\n", ""), "run.t_end"},
      {"missing_dt", with("dt = 0.01\n", ""), "run.dt"},
      {"wrong_type", with("t_end = 0.5", "t_end = \"long\""), "run.t_end"},
      {"dt_zero", with("dt = 0.01", "dt = 0.0"), "run.dt"},
      {"dt_negative", with("dt = 0.01", "dt = -0.1"), "run.dt"},
      {"restitution_above_one", with("restitution = 0.9", "restitution = 1.5"), "collision.restitution"},
      {"restitution_negative", with("restitution = 0.9", "restitution = -0.1"), "collision.restitution"},
      {"restitution_nan", with("restitution = 0.9", "restitution = nan"), "collision.restitution"},
      {"mass_zero", with("particles = 500", "particles = 500\nmass = 0.0"), "species[0].mass"},
      {"diameter_negative", with("particles = 500", "particles = 500\ndiameter = -1.0"), "species[0].diameter"},
      {"density_zero", with("particles = 500", "particles = 500\ndensity = 0.0"), "species[0].density"},
      {"particles_zero", with("particles = 500", "particles = 0"), "species[0].particles"},
      {"replicas_zero", with("replicas = 2", "replicas = 0"), "run.replicas"},
      {"temperature_inf", good_scene + "[initial]\ntemperature = inf\n", "initial.temperature"},
      {"temperature_nan", good_scene + "[initial]\ntemperature = nan\n", "initial.temperature"},
      {"particle_ratio",
       with("[[species]]\nparticles = 500\n",
            "[[species]]\nparticles = 500\ndensity = 1.0\n[[species]]\nparticles = 700\ndensity = 1.0\n"),
       "species[1].particles"},
      {"unknown_kernel", with("restitution = 0.9", "restitution = 0.9\nkernel = \"soft\""), "collision.kernel"},
      {"unknown_method", with("[run]", "[run]\nmethod = \"leapfrog\""), "run.method"},
      {"broken_toml", "[run\nt_end = 1\n", "line 1"},
      {"empty", "", "empty"},
      {"binary",
       std::string("\x7f"
                   "ELF\0\0\x01\x02",
                   8),
       "NUL"},
  };
  for (const Case& c : cases) {
    const fs::path scene = write(c.name + ".toml", c.text);
    const Outcome o = granmc("run " + c.name + ".toml --summary s.json");
    EXPECT_EQ(o.status, 2) << c.name << ": " << o.stderr_text;
    EXPECT_NE(o.stderr_text.find(c.name + ".toml"), std::string::npos) << c.name << ": " << o.stderr_text;
    EXPECT_NE(o.stderr_text.find(c.key), std::string::npos) << c.name << ": " << o.stderr_text;
    EXPECT_EQ(std::count(o.stderr_text.begin(), o.stderr_text.end(), '\n'), 1) << c.name << ": " << o.stderr_text;
    EXPECT_TRUE(outputs().empty()) << c.name;
  }
  const Outcome missing = granmc("run no_such_scene.toml");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.stderr_text.find("no_such_scene.toml"), std::string::npos) << missing.stderr_text;
  EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, UnsupportedCombinationExitsTwoSayingWhatIsSupported) {
  write("event.toml", with("[run]", "[run]\nmethod = \"event\""));
  const Outcome o = granmc("run event.toml");
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.stderr_text.find("supported:"), std::string::npos) << o.stderr_text;
  EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli,
       SpreadParticlesRunsOrSaysWhatItSupports) {  // docs/user-guide/parallel-runs.md, "One system over several ranks"
  write("good.toml", good_scene);
  const Outcome ok = granmc("run good.toml --spread particles --out s.h5 --summary s.json");
  EXPECT_EQ(ok.status, 0) << ok.stderr_text;
  EXPECT_TRUE(fs::exists(dir_ / "s.h5"));
  write("float.toml", with("[run]", "[run]\nstorage = \"float\""));
  const Outcome refused = granmc("run float.toml --spread particles --out f.h5");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.stderr_text.find("float.toml: one system over several ranks (--spread particles) is not "
                                     "implemented for run.storage = \"float\""),
            std::string::npos)
      << refused.stderr_text;
  EXPECT_FALSE(fs::exists(dir_ / "f.h5"));
  const Outcome plan = granmc("run good.toml --spread particles --explain");
  EXPECT_EQ(plan.status, 0) << plan.stderr_text;
  EXPECT_NE(plan.stdout_text.find("spread       every replica is one system over 1 rank(s)"), std::string::npos)
      << plan.stdout_text;
  EXPECT_EQ(granmc("run float.toml --spread particles --explain").status, 2);
}
