#include "spec_check.h"

#include <fmt/format.h>

#include "result.h"
#include "spec_verdict.h"

namespace ballbench::bench {
namespace {

// The scene's spec on the terms SpecCheck judges.
AccuracySpec judged_terms(const Scene& scene) {
  const AccuracySpec whole = scene_spec(scene);
  AccuracySpec s;
  for (const SpecTerm t : {SpecTerm::overlap, SpecTerm::rest_speed}) s[t] = whole[t];
  return s;
}

}  // namespace

bool left_the_box(const Scene& scene, const State& s) {
  if (scene.container.kind != ContainerKind::Box) return false;
  const double d = 2 * scene.radius.maxCoeff();
  for (int i = 0; i < s.n(); ++i) {
    for (int c = 0; c < 2; ++c)
      if (!(s.pos(i, c) > scene.container.min(c) - d && s.pos(i, c) < scene.container.max(c) + d)) return true;
  }
  return false;
}

SpecCheck::SpecCheck(const Scene& scene) : scene_(scene), spec_(judged_terms(scene)), meters_(scene, MetricsConfig{}) {}

void SpecCheck::sample(const State& s) {
  meters_.sample(s);
  ++samples_;
  left_box_ = left_box_ || left_the_box(scene_, s);
}

std::string SpecCheck::verdict(const State& last) {
  meters_.final_state(last);
  Result r;
  r.status = RunStatus::ok;
  r.steps_done = samples_ - 1;  // judge() reads the figures of a run that moved: the states read after the first
  r.metrics = meters_.values();
  const SpecVerdict v = judge(spec_, r);
  met_ = v.met && !left_box_;
  overlap_ = spec_figure(SpecTerm::overlap, r).value_or(0);
  std::string figures;
  for (const SpecTermDef& d : spec_terms())
    if (const auto& bound = spec_[d.term]; bound && v.figures.contains(d.key) && v.figures[d.key].is_number())
      figures += fmt::format("{}{} {:.3g} (<= {:g})", figures.empty() ? "" : ", ", d.key, v.figures[d.key].get<double>(),
                             *bound);
  if (left_box_) return verdict_line(false, "a ball left the box");
  return verdict_line(met_, v.met ? figures : v.why_not);
}

}  // namespace ballbench::bench
