#include "report_suite.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "input_error.h"
#include "match_result.h"
#include "scene_loader.h"
#include "toml_table_reader.h"

namespace ballbench {

std::string report_suites_file() { return scenario_dir() + "/suites/report.toml"; }

namespace {

// measured_matches: match files relative to the suites file's folder, each of a built-in scene the
// suite does not search itself, once.
std::vector<MeasuredMatch> measured_matches(const TableReader& r, const std::string& suites_path,
                                            const std::vector<std::string>& match_scenes,
                                            const std::vector<std::string>& builtin) {
  const char* key = "measured_matches";
  std::vector<MeasuredMatch> out;
  const std::vector<std::string> files = r.strings(key, {});
  for (size_t i = 0; i < files.size(); ++i) {
    const std::string field = fmt::format("{}[{}]", key, i);
    const std::filesystem::path given(files[i]);
    const std::string path =
        given.is_absolute() ? files[i] : (std::filesystem::path(suites_path).parent_path() / given).lexically_normal().string();
    MatchResult m;
    try {
      m = read_match_file(path);
    } catch (const InputError& e) {
      r.fail(r.node(key), field, e.what());
    }
    if (!m.interrupted.empty() || m.shard_count != 1)
      r.fail(r.node(key), field,
             fmt::format("{}: {}; carry a whole search", path,
                         m.interrupted.empty() ? fmt::format("shard {} of {}", m.shard_index, m.shard_count)
                                               : "interrupted by " + m.interrupted));
    if (std::find(builtin.begin(), builtin.end(), m.scene) == builtin.end())
      r.fail(r.node(key), field, fmt::format("{}: its scene '{}' is not a built-in scene", path, m.scene));
    if (std::find(match_scenes.begin(), match_scenes.end(), m.scene) != match_scenes.end())
      r.fail(r.node(key), field, fmt::format("{}: the suite searches '{}' itself (match_scenes)", path, m.scene));
    for (const MeasuredMatch& other : out)
      if (other.scene == m.scene)
        r.fail(r.node(key), field, fmt::format("{}: a second search of '{}' (the first: {})", path, m.scene, other.path));
    out.push_back({m.scene, path});
  }
  return out;
}

}  // namespace

ReportSuite load_report_suite(const std::string& name, const std::string& given_path) {
  const std::string path = given_path.empty() ? report_suites_file() : given_path;
  toml::table doc;
  try {
    doc = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: {}", path, e.source().begin.line, e.description()));
  }
  const toml::table* t = doc[name].as_table();
  if (!t) {
    std::vector<std::string> names;
    for (const auto& [k, v] : doc) names.emplace_back(k.str());
    throw InputError(fmt::format("{}: no suite [{}] (suites: {})", path, name, fmt::join(names, ", ")));
  }
  TableReader r(*t, path, name);
  r.check_keys({"scenes", "unreferenced", "match_scenes", "match_budget", "match_max_halvings", "match_ceiling", "sweep_scenes",
                "stress_scenes", "stress_levels", "seeds", "bench_filters", "bench_min_time", "bench_budget_s",
                "harness_filter", "timeout_s", "costly_engines",
                "match_costly_engines", "measured_matches"});
  ReportSuite s;
  s.name = name;
  const auto names = builtin_scene_names();
  const auto scenes = [&](const char* key) {
    auto v = r.strings(key, {});
    for (size_t i = 0; i < v.size(); ++i)
      if (std::find(names.begin(), names.end(), v[i]) == names.end())
        r.fail(r.node(key), fmt::format("{}[{}]", key, i),
               fmt::format("'{}' is not a built-in scene{}", v[i], did_you_mean(v[i], names)));
    return v;
  };
  const auto positive = [&](const char* key, double fallback) {
    const double v = r.number_or(key, fallback);
    if (!(v > 0)) r.fail(r.node(key), key, fmt::format("must be above 0, got {}", v));
    return v;
  };
  const auto count = [&](const char* key, int fallback) {
    const int64_t v = r.integer(key, fallback);
    if (v < 1 || v > 1000) r.fail(r.node(key), key, fmt::format("must be within 1 .. 1000, got {}", v));
    return int(v);
  };
  s.scenes = scenes("scenes");
  s.unreferenced = scenes("unreferenced");
  for (const char* key : {"unreferenced"})
    for (const auto& v : r.strings(key, {}))
      if (std::find(s.scenes.begin(), s.scenes.end(), v) == s.scenes.end())
        r.fail(r.node(key), key, fmt::format("'{}' is not one of the suite's scenes", v));
  s.match_scenes = scenes("match_scenes");
  s.match_budget = positive("match_budget", s.match_budget);
  if (r.has("match_ceiling")) s.match_ceiling = positive("match_ceiling", s.match_ceiling);
  if (const int64_t k = r.integer("match_max_halvings", s.match_max_halvings); k < 0 || k > 12)
    r.fail(r.node("match_max_halvings"), "match_max_halvings", fmt::format("must be within 0 .. 12, got {}", k));
  else
    s.match_max_halvings = int(k);
  s.sweep_scenes = scenes("sweep_scenes");
  s.stress_scenes = scenes("stress_scenes");
  s.stress_levels = count("stress_levels", s.stress_levels);
  s.seeds = count("seeds", s.seeds);
  s.bench_filters = r.strings("bench_filters", {});
  s.bench_min_time = positive("bench_min_time", s.bench_min_time);
  s.bench_budget_s = positive("bench_budget_s", s.bench_budget_s);
  s.harness_filter = r.string("harness_filter", "");
  s.timeout_s = positive("timeout_s", s.timeout_s);
  s.costly_engines = r.boolean("costly_engines", s.costly_engines);
  s.match_costly_engines = r.strings("match_costly_engines", {});
  s.measured_matches = measured_matches(r, path, s.match_scenes, names);
  return s;
}

}  // namespace ballbench
