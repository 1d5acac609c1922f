#pragma once
// LAMMPS in this process, through its C library API (lammps_open_no_mpi and friends): ranks = 1.
#include <memory>

#include "engine.h"
#include "lammps/lammps_engine.h"
#include "lammps/lammps_input.h"
#include "scene.h"

namespace ballbench::lammps {

std::unique_ptr<Engine> make_library_engine(const Scene& scene, const LammpsSettings& s, const Plan& plan);

}  // namespace ballbench::lammps
