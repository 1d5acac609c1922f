#include "lammps/lammps_input.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "engine.h"
#include "lammps/settings_record.h"

namespace ballbench::lammps {

std::string num(double x) { return fmt::format("{:.17g}", x); }

long substeps_for(double dt, const ContactModel& model) {
  return std::max(1L, static_cast<long>(std::ceil(dt / model.dem_dt_max)));
}

Plan make_plan(const Scene& scene, const LammpsSettings& s) {
  Plan p;
  p.model = derive_contact_model(scene, {s.law, s.overlap_target, s.impact_speed, s.contact_steps});
  const long n = substeps_for(scene.dt, p.model);
  p.substeps = static_cast<int>(std::min<long>(n, std::numeric_limits<int>::max()));
  p.dem_dt = scene.dt / static_cast<double>(n);
  p.skin = s.skin >= 0 ? s.skin : 0.5 * scene.radius.minCoeff();
  // gran/hooke's tangential force is a damper, gamma_t = gamma_n / 2 times the slip, capped by mu
  // F_n: an elastic contact has no damping, so its friction would be ignored.
  if (s.law == ContactLaw::hooke && scene.friction > 0 && p.model.pair.gamma_n == 0)
    throw SceneUnsupported(fmt::format("lammps (hooke): friction {} at restitution 1 would be ignored (hooke's tangential "
                                       "force is a damper of half the normal damping, which is 0 for an elastic "
                                       "contact); use the hertz profile",
                                       scene.friction),
                           settings_record(scene, s, p));
  if (n > s.max_substeps)
    throw SceneUnsupported(fmt::format(
        "lammps ({}): scene '{}' needs {} DEM sub-steps per step (dt {} s over a DEM step of at most {:.3g} s: the "
        "contact time {:.3g} s / {}, stiffness for a ball speed of {:.3g} m/s and an overlap of {:g}% of the smallest "
        "radius), above max_substeps = {} (--set lammps.max_substeps={} runs it)",
        law_name(s.law), scene.name, n, scene.dt, p.model.dem_dt_max, p.model.contact_time, s.contact_steps,
        p.model.ball_speed, s.overlap_target * 100, s.max_substeps, n), settings_record(scene, s, p));
  return p;
}

Domain domain_for(const Scene& scene) {
  const double margin = 4 * scene.radius.maxCoeff();
  Eigen::Vector2d lo, hi;
  if (scene.container.kind == ContainerKind::Box) {
    lo = scene.container.min, hi = scene.container.max;
  } else {
    lo = scene.initial.pos.colwise().minCoeff().transpose(), hi = scene.initial.pos.colwise().maxCoeff().transpose();
  }
  return {lo.x() - margin, hi.x() + margin, lo.y() - margin, hi.y() + margin, -margin, margin};
}

std::string head_commands() {
  // SI units; 2D balls (atom_style sphere with enforce2d, the scene's inertia); shrink-wrapped x and y
  // (m: never lose an atom), periodic z as LAMMPS requires in 2D; an atom map by id, which the
  // library's gather and scatter by id need; ghost atoms carry velocities, as granular pairs need.
  return "units si\n"
         "dimension 2\n"
         "atom_style sphere\n"
         "atom_modify map array\n"
         "boundary m m p\n"
         "comm_modify vel yes\n";
}

std::string box_commands(const Scene& scene) {
  const Domain d = domain_for(scene);
  return fmt::format("region ballbench_box block {} {} {} {} {} {}\ncreate_box 1 ballbench_box\n", num(d.x0), num(d.x1),
                     num(d.y0), num(d.y1), num(d.z0), num(d.z1));
}

std::string data_file(const Scene& scene) {
  const Domain d = domain_for(scene);
  std::string out = fmt::format(
      "LAMMPS data file written by ballbench for scene {}\n\n{} atoms\n1 atom types\n\n{} {} xlo xhi\n{} {} ylo yhi\n{} "
      "{} zlo zhi\n\nAtoms # sphere\n\n",
      scene.name, scene.n(), num(d.x0), num(d.x1), num(d.y0), num(d.y1), num(d.z0), num(d.z1));
  // atom-ID atom-type diameter density x y z; the density is replaced by the mass (masses_file).
  for (int i = 0; i < scene.n(); ++i)
    out += fmt::format("{} 1 {} 1 {} {} 0\n", i + 1, num(2 * scene.radius(i)), num(scene.initial.pos(i, 0)),
                       num(scene.initial.pos(i, 1)));
  // atom-ID vx vy vz wx wy wz: the spin about z is the ball's (0 unless it starts spinning).
  out += "\nVelocities\n\n";
  for (int i = 0; i < scene.n(); ++i)
    out += fmt::format("{} {} {} 0 0 0 {}\n", i + 1, num(scene.initial.vel(i, 0)), num(scene.initial.vel(i, 1)),
                       num(scene.spin(i)));
  return out;
}

std::string masses_file(const Scene& scene) {
  // An atomfile: the count of lines, then atom-ID value.
  std::string out = fmt::format("# ballbench: atom-ID mass (kg)\n{}\n", scene.n());
  for (int i = 0; i < scene.n(); ++i) out += fmt::format("{} {}\n", i + 1, num(scene.mass(i)));
  return out;
}

std::string read_balls_commands(const std::string& data_path, const std::string& masses_path) {
  return fmt::format("read_data {}\nvariable ballbench_mass atomfile {}\nset group all mass v_ballbench_mass\n"
                     "variable ballbench_mass delete\n",
                     data_path, masses_path);
}

std::string integrator_style(Inertia inertia) {
  // nve/sphere takes I = 2/5 m r^2 (a solid sphere); its `disc` keyword (2D only) m r^2 / 2, the
  // only difference between the two (LAMMPS's fix nve/sphere documentation).
  return inertia == Inertia::sphere ? "nve/sphere" : "nve/sphere disc";
}

std::string body_commands(const Scene& scene, const Plan& plan) {
  const ContactModel& m = plan.model;
  const bool hooke = m.law == ContactLaw::hooke;
  // Kn Kt gamma_n gamma_t xmu dampflag: Kt = 2/7 Kn and gamma_t = gamma_n / 2, the values LAMMPS
  // takes for NULL, written out so the record holds them; xmu is the scene's friction (0: none).
  const auto coeffs = [&](const ContactDesign& c) {
    return fmt::format("{} {} {} {} {} 1", num(c.kn), num(c.kn * 2 / 7), num(c.gamma_n), num(c.gamma_n / 2),
                       num(scene.friction));
  };
  std::string out = fmt::format("pair_style {} {}\npair_coeff * *\n", hooke ? "gran/hooke" : "gran/hertz/history", coeffs(m.pair));
  if (scene.container.kind == ContainerKind::Box) {
    const char* wall = hooke ? "hooke" : "hertz/history";
    out += fmt::format("fix ballbench_wall_x all wall/gran {} {} xplane {} {}\n", wall, coeffs(m.wall),
                       num(scene.container.min.x()), num(scene.container.max.x()));
    out += fmt::format("fix ballbench_wall_y all wall/gran {} {} yplane {} {}\n", wall, coeffs(m.wall),
                       num(scene.container.min.y()), num(scene.container.max.y()));
  }
  const double g = scene.gravity.norm();
  if (g > 0)
    out += fmt::format("fix ballbench_gravity all gravity {} vector {} {} 0\n", num(g), num(scene.gravity.x() / g),
                       num(scene.gravity.y() / g));
  // Velocity Verlet for positions, velocities and spins with the scene's moment; enforce2d last,
  // after every force.
  out += fmt::format("fix ballbench_nve all {}\nfix ballbench_2d all enforce2d\n", integrator_style(scene.inertia));
  out += fmt::format("neighbor {} bin\nneigh_modify delay 0 every 1 check yes\n", num(plan.skin));
  out += fmt::format("timestep {}\nthermo_style custom step\nthermo 0\n", num(plan.dem_dt));
  return out;
}

}  // namespace ballbench::lammps
