#include "run_status.h"

#include <array>
#include <ostream>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {
namespace {

constexpr std::array<std::pair<RunStatus, const char*>, 9> kTexts{{
    {RunStatus::ok, "ok"},
    {RunStatus::diverged, "diverged"},
    {RunStatus::failed, "failed"},
    {RunStatus::unsupported, "unsupported"},
    {RunStatus::interrupted, "interrupted"},
    {RunStatus::crashed, "crashed"},
    {RunStatus::timed_out, "timed out"},
    {RunStatus::missed, "missed"},
    {RunStatus::over_cost, "over cost"},
}};

}  // namespace

const char* run_status_text(RunStatus s) {
  for (const auto& [status, text] : kTexts)
    if (status == s) return text;
  return "unknown";
}

RunStatus run_status_from_text(std::string_view text) {
  for (const auto& [status, t] : kTexts)
    if (t == text) return status;
  std::vector<const char*> known;
  for (const auto& entry : kTexts) known.push_back(entry.second);
  throw InputError(fmt::format("unknown run status '{}' (known: {})", text, fmt::join(known, ", ")));
}

std::ostream& operator<<(std::ostream& os, RunStatus s) { return os << run_status_text(s); }

}  // namespace ballbench
