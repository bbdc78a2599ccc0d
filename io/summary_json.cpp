#include "io/summary_json.hpp"

#include <algorithm>
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

/// The entries of `xs` at `at`.
std::vector<double> entries_at(const std::vector<double>& xs, const std::vector<std::size_t>& at) {
  std::vector<double> out;
  out.reserve(at.size());
  for (std::size_t k : at) out.push_back(xs[k]);
  return out;
}

/// A record's value at the summary's sample times (`at`): the series and numbers over the sample times.
RecordValue at_sample_times(RecordValue value, const std::vector<std::size_t>& at) {
  if (auto* xs = std::get_if<std::vector<double>>(&value)) return entries_at(*xs, at);
  if (auto* s = std::get_if<MeanCISeries>(&value)) return MeanCISeries{entries_at(s->mean, at), entries_at(s->ci, at)};
  return value;
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
  j["species"] = nlohmann::json::array();  // the scene contract: present, empty for an intruder scene
  const std::string species_mark = "{species}";
  const std::vector<std::size_t> sample_times = summary_sample_indices(result.times.size());
  for (const OutputRecord& record : output_records()) {
    if (record.summary == InSummary::no || record.kind == RecordKind::rows || record.kind == RecordKind::count_rows ||
        record.kind == RecordKind::group)
      continue;
    const bool per_species = record.path.find(species_mark) != std::string::npos;
    for (std::size_t i = 0; i < (per_species ? report.species.size() : 1); ++i) {
      std::optional<RecordValue> value = record.value(output, i);
      if (!value) continue;
      if (record.summary == InSummary::sample_times) value = at_sample_times(std::move(*value), sample_times);
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

namespace {

/// `j` indented by two spaces per level, an array of numbers (or other scalars) on one line.
void append_indented(std::string& out, const nlohmann::json& j, std::size_t depth) {
  // error_handler::replace: an invalid UTF-8 byte in a name (e.g. the scene path) becomes U+FFFD, not a throw.
  const auto compact = [](const nlohmann::json& x) {
    return x.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  };
  const auto structured = [](const nlohmann::json& x) { return x.is_structured(); };
  if (!j.is_structured() || j.empty() || (j.is_array() && std::none_of(j.begin(), j.end(), structured))) {
    out += compact(j);
    return;
  }
  const std::string indent(2 * (depth + 1), ' ');
  out += j.is_object() ? "{\n" : "[\n";
  std::size_t left = j.size();
  for (auto it = j.begin(); it != j.end(); ++it) {
    out += indent;
    if (j.is_object()) out += compact(nlohmann::json(it.key())) + ": ";
    append_indented(out, *it, depth + 1);
    out += --left > 0 ? ",\n" : "\n";
  }
  out += std::string(2 * depth, ' ') + (j.is_object() ? "}" : "]");
}

}  // namespace

void write_summary(const std::string& path, const nlohmann::json& summary) {
  std::string text;
  append_indented(text, summary, 0);
  write_file_atomically(path, text + '\n', "summary");
}

}  // namespace granmc
