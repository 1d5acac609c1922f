#include "summary_section.h"

#include <algorithm>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accuracy_section.h"
#include "balls_text.h"
#include "conform_section.h"
#include "json_value.h"
#include "markdown_cell.h"
#include "result.h"

namespace ballbench {
namespace {

std::string term_words(SpecTerm t, double bound) {
  switch (t) {
    case SpecTerm::overlap: return fmt::format("overlap ≤ {:g}%", 100 * bound);
    case SpecTerm::tunnelling: return bound == 0 ? "no tunnelling" : fmt::format("≤ {:g} tunnelled", bound);
    case SpecTerm::sticking: return bound == 0 ? "no sticking" : fmt::format("≤ {:g} stuck", bound);
    case SpecTerm::rest_speed: return fmt::format("at rest (≤ {:.2g} m/s)", bound);
    case SpecTerm::energy_drift: return fmt::format("energy kept to {:g}%", 100 * bound);
    case SpecTerm::energy_error: return fmt::format("energy within {:g}% of the reference's", 100 * bound);
    case SpecTerm::horizon: return fmt::format("follows the reference for ≥ {:g} s", bound);
    case SpecTerm::rolling: return fmt::format("rolling speed to {:g}%", 100 * bound);
  }
  return "";
}

// "**chipmunk** as shipped": an engine and its profile.
std::string engine_words(const MatchOutcome& oc) {
  const std::string profile = oc.profile == "stock"   ? " as shipped"
                              : oc.profile == "tuned" ? " tuned"
                              : oc.profile == "default" ? ""
                                                        : fmt::format(" ({})", oc.profile);
  return fmt::format("**{}**{}", oc.engine, profile);
}

// "**chipmunk** as shipped, dt/64, iterations = 5": a configuration found.
std::string configuration_words(const ReportInputs& in, const MatchResult& m, const MatchOutcome& oc) {
  const MatchTry& t = m.tries[oc.found];
  const std::string knob = t.knob.empty() ? "" : fmt::format(", {} = {}", t.knob, json_text(t.value));
  return fmt::format("{}, {}{}{}", engine_words(oc), step_text(t.halvings), knob, refuted_mark(in, oc.engine, oc.profile));
}

// The pick's cells: configuration and cost, or the nearest miss. Those tied with the pick are named;
// their configurations and costs are on the scene's page.
std::pair<std::string, std::string> pick_cells(const ReportInputs& in, const MatchResult& m, EngineRole role) {
  if (const MatchOutcome* oc = cheapest_reached(m, role_name(role))) {
    std::string words = configuration_words(in, m, *oc);
    const char* joint = "; [tied](pages/terms.md#cost-step-and-search) with ";
    std::set<std::string> named{oc->engine};  // an engine once, whichever of its profiles tie
    for (const MatchOutcome* tie : tied_with(m, *oc)) {
      if (!named.insert(tie->engine).second) continue;
      words += joint + engine_words(*tie);
      joint = " and ";
    }
    return {words, cost_spread_text(*oc)};
  }
  const MatchOutcome* near = nearest_unreached(m, role_name(role));
  if (!near) return {"none ran", "n/a"};
  const std::string why = near->stop == SearchStop::ceiling ? fmt::format("within {:g}x our cost", m.ceiling)
                          : near->stop == SearchStop::budget   ? "within the budget"
                          : near->stop == SearchStop::outpaced ? "ranked"
                                                               : "at any step tried";
  const std::string met = near->over_ceiling() || near->outpaced() ? fmt::format(", met at {} ns", cost_text(near->cost_ns))
                                                                   : "";
  return {fmt::format("none {} (nearest: {}{})", why, run_label(near->engine, near->profile), met), "n/a"};
}

std::string ratio_cell(const MatchResult& m) {
  const MatchOutcome* ext = cheapest_reached(m, role_name(EngineRole::external));
  const MatchOutcome* ours = cheapest_reached(m, role_name(EngineRole::ours));
  if (ours && ext) return cheaper_text(ext->cost_ns / ours->cost_ns);
  if (const auto at_least = ours ? ratio_at_least(m, *ours) : std::nullopt) return at_least_text(*at_least);
  if (ours) return "undecided: no external engine met it";
  return ext ? "ours did not meet it" : "n/a";
}

// How the figures were made: cost, the searches' budget and ceiling, when and by which build (one:
// read_report_inputs refuses results of several).
std::string provenance(const ReportInputs& in) {
  double budget = 0, ceiling = 0;
  std::set<std::string> builds, dates, steps;
  for (const MatchResult& m : in.matches) {
    if (in.measured.contains(m.scene)) continue;  // said on its own (measured_text)
    steps.insert(fmt::format("{:g} s", m.dt));
    budget = std::max(budget, m.budget_runs), ceiling = std::max(ceiling, m.ceiling_ns > 0 ? m.ceiling : 0.0);
    if (const auto b = json_string_field(m.context, "build"); !b.empty()) builds.insert(b);
    if (const auto d = json_string_field(m.context, "date"); !d.empty()) dates.insert(d.substr(0, 10));
  }
  std::string md = "Cost: the engine's CPU time per ball per scene step (ns), the configuration found timed alone "
                   "(the fastest of at least three timings of a window of its run, or of all of it where that takes under 0.2 s, "
                   "more for a short one, run on each core in turn, "
                   "each run again until the engine is warm; ± half their range).";
  md += fmt::format(" dt: the scene's own step ({}); a step of dt/64 makes 64 steps per scene step.",
                    steps.size() == 1 ? *steps.begin() + " in each" : fmt::format("{}", fmt::join(steps, ", ")));
  if (budget > 0)
    md += fmt::format(" Each search could spend the work of {:g} runs of its scene at dt{}.", budget,
                      ceiling > 0 ? fmt::format("; an engine past {:g}x our cost is over the ceiling (it cannot be the "
                                                "cheapest), its tries stopped at {:g}x",
                                                ceiling, kClearlyCostlier * ceiling)
                                  : "");
  md += " Every word: [terms](pages/terms.md).";
  const std::string run_build = json_string_field(in.run, "build");
  if (!run_build.empty()) builds.insert(run_build);
  md += fmt::format(" Measured {} on {} ({} cores), {} suite, by build {}.\n\n",
                    dates.empty() ? json_string_field(in.run, "date") : fmt::format("{}", fmt::join(dates, ", ")),
                    json_string_field(in.run, "cpu"), in.run.is_object() ? json_text(in.run.value("cores", nlohmann::json())) : "?",
                    in.run.is_object() ? in.run.value("suite", "quick") : "quick", fmt::join(builds, ", "));
  return md;
}

// The searches carried in rather than run by this report: when, by which build and within what.
std::string measured_text(const ReportInputs& in) {
  std::vector<std::string> each;
  for (const MatchResult& m : in.matches)
    if (in.measured.contains(m.scene))
      each.push_back(fmt::format("`{}` (measured {} by build {}, each search's budget {:g} runs of the scene at dt{})",
                                 m.scene, json_string_field(m.context, "date", "(not recorded)").substr(0, 10),
                                 json_string_field(m.context, "build", "(not recorded)"), m.budget_runs,
                                 m.ceiling_ns > 0 ? fmt::format(", ceiling {:g}x our cost", m.ceiling) : ""));
  if (each.empty()) return "";
  const bool one = each.size() == 1;
  const std::string last = each.back();
  each.pop_back();
  const std::string listed = each.empty() ? last : fmt::format("{} and {}", fmt::join(each, ", "), last);
  return fmt::format("{}, {}, {} too costly for this suite, measured on {} own (`ballbench match`) and carried into "
                     "this report as {}. ",
                     one ? "The carried row" : "The carried rows", listed, one ? "is a search" : "are searches",
                     one ? "its" : "their", one ? "it was" : "they were");
}

}  // namespace

std::string spec_words(const AccuracySpec& spec) {
  std::vector<std::string> words;
  for (const SpecTermDef& d : spec_terms())
    if (const auto& bound = spec[d.term]) words.push_back(term_words(d.term, *bound));
  return fmt::format("{}", fmt::join(words, ", "));
}

std::string summary_section(const ReportInputs& in, const std::vector<Figure>& figures) {
  std::string md =
      "Which 2D ball-physics engine to pick, at equal accuracy: per use case one spec, each engine's cheapest "
      "configuration that meets it (a step size and at most one of its settings), and ours (`home`) against the "
      "cheapest external one.\n\n";
  if (in.matches.empty()) return md + "No equal-accuracy results in this report.\n\n";
  md += "| use case | [spec](pages/terms.md#spec-terms) | cheapest external engine | [cost](pages/terms.md#cost-step-and-search) (ns) | "
        "ours | cost (ns) | ratio |\n|---|---|---|---:|---|---:|---|\n";
  for (const MatchResult& m : in.matches) {
    const auto [ext, ext_cost] = pick_cells(in, m, EngineRole::external);
    const auto [ours, our_cost] = pick_cells(in, m, EngineRole::ours);
    md += fmt::format("| [{}](#{}), {}{} | {} | {} | {} | {} | {} | {} |\n",
                      m.use_case.empty() ? m.scene : m.use_case, accuracy_anchor(m.scene), balls_text(m.n),
                      in.measured.contains(m.scene) ? ", carried (below)" : "",
                      spec_words(m.spec), markdown_cell(ext), ext_cost, markdown_cell(ours), our_cost, ratio_cell(m));
  }
  // At scale: a search at 10^4 balls takes an hour, the full suite's or measured on its own; the step
  // benchmark's scaling is in every report.
  constexpr int kAtScale = 10000;
  const auto at_scale = [&](bool measured) {
    return std::any_of(in.matches.begin(), in.matches.end(),
                       [&](const MatchResult& m) { return m.n >= kAtScale && in.measured.contains(m.scene) == measured; });
  };
  md += "\n";
  md += measured_text(in);
  if (!at_scale(false))  // this report ran none: the full suite's
    md += fmt::format("The {}equal-accuracy searches at 10^4 balls are the full suite's (`scripts/report --full`){}.",
                      at_scale(true) ? "other " : "",
                      in.bench ? "; how each engine's step cost grows is on [scaling](pages/scaling.md)" : "");
  md += "\n\n" + provenance(in);
  for (const Figure& f : figures)
    if (f.kind == FigureKind::fronts) md += fmt::format("![every scene's work-precision front]({})\n\n*{}*\n\n", f.file, f.caption);
  return md;
}

}  // namespace ballbench
