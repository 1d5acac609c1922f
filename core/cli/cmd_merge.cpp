// `ballbench merge`: joins the shards of one plan run on several machines (`--shard I/N`). Sweep
// shards (JSON files) become one sweep file, as if run unsharded; report shards (their --out
// folders) become one results folder, from which REPORT.md is rendered. Shards of different plans,
// a shard given twice or one missing are refused, naming the file.
#include <algorithm>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "commands.h"
#include "progress.h"
#include "data_file.h"
#include "input_error.h"
#include "interrupt.h"
#include "json_value.h"
#include "match.h"
#include "report_writer.h"
#include "run_engines.h"
#include "shard_roll.h"
#include "sweep_result.h"

namespace ballbench::cli {
namespace {

namespace fs = std::filesystem;

struct MergeArgs {
  std::vector<std::string> shards;
  std::string out, csv;
};

bool is_match_file(const std::string& path) {
  const nlohmann::json j = parse_json_file(path, "a shard");
  return j.is_object() && j.contains("kind") && j["kind"] == "match";
}

// The merged JSON and CSV are neither a shard nor an input of the command, nor each other.
void check_merge_outputs(const MergeArgs& a, const std::string& csv) {
  std::vector<PathUse> uses = noted_input_files();
  for (const auto& path : a.shards) uses.push_back({"SHARD", path, false});
  uses.push_back({"--out", a.out, true});
  uses.push_back({"--csv", csv, true});
  check_path_clashes(uses);
}

void merge_matches(const MergeArgs& a) {
  const std::string csv = a.csv.empty() ? sweep_csv_path(a.out) : a.csv;
  check_merge_outputs(a, csv);
  std::vector<MatchResult> shards;
  for (const auto& path : a.shards) shards.push_back(read_match_file(path));
  const MatchResult merged = merge_match_shards(shards, a.shards);
  exit_if_interrupted("nothing written");
  write_match_files(merged, a.out, csv);
  exit_if_interrupted(fmt::format("{} and {} were written whole", a.out, csv));
  fmt::print("merged {} match shards ({} tries) into {} and {}\n", shards.size(), merged.tries.size(), a.out, csv);
}

void merge_sweeps(const MergeArgs& a) {
  const std::string csv = a.csv.empty() ? sweep_csv_path(a.out) : a.csv;
  check_merge_outputs(a, csv);
  std::vector<SweepResult> shards;
  for (const auto& path : a.shards) shards.push_back(read_sweep_file(path));
  const SweepResult merged = merge_sweep_shards(shards, a.shards);
  exit_if_interrupted("nothing written");
  write_sweep_files(merged, a.out, csv);
  exit_if_interrupted(fmt::format("{} and {} were written whole", a.out, csv));
  fmt::print("merged {} shards ({} points) into {} and {}\n", shards.size(), merged.points.size(), a.out, csv);
}

// A report shard's run record: its plan (the suite and its parts) and which shard it is.
struct ReportShard {
  nlohmann::json context;
  nlohmann::json plan;
  int index = 1, count = 1;
};

ReportShard read_report_shard(const std::string& folder) {
  const std::string path = folder + "/results/run.json";
  if (!fs::exists(path))
    throw InputError(fmt::format("merge: {}: no results/run.json (not the --out folder of `ballbench report --shard`)",
                                 folder));
  ReportShard s;
  s.context = parse_json_file(path, "a report's run record");
  if (!s.context.contains("shard") || !s.context.contains("parts"))
    throw InputError(fmt::format("merge: {}: not a report shard (its run.json has no shard; it is a whole report)", path));
  try {
    s.plan = {{"suite", s.context.value("suite", "")},
              {"seeds", s.context.value("seeds", 0)},
              {"engine_list", s.context.value("engine_list", "all")},
              {"parts", s.context.at("parts")},
              {"scene_digests", s.context.value("scene_digests", nlohmann::json::object())},
              {"engines", s.context.value("engines", nlohmann::json::object())}};
    s.index = s.context.at("shard").at("index").get<int>();
    s.count = s.context.at("shard").at("count").get<int>();
  } catch (const nlohmann::json::exception& e) {
    // The run record's fields a merge reads, by type.
    const JsonShape record{{{"suite", ""},
                            {"seeds", 0},
                            {"engine_list", ""},
                            {"parts", nlohmann::json::array({""})},
                            {"engines", nlohmann::json::object()},
                            {"shard", {{"index", 0}, {"count", 0}}}},
                           ""};
    throw InputError(json_type_error(path, "a report's run record", e, s.context, &record));
  }
  if (s.count < 1 || s.count > 10000)
    throw InputError(fmt::format("merge: {}: shard.count: {} is not a shard count", path, s.count));
  return s;
}

// Every shard once, of one report and one build.
void check_shards(const MergeArgs& a, const std::vector<ReportShard>& shards) {
  const ReportShard& first = shards.front();
  ShardRoll roll(first.count, a.shards);
  for (size_t k = 0; k < shards.size(); ++k) {
    const ReportShard& s = shards[k];
    if (s.plan != first.plan || s.count != first.count)
      throw InputError(fmt::format("merge: {} is a shard of another report than {} (its suite, placements, engines, "
                                   "parts, scenes' contents, engine versions or shard count differ)",
                                   a.shards[k], a.shards.front()));
    roll.take(k, s.index, "", json_string_field(s.context, "build"));
  }
  roll.check_complete();
}

// Every shard's result files (its parts) into one results folder; a file in two shards is refused.
// Each is copied beside its place, then renamed: a file in results/ is whole, whenever the merge stops.
size_t copy_results(const MergeArgs& a, const fs::path& results) {
  exit_if_interrupted("nothing written");
  fs::create_directories(results);
  std::vector<std::string> copied;
  for (const auto& folder : a.shards)
    for (const auto& e : fs::directory_iterator(fs::path(folder) / "results")) {
      const std::string name = e.path().filename().string();
      if (!e.is_regular_file() || name == "run.json") continue;
      if (std::find(copied.begin(), copied.end(), name) != copied.end())
        throw InputError(fmt::format("merge: {} is in two shards ({} is one): run each shard into its own folder", name,
                                     folder));
      const std::string target = (results / name).string();
      const std::string tmp = create_temp_beside(target, "a merged result file");
      fs::copy_file(e.path(), tmp, fs::copy_options::overwrite_existing);
      move_file_into_place(tmp, target, "a merged result file");
      copied.push_back(name);
    }
  return copied.size();
}

void merge_reports(const MergeArgs& a) {
  std::vector<ReportShard> shards;
  for (const auto& folder : a.shards) {
    std::error_code ec;
    if (fs::equivalent(folder, a.out, ec))
      throw InputError(fmt::format("merge: --out {} is one of the shards: merge into a folder of its own", a.out));
    shards.push_back(read_report_shard(folder));
  }
  {  // what the merge writes (OUT/results, OUT/figures, OUT/REPORT.md) holds nothing it reads
    std::vector<PathUse> uses = noted_input_files();
    for (const auto& folder : a.shards) uses.push_back({"SHARD", (fs::path(folder) / "results/run.json").string(), false});
    uses.push_back({"--out", (fs::path(a.out) / "results").string(), true, true});
    for (const char* part : kRenderedFolders) uses.push_back({"--out", (fs::path(a.out) / part).string(), true, true});
    uses.push_back({"--out", (fs::path(a.out) / "REPORT.md").string(), true});
    check_path_clashes(uses);
  }
  check_shards(a, shards);
  const ReportShard& first = shards.front();
  const fs::path results = fs::path(a.out) / "results";
  const size_t files = copy_results(a, results);
  // The plan is the shards'; the machines, commands and dates are each shard's (shards), and the
  // merge's own (merge). A merged record has no machine of its own: no shard's stands for all.
  nlohmann::json context = first.context;
  for (const char* k : {"shard", "ran", "left_out", "cpu", "cores", "os", "compiler", "build_type", "flags", "command", "date"})
    context.erase(k);
  const nlohmann::json merging = run_context();
  context["merge"] = {{"command", merging.at("command")}, {"date", merging.at("date")}};
  context["shards"] = nlohmann::json::array();
  for (const auto& s : shards) context["shards"].push_back(s.context);
  write_file_atomically((results / "run.json").string(), context.dump(2) + "\n", "the run record");
  fmt::print("merged {} report shards ({} result files) into {}\n", shards.size(), files, results.string());
  exit_if_interrupted(fmt::format("the merged results are in {}; REPORT.md not rendered (`ballbench report "
                                  "--render-only --out {}` renders it)",
                                  results.string(), a.out));
  render_report_folder(a.out);
  exit_if_interrupted(fmt::format("{}/REPORT.md was written whole", a.out));
}

void merge(const MergeArgs& a) {
  install_interrupt_handlers();
  size_t folders = 0;
  for (const auto& s : a.shards) {
    if (!fs::exists(s)) throw InputError(fmt::format("merge: {}: no such file or folder", s));
    folders += fs::is_directory(s);
  }
  if (folders != 0 && folders != a.shards.size())
    throw InputError("merge: give either sweep shards (JSON files) or report shards (folders), not both");
  if (folders) merge_reports(a);
  else if (is_match_file(a.shards.front())) merge_matches(a);
  else merge_sweeps(a);
}

}  // namespace

void add_merge(CLI::App& app) {
  auto a = std::make_shared<MergeArgs>();
  auto* cmd = app.add_subcommand(
      "merge", "join the shards of one sweep or match (JSON files) or one report (--out folders) run with --shard I/N");
  cmd->add_option("shards", a->shards, "every shard's sweep JSON file, or every shard's report folder")->required();
  cmd->add_option("--out", a->out, "the merged sweep's JSON file, or the merged report's folder")->required();
  cmd->add_option("--csv", a->csv, "sweeps: the merged CSV (default: --out with .csv)");
  add_quiet(cmd, Progress::quiet);
  cmd->callback([a] { merge(*a); });
}

}  // namespace ballbench::cli
