#include "result.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include "data_file.h"
#include "input_error.h"
#include "json_layout.h"
#include "json_value.h"
#include "metrics/catalog.h"
#include "metrics/meter_set.h"

namespace ballbench {
namespace {

double num(const nlohmann::json& j) { return json_number(j); }

// The same inside arrays (series of samples), at any depth: null elements become NaN, which a
// json value can hold.
nlohmann::json nulls_to_nan(nlohmann::json j) {
  if (j.is_object())
    for (auto& x : j) x = nulls_to_nan(std::move(x));
  else if (j.is_array())
    for (auto& x : j) x = x.is_null() ? nlohmann::json(std::nan("")) : nulls_to_nan(std::move(x));
  return j;
}

nlohmann::json event_json(const Event& e) {
  nlohmann::json j = {{"kind", event_kind_name(e.kind)}, {"step", e.step}, {"t", e.t}, {"i", e.i}};
  if (e.j >= 0) j["j"] = e.j;
  j["x"] = e.x, j["y"] = e.y;
  return j;
}

// The features a result records, each under its JSON name.
constexpr std::pair<const char*, bool SceneFeatures::*> kFeatureFields[] = {
    {"gravity", &SceneFeatures::gravity},           {"walls", &SceneFeatures::walls},
    {"equal_radii", &SceneFeatures::equal_radii},   {"equal_masses", &SceneFeatures::equal_masses},
    {"elastic", &SceneFeatures::elastic},           {"frictionless", &SceneFeatures::frictionless},
    {"rotation", &SceneFeatures::rotation}};

// A measurement: its value, or null for a run that has none (Result::measured).
nlohmann::json measurement(const Result& r, double v) { return r.measured() ? nlohmann::json(v) : nlohmann::json(nullptr); }

// A measurement read back: null (not measured) as 0, which Result::measured() tells apart; a field
// results files have always had is required, a later one (`required` false) defaults to 0.
double measurement_from(const nlohmann::json& j, const char* key, bool required = true) {
  if (!required && !j.contains(key)) return 0.0;
  const nlohmann::json& v = j.at(key);
  return v.is_null() ? 0.0 : v.get<double>();
}

Event event_from_json(const nlohmann::json& j) {
  return {event_kind_from_name(j.at("kind").get<std::string>()), j.at("step").get<long>(), num(j.at("t")),
          j.at("i").get<int>(), j.value("j", -1), num(j.at("x")), num(j.at("y"))};
}

}  // namespace

std::string run_label(const std::string& engine, const std::string& profile) {
  return profile == "default" ? engine : engine + "/" + profile;
}

std::string run_label(const Result& r) { return run_label(r.engine, r.profile); }

nlohmann::json to_json(const Result& r) {
  nlohmann::json j;
  j["engine"] = r.engine;
  j["engine_version"] = r.engine_version;
  j["profile"] = r.profile;
  j["engine_limits"] = r.engine_limits;
  j["scene"] = r.scene;
  j["scene_source"] = r.scene_source;
  if (!r.scene_digest.empty()) j["scene_digest"] = r.scene_digest;
  if (!r.build.empty()) j["build"] = r.build;
  if (!r.clamped.empty()) j["clamped"] = r.clamped;
  j["seed_offset"] = r.seed_offset;
  j["n"] = r.n;
  j["dt"] = r.dt;
  j["steps"] = r.steps;
  j["steps_done"] = r.steps_done;
  j["status"] = run_status_text(r.status);
  j["error"] = r.error;
  j["diverged"] = r.diverged();
  j["diverged_step"] = r.diverged() ? nlohmann::json(r.diverged_step) : nlohmann::json(nullptr);
  j["engine_s"] = measurement(r, r.engine_s);
  j["ns_per_step"] = measurement(r, r.ns_per_step);
  j["ns_per_ball_step"] = measurement(r, r.ns_per_ball_step);
  j["harness_s"] = measurement(r, r.harness_s);
  if (r.engine_process_s) {
    j["engine_process_s"] = measurement(r, *r.engine_process_s);
    j["ns_per_ball_step_pipe"] = measurement(r, r.engine_s * 1e9 / std::max(1L, r.steps_done) / std::max(1, r.n));
  }
  if (r.engine_cpu_s) j["engine_cpu_s"] = measurement(r, *r.engine_cpu_s);
  if (r.window_engine_s) j["window_engine_s"] = measurement(r, *r.window_engine_s);
  if (r.window_clock_s) j["window_clock_s"] = measurement(r, *r.window_clock_s);
  if (!r.window_pace.empty() && r.measured()) j["window_pace"] = r.window_pace;
  if (r.warm) j["warm"] = {{"count", r.warm->count}, {"cost_s", r.warm->cost_s}, {"engine_s", r.warm->engine_s}};
  if (!r.pace.empty() && r.measured()) j["pace"] = r.pace;
  j["out_of_plane_max"] = measurement(r, r.out_of_plane_max);
  if (r.scene_features) {
    nlohmann::json& f = j["scene_features"];
    for (const auto& [name, field] : kFeatureFields) f[name] = (*r.scene_features).*field;
  }
  put_metrics(r, j);
  j["events"] = nlohmann::json::array();
  for (const Event& e : r.events) j["events"].push_back(event_json(e));
  j["metrics_config"] = {{"contact_tolerance", r.metrics_config.contact_tolerance},
                         {"stuck_samples", r.metrics_config.stuck_samples},
                         {"divergence_energy_factor", r.metrics_config.divergence_energy_factor},
                         {"sample_every", r.metrics_config.sample_every},
                         {"roll_tolerance", r.metrics_config.roll_tolerance}};
  j["settings"] = r.settings;
  j["skipped"] = r.skipped;
  if (r.reference.available && r.measured()) {
    const auto& e = r.reference;
    j["error_vs_reference"] = {
        {"reference", e.reference},
        {"reference_dt", e.reference_dt},
        {"pos_rms_final", e.pos_rms_final},
        {"pos_rms_max", e.pos_rms_max},
        {"vel_rms_final", e.vel_rms_final},
        {"vel_rms_max", e.vel_rms_max},
        {"energy_rel_max", e.energy_rel_max},
        {"horizon", e.horizon ? nlohmann::json(*e.horizon) : nlohmann::json(nullptr)},
        {"horizon_status", horizon_status_text(horizon_status(e))},
        {"horizon_tolerance", e.horizon_tolerance},
        {"reference_failed_step", e.reference_failed_step >= 0 ? nlohmann::json(e.reference_failed_step) : nlohmann::json(nullptr)},
        {"reference_error", e.reference_error}};
  }
  j["series"] = {{"t", r.series.t},         {"energy", r.series.energy}, {"com_x", r.series.com_x},
                 {"com_y", r.series.com_y}, {"pos_err", r.series.pos_err}, {"tracks", r.series.tracks},
                 {"final_pos", r.series.final_pos}, {"radius_mean", r.series.radius_mean},
                 {"frame_t", r.series.frame_t}, {"frames", r.series.frames}, {"radius", r.series.radius},
                 {"box", r.series.box ? nlohmann::json(*r.series.box) : nlohmann::json(nullptr)}};
  j["checksum"] = {{"final", r.checksum_final}, {"trajectory", r.checksum_trajectory}};
  return j;
}

Result result_from_json(const nlohmann::json& j) {
  Result r;
  r.engine = j.at("engine");
  r.engine_version = j.at("engine_version");
  r.profile = j.value("profile", "");
  r.engine_limits = j.value("engine_limits", "");
  r.scene = j.at("scene");
  r.scene_source = j.value("scene_source", "");
  r.scene_digest = j.value("scene_digest", "");
  r.build = j.value("build", "");
  r.clamped = j.value("clamped", "");
  r.seed_offset = j.value("seed_offset", int64_t{0});
  r.n = j.at("n");
  r.dt = j.at("dt");
  r.steps = j.at("steps");
  r.steps_done = j.value("steps_done", r.steps);
  if (r.n < 0) throw InputError(fmt::format("n: {} is not a ball count", r.n));
  if (r.steps < 0) throw InputError(fmt::format("steps: {} is not a step count", r.steps));
  if (r.steps_done < 0 || r.steps_done > r.steps)
    throw InputError(fmt::format("steps_done: {} is not between 0 and the run's steps ({})", r.steps_done, r.steps));
  try {
    r.status = run_status_from_text(j.value("status", "ok"));
  } catch (const InputError& e) {
    throw InputError(fmt::format("status: {}", e.what()));
  }
  r.error = j.value("error", "");
  r.diverged_step = j.at("diverged_step").is_null() ? -1 : j.at("diverged_step").get<long>();
  // Results files written before the field was named for what it holds call it "wall_s".
  r.engine_s = measurement_from(j, j.contains("engine_s") ? "engine_s" : "wall_s");
  r.ns_per_step = measurement_from(j, "ns_per_step");
  r.ns_per_ball_step = measurement_from(j, "ns_per_ball_step");
  r.harness_s = measurement_from(j, "harness_s", false);
  if (j.contains("engine_process_s")) r.engine_process_s = measurement_from(j, "engine_process_s");
  if (j.contains("engine_cpu_s")) r.engine_cpu_s = measurement_from(j, "engine_cpu_s");
  if (j.contains("window_engine_s")) r.window_engine_s = measurement_from(j, "window_engine_s");
  if (j.contains("window_clock_s")) r.window_clock_s = measurement_from(j, "window_clock_s");
  if (j.contains("window_pace")) r.window_pace = j.at("window_pace").get<std::vector<double>>();
  if (j.contains("warm")) {
    const nlohmann::json& w = j.at("warm");
    r.warm = Result::WarmPasses{w.at("count").get<int>(), w.at("cost_s").get<double>(), w.at("engine_s").get<double>()};
  }
  if (j.contains("pace")) r.pace = j.at("pace").get<std::vector<double>>();
  r.out_of_plane_max = measurement_from(j, "out_of_plane_max", false);
  if (j.contains("scene_features")) {
    const auto& f = j.at("scene_features");
    r.scene_features.emplace();
    for (const auto& [name, field] : kFeatureFields) (*r.scene_features).*field = f.at(name).get<bool>();
  }
  take_metrics(j, r);
  // Results files written before events were recorded have none: their counts stand alone.
  if (j.contains("events"))
    for (const auto& e : j.at("events")) try {
        r.events.push_back(event_from_json(e));
      } catch (const InputError& err) {
        throw InputError(fmt::format("events[{}].kind: {}", r.events.size(), err.what()));
      }
  if (j.contains("metrics_config")) {
    const auto& c = j["metrics_config"];
    r.metrics_config.contact_tolerance = c.at("contact_tolerance");
    r.metrics_config.stuck_samples = c.at("stuck_samples");
    r.metrics_config.divergence_energy_factor = c.at("divergence_energy_factor");
    r.metrics_config.sample_every = c.value("sample_every", 1);
    r.metrics_config.roll_tolerance = c.value("roll_tolerance", MetricsConfig{}.roll_tolerance);
  }
  r.settings = j.value("settings", nlohmann::json::object());
  if (j.contains("skipped")) j["skipped"].get_to(r.skipped);
  if (j.contains("error_vs_reference")) {
    const auto& e = j["error_vs_reference"];
    auto& x = r.reference;
    x.available = true;
    x.reference = e.at("reference");
    x.reference_dt = e.value("reference_dt", r.dt);  // files from before converged references: the run's own step
    x.pos_rms_final = num(e.at("pos_rms_final")), x.pos_rms_max = num(e.at("pos_rms_max"));
    x.vel_rms_final = num(e.at("vel_rms_final")), x.vel_rms_max = num(e.at("vel_rms_max"));
    x.energy_rel_max = num(e.at("energy_rel_max"));
    if (!e.at("horizon").is_null()) x.horizon = e.at("horizon").get<double>();
    x.horizon_tolerance = e.at("horizon_tolerance");
    x.reference_failed_step = e.at("reference_failed_step").is_null() ? -1 : e.at("reference_failed_step").get<long>();
    x.reference_error = e.value("reference_error", "");
  }
  if (j.contains("series")) {
    const nlohmann::json s = nulls_to_nan(j["series"]);
    s.at("t").get_to(r.series.t), s.at("energy").get_to(r.series.energy);
    s.at("com_x").get_to(r.series.com_x), s.at("com_y").get_to(r.series.com_y);
    s.at("pos_err").get_to(r.series.pos_err), s.at("tracks").get_to(r.series.tracks);
    s.at("final_pos").get_to(r.series.final_pos);
    if (s.contains("frames")) s.at("frame_t").get_to(r.series.frame_t), s.at("frames").get_to(r.series.frames);
    if (s.contains("radius")) s.at("radius").get_to(r.series.radius);
    r.series.radius_mean = s.value("radius_mean", 0.0);
    if (s.contains("box") && !s["box"].is_null()) r.series.box = s["box"].get<std::array<double, 4>>();
  }
  if (j.contains("checksum")) {
    r.checksum_final = j["checksum"].value("final", "");
    r.checksum_trajectory = j["checksum"].value("trajectory", "");
  }
  return r;
}

void write_results_file(const std::string& path, const std::vector<Result>& results) {
  nlohmann::json arr = nlohmann::json::array();
  for (const auto& r : results) arr.push_back(to_json(r));
  write_file_atomically(path, json_layout(arr) + "\n", "the results file");
}

namespace {

// A run with every field a results file may hold set, so that its JSON is the shape of any run's.
nlohmann::json result_shape() {
  Result r;
  r.status = RunStatus::diverged;  // with its step
  r.steps_done = 1;                 // a run that made steps writes every figure it measured
  r.engine_process_s = 0;
  r.engine_cpu_s = r.window_engine_s = r.window_clock_s = 0;
  r.pace = r.window_pace = {0.0};
  r.warm = Result::WarmPasses{1, 0, 0};
  r.events.emplace_back();
  r.events.back().j = 1;  // a pair's
  r.reference.available = true;
  r.reference.horizon = 0;
  r.reference.reference_failed_step = 0;
  r.metrics = resting_values();  // every metric as its meter writes it: numbers, counts, [x, y] vectors
  r.skipped = {""};
  auto& s = r.series;
  s.t = s.energy = s.com_x = s.com_y = s.pos_err = s.frame_t = s.radius = {0};
  s.tracks = s.frames = {{{0, 0}}};
  s.final_pos = {{0, 0}};
  s.box = std::array<double, 4>{};
  // A metric of the exemplar that is NaN (a drift relative to no energy) is written null; any run's
  // may be a number there.
  nlohmann::json j = to_json(r);
  const auto numbers = [](auto& self, nlohmann::json& v) -> void {
    if (v.is_null()) v = 0;
    if (v.is_structured())
      for (auto& x : v) self(self, x);
  };
  numbers(numbers, j);
  return j;
}

// One run listed twice would count twice in every table and figure made of the file.
void check_no_repeats(const std::vector<Result>& runs) {
  std::map<std::string, size_t> seen;
  for (size_t k = 0; k < runs.size(); ++k) {
    const Result& r = runs[k];
    const std::string key = fmt::format("{}|{}|{}|{}|{:.17g}|{}", r.scene, r.engine, r.profile, r.seed_offset, r.dt,
                                        r.settings.dump());
    if (const auto [it, fresh] = seen.emplace(key, k); !fresh)
      throw InputError(fmt::format("runs[{}]: the same run as runs[{}] ({} on {}, placement {}): a run is listed once",
                                   k, it->second, run_label(r), r.scene, r.seed_offset));
  }
}

}  // namespace

std::vector<Result> read_results_file(const std::string& path) {
  return read_json_file(
      path, "a ballbench results file",
      [](const nlohmann::json& j) {
        std::vector<Result> out;
        for (const auto& item : j.is_object() ? nlohmann::json::array({j}) : j) {
          try {
            out.push_back(result_from_json(item));
          } catch (const InputError& e) {  // a value no run has (a status, an event's kind)
            throw InputError(j.is_object() ? std::string(e.what()) : fmt::format("runs[{}].{}", out.size(), e.what()));
          }
        }
        check_no_repeats(out);
        return out;
      },
      [](const nlohmann::json& j) {
        return j.is_object() ? JsonShape{result_shape(), ""} : JsonShape{nlohmann::json::array({result_shape()}), "runs"};
      });
}

}  // namespace ballbench
