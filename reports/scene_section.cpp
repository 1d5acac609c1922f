#include "scene_section.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "conform_section.h"
#include "ensemble.h"
#include "json_value.h"
#include "figure_markdown.h"
#include "markdown_buffer.h"
#include "result.h"
#include "markdown_cell.h"
#include "metrics/catalog.h"
#include "no_data.h"
#include "ordered_set.h"
#include "balls_text.h"

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
  if (!r.clamped.empty()) parts.push_back("clamped: " + r.clamped);
  const auto& m = r.metrics;
  const long tunnel_wall = m.count(Metric::tunnelling_wall), tunnel_pair = m.count(Metric::tunnelling_pair);
  const long stick_wall = m.count(Metric::sticking_wall), stick_pair = m.count(Metric::sticking_pair);
  const long tunnels = m.tunnelled(), sticks = m.stuck();
  parts.push_back(tunnels ? fmt::format("tunnelled {} ({} through walls, {} through balls)", times(tunnels),
                                        tunnel_wall, tunnel_pair)
                          : "no tunnelling");
  parts.push_back(sticks ? fmt::format("got stuck {} ({} in walls, {} in balls)", times(sticks), stick_wall, stick_pair)
                         : "no sticking");
  // Only where energy should be kept: with restitution below 1 the loss is the scene's physics.
  if (const auto drift = m.number(Metric::energy_max_rel_drift); drift && r.scene_features && r.scene_features->elastic)
    parts.push_back(fmt::format("energy drifted by up to {:.2g}%", 100 * *drift));
  return fmt::format("{}", fmt::join(parts, "; "));
}



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
  bool against_reference = false;  // left out where no run was compared with a reference
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
         const std::string status =
             r.diverged() ? fmt::format("diverged@{}", r.diverged_step) : std::string(run_status_text(r.status));
         return r.clamped.empty() ? status : status + ", clamped";
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
                 nullptr, view.chaotic ? Place::appendix : Place::table, true});
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
                 nullptr, view.chaotic || view.horizon_exceeded ? Place::table : Place::appendix, true});
  return out;
}

// The columns some run of the scene has a figure for (the slip of a scene that does not rotate is no
// column; nor is the error against a reference where none ran).
std::vector<Column> scene_columns(const std::vector<const Result*>& rows, const SceneView& view) {
  std::vector<Column> cols = columns(view);
  std::erase_if(cols, [&](const Column& c) {
    if (c.metric)
      return std::none_of(rows.begin(), rows.end(), [&](const Result* r) { return !c.metric->get(*r).is_null(); });
    if (c.against_reference)
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

constexpr size_t kTableColumns = 8;

// A scene's table of the columns placed at `place`, the best of each ranked column in bold
// (`bold` false: none).
void put_scene_table(MarkdownBuffer& put, const ReportInputs& in, const std::vector<const Result*>& rows,
                     const std::vector<Column>& all, Place place, bool bold) {
  std::vector<const Column*> cols;
  for (const Column& c : all)
    if (c.place == place || &c == &all.front()) cols.push_back(&c);
  // At most kTableColumns columns a table, so each fits the page: the engine and profile, then the
  // next columns; the status stays in the first.
  for (size_t from = 0; from < cols.size(); from += kTableColumns - 2) {
    const size_t to = std::min(cols.size(), from + kTableColumns - 2);
    put("{}| engine | profile |", from ? "\n" : "");
    for (size_t k = from; k < to; ++k) put(" {} |", cols[k]->header);
    put("\n|---|---|");
    for (size_t k = from; k < to; ++k) put("---|");
    put("\n");
    for (const Result* r : rows) {
      put("| {}{} | {} |", r->engine, refuted_mark(in, r->engine, r->profile), r->profile);
      for (size_t k = from; k < to; ++k) {
        const Column* c = cols[k];
        std::string cell = r->measured() || c == cols.front() ? c->text(*r) : kNoData;
        if (bold)
          if (const auto best = best_value(*c, rows); best && rank_value(*c, *r) == best) cell = "**" + cell + "**";
        put(" {} |", markdown_cell(cell));
      }
      put("\n");
    }
  }
}

// What acts on the balls, as the scene's table is chosen by it.
std::string features_text(const SceneFeatures& f) {
  return fmt::format("{}, {}, {}{}", f.walls ? "walls" : "open space", f.gravity ? "gravity" : "no gravity",
                     f.elastic ? "elastic (restitution 1)" : "restitution below 1",
                     f.frictionless ? "" : ", friction");
}

constexpr const char* kBestNote =
    "Bold marks the best value of a column where a ranking means something (smaller is better; a later horizon is "
    "better), among the runs that ended ok, and only where they differ; n/a: not measured (the run made no step) or "
    "not defined for that run. No cost here: a cost belongs to a configuration that meets a spec, in the "
    "equal-accuracy section.";

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
    if (r->measured()) initial.push_back(r->metrics.value(Metric::penetration_initial));
  if (initial.empty()) return;
  const auto [lo, hi] = std::minmax_element(initial.begin(), initial.end());
  if (*hi <= rows.front()->metrics_config.contact_tolerance) return;
  const std::string low = fmt::format("{:.3g}", *lo), high = fmt::format("{:.3g}", *hi);  // equal as printed: one
  put("The placement starts with balls overlapping by up to {} of a radius ({}`penetration.initial`): not the "
      "engines' doing; the table's penetration is after the start.\n\n",
      high, low == high ? "every engine, " : fmt::format("{} - {} by engine, ", low, high));
}

// The scene's columns that its table leaves out because they do not rank engines there, unmarked.
void put_other_columns(MarkdownBuffer& put, const ReportInputs& in, const std::vector<const Result*>& rows) {
  const std::vector<Column> cols = scene_columns(rows, scene_view(rows));
  if (std::none_of(cols.begin(), cols.end(), [](const Column& c) { return c.place == Place::appendix; })) return;
  put("### The other columns\n\nThe figures the table above leaves out because they do not rank engines on this "
      "scene (the final error on a chaotic scene, a momentum drift where walls and gravity act, the energy drift "
      "where restitution below 1 loses energy by design, the penetration including the placement's), unmarked.\n\n");
  put_scene_table(put, in, rows, cols, Place::appendix, false);
  put("\n");
}


// The scene's trajectory viewer page, as a link (a page, not a picture).
void put_viewer(MarkdownBuffer& put, const std::vector<Figure>& figures, const std::string& scene) {
  for (const Figure& f : figures)
    if (f.kind == FigureKind::viewer && f.scene == scene) put("**Trajectory viewer**: [{}]({}): {}.\n\n", f.file, f.file, f.caption);
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

std::vector<const Result*> rows_of(const ReportInputs& in, const std::string& scene) {
  std::vector<const Result*> rows;
  for (const Result& r : in.results)
    if (r.scene == scene) rows.push_back(&r);
  return rows;
}

}  // namespace

std::vector<std::string> table_scenes(const ReportInputs& in) {
  std::vector<std::string> order = in.run.value("scenes", std::vector<std::string>{});
  std::vector<std::string> have;
  for (const Result& r : in.results) add_once(have, r.scene);
  std::erase_if(order, [&](const std::string& s) { return std::find(have.begin(), have.end(), s) == have.end(); });
  for (const auto& s : have) add_once(order, s);
  return order;
}

std::string scene_line(const ReportInputs& in, const std::string& scene) {
  const auto rows = rows_of(in, scene);
  if (rows.empty()) return "";
  const Result& first = *rows.front();
  const SceneView view = scene_view(rows);
  return fmt::format("{}, dt = {} s, {} steps (`{}`){}", balls_text(first.n), first.dt, first.steps,
                     display_path(first.scene_source), view.features ? "; " + features_text(*view.features) : "");
}

std::string scene_section(const ReportInputs& in, const std::string& scene, const std::vector<Figure>& figures) {
  const auto rows = rows_of(in, scene);
  if (rows.empty()) return "";
  MarkdownBuffer put;
  const SceneView view = scene_view(rows);
  put("## Every engine at the scene's step\n\nEach engine and profile as it is, at dt = {} s: the figures "
      "differ because the engines reach different accuracies at one step. {}\n\n",
      rows.front()->dt, kBestNote);
  put_initial_overlap(put, rows);
  put_scene_table(put, in, rows, scene_columns(rows, view), Place::table, true);
  for (const Result* r : rows)
    if (r->reference.available && r->reference.reference != "exact") {
      put("\nError against {} (a converged run: `exact` cannot run this scene).\n", r->reference.reference);
      break;
    }
  put("\n{}Every run's whole result: [{}]({}).\n\n",
      view.chaotic ? "Chaotic: every engine parts from the reference, so the horizon (the time it stays within a "
                     "tenth of a radius of it) ranks accuracy here, and the final error (below) does not. "
                   : "",
      results_file(in, scene), results_file(in, scene));
  for (const Result* r : rows) put("- **{}**: {}.\n", run_label(*r), verdict(*r));
  put("\n");
  put_viewer(put, figures, scene);
  put_ensemble(put, in, scene);
  for (const FigureKind kind : {FigureKind::energy, FigureKind::picture, FigureKind::animation}) put_figures(put, figures, kind, scene);
  put_other_columns(put, in, rows);
  return put.str();
}

}  // namespace ballbench
