#pragma once
// Running the granmc executable from a test (tests/test_cli.cpp, test_sweep.cpp, test_mpi.cpp): each test
// gets its own empty directory, writes its files there, and runs `LAUNCHER granmc ARGS` in it (LAUNCHER
// empty or e.g. mpirun), getting the exit status, stdout and stderr, or starts granmc in the background (to
// signal it: tests/test_checkpoint.cpp). GRANMC_EXECUTABLE is the granmc binary
// (tests/CMakeLists.txt). The directory is removed after a test that passed and kept after one that failed.
#include <sys/types.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

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

  /// Starts `launcher granmc args` in the test directory in the background (stdout to out.txt, stderr to
  /// err.txt); returns the process id of the launcher (of granmc without one). Its exit status goes to rc.txt
  /// (wait_exit).
  pid_t start(const std::string& args, const std::string& launcher = "") const {
    fs::remove(dir_ / "pid.txt");
    fs::remove(dir_ / "rc.txt");
    write("start.sh", launcher + " '" GRANMC_EXECUTABLE "' " + args +
                          " >out.txt 2>err.txt & echo $! > pid.txt; wait $!; echo $? > rc.txt\n");
    const std::string cmd = "cd '" + dir_.string() + "' && sh start.sh &";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    for (int k = 0; k < 1000 && slurp(dir_ / "pid.txt").empty(); ++k) sleep_ms(5);
    return static_cast<pid_t>(std::stol(slurp(dir_ / "pid.txt")));
  }
  /// Waits for the process started last to exit; its exit status (128 + signal when a signal ended it).
  int wait_exit() const {
    for (int k = 0; k < 60000 && slurp(dir_ / "rc.txt").empty(); ++k) sleep_ms(5);
    return std::stoi(slurp(dir_ / "rc.txt"));
  }
  bool exists(const std::string& name) const { return fs::exists(dir_ / name); }
  static void sleep_ms(int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); }

  fs::path dir_;

 private:
  std::string prefix_;
};

}  // namespace granmc_test
