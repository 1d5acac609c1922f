#include "sweep_result.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <type_traits>

#include <fmt/format.h>

#include "data_file.h"
#include "input_error.h"
#include "shard_roll.h"
#include "json_value.h"

namespace ballbench {

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  if (v.size() % 2) return v[mid];
  return 0.5 * (v[mid] + *std::max_element(v.begin(), v.begin() + mid));
}

double SweepPoint::ns_median() const { return median(ns_per_ball_step); }
double SweepPoint::engine_s_median() const { return median(engine_s); }

void mark_pareto(std::vector<SweepPoint>& points) {
  std::map<std::string, std::vector<SweepPoint*>> by_engine;
  for (auto& p : points) {
    p.pareto = false;
    if (p.status == RunStatus::ok && std::isfinite(p.pos_rms) && !p.engine_s.empty()) by_engine[p.engine].push_back(&p);
  }
  const auto fastest = [](const SweepPoint* p) { return *std::min_element(p->engine_s.begin(), p->engine_s.end()); };
  const auto slowest = [](const SweepPoint* p) { return *std::max_element(p->engine_s.begin(), p->engine_s.end()); };
  const auto beats = [&](const SweepPoint* a, const SweepPoint* b) {
    const bool faster = slowest(a) < fastest(b), not_slower = fastest(a) <= slowest(b);
    return a->pos_rms <= b->pos_rms && not_slower && (a->pos_rms < b->pos_rms || faster);
  };
  for (auto& [engine, ps] : by_engine)
    for (SweepPoint* p : ps)
      p->pareto = std::none_of(ps.begin(), ps.end(), [&](const SweepPoint* q) { return q != p && beats(q, p); });
}

namespace {

// A point's measurement, or null for a point whose run was not measured.
template <class T>
nlohmann::json measured(const SweepPoint& p, T v) {
  return p.measured ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// The same as a CSV cell: empty for none.
template <class T>
std::string measured_cell(const SweepPoint& p, T v) {
  if (!p.measured) return "";
  if constexpr (std::is_floating_point_v<T>) return fmt::format("{:.6g}", v);
  else return fmt::format("{}", v);
}

}  // namespace

nlohmann::json to_json(const SweepResult& s) {
  nlohmann::json points = nlohmann::json::array();
  for (const SweepPoint& p : s.points)
    points.push_back({{"engine", p.engine},
                      {"profile", p.profile},
                      {"knob", p.knob},
                      {"value", p.value},
                      {"dt", p.dt},
                      {"steps", p.steps},
                      {"settings", p.settings},
                      {"status", run_status_text(p.status)},
                      {"error", p.error},
                      {"ns_per_ball_step", p.ns_per_ball_step},
                      {"ns_per_ball_step_median", p.ns_median()},
                      {"engine_s", p.engine_s},
                      {"engine_s_median", p.engine_s_median()},
                      {"pos_rms", measured(p, p.pos_rms)},
                      {"vel_rms", measured(p, p.vel_rms)},
                      {"energy_rel", measured(p, p.energy_rel)},
                      {"tunnelling", measured(p, p.tunnelling)},
                      {"sticking", measured(p, p.sticking)},
                      {"pareto", p.pareto},
                      {"plan_index", p.plan_index}});
  return {{"scene", s.scene},
          {"n", s.n},
          {"horizon", s.horizon},
          {"reference", s.reference},
          {"repeats", s.repeats},
          {"context", s.context},
          {"interrupted", s.interrupted},
          {"plan", s.plan},
          {"shard", {{"index", s.shard_index}, {"count", s.shard_count}}},
          {"points", points}};
}

namespace {

// j[key] as T, or an InputError naming the field ("points[3].dt: expected a number, got string").
template <class T>
T field(const nlohmann::json& j, const char* key, const std::string& where) {
  const std::string name = where.empty() ? key : where + "." + key;
  if (!j.is_object())
    throw InputError(fmt::format("{}: expected an object, got {}", where.empty() ? "the file" : where, json_kind_name(j)));
  const auto it = j.find(key);
  if (it == j.end()) throw InputError(fmt::format("{}: missing", name));
  try {
    return it->get<T>();
  } catch (const nlohmann::json::exception&) {
    const char* want = std::is_same_v<T, std::string> ? "a string" : std::is_same_v<T, bool> ? "true or false" : "a number";
    throw InputError(fmt::format("{}: expected {}, got {}", name, want, json_kind_name(*it)));
  }
}

// j[key], which must be an array.
const nlohmann::json& array_field(const nlohmann::json& j, const char* key, const std::string& where) {
  const std::string name = where.empty() ? key : where + "." + key;
  if (!j.is_object() || !j.contains(key)) throw InputError(fmt::format("{}: missing", name));
  if (!j.at(key).is_array()) throw InputError(fmt::format("{}: expected an array, got {}", name, json_kind_name(j.at(key))));
  return j.at(key);
}

}  // namespace

SweepResult sweep_from_json(const nlohmann::json& j) {
  SweepResult s;
  s.scene = field<std::string>(j, "scene", "");
  s.n = field<int>(j, "n", "");
  s.horizon = field<double>(j, "horizon", "");
  s.reference = field<std::string>(j, "reference", "");
  s.repeats = field<int>(j, "repeats", "");
  s.context = j.value("context", nlohmann::json::object());
  s.interrupted = j.value("interrupted", "");
  s.plan = j.value("plan", nlohmann::json());
  if (j.contains("shard")) {
    s.shard_index = field<int>(j.at("shard"), "index", "shard");
    s.shard_count = field<int>(j.at("shard"), "count", "shard");
    if (s.shard_count < 1 || s.shard_index < 1 || s.shard_index > s.shard_count)
      throw InputError(fmt::format("shard {}/{}: not a shard (I/N with 1 <= I <= N)", s.shard_index, s.shard_count));
  }
  for (const auto& q : array_field(j, "points", "")) {
    SweepPoint p;
    const std::string at = fmt::format("points[{}]", s.points.size());
    p.engine = field<std::string>(q, "engine", at);
    p.profile = field<std::string>(q, "profile", at);
    p.knob = field<std::string>(q, "knob", at);
    p.value = q.at("value");
    p.dt = field<double>(q, "dt", at);
    p.steps = field<long>(q, "steps", at);
    p.settings = q.at("settings");
    p.status = run_status_from_text(field<std::string>(q, "status", at));
    p.error = field<std::string>(q, "error", at);
    for (const auto& x : array_field(q, "ns_per_ball_step", at)) p.ns_per_ball_step.push_back(json_number(x));
    for (const auto& x : array_field(q, "engine_s", at)) p.engine_s.push_back(json_number(x));
    p.pos_rms = json_number(q.at("pos_rms"));
    p.vel_rms = json_number(q.at("vel_rms"));
    p.energy_rel = json_number(q.at("energy_rel"));
    // A point not measured has null counts (and errors); a measured one's error may be null too
    // (NaN: a run that blew up), its counts never.
    p.measured = !q.contains("tunnelling") || !q.at("tunnelling").is_null();
    if (p.measured) p.tunnelling = field<int>(q, "tunnelling", at), p.sticking = field<int>(q, "sticking", at);
    p.pareto = field<bool>(q, "pareto", at);
    p.plan_index = q.value("plan_index", static_cast<long>(s.points.size()));
    s.points.push_back(std::move(p));
  }
  return s;
}

std::string sweep_csv(const SweepResult& s) {
  std::string out =
      "engine,profile,knob,value,dt,steps,status,ns_per_ball_step_median,ns_per_ball_step_min,ns_per_ball_step_max,"
      "engine_s_median,pos_rms,vel_rms,energy_rel,tunnelling,sticking,pareto\n";
  for (const SweepPoint& p : s.points) {
    const auto [lo, hi] = p.ns_per_ball_step.empty()
                              ? std::pair{std::nan(""), std::nan("")}
                              : std::pair{*std::min_element(p.ns_per_ball_step.begin(), p.ns_per_ball_step.end()),
                                          *std::max_element(p.ns_per_ball_step.begin(), p.ns_per_ball_step.end())};
    const std::string value = json_text(p.value);
    out += fmt::format("{},{},{},{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{},{},{},{},{},{}\n", p.engine, p.profile, p.knob,
                       value, p.dt, p.steps, run_status_text(p.status), p.ns_median(), lo, hi, p.engine_s_median(),
                       measured_cell(p, p.pos_rms), measured_cell(p, p.vel_rms), measured_cell(p, p.energy_rel),
                       measured_cell(p, p.tunnelling), measured_cell(p, p.sticking), p.pareto ? 1 : 0);
  }
  return out;
}

SweepResult merge_sweep_shards(const std::vector<SweepResult>& shards, const std::vector<std::string>& names) {
  if (shards.empty()) throw InputError("merge: no shards given");
  const SweepResult& first = shards.front();
  if (first.plan.is_null())
    throw InputError(fmt::format("merge: {} has no plan (written by a ballbench without --shard)", names.front()));
  ShardRoll roll(first.shard_count, names);
  SweepResult out = first;
  out.points.clear();
  out.shard_index = out.shard_count = 1;
  out.context["shards"] = nlohmann::json::array();
  for (size_t k = 0; k < shards.size(); ++k) {
    const SweepResult& s = shards[k];
    if (s.plan != first.plan || s.shard_count != first.shard_count)
      throw InputError(fmt::format("merge: {} is a shard of another sweep than {} (its plan or shard count differs)",
                                   names[k], names.front()));
    roll.take(k, s.shard_index, s.interrupted, json_string_field(s.context, "build"));
    out.context["shards"].push_back(s.context);
    out.points.insert(out.points.end(), s.points.begin(), s.points.end());
  }
  roll.check_complete();
  std::vector<std::string> planned, merged;
  for (size_t k = 0; k < first.plan.value("points", nlohmann::json::array()).size(); ++k) planned.push_back(std::to_string(k));
  for (const SweepPoint& p : out.points) merged.push_back(std::to_string(p.plan_index));
  check_plan_covered(planned, merged, "point");
  std::stable_sort(out.points.begin(), out.points.end(),
                   [](const SweepPoint& a, const SweepPoint& b) { return a.plan_index < b.plan_index; });
  mark_pareto(out.points);
  return out;
}

std::string sweep_csv_path(const std::string& json_path) {
  if (json_path.size() > 5 && json_path.ends_with(".json")) return json_path.substr(0, json_path.size() - 5) + ".csv";
  return json_path + ".csv";
}

void write_sweep_files(const SweepResult& s, const std::string& json_path, const std::string& csv_path) {
  if (!json_path.empty()) write_file_atomically(json_path, to_json(s).dump(2) + "\n", "the sweep results");
  if (!csv_path.empty()) write_file_atomically(csv_path, sweep_csv(s), "the sweep CSV");
}

SweepResult read_sweep_file(const std::string& path) {
  // The shape of a sweep file: one point.
  return read_json_file(path, "a sweep result", [](const nlohmann::json& j) { return sweep_from_json(j); },
                        [](const nlohmann::json&) {
                          SweepResult s;
                          SweepPoint& p = s.points.emplace_back();  // its knob's value: any type
                          p.ns_per_ball_step = p.engine_s = {0};
                          return JsonShape{to_json(s), ""};
                        });
}

}  // namespace ballbench
