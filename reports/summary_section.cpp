#include "summary_section.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accuracy_section.h"
#include "result.h"

namespace ballbench {
namespace {

// The engine and profile with the smallest error on the front's axis at the scene's own step, the
// profile as it is: who is most accurate before anyone refines. Where the spec has no principal
// term (only counts), those that meet it at the scene's step.
std::string most_accurate_at_dt(const MatchResult& m) {
  std::vector<std::pair<double, std::string>> at_dt;
  for (const MatchTry& t : m.tries)
    if (t.halvings == 0 && t.knob.empty())
      if (const auto e = front_error(t, m.spec)) at_dt.emplace_back(*e, run_label(t.engine, t.profile));
  std::stable_sort(at_dt.begin(), at_dt.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  const auto term = principal_term(m.spec);
  if (!term) {
    std::vector<std::string> met;
    for (const MatchTry& t : m.tries)
      if (t.halvings == 0 && t.knob.empty() && t.met) met.push_back(run_label(t.engine, t.profile));
    return met.empty() ? "none meets it at dt" : fmt::format("meet it at dt: {}", fmt::join(met, ", "));
  }
  if (at_dt.empty()) return "n/a";
  // Figures a millionth of the bound apart are round-off: no ranking among them.
  const double level = std::max(at_dt.front().first, *m.spec[*term] * 1e-6);
  std::vector<std::string> equal;
  for (const auto& [e, label] : at_dt)
    if (e <= level) equal.push_back(label);
  if (equal.size() == 1) return fmt::format("{} ({} {:.2g})", equal.front(), spec_term(*term).key, at_dt.front().first);
  const size_t shown = std::min<size_t>(equal.size(), 4);
  return fmt::format("{} equal, {} below {:.0e}: {}{}", equal.size(), spec_term(*term).key, level * 1.0001,
                     fmt::join(equal.begin(), equal.begin() + shown, ", "),
                     equal.size() > shown ? fmt::format(" and {} more", equal.size() - shown) : "");
}

// The cheapest of `role` that met the spec; where none did, the nearest miss, so the reader still
// has a name and a figure.
std::string found_text(const MatchResult& m, EngineRole role) {
  const MatchOutcome* oc = cheapest_reached(m, role_name(role));
  if (!oc) {
    const MatchOutcome* near = nearest_unreached(m, role_name(role));
    return near ? fmt::format("none; nearest: {} ({})", run_label(near->engine, near->profile),
                              miss_text(m, *near))
                : "none";
  }
  return fmt::format("{}, {}: {} ns", run_label(oc->engine, oc->profile), configuration_text(m.tries[oc->found]),
                     cost_text(oc->cost_ns));
}

}  // namespace

std::string summary_section(const ReportInputs& in, const std::vector<Figure>& figures) {
  if (in.matches.empty()) return "";
  std::string md = "## Summary\n\n";
  md += "Each engine is asked for the same accuracy: for every scene a stated spec (overlap, tunnelling, rest, energy, "
        "closed forms; [the terms](../scenarios/README.md#accuracy)), and each engine and profile's cheapest configuration that meets it "
        "(its step size dt/2^k and its own knobs, found by `ballbench match` within a budget of work, so the same on any machine). Cost is the "
        "engine's own step time per ball per scene step, each found configuration timed alone (the median of "
        "three windows of its run).";
  double ceiling = 0;
  for (const MatchResult& m : in.matches) ceiling = std::max(ceiling, m.ceiling_ns > 0 ? m.ceiling : 0.0);
  if (ceiling > 0)
    md += fmt::format(" A try stops once it costs {:g} times our solver's cost (the ceiling): an engine past it "
                      "cannot be the cheapest and is not searched to its end.",
                      ceiling);
  md += "\n\n";
  md += "| scene (class) | spec | cheapest external engine that meets it | ours | ours against it | most accurate at "
        "the scene's dt |\n|---|---|---|---|---|---|\n";
  std::vector<std::string> misses;
  bool undecided = false;  // a row where ours met the spec and no external engine did within its budget
  for (const MatchResult& m : in.matches) {
    const MatchOutcome* ext = cheapest_reached(m, role_name(EngineRole::external));
    const MatchOutcome* ours = cheapest_reached(m, role_name(EngineRole::ours));
    std::string ratio = "n/a";
    if (ours && ext) ratio = cheaper_text(ext->cost_ns / ours->cost_ns);
    else if (const auto at_least = ours ? ratio_at_least(m, *ours) : std::nullopt) ratio = at_least_text(*at_least);
    else if (ours) ratio = "undecided", undecided = true;
    else if (ext) ratio = "ours did not meet it";
    md += fmt::format("| [`{}`](#{}) ({}) | {} | {} | {} | {} | {} |\n", m.scene, accuracy_anchor(m.scene), m.scene_class,
                      m.spec.text(), found_text(m, EngineRole::external), found_text(m, EngineRole::ours), ratio, most_accurate_at_dt(m));
    std::vector<std::string> failed;
    for (const MatchOutcome& oc : m.outcomes)
      if (!oc.reached && verdict_of(m, oc) != MatchVerdict::unsupported)
        failed.push_back(fmt::format("{} ({})", run_label(oc.engine, oc.profile), miss_text(m, oc)));
    if (!failed.empty())
      misses.push_back(fmt::format("- [`{}`](#{}): {}.", m.scene, accuracy_anchor(m.scene), fmt::join(failed, "; ")));
  }
  if (undecided)
    md += "\nWhere no external engine met the spec within its search's budget, the ratio waits on longer "
          "searches (the external engines need their finest steps there): `ballbench match --scene SCENE --budget "
          "2000 --target 10` runs one, and [core/solver/PERFORMANCE.md](../core/solver/PERFORMANCE.md#where-the-"
          "targets-stand) holds those measured.\n";
  if (!misses.empty())
    md += fmt::format("\nDid not meet the spec at any configuration tried (the nearest miss; \"out of budget\": the "
                      "search's work budget ran out first; \"over the ceiling\": its tries passed a multiple of our "
                      "solver's cost and were stopped there):\n\n{}\n",
                      fmt::join(misses, "\n"));
  for (const Figure& f : figures)
    if (f.kind == "fronts") md += fmt::format("\n![every scene's work-precision front]({})\n\n*{}*\n", f.file, f.caption);
  md += "\n";
  return md;
}

}  // namespace ballbench
