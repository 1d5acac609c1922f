#include "friction_section.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>

#include <fmt/format.h>

#include "markdown_buffer.h"
#include "markdown_cell.h"
#include "metrics/angle_of_repose.h"
#include "no_data.h"
#include "ordered_set.h"

namespace ballbench {
namespace {

// A run that made no step (refused, or failed to build) has no figures: its status and why.
bool ran(const Result& r) { return r.steps_done > 0; }
std::string status_text(const Result& r) {
  if (r.status == RunStatus::ok) return "ok";
  return r.error.empty() ? run_status_text(r.status) : fmt::format("{}: {}", run_status_text(r.status), markdown_cell(r.error));
}

std::string or_none(const std::optional<double>& v, const char* format) {
  return v ? fmt::format(fmt::runtime(format), *v) : kNoData;
}

std::string source_text(const Result& r) {
  const std::filesystem::path p(r.scene_source);
  return p.parent_path().filename() == "scenarios" ? "scenarios/" + p.filename().string() : r.scene_source;
}

// One scene of balls rolling on the floor: final speed and time to roll against the closed forms;
// of several balls, the one farthest from its own (the rolling meter's pick, metrics/rolling_metric.cpp).
void put_rolling(MarkdownBuffer& put, const std::string& scene, const std::vector<const Result*>& rows) {
  const Result* any = nullptr;
  for (const Result* r : rows)
    if (r->metrics.has(Metric::rolling_expected_speed)) any = r;
  const bool one = any->n == 1;
  const auto time = [&](const char* before) {
    return any->metrics.has(Metric::rolling_expected_time_to_roll)
               ? fmt::format("{}**{:.3f} s**", before, any->metrics.value(Metric::rolling_expected_time_to_roll))
               : std::string();
  };
  put("### `{}`: rolling against the closed form\n\n", scene);
  if (one)
    put("`{}`; closed forms from the scene (core/metrics/rolling.h): it ends rolling at **{:.4g} m/s**{}.\n\n",
        source_text(*any), any->metrics.value(Metric::rolling_expected_speed), time(" from t = "));
  else
    put("`{}`, {} balls; closed forms from the scene (core/metrics/rolling.h): each ball ends rolling at its own "
        "(v0_i - k r_i w0_i) / (1 + k) (v0_i / (1 + k) without spin){}. The table shows the ball farthest from its "
        "closed form.\n\n",
        source_text(*any), any->n, time(", every one by t = "));
  put("The time to roll is the first sample from which {} (slip below the roll tolerance), so it lies up to a step "
      "after the closed form; `never`: still slipping at the end.\n\n",
      one ? "the ball rolls" : "every ball rolls");
  // Of several balls, each run's farthest may be another ball: its closed form beside its speed.
  put("| engine | status | {} | vs closed form | time to roll (s) | vs closed form | slip at end "
      "(m/s) |\n|---|---|---:|{}---:|---:|---:|---:|\n",
      one ? "final speed (m/s)" : "farthest ball's final speed (m/s) | its closed form (m/s)", one ? "" : "---:|");
  for (const Result* r : rows) {
    if (!ran(*r)) {
      put("| {0} | {1} | {2} |{3} {2} | {2} | {2} | {2} |\n", run_label(*r), status_text(*r), kNoData,
          one ? "" : fmt::format(" {} |", kNoData));
      continue;
    }
    const MetricValues& m = r->metrics;
    const auto speed = m.number(Metric::rolling_speed), expected = m.number(Metric::rolling_expected_speed);
    const auto expected_time = m.number(Metric::rolling_expected_time_to_roll), t = m.number(Metric::slip_time_to_roll);
    std::string speed_error = kNoData, time_error = kNoData;
    if (speed && expected && *expected != 0) {
      const double rel = 100 * (*speed - *expected) / std::abs(*expected);
      speed_error = std::abs(rel) < 0.005 ? "0.00%" : fmt::format("{:+.2f}%", rel);  // no "-0.00%"
    }
    if (t && expected_time) time_error = fmt::format("{:+.3f} s", *t - *expected_time);
    const auto slip = m.number(Metric::slip_final_max);
    put("| {} | {} | {} |{} {} | {} | {} | {} |\n", run_label(*r), status_text(*r),
        or_none(speed, "{:.4f}"), one ? "" : fmt::format(" {} |", or_none(expected, "{:.4f}")), speed_error,
        t ? fmt::format("{:.2f}", *t) : "never", time_error, slip ? fmt::format("{:.2g}", *slip) : kNoData);
  }
  put("\n");
}

// The heaps side by side: one column per scene that measures an angle of repose.
void put_repose(MarkdownBuffer& put, const std::vector<std::string>& scenes,
                const std::vector<std::vector<const Result*>>& rows_of) {
  put("### Angle of repose\n\nBalls let go from a loose block on the floor of a wide box (granular column collapse) "
      "come to rest as a heap whose flanks' slope depends on friction: the same balls with friction and without. "
      "The angle is measured by the harness from each run's final state (`angle_of_repose`, glossary below; "
      "core/metrics/angle_of_repose.h): a frictionless heap spreads flat, near 0; `none`: no flank could be "
      "measured (a layer spread flat, or a column standing).\n\n");
  std::vector<std::string> labels;
  for (const auto& rows : rows_of)
    for (const Result* r : rows) add_once(labels, run_label(*r));
  put("| engine |");
  for (size_t k = 0; k < scenes.size(); ++k)
    put(" `{}` (deg) |", scenes[k]);
  put("\n|---|");
  for (size_t k = 0; k < scenes.size(); ++k) put("---:|");
  put("\n");
  std::vector<std::string> notes;
  for (const std::string& label : labels) {
    put("| {} |", label);
    for (size_t k = 0; k < scenes.size(); ++k) {
      const auto it = std::find_if(rows_of[k].begin(), rows_of[k].end(), [&](const Result* r) { return run_label(*r) == label; });
      if (it == rows_of[k].end()) {
        put(" |");
        continue;
      }
      const Result& r = **it;
      if (!ran(r) || r.status != RunStatus::ok) {
        put(" {} |", ran(r) ? fmt::format("{} (at the end: {})", run_status_text(r.status), or_none(r.metrics.number(Metric::angle_of_repose), "{:.1f}"))
                   : std::string(run_status_text(r.status)));
        if (!r.error.empty()) notes.push_back(fmt::format("{} on `{}`: {}", label, scenes[k], markdown_cell(r.error)));
        continue;
      }
      const auto angle = r.metrics.number(Metric::angle_of_repose);
      put(" {} |", angle ? fmt::format("{:.1f}", *angle) : "none");
    }
    put("\n");
  }
  std::vector<std::string> files;
  for (const auto& rows : rows_of) files.push_back(fmt::format("`{}`", source_text(*rows.front())));
  put("\nScenes: {}.", fmt::join(files, ", "));
  if (!notes.empty()) put(" Runs that did not end ok: {}.", fmt::join(notes, "; "));
  put("\n\n");
}

}  // namespace

std::string friction_section(const std::vector<Result>& results, const std::vector<std::string>& scene_order) {
  std::vector<std::string> rolling, repose;
  for (const std::string& scene : scene_order)
    for (const Result& r : results) {
      if (r.scene != scene) continue;
      if (r.metrics.has(Metric::rolling_expected_speed)) add_once(rolling, scene);
      const bool unmeasured = std::any_of(r.skipped.begin(), r.skipped.end(), [](const std::string& note) {
        return note.starts_with(kReposeUnmeasuredNote);
      });
      if (r.metrics.has(Metric::angle_of_repose) || unmeasured) add_once(repose, scene);
    }
  if (rolling.empty() && repose.empty()) return "";
  const auto rows = [&](const std::string& scene) {
    std::vector<const Result*> out;
    for (const Result& r : results)
      if (r.scene == scene) out.push_back(&r);
    return out;
  };
  MarkdownBuffer put;
  put("Every engine and profile on the scenes that judge friction and rotation against what "
                 "they must do: a ball sliding to roll and a spinning ball dropped, against closed forms, and a heap "
                 "of balls with and without friction, by its angle of repose. Engines without friction refuse these "
                 "scenes (a run that ignored the friction would look right and be wrong); each refusal is shown with "
                 "its reason. Source: `results/SCENE.json`.\n\n");
  for (const std::string& scene : rolling) put_rolling(put, scene, rows(scene));
  if (!repose.empty()) {
    std::vector<std::vector<const Result*>> rows_of;
    for (const std::string& scene : repose) rows_of.push_back(rows(scene));
    put_repose(put, repose, rows_of);
  }
  return fmt::to_string(put.out);
}

}  // namespace ballbench
