#pragma once
// The accuracy a comparison asks of every engine, written once: each term (largest overlap,
// tunnelling, sticking, rest, energy, horizon, closed forms) is a row of spec_terms(), from which
// the scene file's [accuracy] table, the `--spec` flag, `ballbench match`'s table, its JSON and CSV
// and the docs derive. A spec holds a bound for some of the terms; a run meets it when every bound
// term's figure, measured from the run's states by the harness, is within its bound.
//
// Each scene has a class (SceneClass, derived from the scene) whose default spec is documented in
// scenarios/README.md; the scene's [accuracy] table changes it term by term, and flags change that.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ballbench {

struct Scene;

enum class SpecTerm {
  overlap,       // the deepest overlap after the start / radius (penetration.after_start)
  tunnelling,    // passes through a wall or a ball (wall + pair)
  sticking,      // stuck episodes (wall + pair)
  rest_speed,    // the final state's RMS speed (m/s): a pile at rest
  energy_drift,  // the largest relative drift of the total energy (scenes that conserve it)
  energy_error,  // the largest relative energy error against the reference
  horizon,       // how long the positions stay within the horizon tolerance of the reference (s)
  rolling,       // each rolling ball's final speed against its own closed form, the largest relative error
};
inline constexpr int kSpecTermCount = 8;

struct SpecTermDef {
  SpecTerm term;
  const char* key;   // in [accuracy], --spec, JSON and CSV
  const char* unit;  // "" for counts and ratios
  bool at_least;     // the figure must be at least the bound (the horizon); else at most
  bool needs_reference;  // measured against the reference run (`exact`)
  // The figure never falls as a run goes on (a deepest overlap, a count, a largest drift): a run
  // whose figure is past the bound cannot meet it, so it stops there (RunOptions::stop_on_miss).
  bool grows;
  const char* doc;
};

// Every term, in SpecTerm's order.
const std::array<SpecTermDef, kSpecTermCount>& spec_terms();
const SpecTermDef& spec_term(SpecTerm t);
// The term named `key`, or none.
std::optional<SpecTerm> spec_term_named(const std::string& key);

struct AccuracySpec {
  std::array<std::optional<double>, kSpecTermCount> bound;

  std::optional<double>& operator[](SpecTerm t) { return bound[static_cast<int>(t)]; }
  const std::optional<double>& operator[](SpecTerm t) const { return bound[static_cast<int>(t)]; }
  bool needs_reference() const;
  bool empty() const;
  // "overlap <= 0.01, tunnelling <= 0, rest_speed <= 0.0078 m/s"
  std::string text() const;
  nlohmann::json to_json() const;  // {"overlap": 0.01, ...}: the bound terms only
};

// The term a work-precision front plots error along: the first the spec bounds of the rolling
// error (a scene asks for it), the energy error against the reference, the energy drift, the
// overlap, the rest speed (terms with a continuous figure, smaller better); none when the spec
// bounds only counts and the horizon.
std::optional<SpecTerm> principal_term(const AccuracySpec& spec);

// A scene file's [accuracy] table: the terms it sets (a bound, or none where it drops the class's).
struct SceneAccuracy {
  std::array<bool, kSpecTermCount> set{};
  std::array<std::optional<double>, kSpecTermCount> bound;
};

// What kind of scene it is, for its default spec (scenarios/README.md, "Accuracy").
enum class SceneClass {
  gas,      // no gravity: balls fly and collide
  pile,     // gravity and a box: balls settle onto each other (piles, bowls, heaps)
  rolling,  // a scene that asks for `rolling`: balls on the floor, each against its closed form
  free,     // gravity without a box
};
const char* scene_class_name(SceneClass c);
SceneClass scene_class(const Scene& scene);

// The class's default spec for this scene, before its [accuracy] table.
AccuracySpec class_spec(const Scene& scene);
// The scene's spec: the class default, then its [accuracy] table (Scene::accuracy) on top.
AccuracySpec scene_spec(const Scene& scene);

// Sets terms from "KEY=VALUE" texts (`--spec overlap=0.005,rest_speed=none`; "none" drops a
// term); an unknown key or a bad value throws InputError naming `option`.
void apply_spec_texts(AccuracySpec& spec, const std::vector<std::string>& texts, const std::string& option);
// Checks a bound's value for its term; throws InputError("WHERE: WHY") if it is not one.
void check_spec_bound(SpecTerm t, double value, const std::string& where);

}  // namespace ballbench
