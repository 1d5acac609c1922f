#include "lammps/settings_record.h"

#include <fmt/format.h>

namespace ballbench::lammps {
namespace {

nlohmann::json design(const ContactDesign& c) {
  return {{"meff", c.meff},       {"radius", c.radius},          {"approach_speed", c.approach},
          {"kn", c.kn},           {"kt", c.kn * 2 / 7},          {"gamma_n", c.gamma_n},
          {"gamma_t", c.gamma_n / 2}, {"contact_time", c.contact_time}};
}

}  // namespace

nlohmann::json settings_record(const Scene& scene, const LammpsSettings& s, const Plan& plan) {
  const ContactModel& m = plan.model;
  nlohmann::json derived = {{"pair_style", m.law == ContactLaw::hooke ? "gran/hooke" : "gran/hertz/history"},
                            {"wall_style", m.law == ContactLaw::hooke ? "hooke" : "hertz/history"},
                            {"ball_speed", m.ball_speed},
                            {"overlap", m.overlap},
                            {"pair", design(m.pair)},
                            {"wall", design(m.wall)},
                            {"contact_time", m.contact_time},
                            {"restitution_lightest", {{"pair", m.e_light_pair}, {"wall", m.e_light_wall}}},
                            {"dem_dt", plan.dem_dt},
                            {"substeps", plan.substeps},
                            {"skin", plan.skin},
                            {"xmu", scene.friction},
                            {"inertia", fmt::format("{} ({}): fix {}", inertia_name(scene.inertia),
                                                    scene.inertia == Inertia::sphere ? "2/5 m r^2" : "m r^2 / 2",
                                                    integrator_style(scene.inertia))}};
  // LAMMPS's spheres carry no orientation: the angle read back is the adapter's integral of the
  // spins read back (trapezoid), for pictures.
  if (scene.features().rotation)
    derived["angle"] = s.ranks > 1 ? "adapter's trapezoid integral of omega z between samples (sample_every steps)"
                                   : "adapter's trapezoid integral of omega z read after every step";
  if (m.law == ContactLaw::hertz) {
    derived["hertz_damping"] = m.hertz_damping;            // g = gamma_n d*^(3/2) sqrt(R) / v
    derived["hertz_restitution"] = m.hertz_restitution;    // of one contact at the design speed
  }
  nlohmann::json record = lammps_settings_json(s);
  record["law"] = law_name(s.law);
  record["derived"] = derived;
  return record;
}

}  // namespace ballbench::lammps
