#pragma once
// Running the granmc executable from a test (tests/test_cli.cpp, test_sweep.cpp, test_mpi.cpp): each test
// gets its own empty directory, writes its files there, and runs `LAUNCHER granmc ARGS` in it (LAUNCHER
// empty or e.g. mpirun), getting the exit status, stdout and stderr. GRANMC_EXECUTABLE is the granmc binary
// (tests/CMakeLists.txt). The directory is removed after a test that passed and kept after one that failed.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace granmc_test {

namespace fs = std::filesystem;

/// The whole content of a file ("" when it does not exist).
inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

struct Outcome {
  int status = -1;  // exit status, -1 when granmc did not exit normally
  std::string stdout_text;
  std::string stderr_text;
};

class GranmcDirectory : public ::testing::Test {
 protected:
  /// `prefix` names the directory: prefix + the test's name, in GoogleTest's temporary directory.
  explicit GranmcDirectory(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override {
    dir_ = fs::path(::testing::TempDir()) / (prefix_ + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!HasFailure()) fs::remove_all(dir_);
  }

  fs::path write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }

  /// Runs `launcher granmc args` in the test directory.
  Outcome granmc(const std::string& args, const std::string& launcher = "") const {
    const std::string cmd =
        "cd '" + dir_.string() + "' && " + launcher + " '" GRANMC_EXECUTABLE "' " + args + " >stdout.txt 2>stderr.txt";
    const int raw = std::system(cmd.c_str());
    Outcome o;
    o.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    o.stdout_text = slurp(dir_ / "stdout.txt");
    o.stderr_text = slurp(dir_ / "stderr.txt");
    fs::remove(dir_ / "stdout.txt");
    fs::remove(dir_ / "stderr.txt");
    return o;
  }

  fs::path dir_;

 private:
  std::string prefix_;
};

}  // namespace granmc_test
