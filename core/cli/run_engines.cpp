#include "run_engines.h"

#include <algorithm>

#include <fmt/format.h>

#include "input_error.h"
#include "progress.h"

namespace ballbench::cli {
namespace {

std::string opt_drift(const Result& r) {
  return r.metrics.energy.max_rel_drift ? fmt::format("{:.3g}", *r.metrics.energy.max_rel_drift) : "n/a";
}

}  // namespace

void add_setting(nlohmann::json& overrides, const std::string& item) {
  const auto dot = item.find('.'), eq = item.find('=');
  if (dot == std::string::npos || eq == std::string::npos || dot > eq || dot == 0 || eq == dot + 1)
    throw InputError(fmt::format("--set '{}': expected ENGINE.KEY=VALUE", item));
  const std::string value = item.substr(eq + 1);
  nlohmann::json parsed = nlohmann::json::parse(value, nullptr, false);
  if (parsed.is_discarded() || parsed.is_object() || parsed.is_array()) parsed = value;
  overrides[item.substr(0, dot)][item.substr(dot + 1, eq - dot - 1)] = parsed;
}

void print_table(const std::vector<Result>& results) {
  fmt::print("{:<18} {:<10} {:>6} {:>8} {:>11} {:>11} {:>9} {:>9} {:>9} {:>9} {:>10} {:>12}\n", "engine", "status", "n",
             "steps", "E drift", "P drift", "tun.wall", "tun.pair", "stk.wall", "stk.pair", "pen.max", "ns/ball-step");
  for (const auto& r : results) {
    const auto& m = r.metrics;
    fmt::print("{:<18} {:<10} {:>6} {:>8} {:>11} {:>11.3g} {:>9} {:>9} {:>9} {:>9} {:>10.3g} {:>12.1f}\n",
               run_label(r), r.status, r.n, r.steps_done, opt_drift(r), m.momentum.max_abs_drift, m.tunnelling_wall,
               m.tunnelling_pair, m.sticking_wall, m.sticking_pair, m.penetration_max, r.ns_per_ball_step);
  }
  for (const auto& r : results)
    if (!r.error.empty()) fmt::print("{}: {}\n", run_label(r), r.error);
}

std::vector<std::string> profiles_for(const EngineEntry& e, const std::string& profile) {
  const auto& mine = e.info.profiles;
  if (profile == "all") return mine;
  if (!profile.empty() && std::find(mine.begin(), mine.end(), profile) != mine.end()) return {profile};
  return {mine.front()};
}

void check_profile(const std::vector<const EngineEntry*>& engines, const std::string& profile) {
  if (profile.empty() || profile == "all") return;
  std::vector<std::string> known;
  for (const auto* e : engines)
    for (const auto& p : e->info.profiles) {
      if (p == profile) return;
      if (std::find(known.begin(), known.end(), p) == known.end()) known.push_back(p);
    }
  throw InputError(fmt::format("--profile: no selected engine has a profile '{}' (they have: {}, or all)", profile,
                               fmt::join(known, ", ")));
}

std::vector<Result> run_all(const Scene& scene, const std::vector<const EngineEntry*>& engines,
                            const std::string& profile, const RunOptions& base, bool quiet) {
  std::vector<Result> results;
  for (const EngineEntry* e : engines)
    for (const std::string& p : profiles_for(*e, profile)) {
      RunOptions options = base;
      Progress progress(fmt::format("{} ({}) on {}", e->info.name, p, scene.name));
      if (!quiet) options.progress = [&](long done, long total) { progress.update(double(done) / total); };
      options.profile = p;
      options.overrides = base.overrides.value(e->info.name, nlohmann::json::object());
      results.push_back(run_engine(scene, *e, options));
    }
  return results;
}

}  // namespace ballbench::cli
