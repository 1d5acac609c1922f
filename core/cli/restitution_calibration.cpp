#include "restitution_calibration.h"

#include <cmath>

#include <fmt/format.h>

#include "isolated_run.h"
#include "runner.h"
#include "scene_loader.h"

namespace ballbench::cli {
namespace {

// Both scenes: no gravity, dt 0.01, the contact 4.5 steps in (mid-step, as impacts fall), then 15.5
// steps for the contact to end and the balls to part; balls of radius 0.1 and mass 1 in a box of
// side 10 (every engine has walls; the ball-ball pair never reaches them).
constexpr double kDt = 0.01, kContactAt = 0.045;
constexpr long kSteps = 20;

// The scene with restitution e and the given balls ([[ball]] tables).
Scene calibration_scene(double e, const std::string& balls, const std::string& source) {
  return parse_scene(fmt::format(R"(
dt = {}
duration = {}
restitution = {}
[container]
min = [-5.0, -5.0]
max = [5.0, 5.0]
{})",
                                 kDt, kDt * kSteps, e, balls),
                     source);
}

std::string ball(double x, double vx) {
  return fmt::format("[[ball]]\npos = [{}, 0.0]\nvel = [{}, 0.0]\nradius = 0.1\nmass = 1.0\n", x, vx);
}

// A ball at `speed` meeting the wall x = 5.
Scene wall_scene(double e, double speed) {
  return calibration_scene(e, ball(4.9 - speed * kContactAt, speed), "calibration: ball-wall");
}

// Two equal balls approaching at `speed`, head-on.
Scene pair_scene(double e, double speed) {
  const double x = 0.1 + 0.5 * speed * kContactAt;
  return calibration_scene(e, ball(-x, 0.5 * speed) + ball(x, -0.5 * speed), "calibration: ball-ball");
}

}  // namespace

CalibrationResult run_calibration(const std::vector<const EngineEntry*>& engines, const CalibrationOptions& o,
                                  const nlohmann::json& context) {
  CalibrationResult out;
  out.requested = o.requested, out.speeds = o.speeds, out.context = context;
  const IsolationOptions child{o.isolation.timeout_s, ""};
  for (const EngineEntry* e : engines)
    for (const std::string& profile : profiles_for(*e, "all"))
      for (const std::string contact : {"ball-wall", "ball-ball"})
        for (double requested : o.requested)
          for (double speed : o.speeds) {
            const Scene scene = contact == "ball-wall" ? wall_scene(requested, speed) : pair_scene(requested, speed);
            RunOptions options;
            options.profile = profile;
            const Result r = o.isolation.enabled ? run_engine_isolated(scene, *e, options, child)
                                                 : run_engine(scene, *e, options);
            CalibrationPoint p{e->info.name, profile, contact, requested, speed, std::nan(""), r.status, false, r.error};
            // Both scenes start with zero momentum along the contact (the wall's frame for one
            // ball), so the kinetic energy is the energy of the approach.
            if (const auto ratio = r.metrics.energy_ratio(); r.status == RunStatus::ok && ratio)
              p.effective = std::sqrt(std::max(*ratio, 0.0));
            if (r.status == RunStatus::ok && r.metrics.tunnelled() > 0)
              p.tunnelled = true, p.error = "passed through the contact instead of bouncing";
            out.points.push_back(std::move(p));
          }
  return out;
}

}  // namespace ballbench::cli
