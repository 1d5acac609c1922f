#include "bench_results.h"

#include <sstream>

#include "data_file.h"

namespace ballbench {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
  return parts;
}

// A row named KIND/ENGINE/SCENE/N[/...]: the rest of its name read by `name` (throwing if it is
// not one of ours), then its counters by `counters`, unless the benchmark was skipped (its message
// kept as the row's error).
template <class Row, class Name, class Counters>
std::optional<Row> named_row(const nlohmann::json& b, const std::vector<std::string>& parts, Name name,
                             Counters counters) {
  Row row;
  row.engine = parts[1], row.scene = parts[2];
  try {
    row.n = std::stol(parts[3]);
    name(row);
  } catch (const std::exception&) {
    return std::nullopt;  // not one of ours
  }
  if (b.value("error_occurred", false))
    row.error = b.value("error_message", "skipped");
  else
    counters(row);
  return row;
}

std::optional<HarnessRow> harness_row(const nlohmann::json& b, const std::vector<std::string>& parts) {
  return named_row<HarnessRow>(
      b, parts,
      [&](HarnessRow& row) { row.sample_every = std::stoi(parts[4].substr(std::string("sample_every:").size())); },
      [&](HarnessRow& row) {
        row.engine_ns_per_ball_step = b.at("engine_ns_per_ball_step").get<double>();
        row.harness_ns_per_ball_step = b.at("harness_ns_per_ball_step").get<double>();
        row.overhead = b.at("overhead").get<double>();
      });
}

std::optional<FloorRow> floor_row(const nlohmann::json& b, const std::vector<std::string>& parts) {
  return named_row<FloorRow>(
      b, parts, [](FloorRow&) {},
      [&](FloorRow& row) {
        row.engine_ns_per_ball_step = b.at("engine_ns_per_ball_step").get<double>();
        row.engine_cores = b.at("engine_cores").get<double>();
        row.threads = static_cast<int>(b.at("threads").get<double>());
        row.copy_ns_per_ball_step = b.at("copy_ns_per_ball_step").get<double>();
        row.pass_ns_per_ball_step = b.at("pass_ns_per_ball_step").get<double>();
        row.floor = b.at("floor").get<double>();
      });
}

BenchResults bench_from_json(const nlohmann::json& j) {
  BenchResults out;
  out.context = j.value("context", nlohmann::json::object());
  for (const auto& b : j.at("benchmarks")) {
    if (b.value("run_type", "iteration") != "iteration") continue;
    const auto parts = split(b.at("name").get<std::string>(), '/');
    if (parts.size() >= 5 && parts[0] == "harness" && parts[4].starts_with("sample_every:")) {
      if (auto row = harness_row(b, parts)) out.harness.push_back(std::move(*row));
      continue;
    }
    if (parts.size() >= 4 && parts[0] == "floor") {
      if (auto row = floor_row(b, parts)) out.floor.push_back(std::move(*row));
      continue;
    }
    if (parts.size() < 5 || (parts[0] != "step" && parts[0] != "pour" && parts[0] != "pipe"))
      continue;  // then options, e.g. min_time:0.200
    BenchRow row;
    row.window = parts[0];
    row.engine = parts[1], row.profile = parts[2], row.scene = parts[3];
    try {
      row.n = std::stol(parts[4]);
    } catch (const std::exception&) {
      continue;  // not one of ours
    }
    if (b.value("error_occurred", false)) {
      row.error = b.value("error_message", "skipped");
    } else {
      row.ns_per_ball_step = b.at("ns_per_ball_step").get<double>();
      auto optional = [&](const char* key, std::optional<double>& out) {
        if (b.contains(key)) out = b[key].get<double>();
      };
      optional("steps_per_s", row.steps_per_s);
      optional("peak_rss_bytes_per_ball", row.peak_rss_bytes_per_ball);
      optional("engine_bytes_per_ball", row.engine_bytes_per_ball);
      optional("settle_steps", row.settle_steps);
      optional("start_rms_speed", row.start_rms_speed);
      optional("engine_process_ns_per_ball_step", row.pipe_ns_per_ball_step);
      if (std::optional<double> met; optional("spec_met", met), met) {
        row.spec_met = *met != 0;
        row.spec = b.value("label", "");
        if (row.spec.starts_with("spec ")) row.spec.erase(0, 5);
      }
      // An engine in another process: its own step is the headline, the harness's time with the
      // pipe stands beside it.
      if (row.pipe_ns_per_ball_step) std::swap(row.ns_per_ball_step, *row.pipe_ns_per_ball_step);
    }
    (row.window == "pour" ? out.pour : row.window == "pipe" ? out.pipe : out.rows).push_back(std::move(row));
  }
  return out;
}

}  // namespace

BenchResults read_bench_file(const std::string& path) {
  return read_json_file(path, "Google Benchmark JSON", [](const nlohmann::json& j) { return bench_from_json(j); },
                        [](const nlohmann::json&) {
                          // The fields of a benchmark row that bench_from_json reads by type.
                          const nlohmann::json row = {{"name", ""},
                                                      {"run_type", ""},
                                                      {"error_occurred", false},
                                                      {"error_message", ""},
                                                      {"ns_per_ball_step", 0},
                                                      {"steps_per_s", 0},
                                                      {"peak_rss_bytes_per_ball", 0},
                                                      {"engine_bytes_per_ball", 0},
                                                      {"settle_steps", 0},
                                                      {"start_rms_speed", 0},
                                                      {"engine_process_ns_per_ball_step", 0},
                                                      {"spec_met", 0},
                                                      {"label", ""}};
                          return JsonShape{{{"context", nlohmann::json::object()}, {"benchmarks", {row}}}, ""};
                        });
}

}  // namespace ballbench
