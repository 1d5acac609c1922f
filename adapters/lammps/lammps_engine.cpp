#include "lammps/lammps_engine.h"

#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"
#include "lammps/lammps_input.h"
#include "lammps/library_engine.h"
#include "lammps/mpi_engine.h"

namespace ballbench {
namespace {

// The release the library was built from (its package's version, 20210929 for Debian's liblammps);
// each instance's lammps_version() is recorded beside it (settings().derived.library_version).
std::string version_string() {
  constexpr int v = BALLBENCH_LAMMPS_VERSION;
  constexpr const char* months[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  const int month = v / 100 % 100;
  if (month < 1 || month > 12) return std::to_string(v);
  return fmt::format("{} {} {}", v % 100, months[month - 1], v / 10000);
}

// lammps's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings lammps` come from these rows; the contact law is the profile's, not a setting.
const SettingsTable<LammpsSettings>& lammps_settings_table() {
  using S = LammpsSettings;
  static const SettingsTable<S> table(
      "lammps",
      {setting("overlap_target", &S::overlap_target,
               bound([](double f) { return f > 0 && f <= 0.5; }, "(0, 0.5]",
                     "must be above 0 and at most 0.5 (a fraction of the radius)"),
               "1", "largest overlap of the worst-case contact, a fraction of the smallest radius"),
       setting("impact_speed", &S::impact_speed, any_value, "m/s",
               "largest ball speed the stiffness is designed for; <= 0: from the scene"),
       setting("contact_steps", &S::contact_steps, at_least(1, "DEM steps per contact"), "count",
               "DEM steps per contact time"),
       setting("max_substeps", &S::max_substeps, at_least(1), "count", "most DEM sub-steps per step; more is refused"),
       setting("skin", &S::skin, any_value, "m", "neighbour skin; negative: half the smallest radius"),
       setting("ranks", &S::ranks, at_least(1, "1: in this process"), "count",
               "MPI ranks; 1 runs LAMMPS in this process"),
       setting("sample_every", &S::sample_every, at_least(1, "steps"), "steps",
               "states are provided every this many steps"),
       setting("hostfile", &S::hostfile, any_value, "", "Open MPI hostfile for ranks > 1; \"\": this machine"),
       setting("mpirun", &S::mpirun, any_value, "", "the mpirun command, for ranks > 1"),
       setting("lmp", &S::lmp, any_value, "", "the LAMMPS command, for ranks > 1"),
       setting("workdir", &S::workdir, any_value, "", "folder for the files of ranks > 1; \"\": a temporary one")});
  return table;
}

// What the rows cannot say alone: the settings that go together.
void validate(const LammpsSettings& s) {
  if (!s.hostfile.empty()) {
    if (s.ranks == 1) throw InputError("settings.lammps.hostfile: used only with ranks > 1 (mpirun)");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(s.hostfile, ec))
      throw InputError(fmt::format("settings.lammps.hostfile: {} is not a file", s.hostfile));
  }
  if (s.mpirun.empty() || s.lmp.empty()) throw InputError("settings.lammps.mpirun, lmp: must name a command");
}

}  // namespace

nlohmann::json lammps_settings_json(const LammpsSettings& s) { return lammps_settings_table().json(s); }

LammpsSettings lammps_profile(const std::string& profile) {
  LammpsSettings s;
  if (profile == "hooke") s.law = lammps::ContactLaw::hooke;
  else if (profile == "hertz") s.law = lammps::ContactLaw::hertz;
  else throw InputError(fmt::format("lammps: unknown profile '{}' (known: hooke, hertz)", profile));
  return s;
}

EngineEntry lammps_engine() {
  EngineInfo info;
  info.name = "lammps";
  info.version = version_string();
  info.summary = "LAMMPS granular DEM: soft discs (gran/hooke or gran/hertz/history), sub-stepped; MPI with ranks > 1";
  info.limits = "soft spheres: overlaps up to 0.5% of r by design; stiffness from the scene's largest expected speed; "
                "ceil(dt / (contact time / 50)) DEM sub-steps per step, refused above max_substeps (5000); "
                "hertz's restitution is the scene's at the design speed, higher below it; no CCD";
  info.caps.continuous_collision = false;
  info.caps.any_restitution = true;  // hooke's restitution does not depend on the impact speed (no threshold)
  info.caps.deterministic = true;
  info.costly_runs = true;
  // Thousands of DEM sub-steps per step (README.md): 10^4 balls at most, where one step already
  // takes seconds. The scaled scenes' speeds need more sub-steps than the default cap (5000 per
  // step; the gas 8 000 - 9 000), so its rows raise the cap; a bowl whose fall needs more is refused.
  info.bench.sizes = {.free_balls = 10'000, .fluid_balls = 10'000, .settled_balls = 10'000};
  info.bench.settings = {{"max_substeps", 20'000}};
  info.profiles = {"hooke", "hertz"};
  info.settings = lammps_settings_table().describe();
  info.sweep_knobs = {{"contact_steps", nlohmann::json::array({20, 50, 100})},
                      {"overlap_target", nlohmann::json::array({0.02, 0.005, 0.001})}};
  return {info, [](const Scene& scene, const std::string& profile, const nlohmann::json& overrides) {
            LammpsSettings s = lammps_profile(profile);
            lammps_settings_table().read(overrides, s);
            validate(s);
            const lammps::Plan plan = lammps::make_plan(scene, s);
            if (s.ranks > 1) return lammps::make_mpi_engine(scene, s, plan);
            return lammps::make_library_engine(scene, s, plan);
          }};
}

}  // namespace ballbench
