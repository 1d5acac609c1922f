#include "report_writer.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <cctype>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "data_file.h"
#include "input_error.h"
#include "json_value.h"
#include "markdown_cell.h"
#include "metrics/catalog.h"
#include "no_data.h"
#include "ensemble.h"
#include "friction_section.h"
#include "accuracy_section.h"
#include "balls_text.h"
#include "ratio_text.h"
#include "summary_section.h"
#include "ordered_set.h"
#include "runner.h"

namespace ballbench {
namespace {

// A built-in scene as `scenarios/NAME.toml`, whatever folder the results were made in.
std::string display_path(const std::string& source) {
  const std::filesystem::path p(source);
  return p.parent_path().filename() == "scenarios" ? "scenarios/" + p.filename().string() : source;
}

std::string times(long n) { return n == 1 ? "once" : fmt::format("{} times", n); }

std::string verdict(const Result& r) {
  if (!r.measured() || r.status == RunStatus::unsupported || r.status == RunStatus::failed ||
      r.status == RunStatus::crashed || r.status == RunStatus::timed_out)
    return r.error.empty() ? std::string(run_status_text(r.status))
                           : fmt::format("{}: {}", run_status_text(r.status), r.error);
  std::vector<std::string> parts;
  if (r.diverged()) parts.push_back(fmt::format("diverged at step {} ({})", r.diverged_step, r.error));
  const auto& m = r.metrics;
  const long tunnel_wall = m.count("tunnelling.wall"), tunnel_pair = m.count("tunnelling.pair");
  const long stick_wall = m.count("sticking.wall"), stick_pair = m.count("sticking.pair");
  const long tunnels = tunnel_wall + tunnel_pair, sticks = stick_wall + stick_pair;
  parts.push_back(tunnels ? fmt::format("tunnelled {} ({} through walls, {} through balls)", times(tunnels),
                                        tunnel_wall, tunnel_pair)
                          : "no tunnelling");
  parts.push_back(sticks ? fmt::format("got stuck {} ({} in walls, {} in balls)", times(sticks), stick_wall, stick_pair)
                         : "no sticking");
  // Only where energy should be kept: with restitution below 1 the loss is the scene's physics.
  if (const auto drift = m.number("energy.max_rel_drift"); drift && r.scene_features && r.scene_features->elastic)
    parts.push_back(fmt::format("energy drifted by up to {:.2g}%", 100 * *drift));
  if (r.measured()) parts.push_back(fmt::format("{:.0f} ns per ball-step", r.ns_per_ball_step));
  return fmt::format("{}", fmt::join(parts, "; "));
}

// Appends formatted text; the format string is checked at compile time.
struct MarkdownBuffer {
  fmt::memory_buffer out;
  template <class... Args>
  void operator()(fmt::format_string<Args...> f, Args&&... args) {
    fmt::format_to(std::back_inserter(out), f, std::forward<Args>(args)...);
  }
};



// Where a column of a scene goes: its table, or the scene's appendix at the end of the report.
enum class Place { table, appendix };

// One column of a scene's table: its header, its text, and (for "best" marking) a value where
// smaller is better.
struct Column {
  std::string header;
  std::function<std::string(const Result&)> text;
  std::function<std::optional<double>(const Result&)> value;  // null: not ranked; nullopt: this run not ranked
  const MetricDef* metric = nullptr;  // a metric of the catalog: left out where no run has it
  Place place = Place::table;
};

// Was the run compared with a reference other than itself? (The reference's own zero error is not
// a result to rank.)
bool compared(const Result& r) { return r.reference.available && r.engine != r.reference.reference; }

// What decides a scene's columns, from its runs.
struct SceneView {
  std::optional<SceneFeatures> features;  // none in results written before they were recorded
  // Chaotic: every ok run compared with the reference parted from it (a finite horizon), so the
  // final error measures chaos, not the engine, and the horizon is the figure to read.
  bool chaotic = false;
  bool horizon_exceeded = false;  // some run parted from the reference
};

SceneView scene_view(const std::vector<const Result*>& rows) {
  SceneView v;
  for (const Result* r : rows)
    if (r->scene_features) v.features = r->scene_features;
  bool any = false, all = true;
  for (const Result* r : rows) {
    if (!compared(*r) || !r->measured()) continue;
    v.horizon_exceeded |= r->reference.horizon.has_value();
    if (r->status != RunStatus::ok) continue;
    any = true;
    all &= r->reference.horizon.has_value();
  }
  v.chaotic = any && all;
  return v;
}

// The scene's columns, the status first, then the catalog's metrics that have a column
// (core/metrics/catalog.h) in its order, the error against the reference and the timing, each placed
// in the table or the appendix by what means something on this scene.
std::vector<Column> columns(const SceneView& view) {
  std::vector<Column> out = {
      {"status",
       [](const Result& r) {
         return r.diverged() ? fmt::format("diverged@{}", r.diverged_step) : std::string(run_status_text(r.status));
       },
       nullptr}};
  for (const MetricDef& m : metric_catalog()) {
    if (m.column.empty()) continue;
    const bool shown =
        view.features ? meaningful_on(m.meaningful, *view.features, view.chaotic) : m.meaningful != MeaningfulOn::no_scene;
    Column c{m.column,
             [&m](const Result& r) {
               const nlohmann::json v = m.get(r);
               if (!v.is_null()) return metric_text(v);
               return r.measured() && !m.null_text.empty() ? m.null_text : std::string(kNoData);
             },
             nullptr, &m, shown ? Place::table : Place::appendix};
    if (m.ranked)
      c.value = [&m](const Result& r) -> std::optional<double> {
        const nlohmann::json v = m.get(r);
        return v.is_number() ? std::optional(v.get<double>()) : std::nullopt;
      };
    out.push_back(std::move(c));
  }
  out.push_back({"pos error vs reference (m)",
                 [](const Result& r) { return r.reference.available ? fmt::format("{:.3g}", r.reference.pos_rms_final) : kNoData; },
                 [](const Result& r) { return compared(r) ? std::optional(r.reference.pos_rms_final) : std::nullopt; },
                 nullptr, view.chaotic ? Place::appendix : Place::table});
  out.push_back({"horizon (s)",
                 [](const Result& r) {
                   return !r.reference.available ? kNoData
                          : r.reference.horizon  ? fmt::format("{:.3g}", *r.reference.horizon)
                                                 : "never";
                 },
                 // Later is better: rank by minus the horizon, "never" best of all.
                 [](const Result& r) -> std::optional<double> {
                   if (!compared(r)) return std::nullopt;
                   return r.reference.horizon ? -*r.reference.horizon : -std::numeric_limits<double>::max();
                 },
                 nullptr, view.chaotic || view.horizon_exceeded ? Place::table : Place::appendix});
  // Not ranked: at the scene's own step the engines compute to different accuracies; the
  // equal-accuracy sections rank cost.
  Column per_ball{"ns/ball-step", [](const Result& r) { return fmt::format("{:.1f}", r.ns_per_ball_step); }, nullptr};
  Column per_step{"ns/step", [](const Result& r) { return fmt::format("{:.0f}", r.ns_per_step); }, nullptr};
  per_step.place = Place::appendix;
  out.push_back(std::move(per_ball));
  out.push_back(std::move(per_step));
  return out;
}

// The columns some run of the scene has a figure for (the slip of a scene that does not rotate is no
// column; nor is the error against a reference where none ran).
std::vector<Column> scene_columns(const std::vector<const Result*>& rows, const SceneView& view) {
  std::vector<Column> cols = columns(view);
  std::erase_if(cols, [&](const Column& c) {
    if (c.metric)
      return std::none_of(rows.begin(), rows.end(), [&](const Result* r) { return !c.metric->get(*r).is_null(); });
    if (c.header.starts_with("pos error") || c.header.starts_with("horizon"))
      return std::none_of(rows.begin(), rows.end(), [](const Result* r) { return r->reference.available; });
    return false;
  });
  return cols;
}

// The run's value in a ranked column, if its rank means something: it ended ok and was measured.
std::optional<double> rank_value(const Column& c, const Result& r) {
  if (!c.value || r.status != RunStatus::ok || !r.measured()) return std::nullopt;
  const std::optional<double> v = c.value(r);
  return v && !std::isnan(*v) ? v : std::nullopt;
}

// The best value of a ranked column over the scene's runs: none where no ranking means anything
// (fewer than two runs ranked, or all of them equal).
std::optional<double> best_value(const Column& c, const std::vector<const Result*>& rows) {
  std::vector<double> values;
  for (const Result* r : rows)
    if (const auto v = rank_value(c, *r)) values.push_back(*v);
  if (values.size() < 2) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (*lo == *hi) return std::nullopt;
  return *lo;
}

// A scene's table of the columns placed at `place`, the best of each ranked column in bold
// (`bold` false: none).
void put_scene_table(MarkdownBuffer& put, const std::vector<const Result*>& rows, const std::vector<Column>& all,
                     Place place, bool bold) {
  std::vector<const Column*> cols;
  for (const Column& c : all)
    if (c.place == place || &c == &all.front()) cols.push_back(&c);
  put("| engine | profile |");
  for (const Column* c : cols) put(" {} |", c->header);
  put("\n|---|---|");
  for (size_t k = 0; k < cols.size(); ++k) put("---|");
  put("\n");
  for (const Result* r : rows) {
    put("| {} {} | {} |", r->engine, r->engine_version, r->profile);
    for (const Column* c : cols) {
      std::string cell = r->measured() || c == cols.front() ? c->text(*r) : kNoData;
      if (bold)
        if (const auto best = best_value(*c, rows); best && rank_value(*c, *r) == best) cell = "**" + cell + "**";
      put(" {} |", markdown_cell(cell));
    }
    put("\n");
  }
}

// What acts on the balls, as the scene's table is chosen by it.
std::string features_text(const SceneFeatures& f) {
  return fmt::format("{}, {}, {}{}", f.walls ? "walls" : "open space", f.gravity ? "gravity" : "no gravity",
                     f.elastic ? "elastic (restitution 1)" : "restitution below 1",
                     f.frictionless ? "" : ", friction");
}

constexpr const char* kBestNote =
    "bold marks the best value of a column where a ranking means something (smaller is better; a later horizon is "
    "better), among the runs that ended ok, and only where they differ; ns/ball-step is not ranked: at the "
    "scene's own step the engines reach different accuracies (the equal-accuracy sections compare cost). n/a: not measured (the run made no step) or not defined for that run.";

// The scene's results file, relative to the report.
std::string results_file(const ReportInputs& in, const std::string& scene) {
  const auto it = in.result_files.find(scene);
  return it != in.result_files.end() ? it->second : "results/" + scene + ".json";
}

// The placement's overlap, the same for every engine, said once above the table: the table's
// penetration is what the engines let balls sink after the start.
void put_initial_overlap(MarkdownBuffer& put, const std::vector<const Result*>& rows) {
  std::vector<double> initial;
  for (const Result* r : rows)
    if (r->measured()) initial.push_back(r->metrics.value("penetration.initial"));
  if (initial.empty()) return;
  const auto [lo, hi] = std::minmax_element(initial.begin(), initial.end());
  if (*hi <= rows.front()->metrics_config.contact_tolerance) return;
  const std::string low = fmt::format("{:.3g}", *lo), high = fmt::format("{:.3g}", *hi);  // equal as printed: one
  put("The placement starts with balls overlapping by up to {} of a radius ({}`penetration.initial`): not the "
      "engines' doing; the table's penetration is after the start.\n\n",
      high, low == high ? "every engine, " : fmt::format("{} - {} by engine, ", low, high));
}

// Every scene's columns that its table leaves out, at the end of the report.
void put_appendix(MarkdownBuffer& put, const std::vector<std::string>& scene_order,
                  const std::map<std::string, std::vector<const Result*>>& by_scene) {
  put("\n## Appendix: the other columns of each scene\n\nThe figures each scene's table leaves out because they "
      "do not rank engines there (the final error on a chaotic scene, a momentum drift where walls and gravity act, "
      "the energy drift where restitution below 1 loses energy by design, the penetration including the "
      "placement's), unmarked.\n\n");
  for (const auto& scene : scene_order) {
    const auto& rows = by_scene.at(scene);
    const std::vector<Column> cols = scene_columns(rows, scene_view(rows));
    if (std::none_of(cols.begin(), cols.end(), [](const Column& c) { return c.place == Place::appendix; })) continue;
    put("### Appendix: `{}`\n\n", scene);
    put_scene_table(put, rows, cols, Place::appendix, false);
    put("\n");
  }
}

std::string setting_text(const SweepPoint& p) {
  if (p.knob == "dt") return "dt";
  return p.knob + " = " + json_text(p.value);
}

void put_figures(MarkdownBuffer& put, const std::vector<Figure>& figures, const std::string& kind,
                 const std::string& scene) {
  for (const Figure& f : figures)
    if (f.kind == kind && f.scene == scene) put("![{}]({})\n\n*{}*\n\n", f.caption, f.file, f.caption);
}

// The scene's trajectory viewer page, as a link (a page, not a picture).
void put_viewer(MarkdownBuffer& put, const std::vector<Figure>& figures, const std::string& scene) {
  for (const Figure& f : figures)
    if (f.kind == "viewer" && f.scene == scene) put("**Trajectory viewer**: [{}]({}): {}.\n\n", f.file, f.file, f.caption);
}

void put_sweep(MarkdownBuffer& put, const SweepResult& sw, const std::vector<Figure>& figures) {
  put("## Work against precision: `{}`\n\n", sw.scene);
  put("`ballbench sweep` on {}: every engine and profile at several step sizes, and with each of its own "
      "accuracy knobs changed one at a time. Error: position RMS against `{}` at t = {} s (short enough that the "
      "trajectories of a chaotic many-ball system have not yet parted completely); engine time: the engine's own "
      "step time to reach it, median of {} runs. Every point, with its settings: `results/sweep-{}.json` (and "
      "`.csv`).\n\n",
      balls_text(sw.n), sw.reference, sw.horizon, sw.repeats, sw.scene);
  put_figures(put, figures, "work-precision", sw.scene);
  put("Each engine's Pareto front, fastest first: the settings no other setting of the same engine beats, being at "
      "least as accurate and not slower, and more accurate or faster beyond the noise (its slowest timing repeat "
      "below the other's fastest). Two settings whose repeats overlap are equally fast: a ranking inside the "
      "run-to-run noise is no claim, so a front may hold settings whose medians alone would put one behind "
      "another.\n\n");
  put("| engine | profile | setting | dt (s) | engine time (ms): median [min, max] | ns/ball-step | pos error (m) | "
      "energy error | tunnelling | sticking |\n|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<const SweepPoint*> front;
  for (const SweepPoint& p : sw.points)
    if (p.pareto) front.push_back(&p);
  std::map<std::string, size_t> engine_rank;  // engines in the sweep's order, each fastest first
  for (const SweepPoint& p : sw.points) engine_rank.emplace(p.engine, engine_rank.size());
  std::sort(front.begin(), front.end(), [&](const SweepPoint* a, const SweepPoint* b) {
    const size_t ra = engine_rank[a->engine], rb = engine_rank[b->engine];
    return ra != rb ? ra < rb : a->engine_s_median() < b->engine_s_median();
  });
  for (const SweepPoint* p : front) {
    const auto [lo, hi] = std::minmax_element(p->engine_s.begin(), p->engine_s.end());
    put("| {} | {} | {} | {} | {:.3g} [{:.3g}, {:.3g}] | {:.0f} | {:.3g} | {:.3g} | {} | {} |\n", p->engine, p->profile,
        markdown_cell(setting_text(*p)), p->dt, 1e3 * p->engine_s_median(), 1e3 * *lo, 1e3 * *hi, p->ns_median(),
        p->pos_rms, p->energy_rel, p->tunnelling, p->sticking);
  }
  // An engine and profile that refused the scene at every point is named once, with its reason.
  std::set<std::string> ran;  // labels with a point the engine did not refuse
  for (const SweepPoint& p : sw.points)
    if (p.status != RunStatus::unsupported) ran.insert(run_label(p.engine, p.profile));
  std::map<std::string, std::string> refused;  // label -> reason
  for (const SweepPoint& p : sw.points)
    if (!ran.contains(run_label(p.engine, p.profile))) refused.emplace(run_label(p.engine, p.profile), p.error);
  std::vector<std::string> failed;
  for (const SweepPoint& p : sw.points)
    if (p.status != RunStatus::ok && !refused.contains(run_label(p.engine, p.profile)))
      failed.push_back(fmt::format("{} {}: {}{}", run_label(p.engine, p.profile), setting_text(p), run_status_text(p.status),
                                   p.error.empty() ? "" : " (" + p.error + ")"));
  if (!failed.empty()) put("\nPoints that did not complete: {}.\n", fmt::join(failed, "; "));
  for (const auto& [label, why] : refused) put("\n{} refused the scene at every point: {}.\n", label, markdown_cell(why));
  put("\n");
}

void put_frontier(MarkdownBuffer& put, const FrontierResult& f, const std::vector<Figure>& figures) {
  put("## Stability frontier: `{}`\n\n", f.scene);
  put("`ballbench stress` on {}: each knob doubled until a run of {} steps fails (level k runs the knob at "
      "2^(k-1) times the scene's value; `count` tiles the scene side by side). The table gives the largest value "
      "that passed and why the next level failed. Source: `results/stress-{}.json`.\n\n",
      balls_text(f.n), f.steps, f.scene);
  put_figures(put, figures, "frontier", f.scene);
  std::vector<std::string> knobs, engines;
  for (const FrontierRow& r : f.rows) {
    add_once(knobs, r.knob);
    const std::string l = run_label(r.engine, r.profile);
    add_once(engines, l);
  }
  put("| engine |");
  for (const auto& k : knobs) put(" {} |", k);
  put("\n|---|");
  for (size_t k = 0; k < knobs.size(); ++k) put("---|");
  put("\n");
  for (const auto& e : engines) {
    put("| {} |", e);
    for (const auto& k : knobs)
      for (const FrontierRow& r : f.rows)
        if (run_label(r.engine, r.profile) == e && r.knob == k) {
          if (refused(r))
            put(" {} |", markdown_cell(r.failed_next));
          else
            put(" {} ({}) |", r.factor == 0 ? "none" : fmt::format("{:.4g}", r.base * r.factor),
                r.failed_next.empty() ? "passed every level" : "next: " + markdown_cell(r.failed_next));
        }
    put("\n");
  }
  put("\nAt coarse steps (long enough for a ball to collide several times) the pair pass-through test judges a "
      "path bent several times from two samples; `exact` cannot tunnel, so its row shows whether the test cried wolf "
      "at a level.\n\n");
}

// Engines in another process (adapters/process/): what is their step and what is the pipe.
void put_pipe_cost(MarkdownBuffer& put, const BenchResults& bench) {
  std::vector<const BenchRow*> rows;
  for (const BenchRow& r : bench.rows)
    if (r.error.empty() && r.pipe_ns_per_ball_step) rows.push_back(&r);
  if (rows.empty()) return;
  const auto pipe_at = [&](const std::string& scene, long n) -> const BenchRow* {
    for (const BenchRow& p : bench.pipe)
      if (p.scene == scene && p.n == n && p.error.empty()) return &p;
    return nullptr;
  };
  put("Engines in another process (`adapters/process/`, the Node engines) pay the pipe on every step: the step "
      "request, the reply and the state block. The engine's process times its own step call (its ns per ball-step, "
      "as in the tables above); the harness times the whole round trip; `pipe/noop/default/SCENE/N` is a Node "
      "engine that moves nothing (`adapters/node/noop.js`), so its time is the pipe alone.\n\n");
  put("| engine | scene | balls | harness: step and pipe | its own step | pipe alone (`pipe/noop`) |\n"
      "|---|---|---:|---:|---:|---:|\n");
  for (const BenchRow* r : rows) {
    const BenchRow* p = pipe_at(r->scene, r->n);
    put("| {} | {} | {} | {:.0f} | {:.0f} | {} |\n", run_label(r->engine, r->profile), r->scene, r->n,
        *r->pipe_ns_per_ball_step, r->ns_per_ball_step, p ? fmt::format("{:.0f}", p->ns_per_ball_step) : kNoData);
  }
  put("\nns per ball-step. Source: `results/bench.json`.\n\n");
}

// Balls from which a benchmark's memory per ball is the balls' (see put_scaling).
constexpr long kMemoryBalls = 100000;

void put_scaling(MarkdownBuffer& put, const ReportInputs& in, const BenchResults& bench,
                 const std::vector<Figure>& figures) {
  put("## Scaling\n\n`bench/ballbench_step_benchmark` (Google Benchmark): step cost per ball on the scaled "
      "scenes. `gas`: elastic, no gravity; `bowl`: gravity, restitution 0.99; both at the seed's density in a box of "
      "side sqrt(5 n), timed after 5 warm-up steps from the start, so the bowl is timed early in its pour (from 10^5 "
      "balls on the balls are still falling). `settled`: a pile of balls of radius 0.25 (g 9.81, restitution 0.5) run "
      "until at rest, saved, and timed from the saved state once each engine's pile is at rest again (RMS speed "
      "below 1e-3 m/s: an engine starts without the contact impulses that held the pile, which sags and rebounds), "
      "then 5 warm-up steps (100 for the sleeping variants). "
      "`fluid`: the seed-bowl's 10 x 10 box, g 100, restitution 0.99, with n balls at its packing fraction (radius "
      "0.25 sqrt(72 / n)), timed over its first 3 s (300 steps from the start: the pour and the settle). Profiles "
      "`soft` and `soft-sleep` are `home` with `resting = \"soft\"` (and `sleep_speed = 0.05`), `stock-sleep` Box2D's "
      "stock profile with its sleeping on; an engine whose every ball sleeps does next to nothing in a step, so "
      "its figure is the cost of a pile at rest with sleeping, not of a solve. A benchmark that runs past its budget (10 s in the quick report, 60 s in the "
      "full one) stops and is shown as failed, with how far it got and what a step cost below its table. Every engine "
      "runs at the scene's own step, whatever accuracy that gives it (`home`'s default profile builds itself for the "
      "scene's spec, the others do not), so these tables show how each engine's cost grows with the count, not "
      "which is cheaper: the equal-accuracy sections rank cost. Source: `results/bench.json`, Google Benchmark's own JSON.\n\n");
  put_figures(put, figures, "scaling", "");
  std::vector<std::string> scenes;
  std::vector<long> counts;
  std::vector<std::string> engines;
  for (const BenchRow& r : bench.rows) {
    add_once(scenes, r.scene);
    add_once(counts, r.n);
    const std::string l = run_label(r.engine, r.profile);
    add_once(engines, l);
  }
  std::sort(counts.begin(), counts.end());
  for (const auto& scene : scenes) {
    put("ns per ball-step, `{}`:\n\n| engine |", scene);
    for (long n : counts) put(" {} |", n);
    put("\n|---|");
    for (size_t k = 0; k < counts.size(); ++k) put("---:|");
    put("\n");
    for (const auto& e : engines) {
      const bool has_rows = std::any_of(bench.rows.begin(), bench.rows.end(), [&](const BenchRow& r) {
        return r.scene == scene && run_label(r.engine, r.profile) == e;
      });
      if (!has_rows) continue;  // a variant of another scene
      put("| {} |", e);
      for (long n : counts) {
        std::string cell = "";
        for (const BenchRow& r : bench.rows)
          if (r.scene == scene && r.n == n && run_label(r.engine, r.profile) == e)
            cell = !r.error.empty()            ? "failed"
                   : r.ns_per_ball_step >= 10 ? fmt::format("{:.0f}", r.ns_per_ball_step)
                                               : fmt::format("{:.2g}", r.ns_per_ball_step);
        put(" {} |", cell);
      }
      put("\n");
    }
    // Each of our solver's profiles: its rate and memory at its largest count. No ratio to another
    // engine: each ran at the scene's own step, whatever accuracy that gives it.
    const auto sleeps = [](const std::string& profile) { return profile.ends_with("-sleep"); };
    std::vector<std::pair<std::string, std::string>> ours_runs;  // (engine, profile)
    for (const BenchRow& r : bench.rows)
      if (r.scene == scene && role_of(in, r.engine) == EngineRole::ours) add_once(ours_runs, {r.engine, r.profile});
    for (const auto& [engine, profile] : ours_runs) {
      // A pile asleep does no work in a step: its time is no solve, and a ratio or a rate of it no
      // measurement of one.
      if (sleeps(profile)) {
        put("\n`{}`: its balls sleep, so a step does next to nothing: its times above are the cost of a pile at rest "
            "with sleeping, not of a solve, and are not set against other engines.\n",
            run_label(engine, profile));
        continue;
      }
      const auto is_ours = [&](const BenchRow& r) { return r.engine == engine && r.profile == profile; };
      // The profile's largest run: rate and memory.
      const BenchRow* largest = nullptr;
      for (const BenchRow& r : bench.rows)
        if (r.scene == scene && is_ours(r) && r.error.empty() && (!largest || r.n > largest->n)) largest = &r;
      // Memory per ball only where the balls dominate it: below kMemoryBalls the process's fixed cost
      // (and the other benchmarks it ran) would be spread over a few balls.
      if (largest && largest->steps_per_s)
        put("\n`{}` at {}: {:.1f} steps per second{}.\n", run_label(engine, profile), balls_text(largest->n),
            *largest->steps_per_s,
            largest->n < kMemoryBalls
                ? std::string()
                : fmt::format("; memory {} bytes per ball (resident growth from a trimmed heap while the world was "
                              "built and run: what the engine holds), peak resident set of the benchmark process {} "
                              "bytes per ball",
                              largest->engine_bytes_per_ball ? fmt::format("{:.0f}", *largest->engine_bytes_per_ball) : kNoData,
                              largest->peak_rss_bytes_per_ball ? fmt::format("{:.0f}", *largest->peak_rss_bytes_per_ball)
                                                               : kNoData));
    }
    // A settled pile that was still moving when its timed steps began (settling is bounded).
    std::vector<std::string> moving;
    for (const BenchRow& r : bench.rows)
      if (r.scene == scene && r.error.empty() && r.start_rms_speed && *r.start_rms_speed >= 1e-3)
        moving.push_back(fmt::format("{} at {} (RMS speed {:.2g} m/s after {:.0f} steps)", run_label(r.engine, r.profile),
                                     r.n, *r.start_rms_speed, r.settle_steps.value_or(0)));
    if (!moving.empty())
      put("\nNot at rest again within half the budget, so timed while still moving: {}.\n", fmt::join(moving, "; "));
    std::vector<std::string> failures;
    for (const BenchRow& r : bench.rows)
      if (r.scene == scene && !r.error.empty())
        failures.push_back(fmt::format("{} at {}: {}", run_label(r.engine, r.profile), r.n, markdown_cell(r.error)));
    if (!failures.empty()) put("\nFailed: {}.\n", fmt::join(failures, "; "));
    for (const BenchRow& r : bench.pour)
      if (r.scene == scene && role_of(in, r.engine) == EngineRole::ours && r.error.empty() && r.steps_per_s)
        put("\nOver the first second of the pour instead (100 steps from rest, no warm-up; `pour/{}/default/{}/{}`), "
            "`{}` at {} balls makes {:.1f} steps per second: balls reach the floor and pile up, and the grid's cells "
            "grow with the fastest fall (core/solver/PERFORMANCE.md).\n",
            r.engine, r.scene, r.n, r.engine, r.n, *r.steps_per_s);
    put("\n");
  }
  put_pipe_cost(put, bench);
}

// A seed scene over its placements (ensemble.h): each metric's mean with its interval, and how each
// run compares with ours on the same placements. Nothing when the scene ran one placement.
void put_ensemble(MarkdownBuffer& put, const ReportInputs& in, const std::string& scene) {
  std::vector<Result> runs;
  std::vector<int64_t> seeds;
  for (const auto* list : {&in.results, &in.placements})
    for (const Result& r : *list)
      if (r.scene == scene) runs.push_back(r), add_once(seeds, r.seed_offset);
  if (seeds.size() < 2) return;
  std::string ours;
  for (const Result& r : runs)
    if (ours.empty() && role_of(in, r.engine) == EngineRole::ours) ours = run_label(r);
  const auto rows = summarise_ensemble(runs, ours);
  // The columns that mean something on this scene, as in its table: no energy drift where
  // restitution is below 1, no final error where every engine parts from the reference.
  std::vector<const Result*> all;
  for (const Result& r : runs) all.push_back(&r);
  const SceneView view = scene_view(all);
  std::vector<size_t> shown;
  const auto& metrics = ensemble_metrics();
  for (size_t k = 0; k < metrics.size(); ++k)
    if (!view.features || meaningful_on(metrics[k].def->meaningful, *view.features, view.chaotic)) shown.push_back(k);
  put("Over {} random placements (the scene's seeds offset by 0 .. {}; the table above is offset 0): each metric's mean "
      "over the runs that ended ok, with its 95% confidence interval (percentile bootstrap, 2000 resamples). {}\n\n",
      seeds.size(), seeds.size() - 1,
      ours.empty() ? ""
                   : fmt::format("Against `{}` on the same placements (paired): **↑** significantly above, **↓** "
                                 "significantly below (the bootstrap interval of the mean difference leaves out 0), ≈ "
                                 "not significantly different.",
                                 ours));
  put("| engine | ok |");
  for (size_t k : shown) put(" {} |", metrics[k].name);
  put("\n|---|---:|");
  for (size_t k = 0; k < shown.size(); ++k) put("---|");
  put("\n");
  for (const EnsembleRow& row : rows) {
    put("| {} | {} |", row.label, row.placements);
    for (size_t k : shown)
      if (!row.metrics[k]) {
        put(" {} |", kNoData);
      } else {
        const std::string& v = row.versus_ours[k];
        put(" {}{} |", interval_text(*row.metrics[k]),
            v.empty() ? "" : v == "=" ? " ≈" : v == "+" ? " **↑**" : " **↓**");
      }
    put("\n");
  }
  put("\n");
}

// Requested against effective restitution, per engine and profile (calibration_result.h).
void put_calibration(MarkdownBuffer& put, const CalibrationResult& c) {
  put("## Restitution calibration\n\nThe restitution each engine delivers against the one the scene asks for: one ball "
      "meeting a wall, and two equal balls head-on, at the impact speeds given (m/s), no gravity, dt 0.01; measured "
      "from the states as sqrt(kinetic energy after / before). An engine with a bounce threshold shows 0 below it. "
      "Source: `results/calibration.json`.\n\n");
  std::vector<std::string> labels;
  for (const CalibrationPoint& p : c.points) add_once(labels, run_label(p.engine, p.profile));
  for (double requested : c.requested) {
    put("Requested e = {}:\n\n| engine |", requested);
    for (const char* contact : {"ball-wall", "ball-ball"})
      for (double v : c.speeds) put(" {} {} |", contact, v);
    put("\n|---|");
    for (size_t k = 0; k < 2 * c.speeds.size(); ++k) put("---:|");
    put("\n");
    for (const std::string& label : labels) {
      put("| {} |", label);
      for (const char* contact : {"ball-wall", "ball-ball"})
        for (double v : c.speeds) {
          std::string cell;
          for (const CalibrationPoint& p : c.points)
            if (run_label(p.engine, p.profile) == label && p.contact == contact && p.requested == requested &&
                p.speed == v)
              cell = p.measured() ? fmt::format("{:.3f}", p.effective) : calibration_status_text(p);
          put(" {} |", cell);
        }
      put("\n");
    }
    put("\n");
  }
  std::vector<std::string> notes;
  for (const CalibrationPoint& p : c.points)
    if (!p.measured() && p.status != RunStatus::unsupported && !p.error.empty())
      notes.push_back(fmt::format("{} {} e {} at {} m/s: {}", run_label(p.engine, p.profile), p.contact, p.requested,
                                  p.speed, markdown_cell(p.error)));
  if (!notes.empty()) put("Not measured: {}.\n\n", fmt::join(notes, "; "));
}

// Issue 6's fourth target: metrics and sampling at most 10% of the engine's own step time.
void put_harness(MarkdownBuffer& put, const BenchResults& bench) {
  put("## Harness overhead\n\n`bench/ballbench_harness_benchmark` (Google Benchmark): `run_engine` on the scaled "
      "`gas`, 100 steps without a reference, engine step time and harness time (reading each state back, the "
      "tunnelling and finiteness check every step, the sampled metrics and checksums every k-th step) from the same "
      "run. The target is a harness at most 10% of the engine's time (0.10). Source: `results/harness.json`, Google "
      "Benchmark's own JSON.\n\n");
  put("| engine | scene | balls | sampled metrics every | engine ns/ball-step | harness ns/ball-step | harness / engine "
      "|\n|---|---|---:|---:|---:|---:|---:|\n");
  for (const HarnessRow& r : bench.harness) {
    if (!r.error.empty()) {
      put("| {} | {} | {} | {} | failed: {} | | |\n", r.engine, r.scene, r.n, r.sample_every, r.error);
      continue;
    }
    put("| {} | {} | {} | {} | {:.1f} | {:.1f} | {:.2f} |\n", r.engine, r.scene, r.n, r.sample_every,
        r.engine_ns_per_ball_step, r.harness_ns_per_ball_step, r.overhead);
  }
  put("\n");
  // The least any per-step check from states costs, measured beside the engine in one run.
  for (const FloorRow& f : bench.floor) {
    if (!f.error.empty()) {
      put("Floor, `floor/{}/{}/{}`: failed: {}\n\n", f.engine, f.scene, f.n, f.error);
      continue;
    }
    put("Floor, `floor/{0}/{1}/{2}` (same binary, {2} balls): beside `{0}`'s step ({3:.1f} ns per ball-step, keeping "
        "{4:.2f} of {5} cores busy on average), copying the state out once costs {6:.2f} ns per ball-step and one "
        "streaming pass comparing two consecutive states (finiteness, longest step) {7:.2f} ns, both on {5} threads: "
        "together **{8:.2f}** of the engine's step, before any pair search. No harness that reads each state and "
        "compares it with the last can cost less.\n\n",
        f.engine, f.scene, f.n, f.engine_ns_per_ball_step, f.engine_cores, f.threads, f.copy_ns_per_ball_step,
        f.pass_ns_per_ball_step, f.floor);
  }
}

// The machine and build, one column each for the shards of a merged report (`ballbench merge`:
// run.json's "merge" and "shards"), each with the parts it ran and its command.
void put_machines(MarkdownBuffer& put, const nlohmann::json& run) {
  static constexpr const char* kFields[] = {"cpu", "cores", "os", "compiler", "build_type", "flags", "build"};
  const nlohmann::json shards = run.value("shards", nlohmann::json::array());
  put("## Machine and build\n\n");
  if (!shards.is_array() || shards.empty()) {
    put("| | |\n|---|---|\n");
    for (const char* k : kFields)
      if (run.contains(k)) put("| {} | {} |\n", k, markdown_cell(json_text(run[k])));
    return;
  }
  put("Merged from {} shards, each run on its own (`report --shard I/N`; the report's parts dealt round-robin), "
      "joined by `ballbench merge`. Times within a shard's parts come from its machine; compare across shards with "
      "care.\n\n| |",
      shards.size());
  for (const auto& s : shards) put(" shard {}/{} |", s.value(nlohmann::json::json_pointer("/shard/index"), 0),
        s.value(nlohmann::json::json_pointer("/shard/count"), 0));
  put("\n|---|");
  for (size_t k = 0; k < shards.size(); ++k) put("---|");
  put("\n");
  const auto row = [&](const char* name, const std::function<std::string(const nlohmann::json&)>& cell) {
    put("| {} |", name);
    for (const auto& s : shards) put(" {} |", markdown_cell(cell(s)));
    put("\n");
  };
  for (const char* k : kFields)
    row(k, [k](const nlohmann::json& s) { return s.contains(k) ? json_text(s[k]) : std::string(kNoData); });
  row("parts", [](const nlohmann::json& s) {
    const auto ran = s.value("ran", std::vector<std::string>{});
    return ran.empty() ? std::string(kNoData) : fmt::format("{}", fmt::join(ran, ", "));
  });
  row("command", [](const nlohmann::json& s) { return "`" + s.value("command", "?") + "`"; });
  row("date", [](const nlohmann::json& s) { return s.value("date", "?"); });
  put("\n");
}

// What the report was asked to leave out, or could not run (run.json's "left_out", its own and its
// shards'): a section that is missing says why.
void put_left_out(MarkdownBuffer& put, const nlohmann::json& run) {
  std::vector<std::string> lines;
  const auto take = [&](const nlohmann::json& record) {
    for (const auto& l : record.value("left_out", std::vector<std::string>{})) add_once(lines, l);
  };
  take(run);
  for (const auto& s : run.value("shards", nlohmann::json::array())) take(s);
  if (lines.empty()) return;
  put("**Left out of this report**:\n\n");
  for (const auto& l : lines) put("- {}\n", l);
  put("\n");
}

}  // namespace

EngineRole role_of(const ReportInputs& in, const std::string& engine) {
  const auto it = in.roles.find(engine);
  return it == in.roles.end() ? EngineRole::external : it->second;
}

ReportInputs read_report_inputs(const std::string& results_dir) {
  ReportInputs in;
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(results_dir, ec))
    if (e.path().extension() == ".json") files.push_back(e.path());
  if (ec) throw InputError(fmt::format("{}: cannot read the results folder: {}", results_dir, ec.message()));
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    if (name == "run.json") {
      in.run = parse_json_file(f.string(), "a report's run record");
      if (!in.run.is_object())
        throw InputError(fmt::format("{}: not a report's run record (a JSON object): write it again with "
                                     "`ballbench report`",
                                     f.string()));
    } else if (name == "bench.json") {
      in.bench = read_bench_file(f.string());
    } else if (name == "harness.json") {
      in.harness = read_bench_file(f.string());
    } else if (name == "calibration.json") {
      in.calibration = read_calibration_file(f.string());
    } else if (name.starts_with("match-")) {
      in.matches.push_back(read_match_file(f.string()));
    } else if (name.starts_with("sweep-")) {
      in.sweeps.push_back(read_sweep_file(f.string()));
      mark_pareto(in.sweeps.back().points);  // by today's rule, whatever rule wrote the file
    } else if (name.starts_with("stress-")) {
      in.frontiers.push_back(read_frontier_file(f.string()));
    } else {
      for (auto& r : read_results_file(f.string())) {
        in.result_files.emplace(r.scene, "results/" + name);
        (r.seed_offset == 0 ? in.results : in.placements).push_back(std::move(r));
      }
    }
  }
  // The equal-accuracy scenes in the suite's order (run.json's parts), then any others by name.
  const auto parts = in.run.is_object() ? in.run.value("parts", std::vector<std::string>{}) : std::vector<std::string>{};
  const auto rank = [&](const MatchResult& m) {
    return std::find(parts.begin(), parts.end(), "match:" + m.scene) - parts.begin();
  };
  std::stable_sort(in.matches.begin(), in.matches.end(),
                   [&](const MatchResult& a, const MatchResult& b) { return rank(a) < rank(b); });
  if (in.run.is_null())
    throw InputError(fmt::format("{}: no run.json, so no report's results to render (run `ballbench report` "
                                 "without --render-only first)",
                                 results_dir));
  return in;
}

std::string render_report(const ReportInputs& in, const std::vector<Figure>& figures) {
  MarkdownBuffer put;
  const nlohmann::json& run = in.run;
  put("# ballbench report\n\n");
  put("Our ball solver (`home`), the thesis's MATLAB algorithm ported faithfully (`home-seed`), and the external "
      "engines, on identical scenes. Every number below comes from the JSON files in `results/` beside this file; "
      "the metrics are computed by the harness from sampled states, never taken from an engine.\n\n");
  put("Regenerate with `scripts/report` (`scripts/report --full` for the complete evidence). This report: `{}`, {} "
      "suite, {}.\n\n",
      run.contains("merge") ? run["merge"].value("command", "?") : run.value("command", "?"), run.value("suite", "quick"),
      run.contains("merge") ? run["merge"].value("date", "?") : run.value("date", "?"));

  put("{}", summary_section(in, figures));
  put_left_out(put, run);
  put("{}", accuracy_section(in, figures));
  put_machines(put, run);
  put("\nTimes are engine step time only (reading states and computing metrics excluded), one run each on a shared "
      "machine: read the ratios, not the nanoseconds. In each scene's table, {}\n\n",
      kBestNote);

  // Scenes in the suite's order (run.json), then any others in file order.
  std::vector<std::string> scene_order = run.value("scenes", std::vector<std::string>{});
  std::map<std::string, std::vector<const Result*>> by_scene;
  for (const auto& r : in.results) {
    add_once(scene_order, r.scene);
    by_scene[r.scene].push_back(&r);
  }
  std::erase_if(scene_order, [&](const std::string& s) { return !by_scene.contains(s); });
  for (const auto& scene : scene_order) {
    const auto& rows = by_scene[scene];
    const Result& first = *rows.front();
    const SceneView view = scene_view(rows);
    const std::vector<Column> cols = scene_columns(rows, view);
    put("## Scene `{}`\n\n{}, dt = {} s, {} steps (`{}`){}.\n\n", scene, balls_text(first.n), first.dt, first.steps,
        display_path(first.scene_source), view.features ? "; " + features_text(*view.features) : "");
    put_initial_overlap(put, rows);
    put_scene_table(put, rows, cols, Place::table, true);
    for (const Result* r : rows)
      if (r->reference.available && r->reference.reference != "exact") {
        put("\nError against {} (a converged run: `exact` cannot run this scene).\n", r->reference.reference);
        break;
      }
    put("\n{}The other columns: [appendix](#appendix-{}); every run's whole result: `{}`.\n\n",
        view.chaotic ? "Chaotic: every engine parts from the reference, so the horizon (the time it stays within a "
                       "tenth of a radius of it) ranks accuracy here, and the final error (in the appendix) does not. "
                     : "",
        heading_anchor(scene), results_file(in, scene));
    for (const Result* r : rows) put("- **{}**: {}.\n", run_label(*r), verdict(*r));
    put("\n");
    put_viewer(put, figures, scene);
    put_ensemble(put, in, scene);
    put_figures(put, figures, "energy", scene);
    put_figures(put, figures, "picture", scene);
    put_figures(put, figures, "animation", scene);
  }
  put("{}", friction_section(in.results, scene_order));
  for (const SweepResult& sw : in.sweeps) put_sweep(put, sw, figures);
  if (in.bench && !in.bench->rows.empty()) put_scaling(put, in, *in.bench, figures);
  if (in.harness && !in.harness->harness.empty()) put_harness(put, *in.harness);
  for (const FrontierResult& f : in.frontiers) put_frontier(put, f, figures);
  if (in.calibration) put_calibration(put, *in.calibration);

  put("## Engines, profiles and limits\n\n`stock` is the engine as shipped (its defaults); `tuned` is what its own "
      "documentation and issue tracker recommend for elastic balls; our solvers have one profile, `default`. Details "
      "and sources: `adapters/*/README.md`, `core/solver/README.md`.\n\n");
  std::map<std::string, std::vector<std::string>> profiles;
  std::vector<std::string> engine_order;
  std::map<std::string, std::string> limits, versions;
  for (const auto& r : in.results) {
    if (!profiles.contains(r.engine)) engine_order.push_back(r.engine);
    auto& p = profiles[r.engine];
    add_once(p, r.profile);
    limits[r.engine] = r.engine_limits;
    versions[r.engine] = r.engine_version;
  }
  put("| engine | version | profiles | limits that shape its results |\n|---|---|---|---|\n");
  for (const auto& e : engine_order)
    put("| {} | {} | {} | {} |\n", e, versions[e], fmt::join(profiles[e], ", "), markdown_cell(limits[e]));
  std::vector<std::string> settings_links;
  for (const auto& scene : scene_order)
    settings_links.push_back(fmt::format("[{0}]({0})", results_file(in, scene)));
  put("\n## Engine settings\n\nThe effective settings of every run, as its engine reported them (every knob, defaults "
      "included), are the `settings` of its row in the scene's results file: {}.\n",
      fmt::join(settings_links, ", "));
  const MetricsConfig cfg = in.results.empty() ? MetricsConfig{} : in.results.front().metrics_config;
  put("\n## Glossary\n\n");
  for (const MetricDef& m : metric_catalog())
    if (!m.column.empty()) {
      // The unit once: a column's header may already carry it ("slip at end (m/s)").
      const std::string unit = fmt::format(" ({})", m.unit);
      put("- **{}**{}: {}.\n", m.column, m.unit.empty() || m.column.ends_with(unit) ? "" : unit, m.definition(cfg));
    }
  put("- **pos error vs reference**: position RMS error over balls against the event-driven `exact` engine run in "
      "lockstep (for a scene `exact` cannot run, such as rough balls on each other under gravity, a converged run stands in: the scene "
      "stepped by Chipmunk at dt / {}, named under the scene's table), at the last step; **horizon**: the first time that error exceeded a tenth of the mean radius "
      "(chaotic scenes part from any reference, so this says more than a long-run RMS; `never`: it stayed within). "
      "Where `exact` itself failed, the comparison runs up to that step.\n",
      kConvergedSubsteps);
  put("- **ns/step, ns/ball-step**: engine step time only, per step and per ball per step.\n");
  put("- **work against precision**: for each engine and setting, the engine's step time to reach a fixed simulated "
      "time (median of repeated runs, with their spread) against its position RMS error against `exact` at that "
      "time and its energy error (max |E - E_exact| / E0); the **Pareto front** of an engine is its settings that no "
      "other setting of it beats in both.\n");
  put("- **stability frontier**: the largest multiple of a knob (dt, initial speeds, the mass of every other ball, "
      "ball count) at which a run still passes: status ok, no tunnelling, energy within the tolerance of `exact`'s "
      "and not grown.\n");
  put("- **scaling**: ns per ball-step from the step benchmark at each ball count; flat lines are linear cost.\n");
  put("- **diverged@k**: the state became non-finite, or the energy exceeded {} times its initial value, at step k; "
      "metrics cover the steps before.\n", cfg.divergence_energy_factor);
  put("\nEvery metric of a run's JSON, with its unit and definition: `ballbench list --metrics`.\n");
  if (!scene_order.empty()) put_appendix(put, scene_order, by_scene);
  return fmt::to_string(put.out);
}

std::string heading_anchor(const std::string& heading) {
  std::string out;
  for (char c : heading)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') out += static_cast<char>(std::tolower(c));
    else if (c == ' ') out += '-';
  return out;
}

}  // namespace ballbench
