#pragma once
// One of the project's own scenes (the source tree's scenarios/NAME.toml), whatever
// $BALLBENCH_SCENARIOS says: for checks whose closed forms are of that scene as shipped
// (adapters/conformance.cpp).
#include <string>

#include "scene.h"

namespace ballbench {

Scene load_project_scene(const std::string& name);

}  // namespace ballbench
