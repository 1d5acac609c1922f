#include "accuracy_spec.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "input_error.h"
#include "scene.h"

namespace ballbench {

const std::array<SpecTermDef, kSpecTermCount>& spec_terms() {
  static const std::array<SpecTermDef, kSpecTermCount> terms{{
      {SpecTerm::overlap, "overlap", "", false, false, true,
       "the deepest overlap in any sample after the first, as a fraction of the radius (the smaller one for a pair)"},
      {SpecTerm::tunnelling, "tunnelling", "", false, false, true,
       "balls that passed through a wall or through each other within a step (wall + pair)"},
      {SpecTerm::sticking, "sticking", "", false, false, true, "stuck episodes, wall + pair (the sticking metric)"},
      {SpecTerm::rest_speed, "rest_speed", "m/s", false, false, false,
       "the RMS speed of the final state: a pile that should be at rest"},
      {SpecTerm::energy_drift, "energy_drift", "", false, false, true,
       "the largest |E - E0| / E0 over the run: for scenes that conserve energy"},
      {SpecTerm::energy_error, "energy_error", "", false, true, false,
       "the largest |E - E_ref| / E_ref(0) against the reference run"},
      {SpecTerm::horizon, "horizon", "s", true, true, false,
       "how long every ball stays within a tenth of the mean radius (RMS) of the reference run; at least this"},
      {SpecTerm::rolling, "rolling", "", false, false, false,
       "each rolling ball's final speed against its own closed form, the largest |v - v_closed| / |v_closed|"},
  }};
  return terms;
}

const SpecTermDef& spec_term(SpecTerm t) { return spec_terms()[static_cast<int>(t)]; }

std::optional<SpecTerm> spec_term_named(const std::string& key) {
  for (const SpecTermDef& d : spec_terms())
    if (key == d.key) return d.term;
  return std::nullopt;
}

bool AccuracySpec::needs_reference() const {
  for (const SpecTermDef& d : spec_terms())
    if (d.needs_reference && (*this)[d.term]) return true;
  return false;
}

bool AccuracySpec::empty() const {
  return std::none_of(bound.begin(), bound.end(), [](const auto& b) { return b.has_value(); });
}

std::string AccuracySpec::text() const {
  std::vector<std::string> parts;
  for (const SpecTermDef& d : spec_terms())
    if (const auto& b = (*this)[d.term])
      parts.push_back(fmt::format("{} {} {:.3g}{}{}", d.key, d.at_least ? ">=" : "<=", *b, *d.unit ? " " : "", d.unit));
  return parts.empty() ? "no bound" : fmt::format("{}", fmt::join(parts, ", "));
}

nlohmann::json AccuracySpec::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const SpecTermDef& d : spec_terms())
    if (const auto& b = (*this)[d.term]) j[d.key] = *b;
  return j;
}

const char* scene_class_name(SceneClass c) {
  switch (c) {
    case SceneClass::gas: return "gas";
    case SceneClass::pile: return "pile";
    case SceneClass::rolling: return "rolling";
    case SceneClass::free: return "free";
  }
  return "?";
}

SceneClass scene_class(const Scene& scene) {
  const SceneFeatures f = scene.features();
  if (scene.metrics.rolling) return SceneClass::rolling;
  if (!f.gravity) return SceneClass::gas;
  return f.walls ? SceneClass::pile : SceneClass::free;
}

namespace {

// A pile is at rest when its RMS speed is below 1% of sqrt(|g| r): the speed a ball gains falling
// 1/20 000 of its radius, far below anything a reader sees move.
constexpr double kRestSpeedFactor = 0.01;
// Piles and bowls: balls may sink into each other by 1% of the radius, a tenth of a pixel on a
// ball drawn 20 pixels across.
constexpr double kPileOverlap = 0.01;
// Scenes that conserve energy: to round-off, which a double solver keeps far below this over 10^6
// steps and a float engine cannot reach.
constexpr double kEnergyRoundOff = 1e-9;
// The closed forms of friction scenes: to 0.5%.
constexpr double kClosedForm = 0.005;

}  // namespace

AccuracySpec class_spec(const Scene& scene) {
  AccuracySpec s;
  const SceneFeatures f = scene.features();
  s[SpecTerm::tunnelling] = 0;
  // A placement that starts overlapping (the thesis's) takes steps to come apart: its overlap says
  // nothing about the engine until then, so such a scene bounds none by default.
  if (!scene.allow_overlap) s[SpecTerm::overlap] = kPileOverlap;
  switch (scene_class(scene)) {
    case SceneClass::gas:
      if (f.elastic) s[SpecTerm::energy_drift] = kEnergyRoundOff;
      break;
    case SceneClass::pile:
      if (scene.n() > 0)
        s[SpecTerm::rest_speed] = kRestSpeedFactor * std::sqrt(scene.gravity.norm() * scene.radius.mean());
      break;
    case SceneClass::rolling:
      s[SpecTerm::rolling] = kClosedForm;
      break;
    case SceneClass::free:
      break;
  }
  return s;
}

AccuracySpec scene_spec(const Scene& scene) {
  AccuracySpec s = class_spec(scene);
  for (int t = 0; t < kSpecTermCount; ++t)
    if (scene.accuracy.set[t]) s.bound[t] = scene.accuracy.bound[t];
  return s;
}

void check_spec_bound(SpecTerm t, double value, const std::string& where) {
  const SpecTermDef& d = spec_term(t);
  if (!std::isfinite(value) || value < 0)
    throw InputError(fmt::format("{}: {} must be a finite number >= 0, got {}", where, d.key, value));
  if ((t == SpecTerm::tunnelling || t == SpecTerm::sticking) && value != std::floor(value))
    throw InputError(fmt::format("{}: {} is a count: a whole number, got {}", where, d.key, value));
}

void apply_spec_texts(AccuracySpec& spec, const std::vector<std::string>& texts, const std::string& option) {
  std::vector<std::string> given;
  for (const std::string& text : texts) {
    const auto eq = text.find('=');
    const std::string key = text.substr(0, eq);
    const auto term = spec_term_named(key);
    if (eq == std::string::npos || !term) {
      std::vector<std::string> keys;
      for (const SpecTermDef& d : spec_terms()) keys.push_back(d.key);
      throw InputError(fmt::format("{} {}: expected KEY=VALUE with KEY one of {}", option, text, fmt::join(keys, ", ")));
    }
    // One value a term: a second would silently win.
    if (std::find(given.begin(), given.end(), key) != given.end())
      throw InputError(fmt::format("{} {}: {} is given twice", option, text, key));
    given.push_back(key);
    const std::string value = text.substr(eq + 1);
    if (value == "none") {
      spec[*term].reset();
      continue;
    }
    // A decimal number, all of it: no hexadecimal (std::stod reads "0x10" as 16), no spaces.
    double v = 0;
    const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), v, std::chars_format::general);
    if (value.empty() || error != std::errc() || end != value.data() + value.size())
      throw InputError(fmt::format("{} {}: {} is not a decimal number (or `none`)", option, text, value));
    check_spec_bound(*term, v, option + " " + text);
    spec[*term] = v;
  }
}

std::optional<SpecTerm> principal_term(const AccuracySpec& spec) {
  for (SpecTerm t : {SpecTerm::rolling, SpecTerm::energy_error, SpecTerm::energy_drift, SpecTerm::overlap,
                     SpecTerm::rest_speed})
    if (spec[t]) return t;
  return std::nullopt;
}

}  // namespace ballbench
