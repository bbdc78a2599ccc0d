#include "io/sweep_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include <toml++/toml.h>

#include "io/scene_file.hpp"

namespace granmc {

namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// TOML text. toml++ writes floats with 17 significant digits (0.7 -> 0.69999999999999996), which is exact
// but hides the value the user wrote in the stored scene text and in file names; these functions write
// the shortest text that reads back as the same double instead.

std::string float_text(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";  // stays a float when read back
  return s;
}

bool bare_key(std::string_view k) {
  return !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

std::string toml_leaf(const toml::node& n) {  // strings, booleans, dates and times, as toml++ writes them
  std::ostringstream os;
  n.visit([&os](const auto& v) { os << toml::toml_formatter{v}; });
  return os.str();
}

std::string key_text(std::string_view k) {
  return bare_key(k) ? std::string(k) : toml_leaf(toml::value<std::string>(k));
}

/// A table's entries in the order of the file they were read from; entries set by the sweep come last, in
/// key order (toml++ does not copy source positions, so the text does not depend on the sweep file's layout).
std::vector<std::pair<std::string, const toml::node*>> in_source_order(const toml::table& t) {
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [k, n] : t) entries.emplace_back(std::string(k.str()), &n);
  const auto place = [](const toml::node* n) {
    const toml::source_position p = n->source().begin;
    return std::make_tuple(p.line == 0, p.line, p.column);
  };
  std::stable_sort(entries.begin(), entries.end(),
                   [&](const auto& a, const auto& b) { return place(a.second) < place(b.second); });
  return entries;
}

/// A value as it would follow `key = ` in a TOML file (tables inline).
std::string value_text(const toml::node& n) {
  if (const auto* f = n.as_floating_point()) return float_text(f->get());
  if (const auto* i = n.as_integer()) return std::to_string(i->get());
  if (const auto* a = n.as_array()) {
    std::string s = "[";
    for (std::size_t k = 0; k < a->size(); ++k) {
      if (k > 0) s += ", ";
      s += value_text(*a->get(k));
    }
    return s + "]";
  }
  if (const auto* t = n.as_table()) {
    std::string s;
    for (const auto& [k, v] : in_source_order(*t)) {
      s += s.empty() ? "{ " : ", ";
      s += key_text(k) + " = " + value_text(*v);
    }
    return s.empty() ? "{}" : s + " }";
  }
  return toml_leaf(n);
}

bool is_section(const toml::node& n) { return n.is_table() && !n.as_table()->is_inline(); }
bool is_table_array(const toml::node& n) { return n.is_array() && n.as_array()->is_array_of_tables(); }

/// The body of table `t` (whose header is `path`, empty for the root) as TOML: its keys and values first
/// (a key after a header belongs to that header), then its sub-tables, then its arrays of tables.
void write_table(const toml::table& t, const std::string& path, std::string& out) {
  const auto entries = in_source_order(t);
  for (const auto& [k, n] : entries)
    if (!is_section(*n) && !is_table_array(*n)) out += key_text(k) + " = " + value_text(*n) + "\n";
  for (const auto& [k, n] : entries) {
    const std::string header = path.empty() ? key_text(k) : path + "." + key_text(k);
    if (is_section(*n)) {
      if (!out.empty()) out += '\n';
      out += "[" + header + "]\n";
      write_table(*n->as_table(), header, out);
    } else if (is_table_array(*n)) {
      for (const toml::node& element : *n->as_array()) {
        if (!out.empty()) out += '\n';
        out += "[[" + header + "]]\n";
        write_table(*element.as_table(), header, out);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Settings: a dotted key of the scene and the value to set there.

struct Step {
  std::string name;
  std::optional<std::size_t> index;  // species[1]: the second [[species]] table
};

struct Setting {
  std::string key;  // as dotted in the sweep file: "collision.restitution", "species[1].mass"
  std::vector<Step> steps;
  const toml::node* value;  // in the sweep file's table (lives as long as it)
};

/// Settings of a sweep-file table, its sub-tables flattened ("collision.restitution" = x, collision.restitution
/// = x and collision = { restitution = x } all set collision.restitution), in the order of the file.
/// Recursion stops at anything that is not a table: an array is one value (a grid's list, a matrix).
void flatten(const toml::table& t, const std::string& prefix,
             std::vector<std::pair<std::string, const toml::node*>>& out) {
  for (const auto& [k, n] : in_source_order(t)) {
    const std::string key = prefix.empty() ? k : prefix + "." + k;
    if (const auto* sub = n->as_table()) {
      flatten(*sub, key, out);
    } else {
      out.emplace_back(key, n);
    }
  }
}

std::vector<Step> key_steps(const std::string& key, const std::string& where) {
  const std::string bad = where +
                          ": not a scene key; write table.key as in docs/formats/scenes.md, with [i] to choose one "
                          "of several tables (collision.restitution, species[1].mass)";
  std::vector<Step> steps;
  std::size_t at = 0;
  while (true) {
    const std::size_t end = std::min(key.find('.', at), key.size());
    const std::string segment = key.substr(at, end - at);
    Step step;
    const std::size_t bracket = segment.find('[');
    step.name = segment.substr(0, bracket);
    if (!bare_key(step.name)) throw SweepError(bad);
    if (bracket != std::string::npos) {
      const std::string digits = segment.substr(bracket + 1, segment.size() - bracket - 2);
      std::size_t i = 0;
      const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), i);
      if (segment.back() != ']' || digits.empty() || r.ec != std::errc() || r.ptr != digits.data() + digits.size())
        throw SweepError(bad);
      step.index = i;
    }
    steps.push_back(step);
    if (end == key.size()) break;
    at = end + 1;
  }
  if (steps.back().index) throw SweepError(where + ": [i] chooses a table; name a key in it, e.g. species[1].mass");
  return steps;
}

/// Sets the setting's value in `root` (a copy of the base scene), creating missing tables on the way.
void apply(toml::table& root, const Setting& s, const std::string& where) {
  toml::table* t = &root;
  std::string path;
  for (std::size_t k = 0; k + 1 < s.steps.size(); ++k) {
    const Step& step = s.steps[k];
    if (!path.empty()) path += '.';
    path += step.name;
    toml::node* n = t->get(step.name);
    if (step.index) {
      toml::array* a = n ? n->as_array() : nullptr;
      if (!a || !a->is_array_of_tables())
        throw SweepError(where + ": the base scene has no [[" + path + "]] tables for [i] to choose from");
      if (*step.index >= a->size())
        throw SweepError(where + ": the base scene has " + std::to_string(a->size()) + " [[" + path + "]] table" +
                         (a->size() == 1 ? "" : "s") + ", so " + step.name + "[i] needs i < " +
                         std::to_string(a->size()));
      t = a->get(*step.index)->as_table();
      path += '[';
      path += std::to_string(*step.index) + ']';
    } else if (!n) {
      t = t->insert(step.name, toml::table{}).first->second.as_table();
    } else if (is_table_array(*n)) {
      throw SweepError(where + ": " + path + " is a list of [[" + path +
                       "]] tables in the base scene; choose one with " + step.name + "[i]");
    } else if (!(t = n->as_table())) {
      throw SweepError(where + ": " + path + " is a value in the base scene, not a table");
    }
  }
  s.value->visit([&](const auto& v) { t->insert_or_assign(s.steps.back().name, v); });
}

nlohmann::json json_value(const toml::node& n) {
  if (const auto* f = n.as_floating_point()) return f->get();
  if (const auto* i = n.as_integer()) return i->get();
  if (const auto* b = n.as_boolean()) return b->get();
  if (const auto* s = n.as_string()) return s->get();
  if (const auto* a = n.as_array()) {
    nlohmann::json j = nlohmann::json::array();
    for (const toml::node& e : *a) j.push_back(json_value(e));
    return j;
  }
  return value_text(n);  // dates and times: no scene key takes them, and the scene check says so
}

/// Keeps the characters that are safe in a file name on every system.
std::string file_safe(std::string_view s) {
  std::string out;
  for (const char c : s)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' || c == '+' || c == ',')
      out += c;
  return out;
}

// ---------------------------------------------------------------------------------------------
// The sweep file.

std::string read_sweep_text(const std::string& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw SweepError(path + ": cannot open the sweep file: " + ec.message());
  if (!fs::exists(status)) throw SweepError(path + ": cannot open the sweep file: no such file");
  if (fs::is_directory(status)) throw SweepError(path + ": cannot read the sweep file: it is a directory");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buf;
  buf << in.rdbuf();
  if (!in || in.bad()) throw SweepError(path + ": cannot read the sweep file");
  return buf.str();
}

constexpr std::string_view kAllowed = "allowed keys: base, grid, scenes (docs/formats/scenes.md, \"Sweep files\")";

/// The scenes' settings from [grid] (every combination, the first key varying slowest) or [[scenes]].
std::vector<std::vector<Setting>> read_settings(const toml::table& root, const std::string& path) {
  const toml::node* grid = root.get("grid");
  const toml::node* list = root.get("scenes");
  if (!grid == !list)
    throw SweepError(path + ": " + (grid ? "grid and scenes: give one of them" : "missing [grid] or [[scenes]]") +
                     "; a [grid] of values (\"collision.restitution\" = [0.5, 0.7, 0.9]) or [[scenes]] tables of "
                     "values (one scene each)");
  std::vector<std::vector<Setting>> scenes;
  if (grid) {
    if (!grid->is_table()) throw SweepError(path + ": grid: expected a table of dotted keys and their lists of values");
    std::vector<std::pair<std::string, const toml::node*>> keys;
    flatten(*grid->as_table(), "", keys);
    if (keys.empty()) throw SweepError(path + ": grid: no keys; list values as \"collision.restitution\" = [0.5, 0.9]");
    std::vector<std::pair<std::vector<Step>, const toml::array*>> axes;
    for (const auto& [key, n] : keys) {
      const std::string where = path + ": grid." + key;
      const toml::array* values = n->as_array();
      if (!values || values->empty())
        throw SweepError(where + ": expected a non-empty list of the values to sweep, e.g. [0.5, 0.7, 0.9]");
      for (const toml::node& v : *values)
        if (v.is_table())
          throw SweepError(where + ": a grid value is a table; sweep its keys one by one (\"" + key + ".x\" = [...])");
      axes.emplace_back(key_steps(key, where), values);
    }
    std::vector<std::size_t> at(axes.size(), 0);  // an odometer over the axes, the last turning fastest
    while (true) {
      std::vector<Setting> scene;
      for (std::size_t k = 0; k < axes.size(); ++k)
        scene.push_back({keys[k].first, axes[k].first, axes[k].second->get(at[k])});
      scenes.push_back(std::move(scene));
      std::size_t k = axes.size();
      while (k > 0 && ++at[k - 1] == axes[k - 1].second->size()) at[--k] = 0;
      if (k == 0) break;
    }
  } else {
    if (!list->is_array() || !list->as_array()->is_array_of_tables())
      throw SweepError(path + ": scenes: expected [[scenes]] tables, one per scene, of dotted keys and values");
    const toml::array& entries = *list->as_array();
    for (std::size_t i = 0; i < entries.size(); ++i) {
      std::vector<std::pair<std::string, const toml::node*>> keys;
      flatten(*entries.get(i)->as_table(), "", keys);
      std::vector<Setting> scene;
      for (const auto& [key, n] : keys)
        scene.push_back({key, key_steps(key, path + ": scenes[" + std::to_string(i) + "]." + key), n});
      scenes.push_back(std::move(scene));
    }
  }
  return scenes;
}

/// "restitution0.7_seed2": each key's last part and its value, the whole key where two swept keys end
/// alike (species[0].mass and species[1].mass -> species0.mass1.0_species1.mass2.0); "base" for no values.
std::vector<std::string> scene_names(const std::vector<std::vector<Setting>>& scenes) {
  std::map<std::string, std::set<std::string>> keys_by_last;
  for (const auto& scene : scenes)
    for (const Setting& s : scene) keys_by_last[s.steps.back().name].insert(s.key);
  std::vector<std::string> names;
  for (const auto& scene : scenes) {
    std::string name;
    for (const Setting& s : scene) {
      const std::string& last = s.steps.back().name;
      if (!name.empty()) name += '_';
      name += file_safe(keys_by_last[last].size() == 1 ? last : s.key) + file_safe(value_text(*s.value));
    }
    names.push_back(name.empty() ? "base" : name);
  }
  return names;
}

}  // namespace

Sweep load_sweep(const std::string& path) {
  const std::string text = read_sweep_text(path);
  toml::table root;
  try {
    root = toml::parse(text, std::string_view(path));
  } catch (const toml::parse_error& e) {
    const auto& pos = e.source().begin;
    throw SweepError(path + ": line " + std::to_string(pos.line) + ", column " + std::to_string(pos.column) +
                     ": invalid TOML: " + std::string(e.description()) + "; a sweep file must be valid TOML 1.0");
  }
  for (const auto& [k, n] : root)
    if (k != "base" && k != "grid" && k != "scenes")
      throw SweepError(path + ": " + key_text(k.str()) + ": unknown key; " + std::string(kAllowed));
  const toml::node* base = root.get("base");
  if (!base)
    throw SweepError(path +
                     ": base: missing; name the base scene, e.g. base = \"hcs.toml\" (relative to the sweep file)");
  if (!base->is_string())
    throw SweepError(path + ": base: expected a string, the base scene's path relative to the sweep file");

  Sweep sweep;
  sweep.base_path = (fs::path(path).parent_path() / base->as_string()->get()).string();
  Scene base_scene;
  try {
    base_scene = load_scene(sweep.base_path);
  } catch (const SceneError& e) {
    throw SweepError(path + ": base: " + e.what());
  }

  const std::vector<std::vector<Setting>> settings = read_settings(root, path);
  const std::vector<std::string> names = scene_names(settings);
  std::map<std::string, std::size_t> first_with_name;
  for (std::size_t i = 0; i < settings.size(); ++i) {
    SweepScene s;
    s.name = names[i];
    if (const auto [at, fresh] = first_with_name.emplace(s.name, i); !fresh)
      throw SweepError(path + ": scenes " + std::to_string(at->second + 1) + " and " + std::to_string(i + 1) +
                       " of the sweep would both write " + s.name + ".h5; give each scene its own values");
    // Parsed afresh for each scene, not copied: a copy loses the source positions that keep the scene text
    // in the base's order. Cannot fail: load_scene parsed the same text.
    toml::table table = toml::parse(base_scene.source_text, std::string_view(sweep.base_path));
    std::string label = sweep.base_path;
    s.values = nlohmann::json::object();
    for (const Setting& setting : settings[i]) {
      if (s.values.contains(setting.key))
        throw SweepError(path + ": " + setting.key + ": set twice for one scene (a dotted and a nested spelling?)");
      apply(table, setting,
            path + ": " + (root.contains("grid") ? "grid." : "scenes[" + std::to_string(i) + "].") + setting.key);
      s.values[setting.key] = json_value(*setting.value);
      label += s.values.size() == 1 ? " with " : ", ";
      label += setting.key + " = " + value_text(*setting.value);
    }
    std::string scene_text;
    write_table(table, "", scene_text);
    try {
      s.scene = parse_scene(scene_text, label);
    } catch (const SceneError& e) {
      throw SweepError(path + ": " + e.what());
    }
    sweep.scenes.push_back(std::move(s));
  }
  return sweep;
}

}  // namespace granmc
