#pragma once
// What every granmc benchmark program shares: default flags that the user's flags override, and a console
// reporter that remembers each benchmark's counters (the median when there are repetitions) for the ratio
// tables printed after the runs.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

namespace granmc::perf {

/// benchmark::Initialize with 3 repetitions, aggregates only and the given minimum time per benchmark,
/// unless the command line says otherwise. Returns false on unrecognised arguments.
inline bool initialize(int argc, char** argv, const char* min_time) {
  std::vector<std::string> defaults = {"--benchmark_repetitions=3", "--benchmark_report_aggregates_only=true",
                                       std::string("--benchmark_min_time=") + min_time};
  std::vector<char*> args;
  args.push_back(argv[0]);
  for (std::string& d : defaults) args.push_back(d.data());  // first, so the user's flags win
  for (int i = 1; i < argc; ++i) args.push_back(argv[i]);
  int n_args = static_cast<int>(args.size());
  benchmark::Initialize(&n_args, args.data());
  return !benchmark::ReportUnrecognizedArguments(n_args, args.data());
}

class RecordingReporter : public benchmark::ConsoleReporter {
 public:
  explicit RecordingReporter(bool color) : ConsoleReporter(color ? OO_ColorTabular : OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      for (const auto& [name, c] : r.counters)  // a median replaces the single runs
        counters[r.run_name.function_name][r.run_name.args][name] = c.value;
    }
  }
  /// The counter of benchmark `function` at arguments `args`; NaN if it did not run.
  [[nodiscard]] double value(const std::string& function, const std::string& args, const std::string& counter) const {
    const auto f = counters.find(function);
    if (f == counters.end()) return std::nan("");
    const auto a = f->second.find(args);
    if (a == f->second.end()) return std::nan("");
    const auto c = a->second.find(counter);
    return c == a->second.end() ? std::nan("") : c->second;
  }
  std::map<std::string, std::map<std::string, std::map<std::string, double>>> counters;  // [function][args][counter]
};

}  // namespace granmc::perf
