#include "frontier_section.h"

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

#include "balls_text.h"
#include "json_value.h"
#include "figure_markdown.h"
#include "markdown_buffer.h"
#include "result.h"
#include "ordered_set.h"
#include "markdown_cell.h"
#include "no_data.h"

namespace ballbench {
namespace {

void put_frontier(MarkdownBuffer& put, const FrontierResult& f, const std::vector<Figure>& figures) {
  put("## Stability frontier: `{}`\n\n", f.scene);
  put("`ballbench stress` on {}: each knob doubled until a run of {} steps fails (level k runs the knob at "
      "2^(k-1) times the scene's value; `count` tiles the scene side by side). The table gives the largest value "
      "that passed and why the next level failed. Source: `results/stress-{}.json`.\n\n",
      balls_text(f.n), f.steps, f.scene);
  put_figures(put, figures, FigureKind::frontier, f.scene);
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

}  // namespace

std::string frontier_section(const FrontierResult& f, const std::vector<Figure>& figures) {
  MarkdownBuffer put;
  put_frontier(put, f, figures);
  return put.str();
}

}  // namespace ballbench
