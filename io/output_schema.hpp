#pragma once
// The output schema: every record a run writes, declared once. A record has a
// path ("temperature", "species/{species}/a2", "intruder/R"), a kind, units, a meaning and how to read its
// value from a finished run. The HDF5 writer (io/hdf5_output.cpp), the JSON summary (io/summary_json.cpp)
// and the format page (`granmc output-format`, docs/formats/output-format.md) are driven by these declarations, so
// a record has the same name in the HDF5 file and in the summary, and a new record is one declaration.
//
// How each kind is stored:
//   text, number, count, flag: an attribute of the parent group in HDF5 (the root for a top-level record);
//                              a string, number, integer or boolean in JSON
//   numbers:                   a dataset [K] in HDF5; an array in JSON (sample times, shell edges)
//   mean_ci:                   a group with attributes mean and ci; {"mean": x, "ci": y}
//   series:                    a group with datasets mean [K] and ci [K]; {"mean": [...], "ci": [...]}
//   rows, count_rows:          a dataset [R x ...] of doubles or uint64, one row per replica (HDF5 only)
//   group:                     a group with a description (HDF5 only)
// "{species}" in a path stands for each species in turn: the group /species/<name>/ in HDF5, the entry of the
// array "species" in JSON.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "kernel/analysis/run_report.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// The format of the files: a reader refuses a major version it does not know (a record renamed, moved
/// or given another meaning); a minor version adds records only.
inline constexpr int output_format_major = 2;
inline constexpr int output_format_minor = 7;
/// "2.7": the format_version attribute of every HDF5 file and key of every summary.
std::string output_format_version();

enum class RecordKind { text, number, count, flag, numbers, mean_ci, series, rows, count_rows, group };

/// Whether a record is also in the JSON summary, and how much of it.
enum class InSummary {
  no,           // the HDF5 file only (rows and groups always)
  yes,          // the whole record
  sample_times  // a record over the sample times: its values at the summary's sample times only
};

/// The summary holds a record over the sample times at no more than this many of them; the HDF5 file holds
/// every one. A long run's summary stays a summary (the 1D intruder's 2 10^5 samples were 24 MB of JSON).
inline constexpr std::size_t summary_sample_times_max = 101;

/// The indices of the sample times the summary holds, out of `sample_times`: every k-th from the first,
/// k = summary_stride(sample_times), and the last.
std::vector<std::size_t> summary_sample_indices(std::size_t sample_times);
/// k = ceil((K - 1) / (summary_sample_times_max - 1)) for K sample times, at least 1.
std::size_t summary_stride(std::size_t sample_times);

/// Values one per replica (rows), with the shape [R x ...] of the dataset.
template <class T>
struct ReplicaRows {
  std::vector<T> values;  // row-major
  std::vector<std::size_t> dims;
};

using RecordValue = std::variant<std::string, double, std::uint64_t, bool, std::vector<double>, MeanCI, MeanCISeries,
                                 ReplicaRows<double>, ReplicaRows<std::uint64_t>, std::monostate>;

/// What a record is read from.
struct RunOutput {
  const Scene& scene;
  const RunResult& result;
  const RunReport& report;
};

struct OutputRecord {
  std::string path;
  RecordKind kind;
  InSummary summary;
  std::string units;    // "" for dimensionless or not applicable
  std::string meaning;  // one line; the HDF5 description attribute of a dataset or group
  /// The value for species `i` (ignored without "{species}" in the path), or nothing when the run has no such
  /// record (a viscosity without shear, a needle record of a 1D intruder).
  std::function<std::optional<RecordValue>(const RunOutput&, std::size_t i)> value;
};

/// Every record, in the order the writers write them.
const std::vector<OutputRecord>& output_records();

/// The top-level records that describe how and where the run ran, not its results: they differ between runs of
/// one scene and seed by other builds or on other thread or rank counts (build, wall_seconds, threads,
/// threads_per_replica, collision_rounds..., ranks), when every other record is the same bits.
const std::vector<std::string>& machine_records();

/// The HDF5 group name of species i: its name, with '/' replaced (the name itself is the attribute "name").
std::string species_group_name(const std::string& name, std::size_t index);

/// The Markdown page of the format (docs/formats/output-format.md): one table row per record.
std::string output_format_page();

}  // namespace granmc
