#include "match.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

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

std::string run_command(const Scene& scene, const MatchTry& t, bool reference) {
  // A built-in scene by its name, any other by its file; the step in the fewest digits that read
  // back as it (fmt's shortest round trip).
  const bool builtin = scene.source == scenario_dir() + "/" + scene.name + ".toml";
  std::string cmd = fmt::format("ballbench run --scene {} --engine {} --profile {} --dt {}",
                                builtin || scene.source.empty() ? scene.name : scene.source, t.engine, t.profile, t.dt);
  if (!reference) cmd += " --no-reference";
  // Judged at the scene's step times, as the search judged it.
  if (t.halvings > 0) cmd += fmt::format(" --sample-every {}", 1 << t.halvings);
  if (!t.knob.empty()) cmd += fmt::format(" --set {}.{}={}", t.engine, t.knob, json_text(t.value));
  return cmd;
}

// How far a try is from the spec: its worst term's figure over the bound (the bound over the figure
// for a term that must be at least; 1 + the figure for a bound of 0); infinite for a run that did
// not end ok or a term it did not measure.
double miss(const MatchTry& t, const AccuracySpec& spec) {
  if (t.status != RunStatus::ok) return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (const SpecTermDef& d : spec_terms()) {
    const auto& bound = spec[d.term];
    if (!bound) continue;
    const auto f = t.figures.value(d.key, nlohmann::json());
    if (f.is_null()) return std::numeric_limits<double>::infinity();
    const double x = f.get<double>();
    worst = std::max(worst, d.at_least ? (x > 0 ? *bound / x : std::numeric_limits<double>::infinity())
                                       : (*bound > 0 ? x / *bound : 1 + x));
  }
  return worst;
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
        if (tr.met) {
          if (tr.cost_ns < best_cost_) best_cost_ = tr.cost_ns, oc.found = t;
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
    if (shown >= 0) oc.command = run_command(scene_, out_.tries[shown], o_.spec.needs_reference());
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

  Result run_at(const Config& c, int k, double timeout_s, RunOptions r) const {
    Scene s = scene_;
    s.dt = scene_.dt / double(1 << k);
    return o_.isolation.enabled ? run_engine_isolated(s, e_, r, {timeout_s, ""}) : run_engine(s, e_, r);
  }

  int try_config(const Config& c, int k, double budget_left) {
    const auto t0 = Clock::now();
    const Result r = run_at(c, k, std::min(o_.isolation.timeout_s, budget_left), options(c, k));
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
      const Result t = run_at(c, f.halvings, o_.isolation.timeout_s, r);
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

  double budget_left() const {
    return o_.budget_s - std::chrono::duration<double>(Clock::now() - start_).count();
  }
};

std::string cost_text(double ns) { return ns >= 100 ? fmt::format("{:.0f}", ns) : fmt::format("{:.3g}", ns); }

std::string configuration_text(const MatchTry& t) {
  std::string s = t.halvings == 0 ? "dt" : fmt::format("dt/{}", 1 << t.halvings);
  if (!t.knob.empty()) s += fmt::format(", {}={}", t.knob, json_text(t.value));
  return s;
}

std::string figure_text(const nlohmann::json& v) {
  if (v.is_null()) return "-";
  const double x = v.get<double>();
  return x == std::floor(x) && std::abs(x) < 1e9 ? fmt::format("{:.0f}", x) : fmt::format("{:.3g}", x);
}

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

void print_match(const MatchResult& m) {
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
  const MatchOutcome* cheapest = nullptr;
  for (const MatchOutcome& oc : m.outcomes)
    if (oc.reached && oc.role == role_name(EngineRole::external) && (!cheapest || oc.cost_ns < cheapest->cost_ns))
      cheapest = &oc;
  for (const MatchOutcome& oc : m.outcomes) {
    if (oc.role != role_name(EngineRole::ours)) continue;
    const std::string label = run_label(oc.engine, oc.profile);
    if (!oc.reached)
      fmt::print("{}: did not meet the spec\n", label);
    else if (!cheapest)
      fmt::print("{}: {} ns; no external engine met the spec\n", label, cost_text(oc.cost_ns));
    else
      fmt::print("{}: {:.1f}x cheaper than the cheapest external engine that met the spec ({}, {} ns)\n", label,
                 cheapest->cost_ns / oc.cost_ns, run_label(cheapest->engine, cheapest->profile),
                 cost_text(cheapest->cost_ns));
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

nlohmann::json to_json(const MatchResult& m) {
  nlohmann::json tries = nlohmann::json::array(), outcomes = nlohmann::json::array();
  for (const MatchTry& t : m.tries)
    tries.push_back({{"engine", t.engine},       {"profile", t.profile}, {"knob", t.knob},
                     {"value", t.value},         {"halvings", t.halvings}, {"dt", t.dt},
                     {"status", run_status_text(t.status)},       {"error", t.error},   {"met", t.met},
                     {"why_not", t.why_not},     {"figures", t.figures}, {"cost_ns", t.cost_ns},
                     {"cost_pipe_ns", t.cost_pipe_ns ? nlohmann::json(*t.cost_pipe_ns) : nlohmann::json()},
                     {"wall_s", t.wall_s},       {"settings", t.settings}});
  for (const MatchOutcome& o : m.outcomes)
    outcomes.push_back({{"engine", o.engine},       {"profile", o.profile},   {"role", o.role},   {"reached", o.reached},
                        {"found", o.found},         {"best", o.best},         {"tries", o.tries},
                        {"finest_dt", o.finest_dt}, {"cost_repeats", o.cost_repeats}, {"cost_ns", o.cost_ns},
                        {"cost_pipe_ns", o.cost_pipe_ns ? nlohmann::json(*o.cost_pipe_ns) : nlohmann::json()},
                        {"stopped", o.stopped},     {"command", o.command}});
  return {{"kind", "match"},         {"scene", m.scene},     {"scene_source", m.scene_source},
          {"scene_class", m.scene_class}, {"n", m.n},        {"dt", m.dt},
          {"spec", m.spec.to_json()}, {"context", m.context}, {"interrupted", m.interrupted},
          {"shard", {{"index", m.shard_index}, {"count", m.shard_count}}},
          {"tries", tries},          {"outcomes", outcomes}};
}

MatchResult match_from_json(const nlohmann::json& j) {
  if (j.value("kind", "") != "match") throw InputError("not a match result (no \"kind\": \"match\")");
  MatchResult m;
  m.scene = j.at("scene").get<std::string>();
  m.scene_source = j.at("scene_source").get<std::string>();
  m.scene_class = j.at("scene_class").get<std::string>();
  m.n = j.at("n").get<int>();
  m.dt = j.at("dt").get<double>();
  for (const auto& [key, value] : j.at("spec").items()) {
    const auto term = spec_term_named(key);
    if (!term) throw InputError(fmt::format("spec: unknown term '{}'", key));
    m.spec[*term] = value.get<double>();
  }
  m.context = j.at("context");
  m.interrupted = j.at("interrupted").get<std::string>();
  m.shard_index = j.at("shard").at("index").get<int>();
  m.shard_count = j.at("shard").at("count").get<int>();
  const auto opt = [](const nlohmann::json& v) { return v.is_null() ? std::nullopt : std::optional(v.get<double>()); };
  for (const auto& q : j.at("tries")) {
    MatchTry t;
    t.engine = q.at("engine").get<std::string>(), t.profile = q.at("profile").get<std::string>();
    t.knob = q.at("knob").get<std::string>(), t.value = q.at("value");
    t.halvings = q.at("halvings").get<int>(), t.dt = q.at("dt").get<double>();
    t.status = run_status_from_text(q.at("status").get<std::string>()), t.error = q.at("error").get<std::string>();
    t.met = q.at("met").get<bool>(), t.why_not = q.at("why_not").get<std::string>(), t.figures = q.at("figures");
    t.cost_ns = q.at("cost_ns").get<double>(), t.cost_pipe_ns = opt(q.at("cost_pipe_ns"));
    t.wall_s = q.at("wall_s").get<double>(), t.settings = q.at("settings");
    m.tries.push_back(std::move(t));
  }
  for (const auto& q : j.at("outcomes")) {
    MatchOutcome o;
    o.engine = q.at("engine").get<std::string>(), o.profile = q.at("profile").get<std::string>();
    o.role = q.at("role").get<std::string>();
    o.reached = q.at("reached").get<bool>(), o.found = q.at("found").get<int>(), o.best = q.at("best").get<int>();
    o.tries = q.at("tries").get<int>(), o.finest_dt = q.at("finest_dt").get<double>();
    o.cost_repeats = q.at("cost_repeats").get<std::vector<double>>(), o.cost_ns = q.at("cost_ns").get<double>();
    o.cost_pipe_ns = opt(q.at("cost_pipe_ns"));
    o.stopped = q.at("stopped").get<std::string>(), o.command = q.at("command").get<std::string>();
    for (int k : {o.found, o.best})
      if (k >= int(m.tries.size())) throw InputError(fmt::format("outcomes: try {} is not in tries", k));
    m.outcomes.push_back(std::move(o));
  }
  return m;
}

namespace {

std::string match_csv(const MatchResult& m) {
  std::string out = "engine,profile,knob,value,halvings,dt,status,met,cost_ns,cost_pipe_ns,wall_s";
  for (const SpecTermDef& d : spec_terms()) out += fmt::format(",{}", d.key);
  out += ",why_not\n";
  const auto csv_text = [](std::string s) {  // quoted, as RFC 4180
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  for (const MatchTry& t : m.tries) {
    out += fmt::format("{},{},{},{},{},{:.17g},{},{},{:.6g},{},{:.3f}", t.engine, t.profile, t.knob,
                       csv_text(t.value.is_null() ? "" : json_text(t.value)), t.halvings, t.dt, csv_text(run_status_text(t.status)),
                       t.met ? 1 : 0, t.cost_ns, t.cost_pipe_ns ? fmt::format("{:.6g}", *t.cost_pipe_ns) : "", t.wall_s);
    for (const SpecTermDef& d : spec_terms()) {
      const auto v = t.figures.value(d.key, nlohmann::json());
      out += v.is_null() ? "," : fmt::format(",{:.6g}", v.get<double>());
    }
    out += "," + csv_text(t.why_not) + "\n";
  }
  return out;
}

}  // namespace

void write_match_files(const MatchResult& m, const std::string& json_path, const std::string& csv_path) {
  write_file_atomically(json_path, to_json(m).dump(2) + "\n", "the match results");
  write_file_atomically(csv_path, match_csv(m), "the match CSV");
}

MatchResult read_match_file(const std::string& path) {
  return read_json_file(path, "a match result", [](const nlohmann::json& j) { return match_from_json(j); },
                        [](const nlohmann::json&) {
                          MatchResult m;  // the shape of a match file: one try and one outcome, every field set
                          m.tries.emplace_back().cost_pipe_ns = 0;
                          m.outcomes.emplace_back().cost_pipe_ns = 0;
                          return JsonShape{to_json(m), ""};
                        });
}

MatchResult merge_match_shards(const std::vector<MatchResult>& shards, const std::vector<std::string>& names) {
  if (shards.empty()) throw InputError("merge: no shards given");
  const MatchResult& first = shards.front();
  ShardRoll roll(first.shard_count, names);
  MatchResult out = first;
  out.tries.clear(), out.outcomes.clear();
  out.shard_index = out.shard_count = 1;
  out.context["shards"] = nlohmann::json::array();
  for (size_t k = 0; k < shards.size(); ++k) {
    const MatchResult& s = shards[k];
    if (s.scene != first.scene || s.scene_source != first.scene_source || s.spec.to_json() != first.spec.to_json() ||
        s.shard_count != first.shard_count || s.n != first.n || s.dt != first.dt)
      throw InputError(fmt::format("merge: {} is a shard of another match than {} (its scene, spec or shard count "
                                   "differs)",
                                   names[k], names.front()));
    roll.take(k, s.shard_index, s.interrupted);
    out.context["shards"].push_back(s.context);
    const int offset = int(out.tries.size());
    out.tries.insert(out.tries.end(), s.tries.begin(), s.tries.end());
    for (MatchOutcome o : s.outcomes) {
      if (o.found >= 0) o.found += offset;
      if (o.best >= 0) o.best += offset;
      out.outcomes.push_back(std::move(o));
    }
  }
  roll.check_complete();
  return out;
}

}  // namespace ballbench::cli
