#pragma once
// `--spec KEY=VALUE,...` of `run` and `match`: the accuracy the scene is asked for, over its own.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "accuracy_spec.h"
#include "input_error.h"
#include "metrics/energy.h"
#include "scene.h"

namespace ballbench::cli {

// A term the scene cannot measure would leave every engine "not measured", `exact` included:
// refused before any run, naming the term and how to drop it.
inline void check_measurable(const Scene& scene, const AccuracySpec& spec) {
  if (spec[SpecTerm::rolling] && !scene.metrics.rolling)
    throw InputError(fmt::format("--spec rolling: {} has no rolling closed form (balls on a floor with friction, "
                                 "[metrics] rolling = true), so no engine could be judged by it: drop it with "
                                 "rolling=none",
                                 scene.name));
  // The drift is relative to the energy at the start: a scene that starts with none has no drift.
  if (spec[SpecTerm::energy_drift] && !(total_energy(scene.initial, scene, energy_reference(scene)) > 0))
    throw InputError(fmt::format("--spec energy_drift: {} starts with no energy (E0 = 0: its balls at rest and no "
                                 "gravity), so no drift relative to it is defined and no engine could be judged by "
                                 "it: drop it with energy_drift=none",
                                 scene.name));
}

// Sets the terms `texts` name over the scene's spec and writes the result into the scene's
// [accuracy] table, so what builds itself for the scene's spec (home's default profile) builds for
// this one; returns it. No texts: the scene as it is.
inline AccuracySpec ask_scene_for(Scene& scene, const std::vector<std::string>& texts) {
  AccuracySpec spec = scene_spec(scene);
  if (texts.empty()) return spec;
  apply_spec_texts(spec, texts, "--spec");
  if (spec.empty()) throw InputError("--spec: every term dropped: a spec needs at least one bound");
  check_measurable(scene, spec);
  for (size_t t = 0; t < spec.bound.size(); ++t) scene.accuracy.set[t] = true, scene.accuracy.bound[t] = spec.bound[t];
  return spec;
}

}  // namespace ballbench::cli
