#include "calibration_section.h"

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

#include "markdown_buffer.h"
#include "result.h"
#include "json_value.h"
#include "balls_text.h"
#include "markdown_cell.h"
#include "no_data.h"
#include "ordered_set.h"

namespace ballbench {
namespace {

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

}  // namespace

std::string calibration_section(const CalibrationResult& c) {
  MarkdownBuffer put;
  put_calibration(put, c);
  return put.str();
}

}  // namespace ballbench
