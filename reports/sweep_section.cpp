#include "sweep_section.h"

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

#include "json_value.h"
#include "figure_markdown.h"
#include "markdown_buffer.h"
#include "result.h"
#include "ordered_set.h"
#include "balls_text.h"
#include "markdown_cell.h"
#include "no_data.h"

namespace ballbench {
namespace {

std::string setting_text(const SweepPoint& p) {
  if (p.knob == "dt") return "dt";
  return p.knob + " = " + json_text(p.value);
}

void put_sweep(MarkdownBuffer& put, const SweepResult& sw, const std::vector<Figure>& figures) {
  put("## Work against precision: `{}`\n\n", sw.scene);
  put("`ballbench sweep` on {}: every engine and profile at several step sizes, and with each of its own "
      "accuracy knobs changed one at a time. Error: position RMS against `{}` at t = {} s (short enough that the "
      "trajectories of a chaotic many-ball system have not yet parted completely); engine time: the engine's own "
      "step time to reach it, median of {} runs. Every point, with its settings: `results/sweep-{}.json` (and "
      "`.csv`).\n\n",
      balls_text(sw.n), sw.reference, sw.horizon, sw.repeats, sw.scene);
  put_figures(put, figures, FigureKind::work_precision, sw.scene);
  put("Each engine's Pareto front, fastest first: the settings no other setting of the same engine beats, being at "
      "least as accurate and not slower, and more accurate or faster beyond the noise (its slowest timing repeat "
      "below the other's fastest). Two settings whose repeats overlap are equally fast: a ranking inside the "
      "run-to-run noise is no claim, so a front may hold settings whose medians alone would put one behind "
      "another.\n\n");
  put("| engine | setting | dt (s) | engine time (ms): median [min, max] | ns/ball-step | pos error (m) | "
      "energy error | tunnelled, stuck |\n|---|---|---|---|---|---|---|---|\n");
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
    put("| {} | {} | {} | {:.3g} [{:.3g}, {:.3g}] | {:.0f} | {:.3g} | {:.3g} | {}, {} |\n", run_label(p->engine, p->profile),
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

}  // namespace

std::string sweep_section(const SweepResult& sw, const std::vector<Figure>& figures) {
  MarkdownBuffer put;
  put_sweep(put, sw, figures);
  return put.str();
}

}  // namespace ballbench
