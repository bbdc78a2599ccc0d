#pragma once
// Scene files: TOML text -> validated granmc::Scene. This is the only place that checks a scene (the
// scene contract: every key, default and rule is documented in docs/formats/scenes.md). Everything
// downstream may assume the invariants stated in kernel/core/scene.hpp.
#include <stdexcept>
#include <string>
#include <string_view>

#include "kernel/core/scene.hpp"

namespace granmc {

/// A bad scene. what() is one line: "<path>: <key>: <what is wrong>; <what is allowed>", with the key
/// dotted and indexed (run.t_end, species[1].mass, collision.restitution[0][1]). Problems with the file
/// as a whole (missing, empty, binary, invalid TOML) put the position or nothing in place of the key:
/// "<path>: line 3, column 7: invalid TOML: ...".
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Parses and validates a scene from TOML text. `path` is used only in messages and stored in
/// Scene::source_path; Scene::source_text is `toml_text` verbatim. Throws SceneError.
Scene parse_scene(std::string_view toml_text, const std::string& path);

/// Reads the file at `path` and parses it with parse_scene. A missing, unreadable, empty or binary
/// (NUL bytes, invalid UTF-8) file is a SceneError too.
Scene load_scene(const std::string& path);

}  // namespace granmc
