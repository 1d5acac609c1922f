#pragma once
// `--spec KEY=VALUE,...` of `run` and `match`: the accuracy the scene is asked for, over its own.
#include <string>
#include <vector>

#include <fmt/format.h>

#include "accuracy_spec.h"
#include "input_error.h"
#include "scene.h"

namespace ballbench::cli {

// Sets the terms `texts` name over the scene's spec and writes the result into the scene's
// [accuracy] table, so what builds itself for the scene's spec (home's default profile) builds for
// this one; returns it. No texts: the scene as it is.
inline AccuracySpec ask_scene_for(Scene& scene, const std::vector<std::string>& texts) {
  AccuracySpec spec = scene_spec(scene);
  if (texts.empty()) return spec;
  apply_spec_texts(spec, texts, "--spec");
  if (spec.empty()) throw InputError("--spec: every term dropped: a spec needs at least one bound");
  // A term the scene cannot measure would leave every engine "not measured": refused before any run.
  if (spec[SpecTerm::rolling] && !scene.metrics.rolling)
    throw InputError(fmt::format("--spec rolling: {} has no rolling closed form (balls on a floor with friction, "
                                 "[metrics] rolling = true), so no engine could be judged by it: drop it with "
                                 "rolling=none",
                                 scene.name));
  for (size_t t = 0; t < spec.bound.size(); ++t) scene.accuracy.set[t] = true, scene.accuracy.bound[t] = spec.bound[t];
  return spec;
}

}  // namespace ballbench::cli
