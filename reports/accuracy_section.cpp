#include "accuracy_section.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "balls_text.h"
#include "conform_section.h"
#include "json_value.h"
#include "markdown_cell.h"
#include "page_links.h"
#include "report_part.h"
#include "result.h"

namespace ballbench {
namespace {

// The figure of the spec's term that is furthest from its bound in try `t`, as "overlap 0.034".
// A try stopped where it missed is named by the terms it was judged on, those that only grow.
std::string worst_term_text(const MatchTry& t, const AccuracySpec& spec) {
  std::string worst;
  double worst_ratio = -1;
  for (const SpecTermDef& d : spec_terms()) {
    const auto& bound = spec[d.term];
    if (!bound || (t.status == RunStatus::missed && !d.grows)) continue;
    const auto f = t.figures.value(d.key, nlohmann::json());
    if (!f.is_number()) return fmt::format("{} not measured", d.key);
    const double x = f.get<double>();
    const double ratio = term_miss(d, *bound, x);
    if (ratio > worst_ratio) worst_ratio = ratio, worst = fmt::format("{} {}", d.key, figure_text(f));
  }
  return worst;
}

// The searches' outcomes, the cheapest first; then what did not meet the spec.
std::vector<const MatchOutcome*> ranked_rows(const MatchResult& m) {
  std::vector<const MatchOutcome*> rows;
  for (const MatchOutcome& oc : m.outcomes) rows.push_back(&oc);
  std::stable_sort(rows.begin(), rows.end(), [](const MatchOutcome* a, const MatchOutcome* b) {
    const bool ranked_a = a->ranked(), ranked_b = b->ranked();
    if (ranked_a != ranked_b) return ranked_a;
    return ranked_a && a->cost_ns < b->cost_ns;
  });
  return rows;
}

void put_match_table(std::string& md, const ReportInputs& in, const MatchResult& m,
                     const std::vector<const MatchOutcome*>& rows) {
  std::vector<std::string> terms;
  for (const SpecTermDef& d : spec_terms())
    if (m.spec[d.term]) terms.push_back(d.key);
  md += "| engine/profile | meets the spec | configuration | cost (ns) |";
  for (const auto& t : terms) md += fmt::format(" {} |", t);
  md += " tries |\n|---|---|---|---:|";
  for (size_t k = 0; k < terms.size(); ++k) md += "---:|";
  md += "---:|\n";
  for (const MatchOutcome* oc : rows) {
    const std::string label = run_label(oc->engine, oc->profile) + refuted_mark(in, oc->engine, oc->profile);
    const int shown = oc->reached ? oc->found : oc->best;
    const MatchVerdict v = verdict_of(m, *oc);
    md += fmt::format("| {} | {} | ", label,
                      v == MatchVerdict::met         ? "yes"
                      : v == MatchVerdict::cut_short ? markdown_cell("cut short: " + miss_text(m, *oc))
                      : v == MatchVerdict::over_ceiling || v == MatchVerdict::outpaced
                          ? markdown_cell("yes, " + miss_text(m, *oc))
                                                     : markdown_cell("no: " + miss_text(m, *oc)));
    if (shown < 0) {
      md += "n/a | n/a |";
      for (size_t k = 0; k < terms.size(); ++k) md += " n/a |";
    } else {
      const MatchTry& t = m.tries[shown];
      md += fmt::format("{}{} | {} |", oc->reached ? "" : "finest: ", markdown_cell(configuration_text(t)),
                        oc->reached ? cost_spread_text(*oc) : "n/a");
      for (const auto& key : terms) md += fmt::format(" {} |", figure_text(t.figures.value(key, nlohmann::json())));
    }
    md += fmt::format(" {} |\n", oc->tries);
  }
}

// How the cost was measured and how the searches were bounded, when and by which build.
void put_match_method(std::string& md, const MatchResult& m, bool measured) {
  md += fmt::format(
      "\nCost: the engine's step time per ball per scene step in CPU time (a step of dt/8 costs 8 of its steps), "
      "{} (± half their range); figures as the harness measured them from the states at the scene's step times. "
      "\"n/a\": not measured.",
      timing_method_text());
  if (m.budget_runs > 0)
    md += fmt::format(" Each search's budget: {:g} runs of the scene at dt ({:.3g} ball steps); a try stopped where "
                      "a term that only grows passed its bound.",
                      m.budget_runs, m.budget_runs * double(m.run_ball_steps));
  if (m.ceiling_ns > 0)
    md += fmt::format(" Ceiling: {:g}x our solver's cost ({} ns), searched first; a try stopped once its CPU time passed "
                      "{:g}x the ceiling, and a configuration met past the ceiling is over it.",
                      m.ceiling, cost_text(m.ceiling_ns), kClearlyCostlier);
  if (m.within > 0)
    md += fmt::format(" An engine is searched while it can be within {:g}x the cheapest of its kind (ours, external): "
                      "a try stopped once its CPU time passed {:g}x the cheapest configuration met so far, and one met "
                      "past {:g}x, timed alone, is outpaced.",
                      m.within, kClearlyCostlier * m.within, m.within);
  md += fmt::format(" Measured {} by build {}{}.\n\n", json_string_field(m.context, "date", "(not recorded)"),
                    json_string_field(m.context, "build", "(not recorded)"),
                    measured ? ": a search measured on its own (`ballbench match`) and carried into this report as it was"
                             : "");
}

// Each of our profiles that met the spec against the cheapest external engine that did.
void put_our_ratios(std::string& md, const MatchResult& m) {
  const MatchOutcome* ext = cheapest_reached(m, role_name(EngineRole::external));
  for (const MatchOutcome& oc : m.outcomes) {
    if (oc.role != role_name(EngineRole::ours)) continue;
    const std::string label = run_label(oc.engine, oc.profile);
    if (!oc.reached) continue;
    if (ext)
      md += fmt::format("- **{}** costs {} ns: {} than the cheapest external engine that meets the spec "
                        "({}, {} ns at {}).\n",
                        label, cost_text(oc.cost_ns), cheaper_text(ext->cost_ns / oc.cost_ns),
                        run_label(ext->engine, ext->profile), cost_text(ext->cost_ns),
                        configuration_text(m.tries[ext->found]));
    else if (const auto at_least = ratio_at_least(m, oc))
      md += fmt::format("- **{}** costs {} ns: {} than every external engine (each stopped at the ceiling or did not "
                        "meet the spec).\n",
                        label, cost_text(oc.cost_ns), at_least_text(*at_least));
    else
      md += fmt::format("- **{}** costs {} ns; no external engine met the spec.\n", label, cost_text(oc.cost_ns));
  }
}

void section_for(std::string& md, const ReportInputs& in, const MatchResult& m, const std::vector<Figure>& figures) {
  md += fmt::format("## {}\n\n", accuracy_heading(m.scene));
  md += fmt::format("{}, class `{}`, the scene's dt = {:g} s. Spec: {}.", balls_text(m.n), m.scene_class, m.dt,
                    m.spec.text());
  if (!m.interrupted.empty()) md += fmt::format(" **Interrupted by {}: the rows below are what ran.**", m.interrupted);
  md += "\n\n";
  const std::vector<const MatchOutcome*> rows = ranked_rows(m);
  put_match_table(md, in, m, rows);
  const bool measured = in.measured.contains(m.scene);
  put_match_method(md, m, measured);
  put_our_ratios(md, m);
  for (const Figure& f : figures)
    if (f.kind == FigureKind::front && f.scene == m.scene)
      md += fmt::format("\n![work-precision front of {}]({})\n\n*{}*\n", m.scene, f.file, f.caption);
  md += "\n<details><summary>Reproduce each row with <code>ballbench run</code></summary>\n\n";
  for (const MatchOutcome* oc : rows)
    if (!oc->command.empty()) md += fmt::format("- {}: `{}`\n", run_label(oc->engine, oc->profile), oc->command);
  md += fmt::format("\nEvery try: `results/{}`.\n\n</details>\n\n",
                    measured ? part_file({PartKind::measured, m.scene}) : fmt::format("match-{}.csv", m.scene));
}

}  // namespace

MatchVerdict verdict_of(const MatchResult& m, const MatchOutcome& oc) {
  if (oc.cut_short()) return MatchVerdict::cut_short;
  if (oc.over_ceiling()) return MatchVerdict::over_ceiling;
  if (oc.outpaced()) return MatchVerdict::outpaced;
  if (oc.reached) return MatchVerdict::met;
  bool any_ok = false, all_unsupported = true;
  for (const MatchTry& t : m.tries)
    if (t.engine == oc.engine && t.profile == oc.profile) {
      any_ok = any_ok || t.status == RunStatus::ok || t.status == RunStatus::missed;
      all_unsupported = all_unsupported && t.status == RunStatus::unsupported;
    }
  if (oc.tries > 0 && all_unsupported) return MatchVerdict::unsupported;
  return any_ok ? MatchVerdict::not_reached : MatchVerdict::failed;
}

namespace {

// "past 2x the cheapest external engine's cost (10439 ns)": what an outpaced search is past.
std::string outpaced_text(const MatchResult& m, const MatchOutcome& oc) {
  const auto bound = outpace_ns(m, oc.role);
  return "past " + outpace_text(m.within, oc.role, bound ? std::optional(*bound / m.within) : std::nullopt);
}

}  // namespace

std::string miss_text(const MatchResult& m, const MatchOutcome& oc) {
  const MatchVerdict v = verdict_of(m, oc);
  // What met is said by its search's stop, not by a try that missed.
  switch (v) {
    case MatchVerdict::met: return "";
    case MatchVerdict::cut_short:
      return fmt::format("its search stopped at {} before trying every configuration: its cost is an upper bound, "
                         "not ranked",
                         oc.stopped);
    case MatchVerdict::over_ceiling: return fmt::format("past the ceiling ({} ns): not ranked", cost_text(m.ceiling_ns));
    case MatchVerdict::outpaced: return outpaced_text(m, oc) + ": not ranked";
    default: break;
  }
  if (oc.best < 0) return "no configuration ran";
  const MatchTry& b = m.tries[oc.best];
  const std::string finest = oc.finest_dt > 0 ? fmt::format("dt/{:.0f}", std::round(m.dt / oc.finest_dt)) : "dt";
  const std::string stop = oc.stop == SearchStop::budget    ? ", out of budget"
                           : oc.stop == SearchStop::ceiling ? fmt::format(", over the ceiling ({} ns)", cost_text(m.ceiling_ns))
                           : oc.stop == SearchStop::outpaced ? ", " + outpaced_text(m, oc)
                                                            : "";
  // A try stopped where it missed: when it passed its bound.
  const double duration = m.n > 0 ? double(m.run_ball_steps) / m.n * m.dt : 0;
  const std::string when = b.status == RunStatus::missed && duration > 0
                               ? fmt::format(", past its bound by t = {:.3g} s", b.done * duration)
                               : "";
  if (v == MatchVerdict::unsupported) return "unsupported";
  if (v == MatchVerdict::failed)
    return fmt::format("{} at every step down to {}{}", run_status_text(b.status), finest == "dt/1" ? "dt" : finest,
                       stop);
  return fmt::format("{} at {}{}{}", worst_term_text(b, m.spec), step_text(b.halvings), when, stop);
}


std::string cheaper_text(double ratio) {
  return ratio >= 1 ? fmt::format("**{} cheaper**", ratio_text(ratio))
                    : fmt::format("**{} costlier**", ratio_text(1 / ratio));
}

std::string at_least_text(double ratio) { return fmt::format("**over {} cheaper**", ratio_text(ratio)); }

std::string accuracy_heading(const std::string& scene) { return fmt::format("Equal accuracy: `{}`", scene); }

std::string accuracy_anchor(const std::string& scene) { return heading_anchor(accuracy_heading(scene)); }

std::string accuracy_section(const ReportInputs& in, const MatchResult& m, const std::vector<Figure>& figures) {
  std::string md;
  section_for(md, in, m, figures);
  return md;
}

}  // namespace ballbench
