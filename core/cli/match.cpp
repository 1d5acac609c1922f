#include "match.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "isolated_run.h"
#include "json_value.h"
#include "progress.h"
#include "scene_loader.h"
#include "shard_roll.h"
#include "spec_verdict.h"
#include "sweep_result.h"

namespace ballbench::cli {
namespace {

using Clock = std::chrono::steady_clock;

// A configuration of one engine and profile: the profile as it is, or one knob set on top of it.
struct Config {
  std::string knob;
  nlohmann::json value;
  nlohmann::json overrides = nlohmann::json::object();
};

std::vector<Config> configs_for(const Scene& scene, const EngineEntry& e, const std::string& profile, bool knobs) {
  std::vector<Config> out{{}};
  if (!knobs) return out;
  nlohmann::json base = nlohmann::json::object();
  try {  // the profile's own values, to skip a knob value it already has
    base = e.create(scene, profile, merged_settings(scene, e.info.name, {}))->settings();
  } catch (const std::exception&) {
  }
  for (const SweepKnob& k : e.info.sweep_knobs) {
    if (!k.profiles.empty() && std::find(k.profiles.begin(), k.profiles.end(), profile) == k.profiles.end()) continue;
    for (const auto& v : k.values)
      if (!(base.contains(k.key) && base[k.key] == v)) out.push_back({k.key, v, {{k.key, v}}});
  }
  return out;
}

// ns per ball per scene step: the run's engine time over the scene's steps, so every step size is
// costed for the same simulated time.
double cost_per_scene_step(double engine_s, const Scene& scene) {
  return engine_s * 1e9 / (std::max(1, scene.n()) * double(std::max(1L, scene.steps())));
}

std::string run_command(const Scene& scene, const MatchTry& t, const MatchOptions& o) {
  // A built-in scene by its name, any other by its file; the step in the fewest digits that read
  // back as it (fmt's shortest round trip).
  const bool builtin = scene.source == scenario_dir() + "/" + scene.name + ".toml";
  std::string cmd = fmt::format("ballbench run --scene {} --engine {} --profile {} --dt {}",
                                builtin || scene.source.empty() ? scene.name : scene.source, t.engine, t.profile, t.dt);
  if (!o.spec.needs_reference()) cmd += " --no-reference";
  if (!o.spec_texts.empty()) cmd += fmt::format(" --spec {}", fmt::join(o.spec_texts, ","));
  // Judged at the scene's step times, as the search judged it.
  if (t.halvings > 0) cmd += fmt::format(" --sample-every {}", 1 << t.halvings);
  if (!t.knob.empty()) cmd += fmt::format(" --set {}.{}={}", t.engine, t.knob, json_text(t.value));
  return cmd;
}

class Search {
 public:
  Search(const Scene& scene, const EngineEntry& e, std::string profile, const MatchOptions& o, MatchResult& out)
      : scene_(scene), e_(e), profile_(std::move(profile)), o_(o), out_(out) {}

  // First the profile as it is, coarse to fine until it meets the spec; then each knob setting from
  // two halvings coarser than that (a knob may let a longer step meet it) down to where the profile
  // met it (or to the finest step if it never did), refined while it can still be cheaper.
  MatchOutcome run(Progress& progress) {
    MatchOutcome oc;
    oc.engine = e_.info.name, oc.profile = profile_, oc.role = role_name(e_.info.role);
    const auto configs = configs_for(scene_, e_, profile_, o_.knobs);
    start_ = Clock::now();
    int met_at = -1;
    for (size_t c = 0; c < configs.size() && oc.stopped.empty(); ++c) {
      const int first = c == 0 || met_at < 0 ? 0 : std::max(0, met_at - 2);
      const int last = c == 0 || met_at < 0 ? o_.max_halvings : met_at;
      double cost = -1;  // at the last step size it ran ok
      int cost_at = 0;
      for (int k = first; k <= last && oc.stopped.empty(); ++k) {
        if (cost > 0 && cost * std::pow(kHalvingCostFloor, k - cost_at) >= best_cost_) break;  // cannot be cheaper
        if (budget_left() <= 0) {
          oc.stopped = fmt::format("the {:g} s budget", o_.budget_s);
          break;
        }
        const int t = try_config(configs[c], k, budget_left());
        const MatchTry& tr = out_.tries[t];
        ++oc.tries;
        oc.finest_dt = oc.finest_dt > 0 ? std::min(oc.finest_dt, tr.dt) : tr.dt;
        if (interrupt_signal()) oc.stopped = "an interrupt";
        if (tr.status == RunStatus::ok) cost = tr.cost_ns, cost_at = k;
        // A knob whose run is the profile's own, bit for bit, changes nothing here (a stiffness on
        // a path that has none): it is never a finding, at any step.
        if (c == 0 && tr.status == RunStatus::ok) as_is_trajectory_[k] = last_trajectory_;
        if (const auto as_is = as_is_trajectory_.find(k); c > 0 && tr.status == RunStatus::ok &&
                                                             !last_trajectory_.empty() &&
                                                             as_is != as_is_trajectory_.end() &&
                                                             as_is->second == last_trajectory_)
          break;
        if (tr.met) {
          // A knob replaces the profile as it is only when it is cheaper beyond timing noise.
          const double margin = c == 0 || oc.found < 0 || !out_.tries[oc.found].knob.empty() ? 1 : kKnobCostMargin;
          if (tr.cost_ns < best_cost_ * margin) best_cost_ = tr.cost_ns, oc.found = t;
          if (c == 0) met_at = k;
          break;  // finer costs more
        }
        if (oc.best < 0 || miss(tr, o_.spec) < miss(out_.tries[oc.best], o_.spec)) oc.best = t;
        if (tr.status == RunStatus::unsupported || tr.status == RunStatus::timed_out) break;  // finer will not do better
      }
      if (!o_.quiet) progress.update(double(c + 1) / configs.size());
    }
    oc.reached = oc.found >= 0;
    if (oc.reached) {
      oc.stopped.clear();
      retime(oc);
    } else if (oc.stopped.empty()) {
      oc.stopped = fmt::format("dt / 2^{}", o_.max_halvings);
    }
    const int shown = oc.reached ? oc.found : oc.best;
    if (shown >= 0) oc.command = run_command(scene_, out_.tries[shown], o_);
    return oc;
  }

 private:
  RunOptions options(const Config& c, int k) const {
    RunOptions r;
    r.profile = profile_;
    r.overrides = c.overrides;
    // Every configuration is judged at the scene's own step times (tunnelling at every step).
    r.metrics.sample_every = 1 << k;
    r.series_points = 0;
    if (o_.spec.needs_reference()) r.reference = o_.reference, r.converged_reference = o_.converged_reference;
    return r;
  }

  Result run_at(int k, double timeout_s, RunOptions r) const {
    Scene s = scene_;
    s.dt = scene_.dt / double(1 << k);
    return o_.isolation.enabled ? run_engine_isolated(s, e_, r, {timeout_s, ""}) : run_engine(s, e_, r);
  }

  int try_config(const Config& c, int k, double budget_left) {
    const auto t0 = Clock::now();
    const Result r = run_at(k, std::min(o_.isolation.timeout_s, budget_left), options(c, k));
    MatchTry t;
    t.engine = e_.info.name, t.profile = profile_, t.knob = c.knob, t.value = c.value;
    t.halvings = k, t.dt = scene_.dt / double(1 << k);
    t.status = r.status, t.error = r.error;
    t.settings = r.settings;
    const SpecVerdict v = judge(o_.spec, r);
    t.met = v.met, t.why_not = v.why_not, t.figures = v.figures;
    t.cost_ns = cost_per_scene_step(r.engine_process_s.value_or(r.engine_s), scene_);
    if (r.engine_process_s) t.cost_pipe_ns = cost_per_scene_step(r.engine_s, scene_);
    t.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
    last_trajectory_ = r.checksum_trajectory;
    out_.tries.push_back(std::move(t));
    return int(out_.tries.size()) - 1;
  }

  // The found configuration timed again without the reference or sampling beyond the scene's
  // steps: the cost is the median of these and the measuring run.
  void retime(MatchOutcome& oc) {
    const MatchTry& f = out_.tries[oc.found];
    Config c{f.knob, f.value, f.knob.empty() ? nlohmann::json::object() : nlohmann::json{{f.knob, f.value}}};
    oc.cost_repeats = {f.cost_ns};
    std::vector<double> pipe;
    if (f.cost_pipe_ns) pipe.push_back(*f.cost_pipe_ns);
    for (int rep = 0; rep < o_.repeats && !interrupt_signal(); ++rep) {
      RunOptions r = options(c, f.halvings);
      r.reference = nullptr;
      const Result t = run_at(f.halvings, o_.isolation.timeout_s, r);
      if (t.status != RunStatus::ok) break;
      oc.cost_repeats.push_back(cost_per_scene_step(t.engine_process_s.value_or(t.engine_s), scene_));
      if (t.engine_process_s) pipe.push_back(cost_per_scene_step(t.engine_s, scene_));
    }
    oc.cost_ns = median(oc.cost_repeats);
    if (!pipe.empty()) oc.cost_pipe_ns = median(pipe);
  }

  const Scene& scene_;
  const EngineEntry& e_;
  std::string profile_;
  const MatchOptions& o_;
  MatchResult& out_;
  Clock::time_point start_;
  double best_cost_ = std::numeric_limits<double>::infinity();
  std::string last_trajectory_;                  // the last try's trajectory checksum
  std::map<int, std::string> as_is_trajectory_;  // the profile as it is: halvings -> its checksum

  double budget_left() const {
    return o_.budget_s - std::chrono::duration<double>(Clock::now() - start_).count();
  }
};




}  // namespace

MatchResult run_match(const Scene& scene, const std::vector<const EngineEntry*>& engines, const MatchOptions& o,
                      const nlohmann::json& context) {
  if (o.max_halvings < 0 || o.max_halvings > 20) throw InputError("--max-halvings: must be within 0 .. 20");
  if (scene.steps() * (1L << o.max_halvings) > 1'000'000'000L)
    throw InputError(fmt::format("--max-halvings {}: {} steps at dt / 2^{} pass the cap of 1e9 steps", o.max_halvings,
                                 scene.steps() * (1L << o.max_halvings), o.max_halvings));
  if (o.spec.needs_reference() && !o.reference) throw InputError("match: the spec needs a reference run and none is set");
  MatchResult m;
  m.scene = scene.name, m.scene_source = scene.source, m.scene_class = scene_class_name(scene_class(scene));
  m.n = scene.n(), m.dt = scene.dt, m.spec = o.spec, m.context = context;
  m.shard_index = o.shard.index, m.shard_count = o.shard.count;
  size_t item = 0;
  for (const EngineEntry* e : engines)
    for (const std::string& profile : profiles_for(*e, o.profile)) {
      if (!o.shard.takes(item++)) continue;
      if (interrupt_signal()) break;
      Progress progress(fmt::format("match {} {}", scene.name, run_label(e->info.name, profile)));
      m.outcomes.push_back(Search(scene, *e, profile, o, m).run(progress));
    }
  if (interrupt_signal()) m.interrupted = interrupt_name();
  return m;
}

void print_match(const MatchResult& m, std::optional<double> target) {
  fmt::print("Equal accuracy on {} ({} balls, class {}): {}\n", m.scene, m.n, m.scene_class, m.spec.text());
  fmt::print("cost: the engine's own step time per ball per scene step (dt = {:g} s), median of the found "
             "configuration's runs; engines in another process time their own steps (pipe-inclusive beside it)\n",
             m.dt);
  std::vector<std::string> terms;
  for (const SpecTermDef& d : spec_terms())
    if (m.spec[d.term]) terms.push_back(d.key);
  fmt::print("{:<18} {:<12} {:<28} {:>10} {:>10}", "engine/profile", "spec", "configuration", "cost ns", "pipe ns");
  for (const auto& t : terms) fmt::print(" {:>12}", t);
  fmt::print(" {:>5}\n", "tries");
  for (const MatchOutcome& oc : m.outcomes) {
    const int shown = oc.reached ? oc.found : oc.best;
    const std::string label = run_label(oc.engine, oc.profile);
    if (shown < 0) {
      fmt::print("{:<18} {:<12} {}\n", label, "not reached", "no configuration ran");
      continue;
    }
    const MatchTry& t = m.tries[shown];
    fmt::print("{:<18} {:<12} {:<28} {:>10} {:>10}", label, oc.reached ? "met" : "not reached",
               (oc.reached ? "" : "best: ") + configuration_text(t), oc.reached ? cost_text(oc.cost_ns) : "-",
               oc.reached && oc.cost_pipe_ns ? cost_text(*oc.cost_pipe_ns) : "-");
    for (const auto& k : terms) fmt::print(" {:>12}", figure_text(t.figures.value(k, nlohmann::json())));
    fmt::print(" {:>5}\n", oc.tries);
  }
  // Our solver against the cheapest external engine that met the spec.
  const MatchOutcome* cheapest = cheapest_reached(m, role_name(EngineRole::external));
  // The ratio against --target: none where ours did not meet the spec, 0 where no external did.
  const auto against_target = [&](std::optional<double> ratio) {
    if (!target) return std::string();
    if (!ratio) return fmt::format(" (target {:g}x: not met)", *target);
    if (*ratio == 0) return fmt::format(" (target {:g}x: undecided within the budget)", *target);
    if (*ratio >= *target) return fmt::format(" (target {:g}x: met)", *target);
    return fmt::format(" (target {:g}x: not met, {:.1f}x short)", *target, *target / *ratio);
  };
  for (const MatchOutcome& oc : m.outcomes) {
    if (oc.role != role_name(EngineRole::ours)) continue;
    const std::string label = run_label(oc.engine, oc.profile);
    if (!oc.reached)
      fmt::print("{}: did not meet the spec{}\n", label, against_target(std::nullopt));
    else if (!cheapest)
      fmt::print("{}: {} ns; no external engine met the spec{}\n", label, cost_text(oc.cost_ns), against_target(0.0));
    else
      fmt::print("{}: {:.1f}x cheaper than the cheapest external engine that met the spec ({}, {} ns){}\n", label,
                 cheapest->cost_ns / oc.cost_ns, run_label(cheapest->engine, cheapest->profile),
                 cost_text(cheapest->cost_ns), against_target(cheapest->cost_ns / oc.cost_ns));
  }
  for (const MatchOutcome& oc : m.outcomes) {
    if (oc.command.empty()) continue;
    const std::string label = run_label(oc.engine, oc.profile);
    if (oc.reached)
      fmt::print("  {}: {}\n", label, oc.command);
    else
      fmt::print("  {} not reached ({}; stopped at {}): best {}\n", label, m.tries[oc.best].why_not, oc.stopped,
                 oc.command);
  }
}

}  // namespace ballbench::cli
