#pragma once
// Scene files (TOML, schema in scenarios/README.md) -> validated Scene.
// Every problem is an InputError whose message is one line: "FILE:LINE: FIELD: REASON".
#include <cstdint>
#include <string>
#include <vector>

#include "scene.h"

namespace ballbench {

// Parses and validates TOML text; `source` names it in messages. `seed_offset` is added to the seed
// of every [random] and [lattice] table (another placement drawn from the same rules).
Scene parse_scene(const std::string& toml_text, const std::string& source, int64_t seed_offset = 0);

// Reads a scene from a path.
Scene load_scene_file(const std::string& path, int64_t seed_offset = 0);

// `name_or_path` is a built-in scene name (scenarios/NAME.toml) or a path to a file.
Scene load_scene(const std::string& name_or_path, int64_t seed_offset = 0);

// Built-in scene names, sorted.
std::vector<std::string> builtin_scene_names();

// The folder of built-in scenes: $BALLBENCH_SCENARIOS if set, else the source tree's scenarios/.
std::string scenario_dir();

}  // namespace ballbench
