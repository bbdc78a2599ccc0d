// Output: the run report's replica statistics against hand-computed values, the HDF5 file read back with
// the HDF5 C API, the temporary-file-and-rename rule, and the JSON summary contract (docs/formats/scenes.md, "What a
// run writes").
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "granmc/version.hpp"
#include "io/hdf5_output.hpp"
#include "io/output_schema.hpp"
#include "io/summary_json.hpp"
#include "kernel/analysis/run_report.hpp"
#include "tests/test_scenes.hpp"

namespace granmc {
namespace {

namespace fs = std::filesystem;

/// A fresh directory under the system temp directory, removed with its contents at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("granmc_test_output_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  [[nodiscard]] bool holds_temporary_file() const {
    for (const auto& entry : fs::directory_iterator(path))
      if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
    return false;
  }
};

SpeciesSeries species_series(std::vector<double> temperature, std::vector<double> a2) {
  SpeciesSeries s;
  for (double t : temperature) s.log_temperature.push_back(std::log(t));
  s.temperature = std::move(temperature);
  s.a3.assign(a2.size(), 0.0);  // Maxwellian-like
  s.a2 = std::move(a2);
  return s;
}

/// Fills the mixture series of a one-species replica from its species series.
ReplicaSeries replica(SpeciesSeries sp, std::vector<double> collisions, std::uint64_t candidates) {
  ReplicaSeries r;
  r.temperature = sp.temperature;
  r.log_temperature = sp.log_temperature;
  for (std::size_t k = 0; k < sp.temperature.size(); ++k) {
    r.momentum.push_back({1e-15 * static_cast<double>(k), 0.0, -2e-15});
    r.momentum_relative.push_back(1e-16 * static_cast<double>(k + 1));
  }
  r.species.push_back(std::move(sp));
  r.collisions = std::move(collisions);
  r.candidates = candidates;
  r.majorant_updates = 1;
  r.rescales = 2;
  r.momentum_removed_relative = 1e-14;
  return r;
}

/// The scenes below: monodisperse hard-sphere cooling, 2 replicas, 3 sample times; ${species} is one or two
/// [[species]] tables.
constexpr std::string_view scene_text = R"(
  [run]
  method = "dsmc"
  replicas = 2
  t_end = 1.0
  dt = 0.01
  samples = 2

  ${species}

  [collision]
  restitution = 0.9
)";

/// The seed is set after parsing: it needs all 64 bits, and a scene file's seed is a TOML integer, at most
/// 2^63 - 1 (docs/formats/scenes.md). The files written must carry it whole.
constexpr std::uint64_t seed_of_64_bits = 18446744073709551557ULL;

/// One species: the theory applies.
Scene one_species_scene() {
  Scene s = testing::scene_from_toml(scene_text, {{"species", R"(
    [[species]]
    particles = 1000
  )"}});
  s.run.seed = seed_of_64_bits;
  return s;
}

RunResult one_species_result() {
  RunResult r;
  r.times = {0.0, 0.5, 1.0};
  r.species_names = {"a"};
  r.threads = 2;
  r.replicas.push_back(replica(species_series({1.0, 0.8, 0.6}, {0.0, 0.01, 0.02}), {0, 10, 25}, 100));
  r.replicas.push_back(replica(species_series({1.0, 0.6, 0.4}, {0.0, 0.03, 0.04}), {0, 12, 30}, 200));
  return r;
}

/// Two species: T_1/T_2 over samples k >= 1 is (2 + 3)/2 = 2.5 in replica 0 and (1.5 + 2.5)/2 = 2 in replica 1.
Scene two_species_scene() {
  Scene s = testing::scene_from_toml(scene_text, {{"species", R"(
    [[species]]
    name = "a"
    particles = 1000

    [[species]]
    name = "b"
    mass = 2.0
    particles = 1000
  )"}});
  s.run.seed = seed_of_64_bits;
  return s;
}

RunResult two_species_result() {
  RunResult r;
  r.times = {0.0, 0.5, 1.0};
  r.species_names = {"a", "b"};
  const std::vector<std::vector<double>> t1 = {{1.0, 2.0, 3.0}, {1.0, 1.5, 2.5}};
  for (int i = 0; i < 2; ++i) {
    ReplicaSeries rep = replica(species_series(t1[i], {0.0, 0.0, 0.0}), {0, 5, 9}, 50);
    rep.species.push_back(species_series({1.0, 1.0, 1.0}, {0.0, 0.1, 0.2}));
    r.replicas.push_back(std::move(rep));
  }
  return r;
}

const double lambda_p = 3.2;

TEST(Output, ReportReplicaMeansAndConfidenceIntervals) {
  const RunReport report = make_run_report(one_species_scene(), one_species_result(), 1.5);
  EXPECT_EQ(report.method, "dsmc");
  EXPECT_DOUBLE_EQ(report.wall_seconds, 1.5);
  ASSERT_EQ(report.temperature.size(), 3u);
  // k = 1: values 0.8, 0.6 -> mean 0.7, Var = 0.01, ci = 3.2 sqrt(0.01 / 2).
  EXPECT_NEAR(report.temperature.mean[0], 1.0, 1e-15);
  EXPECT_NEAR(report.temperature.ci[0], 0.0, 1e-15);
  EXPECT_NEAR(report.temperature.mean[1], 0.7, 1e-15);
  EXPECT_NEAR(report.temperature.ci[1], lambda_p * std::sqrt(0.01 / 2.0), 1e-14);
  EXPECT_NEAR(report.temperature.mean[2], 0.5, 1e-15);
  EXPECT_NEAR(report.temperature.ci[2], lambda_p * std::sqrt(0.01 / 2.0), 1e-14);
  // ln T at k = 2: ln 0.6, ln 0.4.
  const double l0 = std::log(0.6), l1 = std::log(0.4), lm = (l0 + l1) / 2;
  EXPECT_NEAR(report.log_temperature.mean[2], lm, 1e-15);
  EXPECT_NEAR(report.log_temperature.ci[2], lambda_p * std::sqrt(((l0 - lm) * (l0 - lm) + (l1 - lm) * (l1 - lm)) / 4.0),
              1e-14);
  ASSERT_EQ(report.species.size(), 1u);
  EXPECT_EQ(report.species[0].name, "a");
  EXPECT_NEAR(report.species[0].temperature.mean[1], 0.7, 1e-15);
  EXPECT_NEAR(report.species[0].a2.mean[2], 0.03, 1e-15);
  EXPECT_NEAR(report.species[0].a2.ci[2], lambda_p * std::sqrt(0.0001 / 2.0), 1e-14);
  EXPECT_NEAR(report.momentum_relative.mean[1], 2e-16, 1e-30);
  EXPECT_NEAR(report.momentum_relative.ci[1], 0.0, 1e-30);
  EXPECT_EQ(report.collisions, 55u);  // 25 + 30: the last sample of each replica
  EXPECT_EQ(report.candidates, 300u);
  EXPECT_EQ(report.majorant_updates, 2u);
  EXPECT_EQ(report.rescales, 4u);
  EXPECT_FALSE(report.temperature_ratio.has_value());
  ASSERT_TRUE(report.theory.has_value());
  EXPECT_DOUBLE_EQ(report.theory->alpha, 0.9);
  ASSERT_EQ(report.theory->temperature.size(), 3u);
  EXPECT_DOUBLE_EQ(report.theory->temperature[0], 1.0);
}

TEST(Output, ReportTemperatureRatioForTwoSpecies) {
  const RunReport report = make_run_report(two_species_scene(), two_species_result(), 0.0);
  ASSERT_TRUE(report.temperature_ratio.has_value());
  EXPECT_NEAR(report.temperature_ratio->mean, 2.25, 1e-14);
  EXPECT_NEAR(report.temperature_ratio->ci, lambda_p * std::sqrt(0.0625 / 2.0), 1e-14);
  EXPECT_FALSE(report.theory.has_value());  // the HCS theory is monodisperse
  EXPECT_EQ(report.collisions, 18u);
}

TEST(Output, ReportRejectsInconsistentSeries) {
  RunResult r = one_species_result();
  r.replicas[1].species[0].a2.pop_back();
  EXPECT_THROW(make_run_report(one_species_scene(), r, 0.0), std::invalid_argument);
  r.replicas.clear();
  EXPECT_THROW(make_run_report(one_species_scene(), r, 0.0), std::invalid_argument);
}

// --- HDF5 read-back helpers (C API) ---

std::vector<double> read_doubles(hid_t file, const char* path, std::vector<hsize_t>* dims = nullptr) {
  const hid_t set = H5Dopen2(file, path, H5P_DEFAULT);
  EXPECT_GE(set, 0) << path;
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> d(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space, d.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t x : d) n *= x;
  std::vector<double> v(n);
  EXPECT_GE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), 0) << path;
  H5Sclose(space);
  H5Dclose(set);
  if (dims) *dims = d;
  return v;
}

std::string read_string_attribute(hid_t file, const char* object, const char* name) {
  const hid_t attr = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(attr, 0) << object << " @" << name;
  if (attr < 0) return {};
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  char* text = nullptr;
  EXPECT_GE(H5Aread(attr, type, &text), 0);
  std::string s = text ? text : "";
  H5free_memory(text);
  H5Tclose(type);
  H5Aclose(attr);
  return s;
}

template <class T>
T read_scalar_attribute(hid_t file, const char* object, const char* name, hid_t memory_type) {
  T value{};
  const hid_t attr = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  EXPECT_GE(attr, 0) << object << " @" << name;
  if (attr < 0) return value;
  EXPECT_GE(H5Aread(attr, memory_type, &value), 0);
  H5Aclose(attr);
  return value;
}

TEST(Output, Hdf5FileReadsBack) {
  const TempDir dir;
  const Scene scene = one_species_scene();
  const RunResult result = one_species_result();
  const RunReport report = make_run_report(scene, result, 2.5);
  const std::string path = (dir.path / "run.h5").string();
  write_hdf5(path, scene, result, report);
  ASSERT_TRUE(fs::exists(path));
  EXPECT_FALSE(dir.holds_temporary_file());

  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_string_attribute(file, "/", "scene_text"), scene.source_text);
  EXPECT_EQ(read_string_attribute(file, "/", "scene"), scene.source_path);
  EXPECT_EQ(read_string_attribute(file, "/", "format_version"), output_format_version());
  EXPECT_EQ(read_string_attribute(file, "/", "method"), "dsmc");
  EXPECT_EQ(read_string_attribute(file, "/", "version"), std::string(granmc::version));
  EXPECT_NE(read_string_attribute(file, "/", "units").find("k_B = 1"), std::string::npos);
  EXPECT_EQ(read_scalar_attribute<std::uint64_t>(file, "/", "seed", H5T_NATIVE_UINT64), scene.run.seed);
  EXPECT_EQ(read_scalar_attribute<std::int64_t>(file, "/", "replicas", H5T_NATIVE_INT64), 2);
  EXPECT_EQ(read_scalar_attribute<std::int64_t>(file, "/", "threads", H5T_NATIVE_INT64), 2);
  EXPECT_DOUBLE_EQ(read_scalar_attribute<double>(file, "/", "wall_seconds", H5T_NATIVE_DOUBLE), 2.5);

  EXPECT_EQ(read_doubles(file, "/times"), result.times);
  EXPECT_EQ(read_doubles(file, "/temperature/mean"), report.temperature.mean);
  EXPECT_EQ(read_doubles(file, "/temperature/ci"), report.temperature.ci);
  std::vector<hsize_t> dims;
  const std::vector<double> rows = read_doubles(file, "/temperature/replicas", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{2, 3}));
  EXPECT_EQ(rows, (std::vector<double>{1.0, 0.8, 0.6, 1.0, 0.6, 0.4}));
  EXPECT_EQ(read_doubles(file, "/species/a/a2/ci"), report.species[0].a2.ci);
  read_doubles(file, "/momentum/replicas", &dims);
  EXPECT_EQ(dims, (std::vector<hsize_t>{2, 3, 3}));
  EXPECT_EQ(read_doubles(file, "/collisions/replicas"), (std::vector<double>{0, 10, 25, 0, 12, 30}));
  EXPECT_EQ(read_doubles(file, "/theory/haff_temperature"), report.theory->temperature);
  EXPECT_DOUBLE_EQ(read_scalar_attribute<double>(file, "/theory", "a2", H5T_NATIVE_DOUBLE), report.theory->a2);
  EXPECT_NE(read_string_attribute(file, "/temperature/ci", "description").find("lambda_p"), std::string::npos);

  std::vector<std::uint64_t> candidates(2);
  const hid_t set = H5Dopen2(file, "/counters/candidates", H5P_DEFAULT);
  ASSERT_GE(set, 0);
  EXPECT_GE(H5Dread(set, H5T_NATIVE_UINT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, candidates.data()), 0);
  EXPECT_EQ(candidates, (std::vector<std::uint64_t>{100, 200}));
  H5Dclose(set);
  EXPECT_EQ(H5Lexists(file, "/temperature_ratio", H5P_DEFAULT), 0);
  H5Fclose(file);
}

TEST(Output, Hdf5TwoSpeciesHasRatioAndNoTheory) {
  const TempDir dir;
  const Scene scene = two_species_scene();
  const RunResult result = two_species_result();
  const std::string path = (dir.path / "mix.h5").string();
  write_hdf5(path, scene, result, make_run_report(scene, result, 0.0));
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_NEAR(read_scalar_attribute<double>(file, "/temperature_ratio", "mean", H5T_NATIVE_DOUBLE), 2.25, 1e-14);
  EXPECT_EQ(read_doubles(file, "/species/b/a2/mean"), (std::vector<double>{0.0, 0.1, 0.2}));
  EXPECT_EQ(read_scalar_attribute<std::int64_t>(file, "/species/b", "index", H5T_NATIVE_INT64), 1);
  EXPECT_EQ(H5Lexists(file, "/theory", H5P_DEFAULT), 0);
  H5Fclose(file);
}

TEST(Output, Hdf5FailureThrowsAndLeavesNothing) {
  const Scene scene = one_species_scene();
  const RunResult result = one_species_result();
  const RunReport report = make_run_report(scene, result, 0.0);
  ASSERT_FALSE(fs::exists("/nonexistent-dir"));
  EXPECT_THROW(write_hdf5("/nonexistent-dir/x.h5", scene, result, report), std::runtime_error);
  EXPECT_FALSE(fs::exists("/nonexistent-dir"));
  try {
    write_hdf5("/nonexistent-dir/x.h5", scene, result, report);
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.h5"), std::string::npos) << e.what();
  }

  // The temporary file is written but the rename fails (the target is a directory): nothing remains.
  const TempDir dir;
  fs::create_directory(dir.path / "target");
  EXPECT_THROW(write_hdf5((dir.path / "target").string(), scene, result, report), std::runtime_error);
  EXPECT_FALSE(dir.holds_temporary_file());
  EXPECT_TRUE(fs::is_directory(dir.path / "target"));
}

TEST(Output, SummaryHasTheContractKeys) {
  const Scene scene = two_species_scene();
  const RunResult result = two_species_result();
  const nlohmann::json j = summary_json(scene, result, make_run_report(scene, result, 1.25));
  for (const char* key :
       {"scene", "seed", "replicas", "method", "wall_seconds", "collisions", "times", "temperature", "species",
        "temperature_ratio", "log_temperature", "momentum_relative", "candidates", "threads", "version"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["scene"], scene.source_path);
  EXPECT_EQ(j["seed"].get<std::uint64_t>(), scene.run.seed);
  EXPECT_EQ(j["replicas"], 2);
  EXPECT_EQ(j["method"], "dsmc");
  EXPECT_EQ(j["collisions"], 18);
  EXPECT_EQ(j["times"].size(), 3u);
  EXPECT_EQ(j["temperature"]["mean"].size(), 3u);
  EXPECT_EQ(j["temperature"]["ci"].size(), 3u);
  ASSERT_EQ(j["species"].size(), 2u);
  EXPECT_EQ(j["species"][1]["name"], "b");
  EXPECT_EQ(j["species"][1]["a2"]["mean"][2].get<double>(), 0.2);
  EXPECT_TRUE(j["species"][0]["temperature"].contains("ci"));
  EXPECT_NEAR(j["temperature_ratio"]["mean"].get<double>(), 2.25, 1e-14);
  EXPECT_FALSE(j.contains("theory"));

  const Scene one = one_species_scene();
  const nlohmann::json k = summary_json(one, one_species_result(), make_run_report(one, one_species_result(), 0.0));
  EXPECT_FALSE(k.contains("temperature_ratio"));
  ASSERT_TRUE(k.contains("theory"));
  for (const char* key : {"haff_temperature", "a2", "cooling_rate0", "chi"})
    EXPECT_TRUE(k["theory"].contains(key)) << key;
}

TEST(Output, SummaryWritesNonFiniteAsNull) {
  const TempDir dir;
  const Scene scene = one_species_scene();
  RunResult result = one_species_result();
  result.replicas[0].species[0].a2[2] = std::numeric_limits<double>::quiet_NaN();
  result.replicas[1].momentum_relative[0] = std::numeric_limits<double>::infinity();
  const nlohmann::json j = summary_json(scene, result, make_run_report(scene, result, 0.0));
  EXPECT_TRUE(j["species"][0]["a2"]["mean"][2].is_null());
  EXPECT_TRUE(j["momentum_relative"]["mean"][0].is_null());
  EXPECT_NEAR(j["species"][0]["a2"]["mean"][1].get<double>(), 0.02, 1e-15);

  const std::string path = (dir.path / "summary.json").string();
  write_summary(path, j);
  EXPECT_FALSE(dir.holds_temporary_file());
  std::ifstream in(path);
  const nlohmann::json back = nlohmann::json::parse(in);  // throws if the file is not valid JSON
  EXPECT_TRUE(back["species"][0]["a2"]["mean"][2].is_null());
  EXPECT_EQ(back, j);

  EXPECT_THROW(write_summary("/nonexistent-dir/s.json", j), std::runtime_error);
  EXPECT_FALSE(fs::exists("/nonexistent-dir"));
}

TEST(Output, SummarySampleIndicesAreEveryStrideThAndTheLast) {
  EXPECT_TRUE(summary_sample_indices(0).empty());
  EXPECT_EQ(summary_sample_indices(1), std::vector<std::size_t>{0});
  for (std::size_t k : {std::size_t{2}, std::size_t{101}, std::size_t{102}, std::size_t{1502}, std::size_t{200001}}) {
    const std::vector<std::size_t> at = summary_sample_indices(k);
    const std::size_t stride = summary_stride(k);
    ASSERT_LE(at.size(), summary_sample_times_max) << k;
    EXPECT_EQ(stride, k <= summary_sample_times_max ? 1u : (k - 1 + 99) / 100) << k;
    EXPECT_EQ(at.front(), 0u);
    EXPECT_EQ(at.back(), k - 1) << k;
    for (std::size_t n = 1; n + 1 < at.size(); ++n) EXPECT_EQ(at[n], n * stride) << k;
    EXPECT_GT(at.back(), at[at.size() - 2]);
    EXPECT_LE(at.back() - at[at.size() - 2], stride);
  }
  EXPECT_EQ(summary_sample_indices(200001).size(), 101u);  // 0, 2000, ..., 200000
  EXPECT_EQ(summary_sample_indices(1502).size(), 95u);     // 0, 16, ..., 1488 and 1501
}

/// A long run's summary holds its records over the sample times at every summary_stride-th sample time and
/// the last: the values there are the report's, and the file stays small.
TEST(Output, SummaryHoldsALongRunAtItsSampleTimes) {
  const TempDir dir;
  const Scene scene = one_species_scene();
  constexpr std::size_t sample_times = 1502;
  RunResult r;
  r.species_names = {"a"};
  for (std::size_t k = 0; k < sample_times; ++k) r.times.push_back(0.5 * static_cast<double>(k));
  for (double slope : {0.01, 0.02}) {
    std::vector<double> temperature, a2, collisions;
    for (std::size_t k = 0; k < sample_times; ++k) {
      temperature.push_back(1.0 / (1.0 + slope * r.times[k]));
      a2.push_back(slope * std::sin(static_cast<double>(k)));
      collisions.push_back(10.0 * static_cast<double>(k));
    }
    r.replicas.push_back(replica(species_series(temperature, a2), collisions, 100));
  }
  const RunReport report = make_run_report(scene, r, 0.0);
  const nlohmann::json j = summary_json(scene, r, report);
  const std::vector<std::size_t> at = summary_sample_indices(sample_times);
  EXPECT_EQ(j["summary_stride"].get<std::size_t>(), 16u);
  ASSERT_EQ(j["times"].size(), at.size());
  ASSERT_EQ(j["species"][0]["a2"]["ci"].size(), at.size());
  ASSERT_EQ(j["theory"]["haff_temperature"].size(), at.size());
  for (std::size_t n = 0; n < at.size(); ++n) {
    EXPECT_EQ(j["times"][n].get<double>(), r.times[at[n]]);
    EXPECT_EQ(j["temperature"]["mean"][n].get<double>(), report.temperature.mean[at[n]]);
    EXPECT_EQ(j["species"][0]["a2"]["ci"][n].get<double>(), report.species[0].a2.ci[at[n]]);
    EXPECT_EQ(j["theory"]["haff_temperature"][n].get<double>(), report.theory->temperature[at[n]]);
  }
  // The records that are not over the sample times are whole.
  EXPECT_EQ(j["species"][0]["a2_last_half"]["mean"].get<double>(), report.species[0].a2_last_half.mean);

  const std::string path = (dir.path / "summary.json").string();
  write_summary(path, j);
  EXPECT_LT(fs::file_size(path), 100'000u);
}

}  // namespace
}  // namespace granmc
