#pragma once
// The LAMMPS adapter's effective settings as a run records them: every knob in force and what it
// derives for the scene (stiffness, damping, contact time, sub-steps).
#include <nlohmann/json.hpp>

#include "lammps/lammps_engine.h"
#include "lammps/lammps_input.h"
#include "scene.h"

namespace ballbench::lammps {

nlohmann::json settings_record(const Scene& scene, const LammpsSettings& s, const Plan& plan);

}  // namespace ballbench::lammps
