#pragma once
// The LAMMPS input for a scene, the same commands for the library in this process and for `lmp`
// under mpirun: what runs where differs only in how the atoms come in (lammps_create_atoms, or a
// data file and an atomfile of masses).
#include <string>

#include "lammps/contact_model.h"
#include "lammps/lammps_engine.h"
#include "scene.h"

namespace ballbench::lammps {

// What a run of a scene is: the contact parameters, the sub-steps per step and the DEM step.
struct Plan {
  ContactModel model;
  int substeps = 1;   // DEM steps per ballbench step: ceil(dt / (contact_time / contact_steps))
  double dem_dt = 0;  // dt / substeps (s)
  double skin = 0;    // neighbour skin (m)
};

// DEM sub-steps for a step of `dt` under `model`.
long substeps_for(double dt, const ContactModel& model);

// The plan for `scene`; SceneUnsupported when it needs more than s.max_substeps sub-steps.
Plan make_plan(const Scene& scene, const LammpsSettings& s);

// The simulation box's corners (m): the container (or the balls' extent in open space) widened by
// two of the largest diameters. The boundaries shrink-wrap beyond it (boundary m m p), so no atom
// is ever lost.
struct Domain {
  double x0, x1, y0, y1, z0, z1;
};
Domain domain_for(const Scene& scene);

// Units, dimension, atom style and boundaries: before the box exists.
std::string head_commands();
// The box as a region, for atoms added through the library.
std::string box_commands(const Scene& scene);
// A LAMMPS data file of the balls (Atoms # sphere with diameters, Velocities with the spins about z),
// and the atomfile of
// masses its input reads into a variable; both in id order, ids 1 .. n in scene order.
std::string data_file(const Scene& scene);
std::string masses_file(const Scene& scene);
// read_data of the data file and the masses set from the atomfile.
std::string read_balls_commands(const std::string& data_path, const std::string& masses_path);
// The integrator for the scene's moment of inertia: `nve/sphere disc` (m r^2 / 2, the disk) or
// `nve/sphere` (2/5 m r^2, the sphere).
std::string integrator_style(Inertia inertia);
// Pair style, walls, integrator, 2D, gravity, neighbour lists, timestep: after the atoms exist.
std::string body_commands(const Scene& scene, const Plan& plan);

// A double as LAMMPS reads it back to the same bits.
std::string num(double x);

}  // namespace ballbench::lammps
