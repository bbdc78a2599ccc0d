// The output schema (io/output_schema.hpp) drives both files: every record a run has is in the HDF5 file
// under its path, and in the JSON summary under the same path exactly when it is marked for the summary;
// docs/formats/output-format.md is the page `granmc output-format` prints.
#include <hdf5.h>

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/output_schema.hpp"
#include "tests/granmc_process.hpp"

using namespace granmc;
using granmc_test::Outcome;

namespace {

class OutputFormat : public granmc_test::GranmcDirectory {
 protected:
  OutputFormat() : GranmcDirectory("granmc_format_") {}

  /// Runs the scene and checks every record of the schema against both files.
  void check_records(const std::string& scene_text, const std::vector<std::string>& species) {
    write("scene.toml", scene_text);
    const Outcome o = granmc("run scene.toml --out run.h5 --summary run.json --quiet --threads 2");
    ASSERT_EQ(o.status, 0) << o.stderr_text;
    nlohmann::json summary;
    std::ifstream(dir_ / "run.json") >> summary;
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // a record the run does not have is no error here
    const hid_t file = H5Fopen((dir_ / "run.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    int checked = 0;
    for (const OutputRecord& r : output_records()) {
      const bool per_species = r.path.find("{species}") != std::string::npos;
      for (std::size_t i = 0; i < (per_species ? species.size() : 1); ++i) {
        std::string h5 = "/" + r.path, json_path = "/" + r.path;
        if (per_species) {
          h5.replace(h5.find("{species}"), 9, species[i]);
          json_path.replace(json_path.find("{species}"), 9, std::to_string(i));
        }
        const auto slash = h5.rfind('/');
        const std::string parent = slash == 0 ? "/" : h5.substr(0, slash), leaf = h5.substr(slash + 1);
        const bool attribute = r.kind == RecordKind::text || r.kind == RecordKind::number ||
                               r.kind == RecordKind::count || r.kind == RecordKind::flag;
        // A missing parent makes H5Lexists fail (negative): the record is not there.
        const bool in_hdf5 = attribute ? (parent == "/" || H5Lexists(file, parent.c_str(), H5P_DEFAULT) > 0) &&
                                             H5Aexists_by_name(file, parent.c_str(), leaf.c_str(), H5P_DEFAULT) > 0
                                       : H5Lexists(file, h5.c_str(), H5P_DEFAULT) > 0;
        const bool in_json = summary.contains(nlohmann::json::json_pointer(json_path));
        if (r.kind == RecordKind::group) {  // in JSON only as the parent object of its records
        } else if (r.summary != InSummary::no) {
          EXPECT_EQ(in_json, in_hdf5) << r.path;
        } else {
          EXPECT_FALSE(in_json) << r.path;
        }
        checked += in_hdf5;
      }
    }
    H5Fclose(file);
    EXPECT_GT(checked, 30);
  }
};

}  // namespace

TEST_F(OutputFormat, ThePageIsCurrent) {
  const Outcome o = granmc("output-format");
  ASSERT_EQ(o.status, 0) << o.stderr_text;
  std::ifstream page(GRANMC_SOURCE_DIR "/docs/formats/output-format.md");
  std::stringstream text;
  text << page.rdbuf();
  EXPECT_EQ(o.stdout_text, text.str()) << "docs/formats/output-format.md is stale: run `make output-format-page`";
}

TEST_F(OutputFormat, AGasRunHasEveryRecordUnderOneNameInBothFiles) {
  check_records(
      "[run]\nt_end = 0.5\ndt = 0.01\nsamples = 4\nreplicas = 3\n"
      "[[species]]\nname = \"a\"\nparticles = 600\ndensity = 0.5\n"
      "[[species]]\nname = \"b\"\nmass = 2.0\nparticles = 600\ndensity = 0.5\n"
      "[collision]\nrestitution = 0.8\n[thermostat]\nkind = \"gaussian\"\n[shear]\nrate = 0.2\n",
      {"a", "b"});
}

TEST_F(OutputFormat, ACoolingStateHasItsTheoryUnderOneNameInBothFiles) {
  check_records(
      "[run]\nt_end = 0.5\ndt = 0.01\nsamples = 4\nreplicas = 3\n"
      "[[species]]\nname = \"gas\"\nparticles = 600\n[collision]\nrestitution = 0.8\n",
      {"gas"});
}

TEST_F(OutputFormat, ANeedleRunHasEveryRecordUnderOneNameInBothFiles) {
  check_records(
      "[run]\nmethod = \"gillespie\"\nt_end = 20.0\nsamples = 10\nreplicas = 3\n"
      "[intruder]\ndimension = 2\nmass = 2.0\nrestitution = 0.8\n",
      {});
}
