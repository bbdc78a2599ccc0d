#pragma once
// Sweep files: a base scene and the values to set in it, either a grid (every combination of the listed
// values) or a list (one set of values per scene), -> the scenes of the sweep, each checked as a scene file
// is. The format is documented in docs/formats/scenes.md ("Sweep files"); `granmc sweep` (drivers/sweep.cpp) runs
// the result.
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "kernel/core/scene.hpp"

namespace granmc {

/// A bad sweep file, a bad base scene, or a bad scene made from them. what() is one line that starts with
/// the sweep file's path: "<sweep>: grid.collision.restitution: ...", "<sweep>: base: <base>: ...", or
/// "<sweep>: <base> with collision.restitution = 1.5: collision.restitution: 1.5 is outside [0, 1]".
struct SweepError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SweepScene {
  /// The file name stem of its outputs, made of the values it sets: "restitution0.7", "restitution0.7_seed2",
  /// the base scene's stem when it sets none. Unique within the sweep.
  std::string name;
  /// Dotted key -> value (e.g. {"collision.restitution": 0.7}).
  nlohmann::json values;
  /// The base with the values set. scene.source_text is the TOML text that runs (the base re-written with
  /// the values: comments dropped) and scene.source_path reads "<base> with collision.restitution = 0.7".
  Scene scene;
};

struct Sweep {
  std::string base_path;           // the base scene, from the current directory
  std::vector<SweepScene> scenes;  // in sweep order: a grid's first key varies slowest
};

/// Reads the sweep file at `path` and the base scene it names (relative to the sweep file), and makes and
/// parses every scene (io/scene_file.hpp). Throws SweepError.
Sweep load_sweep(const std::string& path);

}  // namespace granmc
