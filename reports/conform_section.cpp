#include "conform_section.h"

#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "markdown_buffer.h"
#include "markdown_cell.h"
#include "ordered_set.h"
#include "result.h"

namespace ballbench {
namespace {

struct EngineChecks {
  int passed = 0, failed = 0, refused = 0;
  std::vector<std::string> failures, refuted;
};

}  // namespace

std::string refuted_mark(const ReportInputs& in, const std::string& engine, const std::string& profile) {
  if (!in.conform) return "";
  const auto claims = refuted_claims(*in.conform, engine, profile);
  if (claims.empty()) return "";
  return fmt::format(" [⚠ {} refuted](#closed-form-checks)", fmt::join(claims, ", "));
}

std::string conform_section(const ReportInputs& in) {
  if (!in.conform) return "";
  MarkdownBuffer put;
  put("## Closed-form checks\n\n`ballbench conform` on every engine and profile: free fall, bounces with "
      "restitution, head-on and oblique impacts, a ball sliding to roll, a spinning ball dropped, fast balls kept in a "
      "box and an elastic gas's energy, each against its closed form with one tolerance for any engine "
      "(adapters/conformance.h). A capability an engine's handshake claims that a case misses by far is "
      "**refuted**, and every table that shows the engine marks it. Source: `results/conform.json`.{}\n\n",
      in.conform->interrupted.empty() ? "" : fmt::format(" **Interrupted by {}: the rows below are what ran.**",
                                                          in.conform->interrupted));
  std::vector<std::string> order;
  std::map<std::string, EngineChecks> by;
  for (const ConformRow& r : in.conform->rows) {
    const std::string label = r.profile.empty() ? r.engine : run_label(r.engine, r.profile);
    add_once(order, label);
    EngineChecks& e = by[label];
    if (r.verdict == ConformVerdict::pass) ++e.passed;
    else if (r.verdict == ConformVerdict::refused) ++e.refused;
    else ++e.failed, e.failures.push_back(r.why.empty() ? fmt::format("{} {} > {:g}", r.check, conform_figure_text(r.figure), r.tolerance)
                                                        : fmt::format("{}: {}", r.check, r.why));
    if (!r.refuted.empty()) add_once(e.refuted, r.refuted);
  }
  put("| engine/profile | passed | failed | refused | refuted claims | what failed |\n|---|---:|---:|---:|---|---|\n");
  for (const std::string& label : order) {
    const EngineChecks& e = by[label];
    put("| {} | {} | {} | {} | {} | {} |\n", label, e.passed, e.failed, e.refused,
        e.refuted.empty() ? "" : fmt::format("**{}**", fmt::join(e.refuted, ", ")),
        markdown_cell(fmt::format("{}", fmt::join(e.failures, "; "))));
  }
  put("\nRefused: a case the engine says it cannot run (an engine without friction refuses the friction cases), "
      "neither a pass nor a refuted claim.\n\n");
  return put.str();
}

}  // namespace ballbench
