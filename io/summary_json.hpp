#pragma once
// The JSON summary of a run (`granmc run --summary FILE.json`), with the names fixed by SCENES.md
// ("Summary"): scene, seed, replicas, method, wall_seconds, collisions, times, temperature {mean, ci},
// species [{name, temperature {mean, ci}, a2 {mean, ci}}], temperature_ratio {mean, ci} (two species only).
// Added: log_temperature {mean, ci}, momentum_relative {mean, ci}, candidates, majorant_updates, majorant_violations (event), rescales,
// energy_residual_max (time-stepped gas: the steps' energy bookkeeping against a direct sum, rounding only),
// threads, ranks (MPI ranks, 1 without MPI), version, and theory {haff_temperature, a2, cooling_rate0, cooling_rate0_maxwell, chi, alpha,
// collision_frequency0} when the scene is a monodisperse hard-sphere cooling state.
//
// JSON has no NaN or infinity: every non-finite number is written as null (e.g. a2 of a replica set whose
// temperature underflowed), so the file always parses; readers treat null as "not a number".
#include <nlohmann/json.hpp>
#include <string>

#include "io/run_report.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// The summary object of a run.
nlohmann::json summary_json(const Scene& scene, const RunResult& result, const RunReport& report);

/// Writes `summary` to `path + ".tmp-<pid>"` and renames it to `path`; on failure removes the temporary
/// file and throws std::runtime_error naming the path.
void write_summary(const std::string& path, const nlohmann::json& summary);

}  // namespace granmc
