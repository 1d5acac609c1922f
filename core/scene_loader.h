#pragma once
// Scene files (TOML, schema in scenarios/README.md) -> validated Scene.
// Every problem is an InputError whose message is one line: "FILE:LINE: FIELD: REASON".
#include <string>
#include <vector>

#include "scene.h"

namespace ballbench {

// Parses and validates TOML text; `source` names it in messages.
Scene parse_scene(const std::string& toml_text, const std::string& source);

// Reads a scene from a path.
Scene load_scene_file(const std::string& path);

// `name_or_path` is a built-in scene name (scenarios/NAME.toml) or a path to a file.
Scene load_scene(const std::string& name_or_path);

// Built-in scene names, sorted.
std::vector<std::string> builtin_scene_names();

// The folder of built-in scenes: $BALLBENCH_SCENARIOS if set, else the source tree's scenarios/.
std::string scenario_dir();

}  // namespace ballbench
