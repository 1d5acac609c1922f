#include "scene_writer.h"

#include <algorithm>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "accuracy_spec.h"

namespace ballbench {
namespace {

toml::array vec2(double x, double y) { return toml::array{x, y}; }

// A setting's JSON value as TOML: the scalars and arrays settings hold.
toml::table settings_table(const nlohmann::json& settings) {
  toml::table out;
  for (const auto& [key, v] : settings.items()) {
    if (v.is_boolean()) out.insert(key, v.get<bool>());
    else if (v.is_number_integer()) out.insert(key, v.get<int64_t>());
    else if (v.is_number()) out.insert(key, v.get<double>());
    else if (v.is_string()) out.insert(key, v.get<std::string>());
  }
  return out;
}

}  // namespace

SceneSnapshot scene_at_state(const Scene& scene, const State& state, const std::string& name, double duration) {
  SceneSnapshot snap;
  toml::table doc;
  doc.insert("name", name);
  doc.insert("description", fmt::format("{} at t = {:g} s", scene.name, state.t));
  if (!scene.use_case.empty()) doc.insert("use_case", scene.use_case);
  doc.insert("dt", scene.dt);
  doc.insert("duration", duration);
  doc.insert("gravity", vec2(scene.gravity.x(), scene.gravity.y()));
  doc.insert("restitution", scene.restitution);
  doc.insert("friction", scene.friction);
  doc.insert("inertia", inertia_name(scene.inertia));
  doc.insert("allow_overlap", true);
  const bool box = scene.container.kind == ContainerKind::Box;
  if (box)
    doc.insert("container", toml::table{{"kind", "box"},
                                        {"min", vec2(scene.container.min.x(), scene.container.min.y())},
                                        {"max", vec2(scene.container.max.x(), scene.container.max.y())}});
  toml::array balls;
  for (int i = 0; i < state.n(); ++i) {
    double x = state.pos(i, 0), y = state.pos(i, 1);
    const double r = scene.radius(i);
    if (box) {
      const double cx = std::clamp(x, scene.container.min.x() + r, scene.container.max.x() - r);
      const double cy = std::clamp(y, scene.container.min.y() + r, scene.container.max.y() - r);
      if (cx != x || cy != y) {
        ++snap.pushed_in;
        snap.pushed_by = std::max(snap.pushed_by, std::max(std::abs(cx - x), std::abs(cy - y)) / r);
      }
      x = cx, y = cy;
    }
    toml::table b{{"pos", vec2(x, y)}, {"vel", vec2(state.vel(i, 0), state.vel(i, 1))}, {"radius", r},
                  {"mass", scene.mass(i)}};
    if (state.rotates() && state.w(i) != 0) b.insert("spin", state.w(i));
    balls.push_back(std::move(b));
  }
  doc.insert("ball", std::move(balls));
  toml::table metrics;
  for (const RequestedMetricKey& m : kRequestedMetricKeys)
    if (scene.metrics.*m.flag) metrics.insert(m.key, true);
  if (!metrics.empty()) doc.insert("metrics", std::move(metrics));
  toml::table accuracy;
  const AccuracySpec spec = scene_spec(scene);
  for (const SpecTermDef& d : spec_terms()) {
    if (const auto& b = spec[d.term]) accuracy.insert(d.key, *b);
    else accuracy.insert(d.key, false);
  }
  doc.insert("accuracy", std::move(accuracy));
  if (!scene.engine_settings.empty()) {
    toml::table settings;
    for (const auto& [engine, table] : scene.engine_settings.items()) settings.insert(engine, settings_table(table));
    doc.insert("settings", std::move(settings));
  }
  std::ostringstream out;
  out << "# Written by ballbench: " << scene.name << " at t = " << fmt::format("{:g}", state.t) << " s, every ball explicit.\n"
      << doc << "\n";
  snap.text = out.str();
  return snap;
}

}  // namespace ballbench
