// The run plan (kernel/setup/run_plan.hpp): every combination of the scene's kinds is either refused by
// make_plan, with a reason naming what is not supported, or runs through the dispatch, which compiles only
// the supported products; the plan holds the evaluators with the scene's parameters; the name and the
// explanation are read off the plan.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "io/explain_rates.hpp"
#include "io/scene_file.hpp"
#include "kernel/setup/explain.hpp"
#include "kernel/setup/run_scene.hpp"

using namespace granmc;

namespace {

struct Kinds {
  const char* kernel;      // collision.kernel
  double shear;            // shear.rate
  double packing;          // collision.packing_fraction
  const char* thermostat;  // thermostat.kind
  bool relaxation;
  const char* storage;
  int species;
  int dimension = 3;  // run.dimension
};

std::string scene_text(const Kinds& k) {
  std::string t = "[run]\nmethod = \"dsmc\"\nt_end = 0.05\ndt = 0.01\nsamples = 2\nreplicas = 1\nstorage = \"" +
                  std::string(k.storage) + "\"\ndimension = " + std::to_string(k.dimension) + "\n";
  // With a packing fraction, the densities that give it with unit diameters (the scene file checks it under shear):
  // phi = pi n / 6 for spheres, pi n / 4 for disks.
  char density[32];
  std::snprintf(density, sizeof density, "%.17g",
                k.packing > 0.0 ? (k.dimension == 3 ? 6.0 : 4.0) * k.packing / (std::numbers::pi * k.species) : 0.1);
  for (int i = 0; i < k.species; ++i)
    t += "[[species]]\nname = \"s" + std::to_string(i) + "\"\nparticles = 64\ndensity = " + density + "\n";
  t += "[collision]\nkernel = \"" + std::string(k.kernel) + "\"\nrestitution = 0.9\n";
  if (std::string(k.kernel) != "hard-sphere") t += "rate = 0.2\n";
  if (std::string(k.kernel) == "vhs") t += "lambda = 0.5\n";
  if (k.packing > 0.0) t += "packing_fraction = " + std::to_string(k.packing) + "\n";
  t += "[thermostat]\nkind = \"" + std::string(k.thermostat) + "\"\n";
  if (std::string(k.thermostat) == "white-noise") t += "beta = 0.5\n";
  if (k.shear != 0.0) t += "[shear]\nrate = " + std::to_string(k.shear) + "\n";
  if (k.relaxation) t += "[relaxation]\nenabled = true\n";
  return t;
}

}  // namespace

TEST(RunPlan, EveryCombinationRunsOrIsRefusedWithAReason) {
  int ran = 0, refused = 0;
  for (const char* kernel : {"hard-sphere", "maxwell", "vhs"})
    for (double shear : {0.0, 0.3})
      for (double packing : {0.0, 0.1})
        for (const char* thermostat : {"none", "gaussian", "white-noise"})
          for (bool relaxation : {false, true})
            for (const char* storage : {"double", "float"})
              for (int species : {1, 2})
                for (int dimension : {3, 2}) {
                  const Kinds k{kernel, shear, packing, thermostat, relaxation, storage, species, dimension};
                  const std::string text = scene_text(k);
                  Scene scene;
                  try {
                    scene = parse_scene(text, "combination.toml");
                  } catch (const SceneError&) {  // e.g. a mixture with the rate form: the scene file refuses it
                    continue;
                  }
                  RunPlan plan;
                  try {
                    plan = make_plan(scene);
                  } catch (const PlanRefusal& e) {
                    ++refused;
                    EXPECT_NE(std::string(e.what()).find("cannot run"), std::string::npos) << e.what();
                    EXPECT_EQ(plan_refusal(scene), e.what());
                    continue;
                  }
                  ++ran;
                  EXPECT_TRUE(plan_refusal(scene).empty());
                  const RunResult result = run_plan(plan, scene, {});  // a refused product would throw logic_error
                  EXPECT_EQ(result.replicas.size(), 1u) << text;
                }
  // Maxwell and VHS: one species only (rate form), no shear, no relaxation; relaxation: one species.
  EXPECT_GT(ran, 40);
  EXPECT_GT(refused, 40);
  std::printf("%d combinations ran, %d were refused\n", ran, refused);
}

TEST(RunPlan, RefusalsNameWhatIsNotSupported) {
  auto refusal = [](const Kinds& k) { return plan_refusal(parse_scene(scene_text(k), "s.toml")); };
  EXPECT_NE(refusal({"maxwell", 0.3, 0.0, "none", false, "double", 1}).find("[shear] rate with kernel"),
            std::string::npos);
  EXPECT_NE(refusal({"hard-sphere", 0.3, 0.0, "white-noise", false, "double", 1}).find("white-noise thermostat"),
            std::string::npos);
  EXPECT_NE(refusal({"hard-sphere", 0.0, 0.0, "gaussian", true, "double", 2}).find("[relaxation] term"),
            std::string::npos);
  const Scene float_scene = parse_scene(scene_text({"hard-sphere", 0.0, 0.0, "none", false, "float", 1}), "f.toml");
  EXPECT_TRUE(plan_refusal(float_scene).empty());
  EXPECT_NE(plan_refusal(float_scene, Spread::particles).find("run.storage = \"float\""), std::string::npos);
}

TEST(RunPlan, HoldsTheEvaluatorsWithTheSceneParameters) {
  const Scene scene = parse_scene(scene_text({"vhs", 0.0, 0.0, "white-noise", false, "float", 1}), "vhs.toml");
  const RunPlan plan = make_plan(scene);
  const auto& stepped = std::get<SteppedPlan>(plan.scheme);
  EXPECT_EQ(std::get<VariableHardSpheres>(stepped.kernel).lambda, 0.5);
  const WhiteNoise& noise = std::get<0>(std::get<EffectList<WhiteNoise>>(stepped.thermostat).effects);
  EXPECT_EQ(noise.beta, 0.5);
  EXPECT_EQ(noise.masses, std::vector<double>{1.0});
  EXPECT_TRUE(std::holds_alternative<StoredAs<float>>(stepped.storage));
  EXPECT_EQ(instantiation_name(plan, scene), "dsmc<vhs, white-noise>, float storage (16 bytes per particle)");
  const PlanExplanation what = explain_plan(plan, scene, 2);
  EXPECT_EQ(what.bytes_per_particle, 16u);
  EXPECT_EQ(what.particle_bytes, 64u * 16u);
  EXPECT_GT(what.candidates, 0.0);
}

TEST(RunPlan, WeightsMakeTheWeightedPlanOfTheEventScheme) {
  const std::string text = R"([run]
method = "event"
t_end = 0.1
samples = 2
storage = "${storage}"
[[species]]
particles = 64
[collision]
kernel = "vhs"
lambda = 0.5
rate = 0.2
[thermostat]
kind = "white-noise"
beta = 0.5
[weights]
scheme = "swpm"
particles_per_shell = 8
)";
  auto with_storage = [&](const char* storage) {
    std::string t = text;
    t.replace(t.find("${storage}"), 10, storage);
    return parse_scene(t, "weighted.toml");
  };
  const Scene scene = with_storage("double");
  const RunPlan plan = make_plan(scene);
  const auto& weighted = std::get<WeightedPlan>(plan.scheme);
  EXPECT_EQ(std::get<VariableHardSpheres>(weighted.kernel).lambda, 0.5);
  EXPECT_TRUE(weighted.white_noise);
  EXPECT_EQ(instantiation_name(plan, scene), "swpm<vhs, white-noise>");
  EXPECT_GT(explain_plan(plan, scene, 2).candidates, 0.0);
  const RunResult result = run_plan(plan, scene, {});
  ASSERT_EQ(result.replicas.size(), 1u);
  EXPECT_TRUE(result.replicas[0].weighted.has_value());
  EXPECT_NE(plan_refusal(with_storage("float")).find("[weights] with run.storage = \"float\""), std::string::npos);
  EXPECT_NE(plan_refusal(scene, Spread::particles).find("method other than \"dsmc\""), std::string::npos);
  Scene disks = scene;
  disks.run.dimension = 2;  // the weighted disks take the event scheme's kernel in the plane
  const RunPlan weighted_disks = make_plan(disks);
  EXPECT_EQ(std::get<VariableHardDisks>(std::get<WeightedPlan>(weighted_disks.scheme).kernel).lambda, 0.5);
  EXPECT_EQ(instantiation_name(weighted_disks, disks), "swpm<vhs-disk, white-noise>");
  disks.weights.reset();
  const RunPlan event = make_plan(disks);
  EXPECT_EQ(std::get<VariableHardDisks>(std::get<EventPlan>(event.scheme).kernel).lambda, 0.5);
  EXPECT_EQ(instantiation_name(event, disks), "event<vhs-disk, white-noise>");
}

// --explain's time estimate: every class of run that explain_plan names has a measured rate in
// drivers/explain_rates.toml (embedded at build time), and the class follows the scheme, the kernel, the storage
// and whether the particles fit in the caches (100 MB).
TEST(RunPlan, EveryRateClassOfTheTimeEstimateHasAMeasuredRate) {
  const auto rate_class = [](const std::string& method, const std::string& kernel, long particles,
                             const std::string& storage, bool weighted) {
    const std::string text = "[run]\nmethod = \"" + method + "\"\nt_end = 0.1\n" +
                             (method == "dsmc" ? "dt = 0.01\n" : "") + "samples = 1\nstorage = \"" + storage +
                             "\"\n[[species]]\nparticles = " + std::to_string(particles) +
                             "\n[collision]\nkernel = \"" + kernel + "\"\nrate = 1.0\nrestitution = 0.5\n" +
                             "[thermostat]\nkind = \"white-noise\"\nbeta = 1.0\n" +
                             (weighted ? "[weights]\nscheme = \"swpm\"\nparticles_per_shell = 8\n" : "");
    const Scene scene = parse_scene(text, "rates.toml");
    return explain_plan(make_plan(scene), scene, 2).rate_class;
  };
  const std::vector<std::pair<std::string, std::string>> expected = {
      {rate_class("dsmc", "hard-sphere", 1000, "double", false), "stepped.in_cache"},
      {rate_class("dsmc", "hard-sphere", 4000000, "double", false), "stepped.beyond_caches"},
      {rate_class("event", "hard-sphere", 1000, "double", false), "event.in_cache"},
      {rate_class("event", "hard-sphere", 4000000, "double", false), "event.beyond_caches_double"},
      {rate_class("event", "hard-sphere", 8000000, "float", false), "event.beyond_caches_float"},
      {rate_class("event", "maxwell", 1000, "double", false), "event.maxwell_in_cache"},
      {rate_class("event", "maxwell", 4000000, "double", false), "event.maxwell_beyond_caches_double"},
      {rate_class("event", "maxwell", 8000000, "float", false), "event.maxwell_beyond_caches_float"},
      {rate_class("event", "maxwell", 1000, "double", true), "weighted.maxwell"},
      {rate_class("event", "hard-sphere", 1000, "double", true), "weighted.rate_dependent"},
  };
  for (const auto& [named, want] : expected) {
    EXPECT_EQ(named, want);
    EXPECT_GT(measured_candidates_per_second(named), 0.0) << named;
  }
  EXPECT_THROW(measured_candidates_per_second("stepped.on_the_moon"), std::runtime_error);
}

// Elastic particles keep their temperature: the candidates' estimate is the limit alpha -> 1 of the cooling
// gas's (Haff's law), not 0/0.
TEST(RunPlan, TheCandidatesOfAnElasticGasAreTheLimitOfACoolingOnes) {
  const auto candidates = [](double alpha) {
    const Scene scene = parse_scene(
        "[run]\nt_end = 2.0\ndt = 0.1\nsamples = 1\n[[species]]\nparticles = 1000\n"
        "[collision]\nrestitution = " +
            std::to_string(alpha) + "\n",
        "elastic.toml");
    const PlanExplanation what = explain_plan(make_plan(scene), scene, 1);
    EXPECT_FALSE(what.candidates_upper_bound);
    return what.candidates;
  };
  const double elastic = candidates(1.0);
  EXPECT_TRUE(std::isfinite(elastic));
  EXPECT_GT(elastic, 0.0);
  EXPECT_NEAR(candidates(0.999999), elastic, 1e-5 * elastic);
  EXPECT_LT(candidates(0.9), elastic);  // a cooling gas slows down
}
