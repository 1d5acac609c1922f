#pragma once
// `lammps`: LAMMPS granular DEM (Debian's liblammps, 29 Sep 2021) driven through the Engine
// interface: soft spheres in 2D, sub-stepped inside each step, in this process through the C
// library API or, with ranks > 1, under mpirun. The scene mapping, the two profiles and where each
// setting comes from: adapters/lammps/README.md.
#include <string>

#include "engine.h"
#include "lammps/contact_model.h"
#include "scene.h"

namespace ballbench {

// Every knob of the adapter. The contact law is the profile's ("hooke" or "hertz").
struct LammpsSettings {
  lammps::ContactLaw law = lammps::ContactLaw::hooke;
  /// Largest overlap of the worst-case contact, as a fraction of the smallest radius: the stiffness
  /// is chosen so that it is not exceeded. (1)
  double overlap_target = 0.005;
  /// The largest ball speed the stiffness is designed for; <= 0 derives it from the scene
  /// (lammps::expected_ball_speed). (m/s)
  double impact_speed = -1;
  /// DEM steps per contact time: the DEM step is at most contact_time / contact_steps. (count)
  double contact_steps = 50;
  /// The most DEM sub-steps one step may take; a scene needing more is refused (unsupported). (count)
  int max_substeps = 5000;
  /// Neighbour skin; negative: half the smallest radius. (m)
  double skin = -1;
  /// MPI ranks: 1 runs LAMMPS in this process through its library; more run `mpirun -np ranks lmp`.
  int ranks = 1;
  /// Open MPI hostfile for mpirun (ranks > 1); "" runs every rank on this machine. (path)
  std::string hostfile;
  /// States are provided every this many steps (the runner reads only those); with ranks > 1 each
  /// is a dump file LAMMPS writes. (steps)
  int sample_every = 1;
  /// The commands for ranks > 1, looked up on PATH.
  std::string mpirun = "mpirun", lmp = "lmp";
  /// Where the input, data and dump files go with ranks > 1: "" makes a temporary folder (removed
  /// after the run); on a cluster, a folder of a file system rank 0's node shares with this one.
  std::string workdir;
};

// Every user setting's key and value (the settings table's, lammps_engine.cpp), for settings().
nlohmann::json lammps_settings_json(const LammpsSettings& s);

// The settings of a named profile ("hooke" or "hertz"); InputError for any other name.
LammpsSettings lammps_profile(const std::string& profile);

EngineEntry lammps_engine();

}  // namespace ballbench
