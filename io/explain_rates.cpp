#include "io/explain_rates.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "granmc/explain_rates_text.hpp"

namespace granmc {

double measured_candidates_per_second(std::string_view rate_class) {
  static const toml::table rates = toml::parse(explain_rates_text, std::string_view{"drivers/explain_rates.toml"});
  const std::optional<double> rate = rates.at_path(rate_class).value<double>();
  if (!rate || !(*rate > 0.0))
    throw std::runtime_error("drivers/explain_rates.toml: no positive rate for " + std::string(rate_class));
  return *rate;
}

}  // namespace granmc
