#pragma once
// The HDF5 result file of a run: every record of the output schema (io/output_schema.hpp) that the run has,
// laid out as docs/formats/output-format.md describes (generated from the same declarations).
#include <string>

#include "kernel/analysis/run_report.hpp"
#include "kernel/core/scene.hpp"
#include "kernel/observe/gas_series.hpp"

namespace granmc {

/// Writes the result file to `path + ".tmp-<pid>"` and renames it to `path` when complete. On any failure
/// the temporary file is removed, `path` is left untouched, and std::runtime_error says what failed.
void write_hdf5(const std::string& path, const Scene& scene, const RunResult& result, const RunReport& report);

}  // namespace granmc
