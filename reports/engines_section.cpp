#include "engines_section.h"

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
#include "conform_section.h"
#include "markdown_buffer.h"
#include "result.h"
#include "balls_text.h"
#include "markdown_cell.h"
#include "no_data.h"
#include "ordered_set.h"

namespace ballbench {
namespace {

// The machine and build, one column each for the shards of a merged report (`ballbench merge`:
// run.json's "merge" and "shards"), each with the parts it ran and its command.
void put_machines(MarkdownBuffer& put, const nlohmann::json& run) {
  static constexpr const char* kFields[] = {"cpu", "cores", "os", "compiler", "build_type", "flags", "build"};
  const nlohmann::json shards = run.value("shards", nlohmann::json::array());
  put("## Machine and build\n\n");
  if (!shards.is_array() || shards.empty()) {
    put("| | |\n|---|---|\n");
    for (const char* k : kFields)
      if (run.contains(k)) put("| {} | {} |\n", k, markdown_cell(json_text(run[k])));
    return;
  }
  put("Merged from {} shards, each run on its own (`report --shard I/N`; the report's parts dealt round-robin), "
      "joined by `ballbench merge`. Times within a shard's parts come from its machine; compare across shards with "
      "care.\n\n| |",
      shards.size());
  for (const auto& s : shards) put(" shard {}/{} |", s.value(nlohmann::json::json_pointer("/shard/index"), 0),
        s.value(nlohmann::json::json_pointer("/shard/count"), 0));
  put("\n|---|");
  for (size_t k = 0; k < shards.size(); ++k) put("---|");
  put("\n");
  const auto row = [&](const char* name, const std::function<std::string(const nlohmann::json&)>& cell) {
    put("| {} |", name);
    for (const auto& s : shards) put(" {} |", markdown_cell(cell(s)));
    put("\n");
  };
  for (const char* k : kFields)
    row(k, [k](const nlohmann::json& s) { return s.contains(k) ? json_text(s[k]) : std::string(kNoData); });
  row("parts", [](const nlohmann::json& s) {
    const auto ran = s.value("ran", std::vector<std::string>{});
    return ran.empty() ? std::string(kNoData) : fmt::format("{}", fmt::join(ran, ", "));
  });
  row("command", [](const nlohmann::json& s) { return "`" + s.value("command", "?") + "`"; });
  row("date", [](const nlohmann::json& s) { return s.value("date", "?"); });
  put("\n");
}

// What the report was asked to leave out, or could not run (run.json's "left_out", its own and its
// shards'): a section that is missing says why.
void put_left_out(MarkdownBuffer& put, const nlohmann::json& run) {
  std::vector<std::string> lines;
  const auto take = [&](const nlohmann::json& record) {
    for (const auto& l : record.value("left_out", std::vector<std::string>{})) add_once(lines, l);
  };
  take(run);
  for (const auto& s : run.value("shards", nlohmann::json::array())) take(s);
  if (lines.empty()) return;
  put("**Left out of this report**:\n\n");
  for (const auto& l : lines) put("- {}\n", l);
  put("\n");
}

// Each engine's version, profiles and the limits that shape its results, from its runs.
void put_engines(MarkdownBuffer& put, const ReportInputs& in) {
  put("## Engines, profiles and limits\n\n");
  std::map<std::string, std::vector<std::string>> profiles;
  std::vector<std::string> engine_order;
  std::map<std::string, std::string> limits, versions;
  for (const auto& r : in.results) {
    if (!profiles.contains(r.engine)) engine_order.push_back(r.engine);
    add_once(profiles[r.engine], r.profile);
    limits[r.engine] = r.engine_limits;
    versions[r.engine] = r.engine_version;
  }
  put("| engine | version | profiles | limits that shape its results |\n|---|---|---|---|\n");
  for (const auto& e : engine_order)
    put("| {} | {} | {} | {} |\n", e, versions[e], fmt::join(profiles[e], ", "), markdown_cell(limits[e]));
  put("\nWhat each profile is: [profiles](#profiles); sources: `adapters/*/README.md`, "
      "`core/solver/README.md`.\n\n");
  std::vector<std::string> links;
  for (const auto& [scene, file] : in.result_files) links.push_back(fmt::format("[{0}]({0})", file));
  put("The effective settings of every run, as its engine reported them (every knob, defaults included), are the "
      "`settings` of its row in the scene's results file: {}.\n\n",
      fmt::join(links, ", "));
}

}  // namespace

std::string engines_section(const ReportInputs& in) {
  MarkdownBuffer put;
  const nlohmann::json& run = in.run;
  const nlohmann::json& made = run.contains("merge") ? run["merge"] : run;
  put("This report: `{}`, {} suite, {}.\n\n", made.value("command", "?"), run.value("suite", "quick"),
      made.value("date", "?"));
  put_left_out(put, in.run);
  put_engines(put, in);
  put("{}", conform_section(in));
  put_machines(put, in.run);
  return put.str();
}

}  // namespace ballbench
