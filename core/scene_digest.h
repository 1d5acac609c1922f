#pragma once
// A scene's content as 16 hex digits: XXH3-64 of its scene file without balls (scene_writer.h:
// step, gravity, restitution, friction, inertia, container, metrics, spec, settings) and of the
// bytes of every ball's radius, mass and initial state. Any change of a ball, a setting or the spec
// differs; a million balls hash in milliseconds, with no text made of them. Results record it; the
// try store keys by it; resume and merge join only results of the same content.
#include <string>

#include "scene.h"

namespace ballbench {

std::string scene_digest(const Scene& scene);

}  // namespace ballbench
