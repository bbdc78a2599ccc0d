#pragma once
// The JSON summary of a run (`granmc run --summary FILE.json`): the records of the output schema marked for
// the summary (io/output_schema.hpp, docs/formats/output-format.md), under the names they have in the HDF5 file. The
// names the scene contract fixes (docs/formats/scenes.md, "What a run writes": scene, seed, replicas, method,
// wall_seconds, collisions, times, temperature, species [{name, temperature, a2}], temperature_ratio, viscosity,
// intruder) are among them.
//
// A record over the sample times (times, temperature, the species' series, ...) is in the summary at no more
// than summary_sample_times_max of them (io/output_schema.hpp: every summary_stride-th and the last); the
// HDF5 file holds them all. Arrays of numbers are written on one line.
//
// JSON has no NaN or infinity: every non-finite number is written as null (e.g. a2 of a replica set whose
// temperature underflowed), so the file always parses; readers treat null as "not a number".
#include <string>

#include <nlohmann/json.hpp>

#include "kernel/analysis/run_report.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// The summary object of a run.
nlohmann::json summary_json(const Scene& scene, const RunResult& result, const RunReport& report);

/// Writes `summary` to `path + ".tmp-<pid>"` and renames it to `path`; on failure removes the temporary
/// file and throws std::runtime_error naming the path.
void write_summary(const std::string& path, const nlohmann::json& summary);

}  // namespace granmc
