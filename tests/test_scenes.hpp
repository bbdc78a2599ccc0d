#pragma once
// Test scenes from TOML text, read by the real parser (granmc::parse_scene, io/scene_file.hpp; every key is
// documented in docs/formats/scenes.md). A test's scene is then one that `granmc run` accepts, spelled out as a scene
// file would spell it, and checked by the same rules (unknown keys and invalid combinations are errors).
//
//   constexpr std::string_view text = R"(
//     [run]
//     t_end = 2.0
//     dt = 0.01
//     replicas = ${replicas}
//
//     [[species]]
//     particles = 3000
//   )";
//   const Scene s = scene_from_toml(text, {{"replicas", 5}});
//
// ${name} in the text is replaced by the value given for it: a test that runs one scene for several
// parameters keeps one text. Numbers are written so that they read back as the same value (integers as
// integers, doubles in their shortest round-trip form), so a scene built from a computed double (1 / pi,
// 6 phi / pi) holds exactly that double.
#include <charconv>
#include <concepts>
#include <cstddef>
#include <initializer_list>
#include <source_location>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "io/scene_file.hpp"

namespace granmc::testing {

/// The text that replaces a ${name} placeholder.
class TomlValue {
 public:
  /// An integer, written as a TOML integer (`particles`, `replicas`, `samples` and `seed` need one).
  template <std::integral T>
  requires(!std::same_as<T, bool> && !std::same_as<T, char>) TomlValue(T v)
      : text_(std::to_string(v)) {}  // NOLINT: implicit, for {{"replicas", 8}}
  /// A double in its shortest form that reads back as the same double (std::to_chars), with ".0" added when
  /// that form has neither a point nor an exponent, so that TOML reads a float (20000.0, not 20000).
  TomlValue(double v) {  // NOLINT: implicit, for {{"alpha", 0.8}}
    char buffer[64];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
    if (error != std::errc{}) throw std::invalid_argument("TomlValue: cannot write a double");
    text_.assign(buffer, end);
    if (text_.find_first_of(".eEn") == std::string::npos) text_ += ".0";  // n: inf and nan stay as they are
  }
  TomlValue(bool v) : text_(v ? "true" : "false") {}  // NOLINT
  /// Text put in as it is: a string choice inside quotes in the scene text (kind = "${kind}"), or whole lines.
  TomlValue(const char* text) : text_(text) {}             // NOLINT
  TomlValue(std::string_view text) : text_(text) {}        // NOLINT
  TomlValue(std::string text) : text_(std::move(text)) {}  // NOLINT

  [[nodiscard]] const std::string& text() const noexcept { return text_; }

 private:
  std::string text_;
};

/// One placeholder and its value.
struct TomlSetting {
  std::string_view name;
  TomlValue value;
};

/// `text` with each ${name} replaced by its value. A placeholder without a value and a value without a
/// placeholder are errors (std::invalid_argument), so that a test cannot silently run a scene other than the
/// one it spells out.
inline std::string fill_toml(std::string_view text, std::initializer_list<TomlSetting> values) {
  std::string out;
  std::vector<bool> used(values.size(), false);
  std::size_t at = 0;
  while (true) {
    const std::size_t open = text.find("${", at);
    if (open == std::string_view::npos) {
      out.append(text.substr(at));
      break;
    }
    const std::size_t close = text.find('}', open);
    if (close == std::string_view::npos) throw std::invalid_argument("scene text: unterminated ${ placeholder");
    const std::string_view name = text.substr(open + 2, close - open - 2);
    out.append(text.substr(at, open - at));
    std::size_t k = 0;
    for (const TomlSetting& v : values) {
      if (v.name == name) break;
      ++k;
    }
    if (k == values.size()) throw std::invalid_argument("scene text: no value for ${" + std::string(name) + "}");
    out.append(values.begin()[k].value.text());
    used[k] = true;
    at = close + 1;
  }
  std::size_t k = 0;
  for (const TomlSetting& v : values)
    if (!used[k++])
      throw std::invalid_argument("scene text: a value for " + std::string(v.name) + " without ${" +
                                  std::string(v.name) + "} in the text");
  return out;
}

/// The scene of the TOML `text` (with its ${name} placeholders filled from `values`), parsed and checked by
/// granmc::parse_scene. The path in the parser's messages, and in Scene::source_path, names the test and the
/// line that asked for the scene, so a scene the parser refuses fails its test with a message saying where.
inline Scene scene_from_toml(std::string_view text, std::initializer_list<TomlSetting> values = {},
                             std::source_location where = std::source_location::current()) {
  std::string path = where.file_name();
  if (const std::size_t slash = path.rfind('/'); slash != std::string::npos) path.erase(0, slash + 1);
  path.append(":").append(std::to_string(where.line()));
  if (const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info())
    path.append(" (").append(test->test_suite_name()).append(".").append(test->name()).append(")");
  return parse_scene(values.size() == 0 ? std::string(text) : fill_toml(text, values), path);
}

}  // namespace granmc::testing
