#include "frontier_result.h"


#include <fmt/format.h>

#include "data_file.h"
#include "input_error.h"

namespace ballbench {

nlohmann::json to_json(const FrontierResult& f) {
  nlohmann::json rows = nlohmann::json::array();
  for (const FrontierRow& r : f.rows)
    rows.push_back({{"engine", r.engine},
                    {"profile", r.profile},
                    {"knob", r.knob},
                    {"base", r.base},
                    {"factor", r.factor},
                    {"frontier", r.factor > 0 ? nlohmann::json(r.base * r.factor) : nlohmann::json(nullptr)},
                    {"levels_passed", r.levels_passed},
                    {"failed_next", r.failed_next}});
  return {{"scene", f.scene}, {"n", f.n}, {"steps", f.steps}, {"levels", f.levels},
          {"energy_tolerance", f.energy_tolerance}, {"context", f.context}, {"interrupted", f.interrupted}, {"rows", rows}};
}

FrontierResult frontier_from_json(const nlohmann::json& j) {
  FrontierResult f;
  f.scene = j.at("scene").get<std::string>();
  f.n = j.at("n").get<int>();
  f.steps = j.at("steps").get<long>();
  f.levels = j.at("levels").get<int>();
  f.energy_tolerance = j.at("energy_tolerance").get<double>();
  f.context = j.value("context", nlohmann::json::object());
  f.interrupted = j.value("interrupted", "");
  for (const auto& q : j.at("rows"))
    f.rows.push_back({q.at("engine").get<std::string>(), q.at("profile").get<std::string>(),
                      q.at("knob").get<std::string>(), q.at("base").get<double>(), q.at("factor").get<double>(),
                      q.at("levels_passed").get<int>(), q.at("failed_next").get<std::string>()});
  return f;
}

void write_frontier_file(const std::string& path, const FrontierResult& f) {
  write_file_atomically(path, to_json(f).dump(2) + "\n", "the stability frontier");
}

FrontierResult read_frontier_file(const std::string& path) {
  return read_json_file(path, "a stability frontier", [](const nlohmann::json& j) { return frontier_from_json(j); },
                        [](const nlohmann::json&) {
                          FrontierResult f;  // the shape of a frontier file: one row
                          f.rows.emplace_back().factor = 1;
                          return JsonShape{to_json(f), ""};
                        });
}

}  // namespace ballbench
