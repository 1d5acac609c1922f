#include "match.h"

#include <stdlib.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include "core_affinity.h"
#include "cost_pace.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "isolated_run.h"
#include "machine_info.h"
#include "try_store.h"
#include "json_value.h"
#include "progress.h"
#include "scene_loader.h"
#include "scene_digest.h"
#include "shard_roll.h"
#include "shell_word.h"
#include "spec_verdict.h"
#include "sweep_result.h"

namespace ballbench::cli {

std::optional<WindowShares> window_shares(const Result& res, long steps) {
  if (!res.window_engine_s || !res.window_clock_s || !(*res.window_clock_s > 0)) return std::nullopt;
  const double whole = *res.window_clock_s;
  WindowShares w{steps, {}, *res.window_engine_s / whole};
  for (const double s : res.window_pace) w.pace.push_back(s / whole);
  return w;
}

std::pair<long, double> timed_prefix(const WindowShares& w, double run_s) {
  for (int i = 0; i < int(w.pace.size()); ++i)
    if (w.pace[size_t(i)] * run_s >= kTimedWindowSeconds) return {window_prefix_steps(w.steps, i), w.pace[size_t(i)]};
  return {w.steps, w.share};
}

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

std::string run_command(const Scene& scene, const EngineEntry& e, const MatchTry& t, const MatchOptions& o) {
  // A built-in scene by its name, any other by its file; the step in the fewest digits that read
  // back as it (fmt's shortest round trip).
  const bool builtin = scene.source == scenario_dir() + "/" + scene.name + ".toml";
  std::string cmd = "ballbench run";
  // An engine of the user's own engines file is known only with it.
  if (!e.engines_file.empty()) cmd += " --engines " + shell_word(e.engines_file);
  cmd += fmt::format(" --scene {} --engine {} --profile {} --dt {}",
                     shell_word(builtin || scene.source.empty() ? scene.name : scene.source), t.engine, t.profile, t.dt);
  if (!o.spec.needs_reference()) cmd += " --no-reference";
  if (!o.spec_texts.empty()) cmd += fmt::format(" --spec {}", fmt::join(o.spec_texts, ","));
  // Judged at the scene's step times, as the search judged it.
  if (t.halvings > 0) cmd += fmt::format(" --sample-every {}", 1 << t.halvings);
  if (!t.knob.empty()) cmd += fmt::format(" --set {}.{}={}", t.engine, t.knob, json_text(t.value));
  return cmd;
}

// Where a search stopped at the ceiling: "the ceiling (50x our solver's cost: 36547 ns)".
std::string ceiling_text(double ratio, double ns) {
  return fmt::format("the ceiling ({:g}x our solver's cost: {} ns)", ratio, cost_text(ns));
}

// One run at dt / 2^k, in a child process (a crash or hang is that run's result) unless isolation
// is off.
Result run_at(const Scene& scene, const EngineEntry& e, int k, const Isolation& isolation, double timeout_s,
              const RunOptions& r) {
  Scene s = scene;
  s.dt = scene.dt / double(1 << k);
  return isolation.enabled ? run_engine_isolated(s, e, r, {timeout_s, ""}) : run_engine(s, e, r);
}

// The cheapest configuration met so far by an engine of each role (its CPU time while searching),
// shared by the searches running side by side: each try stops past MatchOptions::within times its
// role's.
class Race {
 public:
  void met(EngineRole role, double ns) {
    std::lock_guard lock(mutex_);
    const auto [it, fresh] = cheapest_.emplace(role, ns);
    if (!fresh) it->second = std::min(it->second, ns);
  }
  std::optional<double> cheapest(EngineRole role) const {
    std::lock_guard lock(mutex_);
    const auto it = cheapest_.find(role);
    return it == cheapest_.end() ? std::nullopt : std::optional(it->second);
  }

 private:
  mutable std::mutex mutex_;
  std::map<EngineRole, double> cheapest_;
};

// What a try's cost limit is: the cheapest configuration of its own search that met (a knob's), the
// match's ceiling, or its role's cheapest in the race.
enum class Bound { knob, ceiling, race };
struct CostBound {
  double ns = 0;  // per ball per scene step
  Bound by = Bound::knob;
};

// One configuration's steps: the range the search may try (dt / 2^first .. dt / 2^last) and the
// tries it made.
struct Ladder {
  int first = 0, last = 0;
  std::map<int, int> tried;  // halvings -> try index
};

class Search {
 public:
  Search(const Scene& scene, const EngineEntry& e, std::string profile, std::vector<Config> configs,
         const MatchOptions& o, Race& race)
      : scene_(scene), e_(e), profile_(std::move(profile)), configs_(std::move(configs)), o_(o), race_(race) {}

  // First the profile as it is, coarse to fine until it meets the spec; then each knob setting from
  // two halvings coarser than that, or than the coarsest step a knob met at where the profile never
  // met (a knob may let a longer step meet it), down to where the profile met it (or to the finest
  // step if it never did: a knob that makes steps cheaper, fewer substeps, may meet finer for less).
  // Each configuration's coarsest step that met is a candidate; the one found is chosen among them
  // once they are timed alone (time_found). Until then oc.found is the cheapest while searching.
  MatchOutcome run() {
    MatchOutcome oc;
    oc.engine = e_.info.name, oc.profile = profile_, oc.role = role_name(e_.info.role);
    int met_at = -1;
    for (size_t c = 0; c < configs_.size() && oc.stop == SearchStop::none; ++c) {
      Ladder l;
      const int from = met_at >= 0 ? met_at : coarsest_met();
      l.first = c == 0 || from < 0 ? 0 : std::max(0, from - 2);
      l.last = c == 0 || met_at < 0 ? o_.max_halvings : met_at;
      const int found = climb(c, l, oc);
      if (c == 0) as_is_ = l;
      if (found >= 0 && c == 0) met_at = tries[found].halvings;
    }
    oc.reached = !candidates.empty();
    if (oc.reached) {
      if (!oc.cut_short()) oc.stop = SearchStop::none, oc.stopped.clear();
    } else if (oc.stop == SearchStop::none && hit_ceiling_) {
      oc.stop = SearchStop::ceiling;
      oc.stopped = ceiling_text(o_.ceiling, *ceiling_ns_);
    } else if (oc.stop == SearchStop::none && hit_race_) {
      oc.stop = SearchStop::outpaced;  // mark_outpaced gives it the race's final figure
      oc.stopped = outpace_text(o_.within, role_name(e_.info.role), std::nullopt);
    } else if (oc.stop == SearchStop::none) {
      oc.stop = SearchStop::finest_step, oc.stopped = fmt::format("dt / 2^{}", o_.max_halvings);
    }
    oc.work = used_;
    return oc;
  }

  // The match's ceiling (ns per ball per scene step): every try of this search stops once its CPU
  // time passes kClearlyCostlier times it.
  void set_ceiling(double ns) { ceiling_ns_ = ns; }

  const EngineEntry& entry() const { return e_; }
  const std::string& profile() const { return profile_; }
  // How much this search is likely to cost against the others, to start the costliest first: its
  // configurations, each a ladder of tries, four times over for an engine whose every run starts a
  // process (EngineInfo::costly_runs: its start and its pipe on every try).
  double expected_work() const { return double(configs_.size()) * (e_.info.costly_runs ? 4.0 : 1.0); }
  // The store key of try `index` of this search.
  nlohmann::json key_of(int index) const {
    const MatchTry& t = tries.at(index);
    return store_key({t.knob, t.value, {}}, t.halvings);
  }
  std::vector<MatchTry> tries;
  // A try that met: the scene file its window starts from, and the window's shares of the run's
  // engine time (a timing runs its timed_prefix).
  struct Window {
    std::string scene;
    WindowShares shares;
  };
  std::map<int, Window> windows;  // by try index
  // Each configuration's coarsest step that met the spec (try indices, in search order).
  std::vector<int> candidates;

 private:
  // The coarsest step any configuration met at so far (halvings), or -1.
  int coarsest_met() const {
    int k = -1;
    for (int t : candidates) k = k < 0 ? tries[t].halvings : std::min(k, tries[t].halvings);
    return k;
  }

  // One configuration's steps: coarse to fine, jumping where the misses predict the step that
  // meets, then back coarser until a step does not meet. The coarsest step that met, or -1.
  int climb(size_t c, Ladder& l, MatchOutcome& oc) {
    int k = l.first, met = -1;
    while (k >= l.first && k <= l.last && oc.stop == SearchStop::none) {
      // A step its coarser try's cost already puts well past where it would stop (the ceiling's, the
      // race's, or clearly costlier than a configuration that met), is not run.
      const auto bound = limit(configs_[c]);
      if (const auto projected = projected_cost_ns(l, k);
          projected && bound && *projected > kCeilingProjectionMargin * bound->ns) {
        l.tried[k] = int(tries.size());
        tries.push_back(projected_over_limit(configs_[c], k, *projected, *bound));
        ++oc.tries;
        note_stop(*bound);
        break;
      }
      if (const double need = double(1L << k); used_ + need > o_.budget_runs) {
        oc.stop = SearchStop::budget;
        oc.stopped = fmt::format("the budget ({:g} runs at dt, {:.3g} ball steps)", o_.budget_runs,
                                 o_.budget_runs * double(scene_.n()) * double(scene_.steps()));
        break;
      }
      const int t = try_config(configs_[c], l, k, bound);
      l.tried[k] = t;
      const MatchTry& tr = tries[t];
      ++oc.tries;
      oc.stored += tr.stored;
      oc.finest_dt = oc.finest_dt > 0 ? std::min(oc.finest_dt, tr.dt) : tr.dt;
      if (interrupt_signal()) oc.stop = SearchStop::interrupt, oc.stopped = "an interrupt";
      if (tr.status == RunStatus::over_cost && bound) note_stop(*bound);
      // A knob whose run is the profile's own, bit for bit, changes nothing here (a stiffness on
      // a path that has none): it is never a finding, at any step.
      // (Whole runs only: two runs stopped where they missed are equal only up to that step.)
      if (c == 0 && tr.status == RunStatus::ok) as_is_trajectory_[k] = last_trajectory_;
      if (const auto as_is = as_is_trajectory_.find(k); c > 0 && tr.status == RunStatus::ok &&
                                                       !last_trajectory_.empty() && as_is != as_is_trajectory_.end() &&
                                                       as_is->second == last_trajectory_)
        return -1;
      if (tr.met) {
        race_.met(e_.info.role, tr.cost_ns);
        met = t;
        if (k - 1 >= l.first && !l.tried.count(k - 1)) {  // a jump passed over it: confirm coarser
          --k;
          continue;
        }
        break;
      }
      if (oc.best < 0 || miss(tr, o_.spec) < miss(tries[oc.best], o_.spec)) oc.best = t;
      if (met >= 0) break;  // coarser than one that met, and not met: that one is the step
      // Finer will not do better: refused, hung, or already clearly costlier than what met.
      if (tr.status == RunStatus::unsupported || tr.status == RunStatus::timed_out || tr.status == RunStatus::over_cost)
        break;
      k = next_step(l, k);
    }
    if (met >= 0) {
      candidates.push_back(met);
      oc.found = cheapest_met();
    }
    return met;
  }

  // The cost (ns per ball per scene step) of a whole run at dt / 2^k, from the finest completed or
  // missed try of this configuration before it: its CPU time projected to its whole run
  // (whole_run_cost), twice per halving since.
  std::optional<double> projected_cost_ns(const Ladder& l, int k) const {
    for (auto it = l.tried.rbegin(); it != l.tried.rend(); ++it) {
      if (it->first >= k) continue;
      const MatchTry& t = tries[it->second];
      if ((t.status != RunStatus::ok && t.status != RunStatus::missed) || !(t.cost_ns > 0)) return std::nullopt;
      const auto whole = whole_run_cost(t.cost_ns, t.done, pace_for(l, it->first));
      if (!whole) return std::nullopt;
      return *whole * double(1L << (k - it->first));
    }
    return std::nullopt;
  }

  // A try not run: its projected cost is past its limit.
  MatchTry projected_over_limit(const Config& c, int k, double projected_ns, const CostBound& bound) const {
    MatchTry t;
    t.engine = e_.info.name, t.profile = profile_, t.knob = c.knob, t.value = c.value;
    t.halvings = k, t.dt = scene_.dt / double(1 << k);
    t.status = RunStatus::over_cost, t.done = 0, t.work = 0;
    t.why_not = t.error =
        fmt::format("over cost: not run, its coarser try projects {} ns, past {:g}x where its run would stop ({} ns, "
                    "{})",
                    cost_text(projected_ns), kCeilingProjectionMargin, cost_text(bound.ns), bound_text(bound));
    return t;
  }

  // The next step after a try at k that did not meet: k + 1, or where two completed tries of this
  // configuration predict the miss falls to 1 (its log against the step's, a straight line).
  int next_step(const Ladder& l, int k) const {
    if (k >= l.last) return k + 1;  // the ladder's finest step: none after it
    const MatchTry& b = tries[l.tried.at(k)];
    const double mb = miss(b, o_.spec);
    for (auto it = l.tried.rbegin(); it != l.tried.rend(); ++it) {
      if (it->first >= k) continue;
      const MatchTry& a = tries[it->second];
      const double ma = miss(a, o_.spec);
      if (a.status != RunStatus::ok || b.status != RunStatus::ok || !std::isfinite(ma) || !std::isfinite(mb) ||
          mb <= 1 || ma <= mb)
        return k + 1;
      const double per_halving = std::log2(ma / mb) / double(k - it->first);
      const int jump = int(std::ceil(std::log2(mb) / per_halving - 1e-9));
      return std::clamp(k + jump, k + 1, l.last);
    }
    return k + 1;
  }

  // The pace a try of ladder l at dt / 2^k is projected with (nearest_pace).
  const CostPace* pace_for(const Ladder& l, int k) const {
    return nearest_pace(l.tried, as_is_.tried, paces_, k, pace_ ? &*pace_ : nullptr);
  }

  RunOptions options(const Config& c, const Ladder& l, int k, int index, const std::optional<CostBound>& bound) const {
    RunOptions r;
    r.profile = profile_;
    r.overrides = c.overrides;
    // Every configuration is judged at the scene's own step times (tunnelling at every step).
    r.metrics.sample_every = 1 << k;
    r.series_points = 0;
    // The profile as it is at the scene's own step runs to its end (or its cost limit), whatever it
    // misses: its engine time along the scene is the pace every later try is projected with
    // (cost_pace.h).
    const bool pace_run = c.knob.empty() && k == 0;
    r.stop_on_miss = pace_run ? nullptr : &o_.spec;
    r.record_pace = true;  // every try's, for the tries after it (pace_for)
    r.cost_limit = cost_limit(bound, pace_run ? nullptr : pace_for(l, k));
    if (o_.spec.needs_reference()) r.reference = o_.reference, r.converged_reference = o_.converged_reference;
    // The window a found configuration is timed over: from the middle of its run, at a scene step.
    const long steps = scene_.steps() << k;
    r.window.start = std::max(1L, (steps / 2) >> k << k);
    r.window.steps = std::clamp(std::max(long(double(steps) * kWindowFraction), kMinWindowSteps), 1L,
                                std::max(1L, steps - r.window.start));
    r.window.checkpoint = checkpoint_path(index);
    return r;
  }

  // A knob's run stops once it costs as much as the cheapest configuration that met so far: a knob,
  // later in search order, is found over it only below kKnobCostMargin of its cost, and CPU time's
  // noise between two tries stays short of the 18% between. Any run stops at kClearlyCostlier times
  // the search's ceiling, and at kClearlyCostlier times `within` times the cheapest configuration
  // that met for an engine of its role so far. All are costs per ball per scene step, over the whole
  // run here; the lowest binds (a knob's, where two are equal).
  std::optional<CostBound> limit(const Config& c) const {
    std::optional<CostBound> b;
    const auto take = [&](std::optional<double> ns, Bound by) {
      if (ns && (!b || *ns < b->ns)) b = CostBound{*ns, by};
    };
    if (const int cheapest = cheapest_met(); !c.knob.empty() && cheapest >= 0)
      take(tries[cheapest].cost_ns, Bound::knob);
    if (ceiling_ns_) take(kClearlyCostlier * *ceiling_ns_, Bound::ceiling);
    if (const auto rival = race_.cheapest(e_.info.role); rival && o_.within > 0)
      take(kClearlyCostlier * o_.within * *rival, Bound::race);
    return b;
  }
  std::string bound_text(const CostBound& b) const {
    switch (b.by) {
      case Bound::knob: return "the cost of the cheapest configuration that met";
      case Bound::ceiling:
        return fmt::format("{:g}x the match's ceiling of {:g}x our solver's cost", kClearlyCostlier, o_.ceiling);
      case Bound::race:
        return fmt::format("{:g}x the cheapest {} configuration met so far ({:g} x --within {:g})",
                           kClearlyCostlier * o_.within, role_name(e_.info.role), kClearlyCostlier, o_.within);
    }
    return "";
  }
  // A try stopped at the ceiling or in the race: the search's outcome says which, where it met nothing.
  void note_stop(const CostBound& b) {
    if (b.by == Bound::ceiling) hit_ceiling_ = true;
    if (b.by == Bound::race) hit_race_ = true;
  }
  std::optional<RunOptions::CostLimit> cost_limit(const std::optional<CostBound>& b, const CostPace* pace) const {
    if (!b) return std::nullopt;
    RunOptions::CostLimit l{b->ns * 1e-9 * double(std::max(1, scene_.n())) * double(std::max(1L, scene_.steps())),
                            bound_text(*b), pace ? std::optional(*pace) : std::nullopt};
    if (b->by != Bound::knob) l.linear_margin = kPaceRunLinearMargin;
    return l;
  }
  // The candidate cheapest while searching (its CPU time beside the other searches), or -1.
  int cheapest_met() const {
    int best = -1;
    for (int t : candidates)
      if (best < 0 || tries[t].cost_ns < tries[best].cost_ns) best = t;
    return best;
  }

  // What decides a try's outcome: its key in the results store.
  nlohmann::json store_key(const Config& c, int k) const {
    return {{"kind", "try"},        {"scene", o_.scene_digest}, {"engine", e_.info.name},
            {"version", e_.info.version}, {"profile", profile_}, {"knob", c.knob},
            {"value", c.value},     {"halvings", k},            {"spec", o_.spec.to_json()},
            {"reference", o_.spec.needs_reference() && o_.reference ? o_.reference->info.name : ""},
            {"build", build_id()}};
  }

  // A try of configuration c at dt / 2^k: read from the store where an earlier search measured it
  // (an over-cost stop only under a limit no higher than the one it stopped at), else run.
  int try_config(const Config& c, const Ladder& l, int k, const std::optional<CostBound>& bound) {
    const int index = int(tries.size());
    const RunOptions r = options(c, l, k, index, bound);
    const nlohmann::json key = store_key(c, k);
    const auto kept = o_.store ? o_.store->find(key) : std::nullopt;
    const bool reusable =
        kept && (kept->at("try").at("status") != run_status_text(RunStatus::over_cost) ||
                 (r.cost_limit && r.cost_limit->seconds <= kept->value("cost_limit_s", 0.0)));
    MatchTry t;
    if (reusable) {
      t = match_try_from_json(kept->at("try"));
      t.stored = true;
      // Measured under a higher limit or none: what this limit would have done to it. Under the same
      // limit it stands as it ran (its last steps may pass the limit between two of the run's checks).
      const double run_s = t.cost_ns * 1e-9 * double(std::max(1, scene_.n())) * double(std::max(1L, scene_.steps()));
      const auto ran_under = kept->contains("cost_limit_s") ? std::optional(kept->at("cost_limit_s").get<double>())
                                                            : std::nullopt;
      if (r.cost_limit && t.status == RunStatus::ok && run_s > r.cost_limit->seconds &&
          (!ran_under || r.cost_limit->seconds < *ran_under)) {
        t.status = RunStatus::over_cost, t.met = false, t.work = 0;
        t.why_not = t.error = fmt::format("over cost: its engine time of {:.3g} s passes {:.3g} s, {}", run_s,
                                          r.cost_limit->seconds, r.cost_limit->what);
      }
      last_trajectory_ = kept->value("trajectory", "");
      if (kept->contains("pace")) take_pace(index, kept->at("pace").get<std::vector<double>>(), c.knob.empty() && k == 0);
      if (kept->contains("window")) {
        const nlohmann::json& w = kept->at("window");
        write_file_atomically(r.window.checkpoint, w.at("scene").get<std::string>(), "the window's scene");
        windows[index] = {r.window.checkpoint,
                          {r.window.steps, w.at("pace").get<std::vector<double>>(), w.at("share").get<double>()}};
      }
    } else {
      t = run_try(c, k, r, index);
    }
    used_ += t.work;
    tries.push_back(std::move(t));
    return index;
  }

  MatchTry run_try(const Config& c, int k, const RunOptions& r, int index) {
    const auto t0 = Clock::now();
    const Result res = run_at(scene_, e_, k, o_.isolation, o_.isolation.timeout_s, r);
    MatchTry t;
    t.engine = e_.info.name, t.profile = profile_, t.knob = c.knob, t.value = c.value;
    t.halvings = k, t.dt = scene_.dt / double(1 << k);
    t.status = res.status, t.error = res.error;
    t.settings = res.settings;
    const SpecVerdict v = judge(o_.spec, res);
    t.met = v.met, t.why_not = v.why_not, t.figures = v.figures;
    // Judged against each other while searching (possibly beside other searches): the engine's CPU time.
    t.cost_ns = cost_per_scene_step(res.cost_s(), scene_);
    if (res.engine_process_s) t.cost_pipe_ns = cost_per_scene_step(res.engine_s, scene_);
    t.wall_s = std::chrono::duration<double>(Clock::now() - t0).count();
    t.done = res.steps > 0 ? double(res.steps_done) / double(res.steps) : 1.0;
    // The budget is charged the ball steps the engine took to a run's end, or to where it missed or
    // diverged: what its states decided. A run a cost limit stopped is charged nothing: where the
    // clock stopped it depends on the machine's load (on a settled pile, a knob's run stopped at 6%
    // beside another job and at 89% alone), and the tries a budget leaves room for must not; its
    // limit bounds it. A run the wall clock ended (hung, timed out) or the user interrupted is charged
    // in full.
    const bool decided_by_states = res.status == RunStatus::ok || res.status == RunStatus::missed ||
                                   res.status == RunStatus::diverged || res.status == RunStatus::failed ||
                                   res.status == RunStatus::unsupported;
    t.work = res.status == RunStatus::over_cost ? 0.0 : double(1L << k) * (decided_by_states ? t.done : 1.0);
    last_trajectory_ = res.checksum_trajectory;
    nlohmann::json kept{{"try", to_json(t)}, {"trajectory", last_trajectory_}};
    if (take_pace(index, res.pace, c.knob.empty() && k == 0)) kept["pace"] = res.pace;
    std::error_code ec;
    if (const auto w = window_shares(res, r.window.steps); t.met && w) {
      windows[index] = {r.window.checkpoint, *w};
      kept["window"] = {{"scene", read_text_file(r.window.checkpoint)}, {"pace", w->pace}, {"share", w->share}};
    } else {
      std::filesystem::remove(r.window.checkpoint, ec);
    }
    if (r.cost_limit) kept["cost_limit_s"] = r.cost_limit->seconds;
    // What the clock or the user ended is not kept: another search would not end it alike.
    const bool keep = decided_by_states || res.status == RunStatus::over_cost;
    if (o_.store && keep && !interrupt_signal()) o_.store->keep(store_key(c, k), kept);
    return t;
  }

  // Try `index`'s pace, as far as it ran, and the engine's where it is the profile's run at the
  // scene's step. False: the try gave none (it stopped before kPaceFrom of its steps).
  bool take_pace(int index, const std::vector<double>& seconds, bool pace_run) {
    const auto p = CostPace::from_points(seconds);
    if (!p) return false;
    paces_[index] = *p;
    if (pace_run) pace_ = *p;
    return true;
  }

  std::string checkpoint_path(int index) const {
    return fmt::format("{}/{}-{}-{}.toml", o_.work_dir, e_.info.name, profile_, index);
  }

  const Scene& scene_;
  const EngineEntry& e_;
  std::string profile_;
  std::vector<Config> configs_;
  const MatchOptions& o_;
  Race& race_;
  double used_ = 0;                              // work so far, in runs of the scene at dt
  std::optional<double> ceiling_ns_;             // MatchOptions::ceiling times our solver's cost
  std::optional<CostPace> pace_;                 // the engine's pace on the scene (cost_pace.h)
  std::map<int, CostPace> paces_;                // each try's, by try index
  Ladder as_is_;                                 // the profile as it is: its tries
  bool hit_ceiling_ = false;                     // a try stopped at the ceiling
  bool hit_race_ = false;                        // a try stopped past its role's cheapest (MatchOptions::within)
  std::string last_trajectory_;                  // the last try's trajectory checksum
  std::map<int, std::string> as_is_trajectory_;  // the profile as it is: halvings -> its checksum
};

// A configuration's cost from its timing's repeats: the fastest. What else runs on the machine (a job
// beside it, the host's other guests on a core) only ever adds time, and the cores of a shared host
// differ by a quarter: the median of three repeats reads whichever core two of them landed on, the
// fastest of them spread over the cores reads the same on an idle or a loaded machine.
double fastest_repeat(const std::vector<double>& repeats) {
  return repeats.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::min_element(repeats.begin(), repeats.end());
}

// A configuration to time alone: its try, its store key and the window its run saved; what the
// timing measured.
struct Timed {
  int index = -1;  // the try's, in its search
  const MatchTry* t = nullptr;
  nlohmann::json key;
  const Search::Window* w = nullptr;
  std::vector<double> repeats, pipe;  // ns per ball per scene step; pipe-inclusive for an engine in another process
  bool stored = false;
};

// A timing's key in the results store: the try it times, the repeats and the machine (a cost is a
// measurement of this machine).
nlohmann::json timing_key(const Timed& s, const MatchOptions& o) {
  return {{"kind", "timing"}, {"try", s.key}, {"repeats", o.repeats}, {"cpu", machine_info().cpu}};
}

// A configuration being timed: its window's scene, run options and share of the run, and its
// repeats so far.
struct Running {
  Timed* s;
  Scene window;
  RunOptions r;
  double share = 0;
  double timed_s = 0;  // engine time so far
  bool failed = false;
};

// The subjects whose timing is not in the store and whose window ran (or that are timed_whole): each
// to be timed, warm (RunOptions::passes).
std::vector<Running> to_time(std::vector<Timed>& subjects, const Scene& scene, const MatchOptions& o) {
  std::vector<Running> running;
  for (Timed& s : subjects) {
    if (const auto kept = o.store ? o.store->find(timing_key(s, o)) : std::nullopt) {
      s.repeats = kept->at("cost_repeats").get<std::vector<double>>();
      if (kept->contains("pipe")) s.pipe = kept->at("pipe").get<std::vector<double>>();
      s.stored = true;
      continue;
    }
    RunOptions r;
    r.profile = s.t->profile;
    if (!s.t->knob.empty()) r.overrides = {{s.t->knob, s.t->value}};
    r.series_points = 0;
    r.passes = kTimingPasses;
    // The sampled metrics at the end only: a timing judges nothing, and the harness's work beside
    // each step would fill the caches the engine's next step finds.
    const auto sample_at_end = [](long steps) { return int(std::clamp<long>(steps, 1, std::numeric_limits<int>::max())); };
    const double run_s = s.t->cost_ns * 1e-9 * double(scene.n()) * double(scene.steps());
    if (timed_whole(run_s)) {
      Scene whole = scene;
      whole.dt = scene.dt / double(1 << s.t->halvings);
      r.metrics.sample_every = sample_at_end(whole.steps());
      running.push_back({&s, whole, r, 1.0});
      continue;
    }
    if (!s.w || !(s.w->shares.share > 0)) continue;
    const auto [steps, share] = timed_prefix(s.w->shares, run_s);
    r.steps = steps;
    r.metrics.sample_every = sample_at_end(steps);
    running.push_back({&s, load_scene_file(s.w->scene), r, share});
  }
  return running;
}

// Rounds of one repeat of each window in turn, each round on the next core, until each has its
// repeats (an engine in a process of its own: a fresh process each, its speed differing from one
// process to the next; any other: more while its repeats hold under kTimedSeconds).
void time_rounds(std::vector<Running>& running, const Scene& scene, const EngineEntry& e, const MatchOptions& o) {
  // A repeat of an engine in a process of its own starts that process (Node's start and its
  // compilations, half a second, for a window of milliseconds): --repeats of them.
  const int most = e.info.own_process && o.isolation.enabled ? o.repeats : kTimingRepeatsFactor * o.repeats;
  const auto more = [&](const Running& x) {
    const int rep = int(x.s->repeats.size());
    return !x.failed && (rep < o.repeats || (x.timed_s < kTimedSeconds && rep < most));
  };
  IsolationOptions fresh{o.isolation.timeout_s, ""};
  fresh.fresh_process = true;
  const std::vector<int> cores = allowed_cores();
  bool any = true;
  for (size_t round = 0; any && !interrupt_signal(); ++round) {
    any = false;
    fresh.core = cores.empty() ? -1 : cores[round % cores.size()];
    for (Running& x : running) {
      if (!more(x) || interrupt_signal()) continue;
      any = true;
      const Result t = o.isolation.enabled ? run_engine_isolated(x.window, e, x.r, fresh) : [&] {
        const CorePin pin(fresh.core);
        return run_engine(x.window, e, x.r);
      }();
      if (t.status != RunStatus::ok || t.steps_done < 1) {
        x.failed = true;
        continue;
      }
      // CPU time, as while searching: another job on the cores changes it less than the wall time
      // (10-25% on this 2-core VM, with what the other job runs), and an engine on several threads
      // is charged for each.
      const auto whole = [&](double window_s) { return cost_per_scene_step(window_s / x.share, scene); };
      // A repeat's figure: the mean of its warm passes (Result::warm), else its one pass.
      x.timed_s += t.warm ? t.warm->count * t.warm->cost_s : t.cost_s();
      x.s->repeats.push_back(whole(t.warm ? t.warm->cost_s : t.cost_s()));
      if (t.engine_process_s) x.s->pipe.push_back(whole(t.warm ? t.warm->engine_s : t.engine_s));
    }
  }
}

// Configurations of one engine timed alone: each window, from the state its run saved there, run
// warm in turn (one repeat of each, then the next: a change in the machine's load falls on all
// alike), `repeats` times or more, each scaled by its window's share of its run's engine time (cost
// per ball per scene step of the whole run). Each round runs on the next core (core_affinity.h),
// and a configuration's cost is its fastest repeat (fastest_repeat). A timing kept in the store is
// read, not run. Where no window ran ok, the try's own cost stands.
void time_alone(std::vector<Timed>& subjects, const Scene& scene, const EngineEntry& e, const MatchOptions& o) {
  std::vector<Running> running = to_time(subjects, scene, o);
  time_rounds(running, scene, e, o);
  for (const Running& x : running)
    if (o.store && int(x.s->repeats.size()) >= o.repeats && !interrupt_signal()) {
      nlohmann::json kept{{"cost_repeats", x.s->repeats}};
      if (!x.s->pipe.empty()) kept["pipe"] = x.s->pipe;
      o.store->keep(timing_key(*x.s, o), kept);
    }
  for (Timed& s : subjects)
    if (s.repeats.empty()) {
      s.repeats = {s.t->cost_ns};
      if (s.t->cost_pipe_ns) s.pipe = {*s.t->cost_pipe_ns};
    }
}

// A folder of this match's own for the windows' scene files, removed with everything in it.
class WorkDir {
 public:
  WorkDir() : path(make_work_folder("ballbench-match")) {}
  ~WorkDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  WorkDir(const WorkDir&) = delete;
  WorkDir& operator=(const WorkDir&) = delete;
  std::string path;
};

}  // namespace

namespace {

void check_match_options(const Scene& scene, const MatchOptions& options) {
  if (options.max_halvings < 0 || options.max_halvings > 20) throw InputError("--max-halvings: must be within 0 .. 20");
  if (scene.steps() * (1L << options.max_halvings) > 1'000'000'000L)
    throw InputError(fmt::format("--max-halvings {}: {} steps at dt / 2^{} pass the cap of 1e9 steps",
                                 options.max_halvings, scene.steps() * (1L << options.max_halvings),
                                 options.max_halvings));
  if (options.spec.needs_reference() && !options.reference)
    throw InputError("match: the spec needs a reference run and none is set");
  if (!(options.budget_runs > 0)) throw InputError("--budget: must be above 0");
  if (options.jobs < 1) throw InputError("--jobs: must be at least 1");
}

MatchResult match_header(const Scene& scene, const MatchOptions& o, const nlohmann::json& context) {
  MatchResult m;
  m.scene = scene.name, m.scene_source = scene.source, m.scene_class = scene_class_name(scene_class(scene));
  m.use_case = scene.use_case;
  m.scene_digest = o.scene_digest;
  m.n = scene.n(), m.dt = scene.dt, m.spec = o.spec, m.context = context;
  m.budget_runs = o.budget_runs, m.run_ball_steps = long(scene.n()) * scene.steps();
  m.within = o.within;
  m.shard_index = o.shard.index, m.shard_count = o.shard.count;
  return m;
}

// The searches of one match, with what became of each.
struct SearchPlan {
  std::unique_ptr<Race> race = std::make_unique<Race>();  // shared by the searches (they hold it)
  std::vector<std::unique_ptr<Search>> searches;
  std::vector<bool> taken;  // this shard's own (the others only search to set the ceiling)
  std::vector<bool> first;  // sets the ceiling: searched before the rest
  std::vector<bool> timed;  // its found configuration timed alone (time_found)
  std::vector<std::optional<MatchOutcome>> outcomes;
  std::vector<std::string> every;  // every search of the match, "engine/profile", whichever shard runs it
};

// The searches, dealt out to the shards; each engine's configurations read here, in this thread
// (building an engine to read its settings), before any search starts. Under a ceiling, our
// solver's default profile searches first (in every shard: the ceiling is a multiple of it).
SearchPlan plan_searches(const Scene& scene, const std::vector<const EngineEntry*>& engines, const MatchOptions& o) {
  SearchPlan plan;
  size_t item = 0;
  for (const EngineEntry* e : engines)
    for (const std::string& profile : profiles_for(*e, o.profile)) {
      plan.every.push_back(e->info.name + "/" + profile);
      const bool takes = o.shard.takes(item++);
      const bool sets_ceiling = o.ceiling > 0 && e->info.role == EngineRole::ours && profile == e->info.profiles.front();
      if (!takes && !sets_ceiling) continue;
      plan.searches.push_back(
          std::make_unique<Search>(scene, *e, profile, configs_for(scene, *e, profile, o.knobs), o, *plan.race));
      plan.taken.push_back(takes), plan.first.push_back(sets_ceiling);
    }
  if (o.ceiling > 0 && std::find(plan.first.begin(), plan.first.end(), true) == plan.first.end())
    throw InputError("--ceiling: a multiple of our solver's cost, and our solver (home) is not among --engine");
  plan.outcomes.resize(plan.searches.size());
  plan.timed.resize(plan.searches.size());
  return plan;
}

// Runs the searches of one phase, `o.jobs` at once: those that set the ceiling, or the rest.
void run_phase(SearchPlan& plan, bool setting_ceiling, const MatchOptions& o, Progress& progress, size_t& done) {
  std::vector<size_t> items;
  for (size_t i = 0; i < plan.searches.size(); ++i)
    if (plan.first[i] == setting_ceiling) items.push_back(i);
  // The costliest first, so that the last to finish is a short one and no core waits at the end
  // (longest processing time first). What a search finds never depends on when it ran; which tries
  // an outpaced engine runs does (Race), what is found for it does not (mark_outpaced).
  std::stable_sort(items.begin(), items.end(), [&](size_t a, size_t b) {
    return plan.searches[a]->expected_work() > plan.searches[b]->expected_work();
  });
  std::mutex done_mutex;
  std::atomic<size_t> next{0};
  const auto worker = [&] {
    for (size_t n = next++; n < items.size() && !interrupt_signal(); n = next++) {
      const auto t0 = std::chrono::steady_clock::now();
      Search& s = *plan.searches[items[n]];
      MatchOutcome oc = s.run();
      const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::lock_guard lock(done_mutex);
      ++done;
      if (!o.quiet)
        progress.count(done, plan.searches.size(),
                       fmt::format("{}: {}, {} {} in {:.0f} s", run_label(s.entry().info.name, s.profile()),
                                   oc.reached ? "met at " + configuration_text(s.tries[oc.found])
                                   : oc.stopped.empty() ? "not met"
                                                        : "not met: stopped at " + oc.stopped,
                                   oc.tries, oc.tries == 1 ? "try" : "tries", took));
      plan.outcomes[items[n]] = std::move(oc);
    }
  };
  std::vector<std::thread> team;
  for (int j = 1; j < std::min<int>(o.jobs, int(items.size())); ++j) team.emplace_back(worker);
  worker();
  for (auto& t : team) t.join();
}

// Search i's configuration found, once: of the configurations that met, those within
// kClearlyCostlier of the cheapest while searching are timed alone (time_alone: after an
// interrupt, their own runs' costs), and the first in search order that costs less than the
// cheapest of them over kKnobCostMargin is found; the others are named beside it.
void time_found(SearchPlan& plan, size_t i, const Scene& scene, const MatchOptions& o) {
  MatchOutcome& oc = *plan.outcomes[i];
  if (!oc.reached || plan.timed[i]) return;
  Search& s = *plan.searches[i];
  double cheapest = std::numeric_limits<double>::infinity();
  for (int t : s.candidates) cheapest = std::min(cheapest, s.tries[t].cost_ns);
  std::vector<Timed> subjects;
  for (int t : s.candidates)
    if (s.tries[t].cost_ns <= kClearlyCostlier * cheapest) {
      Timed& x = subjects.emplace_back();
      x.index = t, x.t = &s.tries[t], x.key = s.key_of(t);
      if (const auto w = s.windows.find(t); w != s.windows.end()) x.w = &w->second;
    }
  time_alone(subjects, scene, s.entry(), o);
  double least = std::numeric_limits<double>::infinity();
  for (const Timed& x : subjects) least = std::min(least, fastest_repeat(x.repeats));
  const auto pick = std::find_if(subjects.begin(), subjects.end(),
                                 [&](const Timed& x) { return fastest_repeat(x.repeats) * kKnobCostMargin <= least; });
  oc.found = pick->index;
  oc.cost_repeats = pick->repeats, oc.cost_ns = fastest_repeat(pick->repeats);
  oc.cost_pipe_ns = pick->pipe.empty() ? std::nullopt : std::optional(fastest_repeat(pick->pipe));
  oc.timing_stored = pick->stored;
  oc.also_met.clear();
  for (const Timed& x : subjects)
    if (x.index != pick->index) oc.also_met.push_back({x.index, fastest_repeat(x.repeats)});
  plan.timed[i] = true;
}

// The ceiling from our solver's cheapest configuration found, timed alone (the cost the report
// shows beside it: "over 80x" is 80 times that); where it met nothing, nothing is a multiple of its
// cost: no ceiling.
void set_ceiling(SearchPlan& plan, const Scene& scene, const MatchOptions& o, MatchResult& m) {
  std::optional<double> ours;
  for (size_t i = 0; i < plan.searches.size(); ++i)
    if (plan.first[i] && plan.outcomes[i] && plan.outcomes[i]->reached) {
      time_found(plan, i, scene, o);
      const double ns = plan.outcomes[i]->cost_ns;
      ours = ours ? std::min(*ours, ns) : ns;
    }
  if (!ours) return;
  m.ceiling = o.ceiling, m.ceiling_ns = o.ceiling * *ours;
  for (auto& s : plan.searches) s->set_ceiling(m.ceiling_ns);
}

// Every search's tries in the order of the searches; each found configuration timed alone.
void gather(SearchPlan& plan, const Scene& scene, const MatchOptions& o, MatchResult& m) {
  for (size_t i = 0; i < plan.searches.size(); ++i) {
    if (!plan.taken[i]) continue;  // another shard's
    Search& s = *plan.searches[i];
    if (!plan.outcomes[i]) {  // interrupted before it started: its row says so
      MatchOutcome oc;
      oc.engine = s.entry().info.name, oc.profile = s.profile(), oc.role = role_name(s.entry().info.role);
      oc.stop = SearchStop::interrupt, oc.stopped = "an interrupt, before it started";
      m.outcomes.push_back(std::move(oc));
      continue;
    }
    time_found(plan, i, scene, o);
    MatchOutcome oc = std::move(*plan.outcomes[i]);
    if (oc.reached && !oc.cut_short() && m.ceiling_ns > 0 && oc.cost_ns > m.ceiling_ns) {
      oc.stop = SearchStop::ceiling;
      oc.stopped = fmt::format("{}, met at {} ns", ceiling_text(o.ceiling, m.ceiling_ns), cost_text(oc.cost_ns));
    }
    const int shown = oc.reached ? oc.found : oc.best;
    if (shown >= 0) oc.command = run_command(scene, s.entry(), s.tries[shown], o);
    oc.shift_tries(int(m.tries.size()));
    m.tries.insert(m.tries.end(), s.tries.begin(), s.tries.end());
    m.outcomes.push_back(std::move(oc));
  }
  mark_outpaced(m);
}

}  // namespace

MatchResult run_match(const Scene& scene, const std::vector<const EngineEntry*>& engines, const MatchOptions& options,
                      const nlohmann::json& context) {
  check_match_options(scene, options);
  WorkDir work;
  MatchOptions o = options;
  o.work_dir = work.path;
  o.scene_digest = scene_digest(scene);  // what the store keys it by
  if (!o.isolation.enabled) o.jobs = 1;  // engines in this process run one at a time
  MatchResult m = match_header(scene, o, context);
  SearchPlan plan = plan_searches(scene, engines, o);
  m.searches = plan.every;
  Progress progress(fmt::format("match {} ({} searches, {} at once)", scene.name, plan.searches.size(),
                                std::min<size_t>(o.jobs, plan.searches.size())));
  size_t done = 0;
  run_phase(plan, true, o, progress, done);
  if (o.ceiling > 0) set_ceiling(plan, scene, o, m);
  run_phase(plan, false, o, progress, done);
  gather(plan, scene, o, m);
  if (interrupt_signal()) m.interrupted = interrupt_name();
  return m;
}

namespace {

// One line per engine and profile: met or not, the configuration, its cost and figures.
void print_match_rows(const MatchResult& m) {
  std::vector<std::string> terms;
  for (const SpecTermDef& d : spec_terms())
    if (m.spec[d.term]) terms.push_back(d.key);
  fmt::print("{:<18} {:<12} {:<28} {:>14} {:>10}", "engine/profile", "spec", "configuration", "cost ns", "pipe ns");
  for (const auto& t : terms) fmt::print(" {:>12}", t);
  fmt::print(" {:>5} {:>6}\n", "tries", "stored");
  for (const MatchOutcome& oc : m.outcomes) {
    const int shown = oc.reached ? oc.found : oc.best;
    const std::string label = run_label(oc.engine, oc.profile);
    if (shown < 0) {
      fmt::print("{:<18} {:<12} {}\n", label, "not reached",
                 oc.stop == SearchStop::interrupt ? "interrupted before it started" : "no configuration ran");
      continue;
    }
    const MatchTry& t = m.tries[shown];
    fmt::print("{:<18} {:<12} {:<28} {:>14} {:>10}", label,
               oc.cut_short()                    ? "cut short"
               : oc.stop == SearchStop::ceiling ? "over ceiling"
               : oc.stop == SearchStop::outpaced ? "outpaced"
               : oc.reached                     ? "met"
                                                : "not reached",
               (oc.reached ? "" : "best: ") + configuration_text(t), oc.reached ? cost_spread_text(oc) : "-",
               oc.reached && oc.cost_pipe_ns ? cost_text(*oc.cost_pipe_ns) : "-");
    for (const auto& k : terms) fmt::print(" {:>12}", figure_text(t.figures.value(k, nlohmann::json())));
    fmt::print(" {:>5} {:>6}\n", oc.tries, oc.stored);
  }
  for (const MatchOutcome& oc : m.outcomes) {
    if (oc.cut_short())
      fmt::print("{}: cut short: it met the spec, but its search stopped at {} before trying every "
                 "configuration; its cost is an upper bound, not ranked\n",
                 run_label(oc.engine, oc.profile), oc.stopped);
    if (oc.over_ceiling())
      fmt::print("{}: over the ceiling: it met the spec, but its cost timed alone is past {}; not ranked\n",
                 run_label(oc.engine, oc.profile), oc.stopped);
    if (oc.stop == SearchStop::outpaced)
      fmt::print("{}: outpaced: {} past {}; not ranked\n", run_label(oc.engine, oc.profile),
                 oc.reached ? "it met the spec, but its cost timed alone is" : "its tries stopped", oc.stopped);
    if (!oc.also_met.empty()) {
      std::vector<std::string> others;
      for (const MatchAlternative& a : oc.also_met)
        others.push_back(fmt::format("{} ({} ns)", configuration_text(m.tries[a.index]), cost_text(a.cost_ns)));
      fmt::print("{}: also met, timed beside it: {}\n", run_label(oc.engine, oc.profile), fmt::join(others, "; "));
    }
  }
}

// Each of our profiles against the cheapest external engine that met the spec (and --target).
void print_our_ratios(const MatchResult& m, std::optional<double> target) {
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
    if (oc.cut_short())
      fmt::print("{}: not compared: its search was cut short{}\n", label, against_target(std::nullopt));
    else if (oc.outpaced())
      fmt::print("{}: not compared: outpaced by another of ours{}\n", label, against_target(std::nullopt));
    else if (!oc.reached)
      fmt::print("{}: did not meet the spec{}{}\n", label,
                 oc.stopped.empty() ? "" : fmt::format(" (its search stopped at {})", oc.stopped),
                 against_target(std::nullopt));
    else if (const auto at_least = cheapest ? std::nullopt : ratio_at_least(m, oc))
      fmt::print("{}: over {:.1f}x cheaper than every external engine (each stopped at the ceiling of {} ns or did "
                 "not meet the spec){}\n",
                 label, *at_least, cost_text(m.ceiling_ns), against_target(*at_least));
    else if (!cheapest)
      fmt::print("{}: {} ns; no external engine met the spec{}\n", label, cost_text(oc.cost_ns), against_target(0.0));
    else
      fmt::print("{}: {:.1f}x cheaper than the cheapest external engine that met the spec ({}, {} ns){}\n", label,
                 cheapest->cost_ns / oc.cost_ns, run_label(cheapest->engine, cheapest->profile),
                 cost_text(cheapest->cost_ns), against_target(cheapest->cost_ns / oc.cost_ns));
  }
}

}  // namespace

void print_match(const MatchResult& m, std::optional<double> target) {
  fmt::print("Equal accuracy on {} ({} balls, class {}): {}\n", m.scene, m.n, m.scene_class, m.spec.text());
  fmt::print("cost: the engine's step time per ball per scene step (dt = {:g} s) in CPU time, {}; engines in another "
             "process time their own steps (pipe-inclusive beside it)\n",
             m.dt, timing_method_text());
  fmt::print("budget: {:g} runs of the scene at dt per search ({:.3g} ball steps); a try stops where a term that only "
             "grows is past its bound\n",
             m.budget_runs, m.budget_runs * double(m.run_ball_steps));
  print_match_rows(m);
  print_our_ratios(m, target);
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
