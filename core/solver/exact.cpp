#include "solver/exact.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"
#include "solver/exact_events.h"
#include "solver/exact_sim.h"

namespace ballbench {
namespace {

// Default contact_time and rest_velocity as fractions of the scene's time and speed scales.
constexpr double kAutoScale = 1e-2;
// Default wake_velocity as a multiple of rest_velocity.
constexpr double kAutoWake = 10.0;

// Why `exact` cannot run a scene in closed form, or "". A rough ball alone under gravity is exact
// (flights, rough impacts, sliding and rolling on a wall: EXACT.md, "Friction"), and so are rough
// balls without gravity (every impact binary); rough balls under gravity come to rest on one another,
// a frictional multi-contact problem with no closed form (nor a unique hard-disk answer).
std::string exact_refusal(const Scene& scene) {
  if (scene.friction > 0 && scene.features().gravity && scene.n() > 1)
    return "rough balls resting on each other under gravity have no closed form (the reference is a converged run)";
  return "";
}

// exact's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings exact` come from these rows. The scene-dependent checks stay in the factory.
const SettingsTable<ExactSettings>& exact_settings_table() {
  using S = ExactSettings;
  static const SettingsTable<S> table(
      "exact",
      {setting("contact_time", &S::contact_time, any_value, "s",
               "flight a supported ball keeps per collision; < 0: automatic"),
       setting("rest_velocity", &S::rest_velocity, any_value, "m/s", "impacts slower than this settle; < 0: automatic"),
       setting("sleep", &S::sleep, any_value, "", "a settled, supported ball sleeps"),
       setting("wake_velocity", &S::wake_velocity, any_value, "m/s",
               "impacts this fast wake a sleeping ball; < 0: 10 rest_velocity"),
       setting("support_gap", &S::support_gap, any_value, "m",
               "gap within which a support carries a ball; < 0: automatic"),
       setting("cell_size", &S::cell_size, any_value, "m", "neighbour grid's cell width; < 0: automatic"),
       setting("max_events_per_ball", &S::max_events_per_ball, at_least(1), "count",
               "more events per ball in one step fail the run")});
  return table;
}

// The Engine adapter: one ExactSim, stepped by its event loop and read back.
class Exact final : public Engine {
 public:
  Exact(const Scene& scene, const ExactSettings& settings) : sim_(scene, settings) {}

  void step(double dt) override { run_events_until(sim_, sim_.time + dt); }

  void read(State& out) const override {
    const ExactBalls& balls = sim_.balls;
    const int n = sim_.model.ball_count;
    out.t = sim_.time;
    out.resize(n, sim_.model.rotation);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 2; ++k) out.pos(i, k) = balls.pos[k][i], out.vel(i, k) = balls.vel[k][i];
    if (sim_.model.rotation)
      for (int i = 0; i < n; ++i) out.w(i) = balls.spin[i], out.angle(i) = balls.angle[i];
  }

  nlohmann::json settings() const override { return exact_settings_table().json(sim_.model.settings); }

 private:
  ExactSim sim_;
};

}  // namespace

EngineEntry exact_engine() {
  EngineInfo info;
  info.name = "exact";
  info.role = EngineRole::reference;
  info.version = "1.0";
  info.summary =
      "event-driven reference: exact parabolic flights, binary collisions in time order, rest rules for piles";
  info.caps.continuous_collision = true;
  info.caps.deterministic = true;
  info.caps.any_restitution = true;
  info.caps.friction = true;  // closed-form cases only: `refuses` names the rest
  info.refuses = exact_refusal;
  info.settings = exact_settings_table().describe();
  // No piles: an event-driven solver without a resting contact model does not finish a step of a
  // pile at rest (100 balls: no step in 100 s).
  info.bench.sizes = {.free_balls = 100'000, .fluid_balls = 0, .settled_balls = 0};
  return {info, [](const Scene& scene, const std::string&, const nlohmann::json& overrides) {
            ExactSettings s;
            exact_settings_table().read(overrides, s);
            if (const std::string why = exact_refusal(scene); !why.empty()) throw SceneUnsupported("exact: " + why);
            const double rmin = scene.n() > 0 ? scene.radius.minCoeff() : 1.0;
            const double rmax = scene.n() > 0 ? scene.radius.maxCoeff() : 1.0;
            if (s.cell_size > 0 && s.cell_size < 2 * rmax)
              throw InputError(
                  fmt::format("settings.exact.cell_size: must be at least the largest diameter, {} m", 2 * rmax));
            // Resolve the automatic values (negative = automatic), so settings() shows those in force.
            const double g = scene.gravity.norm();
            const double v0 = scene.n() > 0 ? std::sqrt(scene.initial.vel.rowwise().squaredNorm().maxCoeff()) : 0.0;
            const double v_scale = std::max(std::sqrt(g * rmin), v0);  // speed scale of the scene (m/s)
            if (s.contact_time < 0) s.contact_time = v_scale > 0 ? kAutoScale * rmin / v_scale : 0.0;
            if (s.rest_velocity < 0) s.rest_velocity = g > 0 ? kAutoScale * v_scale : 0.0;
            if (s.wake_velocity < 0) s.wake_velocity = kAutoWake * s.rest_velocity;
            if (s.support_gap < 0)
              s.support_gap = std::max(g > 0 ? s.rest_velocity * s.rest_velocity / g : 0.0, 1e-9 * rmin);
            if (g > 0 && !(s.contact_time > 0))
              throw InputError("settings.exact.contact_time: must be > 0 under gravity (it ends resting contacts)");
            if (g > 0 && !(s.rest_velocity > 0))
              throw InputError(
                  "settings.exact.rest_velocity: must be > 0 under gravity (it ends bouncing on supports)");
            return std::unique_ptr<Engine>(std::make_unique<Exact>(scene, s));
          }, {}};
}

}  // namespace ballbench
