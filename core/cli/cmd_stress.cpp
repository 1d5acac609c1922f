// `ballbench stress`: for each engine, raise one knob at a time (dt, initial speed, mass ratio,
// ball count) by factors of 2 until a run fails, and print the stability frontier: the largest
// value that still passed, and why the next one failed.
#include <filesystem>
#include <fstream>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "input_error.h"
#include "registry.h"
#include "run_engines.h"
#include "scene_loader.h"

namespace ballbench::cli {
namespace {

struct StressArgs {
  std::string scene, engines, profile, knobs = "dt,speed,mass-ratio,count", json;
  long steps = 200;
  int levels = 6;
  double energy_tolerance = 0.1;
};

// The scene with one knob raised by `factor`.
Scene stressed(const Scene& base, const std::string& knob, double factor) {
  Scene s = base;
  if (knob == "dt") {
    s.dt *= factor;
  } else if (knob == "speed") {
    s.initial.vel *= factor;
  } else if (knob == "mass-ratio") {
    for (int i = 1; i < s.n(); i += 2) s.mass(i) *= factor;  // every other ball heavier
  } else if (knob == "count") {
    // Tile the scene: factor 2^k copies side by side in a box grown to match (box scenes only).
    const int copies = static_cast<int>(factor);
    const Eigen::Vector2d size = base.container.max - base.container.min;
    const int n = base.n();
    s.radius.resize(n * copies), s.mass.resize(n * copies), s.initial.resize(n * copies);
    for (int c = 0; c < copies; ++c) {
      const Eigen::RowVector2d shift(size.x() * c, 0.0);
      s.radius.segment(c * n, n) = base.radius, s.mass.segment(c * n, n) = base.mass;
      s.initial.pos.middleRows(c * n, n) = base.initial.pos.rowwise() + shift;
      s.initial.vel.middleRows(c * n, n) = base.initial.vel;
    }
    s.container.max.x() = base.container.min.x() + size.x() * copies;
  }
  return s;
}

// Why a run failed the stress criteria, or "" if it passed.
std::string failure(const Result& r, double energy_tolerance) {
  if (r.status != "ok") return r.status + (r.error.empty() ? "" : ": " + r.error);
  if (r.metrics.tunnelling_wall) return fmt::format("{} wall escapes", r.metrics.tunnelling_wall);
  if (r.metrics.tunnelling_pair) return fmt::format("{} pair pass-throughs", r.metrics.tunnelling_pair);
  if (r.reference.available && r.reference.reference_failed_step < 0 && r.reference.energy_rel_max > energy_tolerance)
    return fmt::format("energy off the reference by {:.3g}", r.reference.energy_rel_max);
  if (r.metrics.energy.initial > 0 && r.metrics.energy.final > (1 + energy_tolerance) * r.metrics.energy.initial)
    return fmt::format("energy grew to {:.3g} x", r.metrics.energy.final / r.metrics.energy.initial);
  return "";
}

void stress(const StressArgs& a) {
  const Scene base = load_scene(a.scene);
  const auto engines = parse_engine_list(a.engines);
  check_profile(engines, a.profile);
  std::vector<std::string> knobs;
  for (size_t p = 0, q; p <= a.knobs.size(); p = q + 1) {
    q = a.knobs.find(',', p);
    if (q == std::string::npos) q = a.knobs.size();
    const std::string k = a.knobs.substr(p, q - p);
    if (k != "dt" && k != "speed" && k != "mass-ratio" && k != "count")
      throw InputError(fmt::format("--knobs: unknown knob '{}' (known: dt, speed, mass-ratio, count)", k));
    if (k == "count" && base.container.kind != ContainerKind::Box)
      throw InputError("--knobs: count tiles the scene's box, and this scene has none");
    knobs.push_back(k);
  }
  RunOptions options;
  options.steps = a.steps;
  options.reference = reference_engine();
  nlohmann::json out = nlohmann::json::array();
  fmt::print("{:<18} {:<11} {:>10} {:>10}  {}\n", "engine", "knob", "base", "frontier", "next level failed by");
  for (const EngineEntry* e : engines)
    for (const std::string& profile : profiles_for(*e, a.profile))
      for (const std::string& knob : knobs) {
        const double base_value = knob == "dt" ? base.dt : knob == "count" ? base.n() : 1.0;
        double passed = 0, factor = 1;
        std::string why;
        for (int level = 0; level < a.levels; ++level, factor *= 2) {
          options.profile = profile;
          const Result r = run_engine(stressed(base, knob, factor), *e, options);
          why = failure(r, a.energy_tolerance);
          if (!why.empty()) break;
          passed = factor;
        }
        const std::string label = profile == "default" ? e->info.name : e->info.name + "/" + profile;
        const std::string frontier = passed == 0 ? "none" : fmt::format("{:.4g}", base_value * passed);
        fmt::print("{:<18} {:<11} {:>10.4g} {:>10}  {}\n", label, knob, base_value, frontier,
                   why.empty() ? fmt::format("(passed all {} levels)", a.levels) : why);
        out.push_back({{"engine", e->info.name}, {"profile", profile}, {"knob", knob}, {"base", base_value},
                       {"frontier", passed == 0 ? nlohmann::json(nullptr) : nlohmann::json(base_value * passed)},
                       {"factor", passed}, {"failed_next", why}});
      }
  if (!a.json.empty()) {
    std::ofstream f(a.json + ".tmp");
    f << out.dump(2) << '\n';
    f.close();
    std::filesystem::rename(a.json + ".tmp", a.json);
  }
}

}  // namespace

void add_stress(CLI::App& app) {
  auto a = std::make_shared<StressArgs>();
  auto* cmd = app.add_subcommand("stress", "raise one knob at a time until each engine fails: the stability frontier");
  cmd->add_option("--scene", a->scene, "built-in scene name or path to a .toml scene file")->required();
  cmd->add_option("--engine", a->engines, "engine name, comma-separated names, or all")->required();
  cmd->add_option("--profile", a->profile, "settings profile, or all");
  cmd->add_option("--knobs", a->knobs, "comma-separated: dt, speed, mass-ratio, count (default: all four)");
  cmd->add_option("--steps", a->steps, "steps per run (default 200)")->check(CLI::PositiveNumber);
  cmd->add_option("--levels", a->levels, "doublings tried per knob (default 6: up to 32 x)")->check(CLI::Range(1, 20));
  cmd->add_option("--energy-tolerance", a->energy_tolerance,
                  "a run fails when its energy is off the reference (or grew) by more than this fraction (default 0.1)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--json", a->json, "write the frontiers as JSON to FILE");
  cmd->callback([a] { stress(*a); });
}

}  // namespace ballbench::cli
