#include "io/summary_json.hpp"

#include <cmath>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/output_schema.hpp"

namespace granmc {
namespace {

/// A number, or null when it is not finite (JSON has no NaN or infinity).
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json numbers(const std::vector<double>& xs) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : xs) a.push_back(number(x));
  return a;
}

nlohmann::json to_json(const RecordValue& value) {
  return std::visit(
      [](const auto& v) -> nlohmann::json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>)
          return number(v);
        else if constexpr (std::is_same_v<T, std::vector<double>>)
          return numbers(v);
        else if constexpr (std::is_same_v<T, MeanCI>)
          return {{"mean", number(v.mean)}, {"ci", number(v.ci)}};
        else if constexpr (std::is_same_v<T, MeanCISeries>)
          return {{"mean", numbers(v.mean)}, {"ci", numbers(v.ci)}};
        else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, std::uint64_t> ||
                           std::is_same_v<T, bool>)
          return v;
        else
          return nullptr;  // rows and groups are not in the summary
      },
      value);
}

}  // namespace

nlohmann::json summary_json(const Scene& scene, const RunResult& result, const RunReport& report) {
  const RunOutput output{scene, result, report};
  nlohmann::json j = nlohmann::json::object();
  j["species"] = nlohmann::json::array();  // SCENES.md: present, empty for an intruder scene
  const std::string species_mark = "{species}";
  for (const OutputRecord& record : output_records()) {
    if (!record.summary || record.kind == RecordKind::rows || record.kind == RecordKind::count_rows ||
        record.kind == RecordKind::group)
      continue;
    const bool per_species = record.path.find(species_mark) != std::string::npos;
    for (std::size_t i = 0; i < (per_species ? report.species.size() : 1); ++i) {
      const std::optional<RecordValue> value = record.value(output, i);
      if (!value) continue;
      nlohmann::json* at = &j;
      std::size_t from = 0;
      for (std::size_t slash; (slash = record.path.find('/', from)) != std::string::npos; from = slash + 1) {
        const std::string segment = record.path.substr(from, slash - from);
        at = segment == species_mark ? &(*at)[i] : &(*at)[segment];
      }
      (*at)[record.path.substr(from)] = to_json(*value);
    }
  }
  return j;
}

void write_summary(const std::string& path, const nlohmann::json& summary) {
  // error_handler::replace: an invalid UTF-8 byte in a name (e.g. the scene path) becomes U+FFFD, not a throw.
  write_file_atomically(path, summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + '\n', "summary");
}

}  // namespace granmc
