#include "io/scene_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include <toml++/toml.h>

namespace granmc {

namespace {

// The keys of every table, in the order of docs/formats/scenes.md (the order the messages list them in).
constexpr std::string_view kTopLevel[] = {"run",        "species", "collision", "thermostat", "shear",
                                          "relaxation", "initial", "intruder",  "output",     "weights"};
constexpr std::string_view kTopLevelLabels =
    "[run], [[species]], [collision], [thermostat], [shear], [relaxation], [initial], [intruder], [output], "
    "[weights]";

struct KnownTable {
  std::string_view label;  // as written in a scene: "[run]", "[[species]]", "output.histogram"
  std::vector<std::string_view> keys;
};

const std::vector<KnownTable>& known_tables() {
  static const std::vector<KnownTable> tables = {
      {"[run]",
       {"method", "seed", "replicas", "t_end", "dt", "samples", "dt_scaling", "sample_spacing", "storage",
        "checkpoint_every", "dimension"}},
      {"[[species]]", {"name", "mass", "diameter", "density", "particles"}},
      {"[collision]",
       {"kernel", "lambda", "rate", "restitution", "packing_fraction", "tangential_restitution", "reduced_inertia"}},
      {"[thermostat]", {"kind", "zeta", "beta", "rotational_share"}},
      {"[shear]", {"rate"}},
      {"[relaxation]", {"enabled", "a2"}},
      {"[initial]", {"temperature", "zero_momentum"}},
      {"[intruder]", {"dimension", "mass", "restitution", "bath", "bath_a", "bath_density", "length", "inertia"}},
      {"[output]", {"histogram"}},
      {"output.histogram", {"shells", "radius", "speed"}},
      {"[weights]", {"scheme", "particles_per_shell", "growth"}},
  };
  return tables;
}

const KnownTable& known(std::string_view label) {
  for (const auto& t : known_tables())
    if (t.label == label) return t;
  throw std::logic_error("scene_file: unknown table label");
}

// ---------------------------------------------------------------------------------------------
// Formatting for messages.

std::string fmt(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string fmt(std::int64_t x) { return std::to_string(x); }

std::string fmt_short(double x) {  // 6 significant digits, for derived quantities such as ratios
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string quote_str(std::string_view s) {
  std::string out = "\"";
  std::size_t n = 0;
  for (const char c : s) {
    if (++n > 60) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(u));
      out += buf;
    } else {
      out += c;
    }
  }
  out += '"';
  return out;
}

/// A key as written in a message: bare when it is a TOML bare key, quoted (and escaped) otherwise.
std::string key_text(std::string_view k) {
  const bool bare = !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  return bare ? std::string(k) : quote_str(k);
}

std::string list(const std::vector<std::string_view>& items) {
  std::string out;
  for (const auto item : items) {
    if (!out.empty()) out += ", ";
    out += item;
  }
  return out;
}

/// "a string (\"5\")", "an integer (3)", "a table", ...: what a node is, for type errors.
std::string describe(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string:
      return "a string (" + quote_str(n.as_string()->get()) + ")";
    case toml::node_type::integer:
      return "an integer (" + fmt(n.as_integer()->get()) + ")";
    case toml::node_type::floating_point:
      return "a float (" + fmt(n.as_floating_point()->get()) + ")";
    case toml::node_type::boolean:
      return std::string("a boolean (") + (n.as_boolean()->get() ? "true" : "false") + ")";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "an empty value";
  }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const auto ca = std::tolower(static_cast<unsigned char>(a[i - 1]));
      const auto cb = std::tolower(static_cast<unsigned char>(b[j - 1]));
      const bool same = ca == cb || ((ca == '-' || ca == '_') && (cb == '-' || cb == '_'));
      const std::size_t next = std::min({row[j] + 1, row[j - 1] + 1, diag + (same ? 0 : 1)});
      diag = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

/// The closest candidate within a small edit distance, or nothing.
std::optional<std::string_view> closest(std::string_view word, const std::vector<std::string_view>& candidates) {
  std::optional<std::string_view> best;
  std::size_t best_d = std::max<std::size_t>(1, std::min<std::size_t>(2, word.size() / 3));
  for (const auto c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d <= best_d && (!best || d < best_d)) {
      best = c;
      best_d = d;
    }
  }
  return best;
}

/// " (did you mean t_end?)", " (it belongs in [collision])" or "".
std::string unknown_key_hint(std::string_view key, std::string_view own_label,
                             const std::vector<std::string_view>& allowed) {
  if (const auto c = closest(key, allowed)) return " (did you mean " + std::string(*c) + "?)";
  std::string where;
  for (const auto& t : known_tables()) {
    if (t.label == own_label) continue;
    if (std::find(t.keys.begin(), t.keys.end(), key) == t.keys.end()) continue;
    if (!where.empty()) where += " or ";
    where += t.label;
  }
  if (!where.empty()) return " (it belongs in " + where + ")";
  return {};
}

// ---------------------------------------------------------------------------------------------
// Text checks before TOML: empty, binary, invalid UTF-8.

std::pair<std::size_t, std::size_t> line_column(std::string_view text, std::size_t offset) {
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++col;  // count code points, not continuation bytes
    }
  }
  return {line, col};
}

/// Offset of the first byte that does not start a valid UTF-8 sequence (overlong forms, surrogates
/// and code points above U+10FFFF are invalid), or npos.
std::size_t first_invalid_utf8(std::string_view s) {
  const auto* p = reinterpret_cast<const unsigned char*>(s.data());
  const std::size_t n = s.size();
  std::size_t i = 0;
  while (i < n) {
    const unsigned c = p[i];
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t len = 0;
    unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
    if (c >= 0xC2 && c <= 0xDF) {
      len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      len = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      len = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return i;
    }
    if (i + len > n) return i;
    if (p[i + 1] < lo || p[i + 1] > hi) return i;
    for (std::size_t k = 2; k < len; ++k)
      if (p[i + k] < 0x80 || p[i + k] > 0xBF) return i;
    i += len;
  }
  return std::string_view::npos;
}

void check_text(std::string_view text, const std::string& path) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    throw SceneError(path +
                     ": the file is empty; a scene needs at least a [run] table with t_end "
                     "(see docs/formats/scenes.md)");
  }
  if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
    const auto [line, col] = line_column(text, nul);
    throw SceneError(path + ": binary file (NUL byte at line " + std::to_string(line) + ", column " +
                     std::to_string(col) + "); a scene must be a UTF-8 TOML text file");
  }
  if (const auto bad = first_invalid_utf8(text); bad != std::string_view::npos) {
    const auto [line, col] = line_column(text, bad);
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned>(static_cast<unsigned char>(text[bad])));
    throw SceneError(path + ": not UTF-8 text (invalid byte " + byte + " at line " + std::to_string(line) +
                     ", column " + std::to_string(col) + "); a scene must be a UTF-8 TOML text file");
  }
}

// ---------------------------------------------------------------------------------------------
// The reader: typed access with dotted keys, and one throw per problem.

/// One table of the scene (possibly absent): where it is and how its keys are named.
struct Section {
  const toml::table* table = nullptr;
  std::string prefix;      // "run.", "species[1].", "output.histogram."
  std::string_view label;  // "[run]", "[[species]]", "output.histogram"

  const toml::node* get(std::string_view k) const { return table ? table->get(k) : nullptr; }
  bool has(std::string_view k) const { return get(k) != nullptr; }
  std::string key(std::string_view k) const { return prefix + std::string(k); }
};

constexpr std::int64_t kIntMax = std::numeric_limits<int>::max();
constexpr std::int64_t kInt64Max = std::numeric_limits<std::int64_t>::max();

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path) {}

  [[noreturn]] void fail(std::string_view key, std::string_view what) const {
    std::string m = path_;
    m += ": ";
    m += key;
    m += ": ";
    m += what;
    throw SceneError(m);
  }

  [[noreturn]] void wrong_type(std::string_view key, const toml::node& n, std::string_view expected) const {
    fail(key, "got " + describe(n) + "; expected " + std::string(expected));
  }

  /// Unknown keys are errors: report the first one in file order, with a hint and the allowed keys.
  void check_keys(const Section& s) const {
    if (!s.table) return;
    const auto& allowed = known(s.label).keys;
    const toml::node* first = nullptr;
    std::string_view first_key;
    for (auto&& [k, v] : *s.table) {
      if (std::find(allowed.begin(), allowed.end(), k.str()) != allowed.end()) continue;
      if (!first || before(v, *first)) {
        first = &v;
        first_key = k.str();
      }
    }
    if (!first) return;
    fail(s.prefix + key_text(first_key), "unknown key" + unknown_key_hint(first_key, s.label, allowed) +
                                             "; allowed keys in " + std::string(s.label) + ": " + list(allowed));
  }

  void check_top_level(const toml::table& root) const {
    const toml::node* first = nullptr;
    std::string_view first_key;
    for (auto&& [k, v] : root) {
      if (std::find(std::begin(kTopLevel), std::end(kTopLevel), k.str()) != std::end(kTopLevel)) continue;
      if (!first || before(v, *first)) {
        first = &v;
        first_key = k.str();
      }
    }
    if (!first) return;
    const std::vector<std::string_view> top(std::begin(kTopLevel), std::end(kTopLevel));
    fail(key_text(first_key), "unknown key" + unknown_key_hint(first_key, "", top) +
                                  "; allowed top-level tables: " + std::string(kTopLevelLabels));
  }

  /// The table `name` of the root, or an absent Section; anything else than a table is an error.
  Section table(const toml::table& root, std::string_view name, std::string_view label) const {
    Section s{nullptr, std::string(name) + ".", label};
    if (const toml::node* n = root.get(name)) {
      if (!n->is_table()) wrong_type(name, *n, "a table " + std::string(label));
      s.table = n->as_table();
    }
    return s;
  }

  std::optional<double> number(const Section& s, std::string_view k, std::string_view expected) const {
    const toml::node* n = s.get(k);
    if (!n) return std::nullopt;
    if (const auto* i = n->as_integer()) return static_cast<double>(i->get());
    if (const auto* f = n->as_floating_point()) return f->get();
    wrong_type(s.key(k), *n, expected);
  }

  std::optional<std::int64_t> integer(const Section& s, std::string_view k, std::string_view expected) const {
    const toml::node* n = s.get(k);
    if (!n) return std::nullopt;
    if (const auto* i = n->as_integer()) return i->get();
    if (const auto* f = n->as_floating_point()) {
      const double x = f->get();
      if (std::isfinite(x) && x == std::floor(x) && std::abs(x) < 9.2e18) {
        fail(s.key(k), "got a float (" + fmt(x) + "); expected " + std::string(expected) + " (write " +
                           fmt(static_cast<std::int64_t>(x)) + ", without a decimal point or exponent)");
      }
    }
    wrong_type(s.key(k), *n, expected);
  }

  std::optional<std::string> string(const Section& s, std::string_view k, std::string_view expected) const {
    const toml::node* n = s.get(k);
    if (!n) return std::nullopt;
    if (const auto* v = n->as_string()) return v->get();
    wrong_type(s.key(k), *n, expected);
  }

  std::optional<bool> boolean(const Section& s, std::string_view k) const {
    const toml::node* n = s.get(k);
    if (!n) return std::nullopt;
    if (const auto* v = n->as_boolean()) return v->get();
    wrong_type(s.key(k), *n, "a boolean (true or false)");
  }

  /// A string from a fixed set of names.
  template <class E>
  std::optional<E> choice(const Section& s, std::string_view k,
                          std::initializer_list<std::pair<std::string_view, E>> choices) const {
    std::vector<std::string_view> names;
    std::string allowed;
    for (const auto& c : choices) {
      names.push_back(c.first);
      if (!allowed.empty()) allowed += " | ";
      allowed += quote_str(c.first);
    }
    const auto v = string(s, k, "a string: " + allowed);
    if (!v) return std::nullopt;
    for (const auto& c : choices)
      if (c.first == *v) return c.second;
    std::string hint;
    if (const auto c = closest(*v, names)) hint = " (did you mean " + quote_str(*c) + "?)";
    fail(s.key(k), quote_str(*v) + " is not a known value" + hint + "; allowed: " + allowed);
  }

  // Range checks. NaN fails every one of them.
  double positive(std::string_view key, double x) const {
    if (std::isnan(x)) fail(key, "nan is not a number; expected a finite number > 0");
    if (std::isinf(x)) fail(key, fmt(x) + " is not finite; expected a finite number > 0");
    if (!(x > 0)) fail(key, fmt(x) + " is not > 0; expected a finite number > 0");
    return x;
  }
  double non_negative(std::string_view key, double x) const {
    if (std::isnan(x)) fail(key, "nan is not a number; expected a finite number >= 0");
    if (std::isinf(x)) fail(key, fmt(x) + " is not finite; expected a finite number >= 0");
    if (x < 0) fail(key, fmt(x) + " is negative; expected a finite number >= 0");
    return x == 0 ? 0.0 : x;  // -0.0 -> 0.0
  }
  double finite(std::string_view key, double x) const {
    if (!std::isfinite(x)) fail(key, fmt(x) + " is not finite; expected a finite number");
    return x;
  }
  double unit_closed(std::string_view key, double x) const {  // [0, 1]
    if (std::isnan(x)) fail(key, "nan is not a number; expected a number in [0, 1]");
    if (x < 0 || x > 1) fail(key, fmt(x) + " is outside [0, 1]");
    return x == 0 ? 0.0 : x;
  }
  double unit_half_open(std::string_view key, double x) const {  // [0, 1)
    if (std::isnan(x)) fail(key, "nan is not a number; expected a number in [0, 1)");
    if (x < 0 || x >= 1) fail(key, fmt(x) + " is outside [0, 1)");
    return x == 0 ? 0.0 : x;
  }
  std::int64_t int_range(std::string_view key, std::int64_t v, std::int64_t lo, std::int64_t hi) const {
    if (v < lo || v > hi) fail(key, fmt(v) + " is outside [" + fmt(lo) + ", " + fmt(hi) + "]");
    return v;
  }

  void read(const toml::table& root, Scene& scene) const;

 private:
  static bool before(const toml::node& a, const toml::node& b) {
    const auto& pa = a.source().begin;
    const auto& pb = b.source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  }

  void read_run(const Section& s, RunConfig& run) const;
  void read_species(const toml::table& root, Scene& scene) const;
  const toml::array* species_tables(const toml::table& root, const Scene& scene) const;
  void read_one_species(const toml::node& el, std::size_t i, Scene& scene) const;
  void check_particle_ratio(const Scene& scene) const;
  void read_collision(const Section& s, Scene& scene) const;
  void read_thermostat(const Section& s, ThermostatConfig& th, bool rough) const;
  void read_intruder(const Section& s, IntruderConfig& in) const;
  void read_output(const Section& s, HistogramConfig& h) const;
  void read_weights(const Section& s, Scene& scene) const;

  const std::string& path_;
};

void Reader::read_run(const Section& s, RunConfig& run) const {
  check_keys(s);
  run.method =
      choice<Method>(s, "method", {{"dsmc", Method::dsmc}, {"event", Method::event}, {"gillespie", Method::gillespie}})
          .value_or(run.method);
  const std::string method = quote_str(method_name(run.method));

  if (const auto seed = integer(s, "seed", "an integer in [0, 9223372036854775807]")) {
    if (*seed < 0) {
      fail(s.key("seed"), fmt(*seed) +
                              " is outside [0, 9223372036854775807]; seeds are unsigned, and TOML "
                              "integers are signed 64-bit, so a scene can give 0 to 2^63 - 1");
    }
    run.seed = static_cast<std::uint64_t>(*seed);
  }
  if (const auto r = integer(s, "replicas", "an integer in [1, 2147483647]"))
    run.replicas = static_cast<int>(int_range(s.key("replicas"), *r, 1, kIntMax));
  if (const auto sm = integer(s, "samples", "an integer in [1, 2147483647]"))
    run.samples = static_cast<int>(int_range(s.key("samples"), *sm, 1, kIntMax));

  const auto t_end = number(s, "t_end", "a finite number > 0");
  if (!t_end) fail(s.key("t_end"), "missing required key; set the run length t_end > 0 (scene time units) in [run]");
  run.t_end = positive(s.key("t_end"), *t_end);

  run.dt_scaling = choice<DtScaling>(s, "dt_scaling", {{"fixed", DtScaling::fixed}, {"thermal", DtScaling::thermal}})
                       .value_or(run.dt_scaling);
  run.sample_spacing =
      choice<SampleSpacing>(s, "sample_spacing", {{"linear", SampleSpacing::linear}, {"log", SampleSpacing::log}})
          .value_or(run.sample_spacing);
  run.storage =
      choice<Storage>(s, "storage", {{"double", Storage::double_precision}, {"float", Storage::single_precision}})
          .value_or(run.storage);

  const auto dt = number(s, "dt", "a finite number >= 0");
  if (dt) run.dt = non_negative(s.key("dt"), *dt);
  if (const auto every = number(s, "checkpoint_every", "a finite number >= 0 (minutes)"))
    run.checkpoint_every = non_negative(s.key("checkpoint_every"), *every);
  if (const auto d = integer(s, "dimension", "2 or 3")) {
    if (*d != 2 && *d != 3)
      fail(s.key("dimension"), fmt(*d) + " is not 2 or 3: a gas of hard disks (2) or of hard spheres (3)");
    run.dimension = static_cast<int>(*d);
  }
  if (run.method == Method::dsmc) {
    if (!dt) {
      fail(s.key("dt"), "missing required key for method \"dsmc\"; set a time step 0 < dt <= t_end in [run]");
    }
    if (!(run.dt > 0)) fail(s.key("dt"), "0 is not > 0; method \"dsmc\" needs a time step 0 < dt <= t_end");
    if (run.dt > run.t_end) {
      fail(s.key("dt"), fmt(run.dt) + " is larger than run.t_end = " + fmt(run.t_end) +
                            "; method \"dsmc\" needs a time step 0 < dt <= t_end");
    }
  }
  if (run.sample_spacing == SampleSpacing::log && !(run.dt > 0 && run.dt < run.t_end)) {
    fail(s.key("dt"),
         (dt ? fmt(run.dt) + " is not inside (0, t_end = " + fmt(run.t_end) + ")" : std::string("missing")) +
             "; sample_spacing = \"log\" needs 0 < dt < t_end (dt is the first sample time after 0)");
  }
  if (run.dt_scaling == DtScaling::thermal && run.method != Method::dsmc) {
    fail(s.key("dt_scaling"), "\"thermal\" has no effect with method " + method +
                                  "; only method \"dsmc\" has a time step to scale (use \"fixed\" or remove the key)");
  }
}

/// The [[species]] array the method needs, or nothing for an intruder scene; fails when the tables do not go
/// with the method.
const toml::array* Reader::species_tables(const toml::table& root, const Scene& scene) const {
  const toml::node* node = root.get("species");
  const std::string method = quote_str(method_name(scene.run.method));
  const toml::array* arr = nullptr;
  if (node) {
    if (node->is_table()) {
      fail("species",
           "got a table ([species]); expected an array of tables: write [[species]] (double "
           "brackets) once per species");
    }
    arr = node->as_array();
    if (!arr) wrong_type("species", *node, "an array of tables ([[species]])");
  }
  const bool has_intruder = root.get("intruder") != nullptr;

  // Which tables go with which method.
  if (scene.run.method == Method::gillespie) {
    if (node) {
      fail("species",
           "not allowed with method \"gillespie\"; an intruder scene describes its bath in [intruder] "
           "and has no [[species]]");
    }
    if (!has_intruder) fail("intruder", "missing required table for method \"gillespie\"; add an [intruder] table");
    return nullptr;
  }
  if (has_intruder && scene.run.method == Method::event) {
    fail("intruder",
         "not allowed with method \"event\"; [intruder] needs method \"gillespie\" or \"dsmc\" (the "
         "intruder's DSMC alternative)");
  }
  if (has_intruder && node) {
    fail("intruder",
         "not allowed together with [[species]]; a scene is either a gas ([[species]], methods "
         "\"dsmc\" and \"event\") or an intruder in a bath ([intruder], methods \"gillespie\" and "
         "\"dsmc\"), not both");
  }
  if (has_intruder) return nullptr;  // intruder DSMC alternative
  if (!node) {
    fail("species", "missing required [[species]] table for method " + method + "; add one or two [[species]] tables" +
                        (scene.run.method == Method::dsmc ? " (or an [intruder] table for an intruder scene)" : ""));
  }
  if (arr->empty()) fail("species", "empty array; method " + method + " needs 1 or 2 species");
  if (arr->size() > 2) {
    fail("species",
         std::to_string(arr->size()) + " species given; at most 2 are supported (1 or 2 [[species]] tables)");
  }

  return arr;
}

void Reader::read_species(const toml::table& root, Scene& scene) const {
  const toml::array* arr = species_tables(root, scene);
  if (!arr) return;
  for (std::size_t i = 0; i < arr->size(); ++i) read_one_species(*arr->get(i), i, scene);
  if (scene.species.size() == 2) check_particle_ratio(scene);
}

/// species[i] from its table, appended to scene.species.
void Reader::read_one_species(const toml::node& el, std::size_t i, Scene& scene) const {
  const std::string idx = "species[" + std::to_string(i) + "]";
  if (!el.is_table()) wrong_type(idx, el, "a table ([[species]])");
  const Section s{el.as_table(), idx + ".", "[[species]]"};
  check_keys(s);
  SpeciesConfig sp;
  sp.name = std::string(1, static_cast<char>('a' + i));
  if (const auto name = string(s, "name", "a non-empty string")) {
    if (name->find_first_not_of(" \t") == std::string::npos)
      fail(s.key("name"), "empty name; expected a non-empty string");
    for (const char c : *name) {
      const auto u = static_cast<unsigned char>(c);
      if (u < 0x20 || u == 0x7f || c == '/')
        fail(s.key("name"),
             quote_str(*name) + " contains '/' or a control character; expected a plain name such as \"a\"");
    }
    sp.name = *name;
  }
  if (const auto m = number(s, "mass", "a finite number > 0")) sp.mass = positive(s.key("mass"), *m);
  if (const auto d = number(s, "diameter", "a finite number > 0")) sp.diameter = positive(s.key("diameter"), *d);
  if (const auto n = number(s, "density", "a finite number > 0")) sp.density = positive(s.key("density"), *n);
  const auto np = integer(s, "particles", "an integer >= 1");
  if (!np) fail(s.key("particles"), "missing required key; set the number of simulated particles N_i >= 1");
  if (*np < 1) fail(s.key("particles"), fmt(*np) + " is not > 0; expected an integer >= 1");
  sp.particles = *np;
  for (std::size_t j = 0; j < scene.species.size(); ++j) {
    if (scene.species[j].name == sp.name) {
      fail(s.key("name"), quote_str(sp.name) + " is already the name of species[" + std::to_string(j) +
                              "]; species names must be unique" +
                              (s.has("name") ? "" : " (default names are \"a\", \"b\" by index)"));
    }
  }
  scene.species.push_back(std::move(sp));
}

/// N_0/N_1 must equal n_0/n_1 to 1 %.
void Reader::check_particle_ratio(const Scene& scene) const {
  const auto& a = scene.species[0];
  const auto& b = scene.species[1];
  const double ratio_N = static_cast<double>(a.particles) / static_cast<double>(b.particles);
  const double ratio_n = a.density / b.density;
  if (!(std::abs(ratio_N / ratio_n - 1.0) <= 0.01 + 1e-12)) {
    const double want = static_cast<double>(a.particles) * b.density / a.density;
    std::string hint;
    if (want >= 1 && want < 9e18)
      hint = ", e.g. species[1].particles = " + fmt(static_cast<std::int64_t>(std::llround(want)));
    fail("species[1].particles",
         "the particle ratio N_0/N_1 = " + fmt(a.particles) + "/" + fmt(b.particles) + " = " + fmt_short(ratio_N) +
             " differs from the density ratio n_0/n_1 = " + fmt(a.density) + "/" + fmt(b.density) + " = " +
             fmt_short(ratio_n) + " by more than 1%; choose particles with N_0/N_1 = n_0/n_1" + hint);
  }
}

void Reader::read_collision(const Section& s, Scene& scene) const {
  check_keys(s);
  CollisionConfig& c = scene.collision;
  c.kernel = choice<CollisionKernel>(s, "kernel",
                                     {{"hard-sphere", CollisionKernel::hard_sphere},
                                      {"maxwell", CollisionKernel::maxwell},
                                      {"vhs", CollisionKernel::vhs}})
                 .value_or(c.kernel);
  // lambda is the VHS exponent; the named kernels fix it (hard-sphere 1, maxwell 0).
  const auto lambda = number(s, "lambda", "a number in [0, 1]");
  if (lambda) c.lambda = unit_closed(s.key("lambda"), *lambda);
  if (c.kernel == CollisionKernel::maxwell) {
    if (lambda && c.lambda != 0.0)
      fail(s.key("lambda"), fmt(c.lambda) +
                                " contradicts kernel = \"maxwell\" (lambda = 0); use kernel = \"vhs\" "
                                "for 0 < lambda < 1, or remove lambda");
    c.lambda = 0.0;
  } else if (c.kernel == CollisionKernel::hard_sphere) {
    if (lambda && c.lambda != 1.0)
      fail(s.key("lambda"), fmt(c.lambda) +
                                " contradicts kernel = \"hard-sphere\" (lambda = 1); use kernel = "
                                "\"vhs\" for 0 < lambda < 1, or remove lambda");
    c.lambda = 1.0;
  }

  if (const auto rate = number(s, "rate", "a finite number >= 0")) c.rate = non_negative(s.key("rate"), *rate);
  if (c.rate > 0 && scene.species.size() > 1) {
    fail(s.key("rate"), fmt(c.rate) +
                            " > 0 selects the one-species Gamba form (B = rate |u|^lambda), but the scene "
                            "has " +
                            std::to_string(scene.species.size()) + " species; use rate = 0 for mixtures");
  }

  const std::string rkey = s.key("restitution");
  const char* rexpect = "a number in [0, 1] or a symmetric 2x2 array [[a11, a12], [a12, a22]]";
  if (const toml::node* n = s.get("restitution")) {
    if (n->is_number()) {
      const double a = unit_closed(rkey, *number(s, "restitution", rexpect));
      for (auto& row : c.restitution) row = {a, a};
    } else if (const auto* arr = n->as_array()) {
      if (arr->size() != 2) {
        fail(rkey, "got an array of " + std::to_string(arr->size()) + " elements; expected " + rexpect);
      }
      for (std::size_t i = 0; i < 2; ++i) {
        const std::string ikey = rkey + "[" + std::to_string(i) + "]";
        const toml::node& row_node = *arr->get(i);
        const auto* row = row_node.as_array();
        if (!row) wrong_type(ikey, row_node, "an array of 2 numbers (a row of [[a11, a12], [a12, a22]])");
        if (row->size() != 2) {
          fail(ikey, "got an array of " + std::to_string(row->size()) +
                         " elements; expected 2 numbers (a row of [[a11, a12], [a12, a22]])");
        }
        for (std::size_t j = 0; j < 2; ++j) {
          const std::string jkey = ikey + "[" + std::to_string(j) + "]";
          const toml::node& el = *row->get(j);
          double v = 0.0;
          if (const auto* iv = el.as_integer())
            v = static_cast<double>(iv->get());
          else if (const auto* fv = el.as_floating_point())
            v = fv->get();
          else
            wrong_type(jkey, el, "a number in [0, 1]");
          c.restitution[i][j] = unit_closed(jkey, v);
        }
      }
      if (c.restitution[0][1] != c.restitution[1][0]) {
        fail(rkey, "the matrix is not symmetric (a12 = " + fmt(c.restitution[0][1]) +
                       ", a21 = " + fmt(c.restitution[1][0]) + "); expected [[a11, a12], [a12, a22]] with a21 = a12");
      }
    } else {
      wrong_type(rkey, *n, rexpect);
    }
  }

  if (const auto phi = number(s, "packing_fraction", "a number in [0, 1)"))
    c.packing_fraction = unit_half_open(s.key("packing_fraction"), *phi);

  // Rough particles (docs/methods/derivations/rough-hcs.md): beta = -1 is the smooth gas.
  if (const auto beta = number(s, "tangential_restitution", "a number in [-1, 1]")) {
    if (!(*beta >= -1.0 && *beta <= 1.0))
      fail(s.key("tangential_restitution"),
           fmt(*beta) + " is outside [-1, 1] (-1: smooth, 0: sticking tangentially, 1: perfectly rough)");
    c.tangential_restitution = *beta;
  }
  c.reduced_inertia = scene.run.dimension == 2 ? 0.5 : 0.4;  // a uniform disk, a uniform sphere
  if (const auto kappa = number(s, "reduced_inertia", "a number in (0, 1]")) {
    if (!(*kappa > 0.0 && *kappa <= 1.0))
      fail(s.key("reduced_inertia"), fmt(*kappa) +
                                         " is outside (0, 1]: kappa = 4 I / (m sigma^2) is 2/5 for a uniform sphere, "
                                         "2/3 for a hollow one, 1/2 for a uniform disk and 1 for a ring");
    c.reduced_inertia = *kappa;
  }
}

void Reader::read_thermostat(const Section& s, ThermostatConfig& th, bool rough) const {
  check_keys(s);
  th.kind = choice<ThermostatKind>(s, "kind",
                                   {{"none", ThermostatKind::none},
                                    {"gaussian", ThermostatKind::gaussian},
                                    {"white-noise", ThermostatKind::white_noise}})
                .value_or(th.kind);

  const char* zexpect = "a finite number or \"cooling-rate\"";
  if (const toml::node* n = s.get("zeta")) {
    if (const auto* str = n->as_string()) {
      if (str->get() != "cooling-rate")
        fail(s.key("zeta"), quote_str(str->get()) + " is not allowed; expected " + zexpect);
      th.zeta_is_cooling_rate = true;
      th.zeta = 0.0;
    } else if (n->is_number()) {
      th.zeta = finite(s.key("zeta"), *number(s, "zeta", zexpect));
      th.zeta_is_cooling_rate = false;
      if (th.kind != ThermostatKind::gaussian) {
        fail(s.key("zeta"), "a fixed zeta has no effect with kind = " +
                                quote_str(th.kind == ThermostatKind::none ? "none" : "white-noise") +
                                "; zeta applies only to kind = \"gaussian\"");
      }
    } else {
      wrong_type(s.key("zeta"), *n, zexpect);
    }
  }

  if (const auto beta = number(s, "beta", "a finite number >= 0")) {
    th.beta = non_negative(s.key("beta"), *beta);
    if (th.beta > 0 && th.kind != ThermostatKind::white_noise) {
      fail(s.key("beta"), fmt(th.beta) + " has no effect with kind = " +
                              quote_str(th.kind == ThermostatKind::none ? "none" : "gaussian") +
                              "; beta applies only to kind = \"white-noise\"");
    }
  }
  if (th.kind == ThermostatKind::white_noise && !(th.beta > 0)) {
    fail(s.key("beta"), std::string(s.has("beta") ? "0 is not > 0" : "missing") +
                            "; kind = \"white-noise\" needs a diffusion coefficient beta > 0");
  }
  // The splitting thermostat of Megias and Santos, Front. Phys. 10 (2022) 971671 (effects/white_noise.hpp).
  if (const auto share = number(s, "rotational_share", "a number in [0, 1]")) {
    if (!(*share >= 0.0 && *share <= 1.0)) fail(s.key("rotational_share"), fmt(*share) + " is outside [0, 1]");
    if (th.kind != ThermostatKind::white_noise || !rough)
      fail(s.key("rotational_share"),
           "applies only to kind = \"white-noise\" with rough particles (collision.tangential_restitution > -1)");
    th.rotational_share = *share;
  }
}

void Reader::read_intruder(const Section& s, IntruderConfig& in) const {
  check_keys(s);
  if (const auto d = integer(s, "dimension", "1 (point intruder on a line) or 2 (needle in the plane)")) {
    if (*d != 1 && *d != 2)
      fail(s.key("dimension"),
           fmt(*d) + " is not allowed; expected 1 (point intruder on a line) or 2 (needle in the plane)");
    in.dimension = static_cast<int>(*d);
  }
  if (const auto m = number(s, "mass", "a finite number > 0")) in.mass = positive(s.key("mass"), *m);
  if (const auto a = number(s, "restitution", "a number in [0, 1]"))
    in.restitution = unit_closed(s.key("restitution"), *a);
  in.bath = choice<BathKind>(s, "bath", {{"gaussian", BathKind::gaussian}, {"power-law", BathKind::power_law}})
                .value_or(in.bath);
  if (const auto a = number(s, "bath_a", "a finite number > 0")) in.bath_a = positive(s.key("bath_a"), *a);
  if (const auto n = number(s, "bath_density", "a finite number > 0"))
    in.bath_density = positive(s.key("bath_density"), *n);
  if (const auto l = number(s, "length", "a finite number > 0")) in.length = positive(s.key("length"), *l);
  if (const auto i = number(s, "inertia", "a finite number >= 0")) in.inertia = non_negative(s.key("inertia"), *i);
}

void Reader::read_output(const Section& s, HistogramConfig& h) const {
  check_keys(s);
  const toml::node* n = s.get("histogram");
  if (!n) return;
  if (!n->is_table()) wrong_type(s.key("histogram"), *n, "an inline table { shells = 128, radius = 16.0 }");
  const Section hs{n->as_table(), "output.histogram.", "output.histogram"};
  check_keys(hs);
  if (const auto shells = integer(hs, "shells", "an integer in [1, 2147483647]"))
    h.shells = static_cast<int>(int_range(hs.key("shells"), *shells, 1, kIntMax));
  if (const auto r = number(hs, "radius", "a finite number > 0")) h.radius = positive(hs.key("radius"), *r);
  if (const auto speed = choice<HistogramSpeed>(
          hs, "speed", {{"scaled", HistogramSpeed::scaled}, {"velocity", HistogramSpeed::velocity}}))
    h.speed = *speed;
}

void Reader::read_weights(const Section& s, Scene& scene) const {
  check_keys(s);
  WeightsConfig w;
  if (!choice<bool>(s, "scheme", {{"swpm", true}}))
    fail(s.key("scheme"), "missing required key; write scheme = \"swpm\" (stochastic weighted particles) in [weights]");
  if (scene.run.method != Method::event)
    fail(s.key("scheme"),
         "\"swpm\" needs run.method = \"event\" (the time-step-free scheme of 001 sec. 4 that "
         "it extends); got " +
             quote_str(method_name(scene.run.method)));
  if (const auto m = integer(s, "particles_per_shell", "an integer in [4, 2147483647]"))
    w.particles_per_shell = static_cast<int>(int_range(s.key("particles_per_shell"), *m, 4, kIntMax));
  if (const auto g = number(s, "growth", "a finite number > 1")) {
    if (!(*g > 1.0) || !std::isfinite(*g)) fail(s.key("growth"), fmt(*g) + " is not a finite number > 1");
    w.growth = *g;
  }
  scene.weights = w;
}

void Reader::read(const toml::table& root, Scene& scene) const {
  check_top_level(root);
  const Section run = table(root, "run", "[run]");
  const Section collision = table(root, "collision", "[collision]");
  const Section thermostat = table(root, "thermostat", "[thermostat]");
  const Section shear = table(root, "shear", "[shear]");
  const Section relaxation = table(root, "relaxation", "[relaxation]");
  const Section initial = table(root, "initial", "[initial]");
  const Section intruder = table(root, "intruder", "[intruder]");
  const Section output = table(root, "output", "[output]");
  const Section weights = table(root, "weights", "[weights]");

  read_run(run, scene.run);
  read_species(root, scene);
  read_collision(collision, scene);
  read_thermostat(thermostat, scene.thermostat, granmc::rough(scene.collision));

  check_keys(shear);
  if (const auto a = number(shear, "rate", "a finite number")) scene.shear_rate = finite(shear.key("rate"), *a);
  // Under shear the Enskog gas feels sigma and n beyond chi (the contact shift sigma_ij a and the transfer
  // across sigma_ij, 000 eq. 18), so phi must be the packing fraction of the species as given: sum_i pi n_i
  // sigma_i^3 / 6, or sum_i pi n_i sigma_i^2 / 4 for disks.
  if (const double phi = scene.collision.packing_fraction; scene.shear_rate != 0.0 && phi > 0.0) {
    const bool disks = scene.run.dimension == 2;
    double from_species = 0.0;
    for (const SpeciesConfig& sp : scene.species)
      from_species += disks ? std::numbers::pi / 4.0 * sp.density * sp.diameter * sp.diameter
                            : std::numbers::pi / 6.0 * sp.density * std::pow(sp.diameter, 3);
    if (!(std::fabs(from_species - phi) <= 1e-6 * phi))
      fail("shear.rate",
           "with collision.packing_fraction = " + std::to_string(phi) +
               (disks ? " needs species densities and diameters with sum_i pi n_i sigma_i^2 / 4 = phi (now "
                      : " needs species densities and diameters with sum_i pi n_i sigma_i^3 / 6 = phi (now ") +
               std::to_string(from_species) +
               "): under shear the Enskog contact shift and collisional "
               "transfer depend on n and sigma themselves (000 eqs. 2, 18); for one species of "
               "diameter 1 set density = " +
               (disks ? "4 phi / pi" : "6 phi / pi"));
  }

  check_keys(relaxation);
  scene.relaxation = boolean(relaxation, "enabled").value_or(false);
  if (scene.relaxation && scene.thermostat.kind != ThermostatKind::gaussian) {
    fail("relaxation.enabled",
         "true needs thermostat.kind = \"gaussian\" (the BGK-like relaxation to the HCS of "
         "003 acts together with the Gaussian thermostat); set [thermostat] kind = \"gaussian\"");
  }
  if (const auto a2 = number(relaxation, "a2", "a number in [-0.5, 0.5]")) {
    if (!(std::fabs(*a2) <= 0.5))
      fail("relaxation.a2",
           "must be in [-0.5, 0.5] (the Sonine-corrected Maxwellian "
           "is sampled from its positive part), got " +
               std::to_string(*a2));
    if (!scene.relaxation) fail("relaxation.a2", "applies only with enabled = true");
    scene.relaxation_a2 = *a2;
  }

  check_keys(initial);
  if (const auto t = number(initial, "temperature", "a finite number > 0"))
    scene.initial_temperature = positive(initial.key("temperature"), *t);
  scene.initial_zero_momentum = boolean(initial, "zero_momentum").value_or(true);

  if (intruder.table) {
    if (run.has("dimension"))
      fail("run.dimension", "applies to a gas; an intruder's dimension is [intruder] dimension");
    IntruderConfig in;
    read_intruder(intruder, in);
    scene.intruder = in;
  }
  read_output(output, scene.histogram);
  if (weights.table) read_weights(weights, scene);
}

std::string parse_error_message(const toml::parse_error& e, const std::string& path) {
  const auto& pos = e.source().begin;
  std::string m = path + ": line " + std::to_string(pos.line) + ", column " + std::to_string(pos.column) +
                  ": invalid TOML: " + std::string(e.description());
  if (e.description().find("representable in 64 bits") != std::string_view::npos) {
    m += "; TOML integers are signed 64-bit, at most 9223372036854775807 (so run.seed is in [0, 2^63 - 1])";
  } else {
    m += "; a scene must be valid TOML 1.0 (https://toml.io)";
  }
  return m;
}

}  // namespace

Scene parse_scene(std::string_view toml_text, const std::string& path) {
  check_text(toml_text, path);
  toml::table root;
  try {
    root = toml::parse(toml_text, std::string_view(path));
  } catch (const toml::parse_error& e) {
    throw SceneError(parse_error_message(e, path));
  }
  Scene scene;
  Reader(path).read(root, scene);
  scene.source_path = path;
  scene.source_text = std::string(toml_text);
  return scene;
}

Scene load_scene(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw SceneError(path + ": cannot open the scene file: " + ec.message());
  if (!fs::exists(status)) throw SceneError(path + ": cannot open the scene file: no such file");
  if (fs::is_directory(status)) throw SceneError(path + ": cannot read the scene file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw SceneError(path + ": cannot open the scene file: " + (err ? std::strerror(err) : "unknown error"));
  }
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) throw SceneError(path + ": cannot read the scene file: read error");
  return parse_scene(buf.str(), path);
}

}  // namespace granmc
