#pragma once
// The measured candidate rates behind `granmc run --explain`'s time estimate: drivers/explain_rates.toml,
// embedded at build time, looked up by the rate class that kernel/setup/explain.hpp names.
#include <string_view>

namespace granmc {

/// Candidates per second per thread of a run of `rate_class` (for example "stepped.beyond_caches"). Throws
/// std::runtime_error naming the class and the file when the file has no positive value for it.
double measured_candidates_per_second(std::string_view rate_class);

}  // namespace granmc
