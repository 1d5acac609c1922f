#include "calibration_result.h"

#include "data_file.h"
#include "json_value.h"

namespace ballbench {

const char* calibration_status_text(const CalibrationPoint& p) {
  return p.tunnelled ? "tunnelled" : run_status_text(p.status);
}

nlohmann::json to_json(const CalibrationResult& c) {
  nlohmann::json points = nlohmann::json::array();
  for (const CalibrationPoint& p : c.points)
    points.push_back({{"engine", p.engine},
                      {"profile", p.profile},
                      {"contact", p.contact},
                      {"requested", p.requested},
                      {"speed", p.speed},
                      {"effective", p.effective},
                      {"status", calibration_status_text(p)},
                      {"error", p.error}});
  return {{"requested", c.requested}, {"speeds", c.speeds}, {"context", c.context}, {"points", points}};
}

CalibrationResult calibration_from_json(const nlohmann::json& j) {
  CalibrationResult c;
  for (const auto& x : j.at("requested")) c.requested.push_back(json_number(x));
  for (const auto& x : j.at("speeds")) c.speeds.push_back(json_number(x));
  c.context = j.value("context", nlohmann::json::object());
  for (const auto& q : j.at("points")) {
    CalibrationPoint p;
    p.engine = q.at("engine").get<std::string>();
    p.profile = q.at("profile").get<std::string>();
    p.contact = q.at("contact").get<std::string>();
    p.requested = json_number(q.at("requested"));
    p.speed = json_number(q.at("speed"));
    p.effective = json_number(q.at("effective"));
    const auto status = q.at("status").get<std::string>();
    p.tunnelled = status == "tunnelled";
    p.status = p.tunnelled ? RunStatus::ok : run_status_from_text(status);
    p.error = q.at("error").get<std::string>();
    c.points.push_back(std::move(p));
  }
  return c;
}

void write_calibration_file(const std::string& path, const CalibrationResult& c) {
  write_file_atomically(path, to_json(c).dump(2) + "\n", "the restitution calibration");
}

CalibrationResult read_calibration_file(const std::string& path) {
  return read_json_file(path, "a restitution calibration", [](const nlohmann::json& j) { return calibration_from_json(j); },
                        [](const nlohmann::json&) {
                          CalibrationResult c;  // the shape of a calibration file: one point
                          c.requested = c.speeds = {0};
                          c.points.emplace_back();
                          return JsonShape{to_json(c), ""};
                        });
}

}  // namespace ballbench
