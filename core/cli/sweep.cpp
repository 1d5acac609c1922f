#include "sweep.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "input_error.h"
#include "interrupt.h"
#include "isolated_run.h"
#include "scene_digest.h"
#include "json_value.h"
#include "progress.h"

namespace ballbench::cli {
namespace {

constexpr double kMaxSweepSteps = 1e9;  // as a scene's own cap

// The profile's effective settings, to skip knob values it already has; empty if the engine cannot
// be built here (the points then all run, and their runs report why).
nlohmann::json profile_settings(const Scene& scene, const EngineEntry& e, const std::string& profile) {
  try {
    return e.create(scene, profile, merged_settings(scene, e.info.name, {}))->settings();
  } catch (const std::exception&) {
    return nlohmann::json::object();
  }
}

}  // namespace

std::vector<SweepPlanItem> plan_sweep(const Scene& scene, const std::vector<const EngineEntry*>& engines,
                                      const SweepOptions& o) {
  if (!(o.horizon > 0)) throw InputError("--horizon: must be positive");
  std::vector<SweepPlanItem> plan;
  auto steps_for = [&](double dt) {
    if (!(o.horizon / dt <= kMaxSweepSteps))
      throw InputError(fmt::format("--horizon {} s at a step of {} s (dt factors {}) is more than the cap of 1e9 steps",
                                   o.horizon, dt, fmt::join(o.dt_factors, ",")));
    const long steps = std::lround(o.horizon / dt);
    if (steps < 1 || std::abs(steps * dt - o.horizon) > 1e-9 * o.horizon)
      throw InputError(fmt::format("--horizon {} s is not a whole number of steps of {} s (dt factors {})", o.horizon,
                                   dt, fmt::join(o.dt_factors, ",")));
    return steps;
  };
  for (const EngineEntry* e : engines)
    for (const std::string& profile : profiles_for(*e, o.profile)) {
      for (double f : o.dt_factors) {
        const double dt = scene.dt * f;
        plan.push_back({e, profile, "dt", dt, nlohmann::json::object(), dt, steps_for(dt)});
      }
      if (!o.knobs || e->info.sweep_knobs.empty()) continue;
      const nlohmann::json base = profile_settings(scene, *e, profile);
      for (const SweepKnob& k : e->info.sweep_knobs) {
        if (!k.profiles.empty() && std::find(k.profiles.begin(), k.profiles.end(), profile) == k.profiles.end())
          continue;  // a setting this profile's runs do not read
        for (const auto& v : k.values) {
          if (base.contains(k.key) && base[k.key] == v) continue;  // the dt series has this point
          plan.push_back({e, profile, k.key, v, {{k.key, v}}, scene.dt, steps_for(scene.dt)});
        }
      }
    }
  return plan;
}

nlohmann::json plan_record(const Scene& scene, const std::vector<SweepPlanItem>& plan, const SweepOptions& o) {
  nlohmann::json points = nlohmann::json::array();
  for (const SweepPlanItem& item : plan)
    points.push_back({item.engine->info.name, item.engine->info.version, item.profile, item.knob, item.value, item.dt,
                      item.steps});
  return {{"scene", scene.name}, {"scene_digest", scene_digest(scene)}, {"n", scene.n()}, {"horizon", o.horizon},
          {"reference", o.reference ? o.reference->info.name : ""}, {"repeats", o.repeats}, {"points", points}};
}

namespace {

// Runs in this process or a child, as asked. A point whose settings the engine refuses (a value of
// its own sweep_knobs, say) fails that point.
Result run_point(const Scene& s, const EngineEntry& e, const RunOptions& r, const SweepOptions& o) {
  try {
    return o.isolation.enabled ? run_engine_isolated(s, e, r, IsolationOptions{o.isolation.timeout_s, ""})
                               : run_engine(s, e, r);
  } catch (const InputError& err) {
    Result failed = result_header(s, e, r);
    failed.status = RunStatus::failed;
    failed.error = fmt::format("the engine refused this point's settings {}: {}", r.overrides.dump(), err.what());
    return failed;
  }
}

// One point: its measured run (error against the reference, metrics; its timing is not used, since
// the reference stepping in lockstep shares the caches), then the timing runs, the engine alone.
SweepPoint measure_point(const Scene& scene, const SweepPlanItem& item, size_t k, const SweepOptions& o) {
  Scene s = scene;
  s.dt = item.dt;
  RunOptions options;
  options.steps = item.steps;
  options.profile = item.profile;
  options.overrides = item.overrides;
  options.reference = item.engine == o.reference ? nullptr : o.reference;
  const Result r = run_point(s, *item.engine, options, o);
  SweepPoint p;
  p.engine = item.engine->info.name, p.profile = item.profile, p.knob = item.knob, p.value = item.value;
  p.dt = item.dt, p.steps = item.steps, p.settings = r.settings;
  p.status = r.status, p.error = r.error, p.measured = r.measured();
  if (options.reference) {
    p.pos_rms = r.reference.pos_rms_final, p.vel_rms = r.reference.vel_rms_final;
    p.energy_rel = r.reference.energy_rel_max;
  }  // else: the reference against itself, error 0 by definition
  p.tunnelling = r.metrics.tunnelled();
  p.sticking = r.metrics.stuck();
  p.plan_index = static_cast<long>(k);
  options.reference = nullptr;
  for (int rep = 0; rep < o.repeats && r.status == RunStatus::ok; ++rep) {
    const Result t = run_point(s, *item.engine, options, o);
    if (t.status == RunStatus::interrupted) p.status = t.status, p.error = t.error;  // no timing: not ok
    if (t.status != RunStatus::ok) break;
    p.ns_per_ball_step.push_back(t.ns_per_ball_step);
    p.engine_s.push_back(t.engine_process_s.value_or(t.engine_s));  // the engine's own time, as ns_per_ball_step
  }
  return p;
}

}  // namespace

SweepResult run_sweep(const Scene& scene, const std::vector<const EngineEntry*>& engines, const SweepOptions& o,
                      const nlohmann::json& context) {
  if (o.repeats < 1) throw InputError("--repeats: must be at least 1");
  if (!o.reference) throw InputError("sweep: no reference engine");
  const auto plan = plan_sweep(scene, engines, o);
  std::vector<size_t> mine;  // this shard's places in the plan, dealt round-robin so shards mix engines
  for (size_t k = 0; k < plan.size(); ++k)
    if (o.shard.takes(k)) mine.push_back(k);
  SweepResult out;
  out.plan = plan_record(scene, plan, o);
  out.shard_index = o.shard.index, out.shard_count = o.shard.count;
  out.scene = scene.name, out.n = scene.n(), out.horizon = o.horizon;
  out.reference = o.reference->info.name, out.repeats = o.repeats, out.context = context;
  Progress progress(o.shard.all()
                        ? fmt::format("sweep {} ({} points x {} runs)", scene.name, plan.size(), o.repeats + 1)
                        : fmt::format("sweep {} shard {}/{} ({} of {} points x {} runs)", scene.name, o.shard.index,
                                      o.shard.count, mine.size(), plan.size(), o.repeats + 1));
  for (size_t m = 0; m < mine.size(); ++m) {
    out.points.push_back(measure_point(scene, plan[mine[m]], mine[m], o));
    if (interrupt_signal()) {  // the point in progress is kept, marked by its run's status
      out.interrupted = interrupt_name();
      break;
    }
    if (!o.quiet) progress.update(double(m + 1) / mine.size());
  }
  mark_pareto(out.points);
  return out;
}

void print_pareto(const SweepResult& s) {
  fmt::print("Pareto fronts on {} ({} balls): position RMS error against {} at t = {} s vs engine time\n", s.scene,
             s.n, s.reference, s.horizon);
  fmt::print("{:<10} {:<8} {:<22} {:>9} {:>12} {:>12} {:>11} {:>11}\n", "engine", "profile", "knob = value", "dt",
             "engine ms", "ns/ball-step", "pos.err", "E err");
  for (const SweepPoint& p : s.points) {
    if (!p.pareto) continue;
    fmt::print("{:<10} {:<8} {:<22} {:>9.4g} {:>12.4g} {:>12.1f} {:>11.3g} {:>11.3g}\n", p.engine, p.profile,
               p.knob == "dt" ? "dt" : p.knob + " = " + json_text(p.value), p.dt, 1e3 * p.engine_s_median(),
               p.ns_median(), p.pos_rms, p.energy_rel);
  }
  for (const SweepPoint& p : s.points)
    if (p.status != RunStatus::ok)
      fmt::print("{}/{} {} = {}: {}{}\n", printable(p.engine), printable(p.profile), p.knob, json_text(p.value),
                 run_status_text(p.status), p.error.empty() ? "" : ": " + printable(p.error));
}

}  // namespace ballbench::cli
