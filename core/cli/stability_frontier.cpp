#include "stability_frontier.h"

#include <algorithm>

#include <fmt/format.h>

#include "input_error.h"
#include "interrupt.h"
#include "isolated_run.h"
#include "progress.h"

namespace ballbench::cli {

Scene stressed(const Scene& base, const std::string& knob, double factor) {
  Scene s = base;
  if (knob == "dt") {
    s.dt *= factor;
  } else if (knob == "speed") {
    s.initial.vel *= factor;
  } else if (knob == "mass-ratio") {
    for (int i = 1; i < s.n(); i += 2) s.mass(i) *= factor;  // every other ball heavier
  } else if (knob == "count") {
    // Tile the scene: `factor` copies side by side in a box grown to match (box scenes only).
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

std::string stress_failure(const Result& r, double energy_tolerance) {
  if (r.status != RunStatus::ok) return run_status_text(r.status) + (r.error.empty() ? "" : ": " + r.error);
  auto count = [](int k, const char* what) { return fmt::format("{} {}{}", k, what, k == 1 ? "" : "s"); };
  if (const long n = r.metrics.count(Metric::tunnelling_wall)) return count(n, "wall escape");
  if (const long n = r.metrics.count(Metric::tunnelling_pair)) return count(n, "pair pass-through");
  if (r.reference.available && r.reference.reference_failed_step < 0 && r.reference.energy_rel_max > energy_tolerance)
    return fmt::format("energy off the reference by {:.3g}", r.reference.energy_rel_max);
  if (const auto ratio = r.metrics.energy_ratio(); ratio && *ratio > 1 + energy_tolerance)
    return fmt::format("energy grew to {:.3g} x", *ratio);
  return "";
}

void check_stress_knobs(const Scene& base, const std::vector<std::string>& knobs) {
  if (knobs.empty()) throw InputError("--knobs: name at least one knob (dt, speed, mass-ratio, count)");
  for (const std::string& k : knobs) {
    if (std::find(kStressKnobs.begin(), kStressKnobs.end(), k) == kStressKnobs.end())
      throw InputError(fmt::format("--knobs: unknown knob '{}'{} (known: {})", k, did_you_mean(k, kStressKnobs),
                                   fmt::join(kStressKnobs, ", ")));
    if (std::count(knobs.begin(), knobs.end(), k) > 1) throw InputError(fmt::format("--knobs: '{}' is named twice", k));
    if (k == "count" && base.container.kind != ContainerKind::Box)
      throw InputError("--knobs: count tiles the scene's box, and this scene has none");
  }
}

FrontierResult run_frontier(const Scene& base, const std::vector<const EngineEntry*>& engines, const StressOptions& o,
                            const nlohmann::json& context) {
  check_stress_knobs(base, o.knobs);
  FrontierResult out;
  out.scene = base.name, out.n = base.n(), out.steps = o.steps, out.levels = o.levels;
  out.energy_tolerance = o.energy_tolerance, out.context = context;
  RunOptions options;
  options.steps = o.steps;
  options.reference = o.reference;
  const IsolationOptions child{o.isolation.timeout_s, ""};
  size_t total = 0, done = 0;
  for (const EngineEntry* e : engines) total += profiles_for(*e, o.profile).size() * o.knobs.size();
  Progress progress(fmt::format("stress {} ({} frontiers)", base.name, total));
  for (const EngineEntry* e : engines)
    for (const std::string& profile : profiles_for(*e, o.profile))
      for (const std::string& knob : o.knobs) {
        FrontierRow row;
        row.engine = e->info.name, row.profile = profile, row.knob = knob;
        row.base = knob == "dt" ? base.dt : knob == "count" ? base.n() : 1.0;
        double factor = 1;
        for (int level = 0; level < o.levels; ++level, factor *= 2) {
          options.profile = profile;
          const Scene s = stressed(base, knob, factor);
          const Result r = o.isolation.enabled ? run_engine_isolated(s, *e, options, child) : run_engine(s, *e, options);
          row.failed_next = stress_failure(r, o.energy_tolerance);
          if (!row.failed_next.empty()) break;
          row.factor = factor, row.levels_passed = level + 1;
        }
        out.rows.push_back(std::move(row));
        if (interrupt_signal()) {  // the frontier in progress is kept, its last run failed as interrupted
          out.interrupted = interrupt_name();
          return out;
        }
        if (!o.quiet) progress.update(double(++done) / total);
      }
  return out;
}

void print_frontier(const FrontierResult& f) {
  fmt::print("{:<18} {:<11} {:>10} {:>10}  {}\n", "engine", "knob", "base", "frontier", "next level failed by");
  for (const FrontierRow& r : f.rows) {
    const std::string label = run_label(r.engine, r.profile);
    const std::string frontier =
        refused(r) ? "refused" : r.factor == 0 ? "none" : fmt::format("{:.4g}", r.base * r.factor);
    fmt::print("{:<18} {:<11} {:>10.4g} {:>10}  {}\n", label, r.knob, r.base, frontier,
               r.failed_next.empty() ? fmt::format("(passed all {} levels)", f.levels) : r.failed_next);
  }
}

}  // namespace ballbench::cli
