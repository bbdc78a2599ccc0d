#pragma once
// The granmc command line (CLI11): `granmc run`, `granmc sweep`, `granmc theory`. Exit status: 0 success,
// 2 bad scene, sweep file or arguments (one message on stderr, no output files), 1 failure during the run,
// 3 interrupted (docs/user-guide/command-line.md, "Exit status").

namespace granmc {

inline constexpr int exit_ok = 0;
inline constexpr int exit_run_failure = 1;
inline constexpr int exit_bad_input = 2;

int cli_main(int argc, char** argv);

}  // namespace granmc
