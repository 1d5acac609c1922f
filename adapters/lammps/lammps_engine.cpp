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

void validate(const LammpsSettings& s) {
  if (!(s.overlap_target > 0 && s.overlap_target <= 0.5))
    throw InputError("settings.lammps.overlap_target: must be above 0 and at most 0.5 (a fraction of the radius)");
  if (!(s.contact_steps >= 1)) throw InputError("settings.lammps.contact_steps: must be >= 1 (DEM steps per contact)");
  if (s.max_substeps < 1) throw InputError("settings.lammps.max_substeps: must be >= 1");
  if (s.ranks < 1) throw InputError("settings.lammps.ranks: must be >= 1 (1: in this process)");
  if (s.sample_every < 1) throw InputError("settings.lammps.sample_every: must be >= 1 (steps)");
  if (!s.hostfile.empty()) {
    if (s.ranks == 1) throw InputError("settings.lammps.hostfile: used only with ranks > 1 (mpirun)");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(s.hostfile, ec))
      throw InputError(fmt::format("settings.lammps.hostfile: {} is not a file", s.hostfile));
  }
  if (s.mpirun.empty() || s.lmp.empty()) throw InputError("settings.lammps.mpirun, lmp: must name a command");
}

}  // namespace

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
  info.profiles = {"hooke", "hertz"};
  info.sweep_knobs = {{"contact_steps", nlohmann::json::array({20, 50, 100})},
                      {"overlap_target", nlohmann::json::array({0.02, 0.005, 0.001})}};
  return {info, [](const Scene& scene, const std::string& profile, const nlohmann::json& overrides) {
            LammpsSettings s = lammps_profile(profile);
            SettingsReader r("lammps", overrides);
            r.get("overlap_target", s.overlap_target);
            r.get("impact_speed", s.impact_speed);
            r.get("contact_steps", s.contact_steps);
            r.get("max_substeps", s.max_substeps);
            r.get("skin", s.skin);
            r.get("ranks", s.ranks);
            r.get("sample_every", s.sample_every);
            r.get("hostfile", s.hostfile);
            r.get("mpirun", s.mpirun);
            r.get("lmp", s.lmp);
            r.get("workdir", s.workdir);
            r.finish();
            validate(s);
            const lammps::Plan plan = lammps::make_plan(scene, s);
            if (s.ranks > 1) return lammps::make_mpi_engine(scene, s, plan);
            return lammps::make_library_engine(scene, s, plan);
          }};
}

}  // namespace ballbench
