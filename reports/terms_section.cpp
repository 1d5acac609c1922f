#include "terms_section.h"

#include <fmt/format.h>

#include "accuracy_spec.h"
#include "markdown_buffer.h"
#include "match_result.h"
#include "metrics/catalog.h"
#include "runner.h"

namespace ballbench {
namespace {

// The spec's terms as core/accuracy_spec.cpp declares them, each with its unit.
void put_spec_terms(MarkdownBuffer& put) {
  put("## Spec terms\n\nA spec bounds some of these, each measured by the harness from the run's states (never taken "
      "from an engine); a configuration meets the spec when every bounded term is within its bound. Scenes and their "
      "classes' default specs: [scenarios/README.md](../scenarios/README.md#accuracy).\n\n");
  put("| term | unit | bound | what is measured |\n|---|---|---|---|\n");
  for (const SpecTermDef& d : spec_terms())
    put("| `{}` | {} | at {} | {} |\n", d.key, *d.unit ? d.unit : "none (a count or a fraction)",
        d.at_least ? "least" : "most", d.doc);
  put("\n");
}

void put_cost_terms(MarkdownBuffer& put) {
  put("## Cost, step and search\n\n"
      "- **cost** (ns): the engine's own step time per ball per scene step, in CPU time (an engine on several threads "
      "is charged for each; an engine in another process times its own step call). A configuration at dt/8 makes 8 "
      "steps per scene step, so it costs 8 of them. The cost is that of {} (a host's cores can differ by a quarter, "
      "and a job beside the timing only adds time), with half their range as its spread (`±2%`). Where several configurations of one engine met the spec at costs within "
      "{:g}x of each other, they are timed in turn and the first in search order (the profile as it is, then each "
      "knob) is the one found unless a later one costs less than {:g} of it; the others are named beside it.\n"
      "- **a tie**: two engines whose costs' ranges overlap: the timing cannot tell them apart, and either is the "
      "pick; the summary names both.\n"
      "- **dt, dt/2^k**: dt is the scene's own step (s); a configuration at dt/2^k steps 2^k times as often.\n"
      "- **configuration**: a profile, at one step size, with at most one of the engine's own knobs set on top of it "
      "(`iterations=5`).\n"
      "- **budget**: each search's work, in runs of the whole scene at dt (n balls x steps ball steps each); a try "
      "at dt/2^k costs 2^k of them, one that stopped where it missed its share, one stopped at a cost limit nothing. "
      "Work, not seconds, so one build finds the "
      "same configurations on any machine.\n"
      "- **ceiling**: a multiple of our solver's cost (searched first); an engine past it cannot be the cheapest. A "
      "try stops once its CPU time passes {:g} times the ceiling (so far past it that the machine's load cannot carry "
      "a try under the ceiling over it), and a configuration that met at a cost past the ceiling is \"over the "
      "ceiling\", not ranked. Where every external engine is over it, our ratio reads \"over Nx\".\n"
      "- **outpaced**: an engine whose configurations cost more than a multiple (each scene's section states it) "
      "of the cheapest configuration any engine of its kind (ours, external) met: it cannot be the cheapest, so "
      "its tries stop once their CPU time passes {:g} times that, and one that met past it is \"outpaced\", not "
      "ranked.\n"
      "- **not reached**: no configuration tried met the spec; the nearest miss is named with its figure and step; "
      "\"out of budget\", \"over the ceiling\" and \"outpaced\" say why the search stopped.\n"
      "- **cut short**: a configuration met the spec, but the search stopped (its budget, an interrupt) before "
      "trying every configuration, so a cheaper one may exist: its cost is an upper bound and it is not ranked.\n\n",
      timing_method_text(), kClearlyCostlier, kKnobCostMargin, kClearlyCostlier, kClearlyCostlier);
}

void put_profiles(MarkdownBuffer& put) {
  put("## Profiles\n\n"
      "- **stock**: an external engine as shipped (its own defaults).\n"
      "- **tuned**: what the engine's own documentation and issue tracker recommend for balls like these "
      "(`adapters/*/README.md` cites them).\n"
      "- **home** (ours): **default** builds itself for the spec asked (its method, substeps and iterations chosen "
      "from the scene and the spec); **events** resolves every contact as an event in time order; **soft** holds "
      "resting contacts as stiff springs (`core/solver/README.md`).\n"
      "- **home-seed**: the thesis's MATLAB algorithm ported faithfully, as the thesis ran it.\n"
      "- **exact**: the event-driven reference: every collision at its time, to round-off "
      "(`core/solver/EXACT.md`).\n\n");
}

void put_metric_columns(MarkdownBuffer& put, const ReportInputs& in) {
  const MetricsConfig cfg = in.results.empty() ? MetricsConfig{} : in.results.front().metrics_config;
  put("## Table columns\n\n");
  for (const MetricDef& m : metric_catalog())
    if (!m.column.empty()) {
      // The unit once: a column's header may already carry it ("slip at end (m/s)").
      const std::string unit = fmt::format(" ({})", m.unit);
      put("- **{}**{}: {}.\n", m.column, m.unit.empty() || m.column.ends_with(unit) ? "" : unit, m.definition(cfg));
    }
  put("- **pos error vs reference** (m): position RMS error over balls against the event-driven `exact` engine run "
      "in lockstep (for a scene `exact` cannot run, such as rough balls on each other under gravity, a converged run "
      "stands in: the scene stepped by Chipmunk at dt / {}, named under the scene's table), at the last step; "
      "**horizon** (s): the first time that error exceeded a tenth of the mean radius (chaotic scenes part from any "
      "reference, so this says more than a long-run RMS; `never`: it stayed within). Where `exact` itself failed, "
      "the comparison runs up to that step.\n",
      kConvergedSubsteps);
  put("- **diverged@k**: the state became non-finite, or the energy exceeded {} times its initial value, at step k; "
      "metrics cover the steps before.\n",
      cfg.divergence_energy_factor);
  put("- **work against precision**: for each engine and setting, the engine's step time to reach a fixed simulated "
      "time (median of repeated runs, with their spread) against its position RMS error against `exact` at that "
      "time and its energy error (max |E - E_exact| / E0); the **Pareto front** of an engine is its settings that no "
      "other setting of it beats in both.\n");
  put("- **stability frontier**: the largest multiple of a knob (dt, initial speeds, the mass of every other ball, "
      "ball count) at which a run still passes: status ok, no tunnelling, energy within the tolerance of `exact`'s "
      "and not grown.\n");
  put("- **scaling**: ns per ball-step from the step benchmark at each ball count; flat lines are linear cost.\n");
  put("\nEvery metric of a run's JSON, with its unit and definition: `ballbench list --metrics`.\n");
}

}  // namespace

std::string terms_section(const ReportInputs& in) {
  MarkdownBuffer put;
  put_spec_terms(put);
  put_cost_terms(put);
  put_profiles(put);
  put_metric_columns(put, in);
  return put.str();
}

}  // namespace ballbench
