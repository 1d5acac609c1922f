#pragma once
// LAMMPS under MPI (ranks > 1): `mpirun -np N [--hostfile F] lmp -in FILE`, with the input the
// adapter writes, driven one sample at a time through lmp's standard input and read back from the
// dump file it writes at each sample.
#include <memory>

#include "engine.h"
#include "lammps/lammps_engine.h"
#include "lammps/lammps_input.h"
#include "scene.h"

namespace ballbench::lammps {

std::unique_ptr<Engine> make_mpi_engine(const Scene& scene, const LammpsSettings& s, const Plan& plan);

}  // namespace ballbench::lammps
