#include "metrics/catalog.h"

#include <fmt/format.h>

#include "json_value.h"
#include "metrics/angle_of_repose.h"
#include "result.h"

namespace ballbench {
namespace {

using nlohmann::json;

// Counts and the outcome of a run move only when its behaviour does, never by round-off.
constexpr Tolerance kExact{0.0, 0.0};
// Real-valued metrics of our double solvers: the same source gives the same bits on every build we
// make (-ffp-contract=off); 1e-9 leaves room for a compiler reordering a sum, while a change of
// algorithm or constant moves them far more. The absolute floor is for round-off around zero (the
// momentum drift of a conserving solver).
constexpr Tolerance kReal{1e-9, 1e-12};

json optional_json(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }
json vec_json(const Eigen::Vector2d& v) { return json::array({v.x(), v.y()}); }
Eigen::Vector2d vec_from(const json& j) { return {json_number(j.at(0)), json_number(j.at(1))}; }

// A definition that quotes no tolerance.
std::function<std::string(const MetricsConfig&)> fixed(std::string text) {
  return [text = std::move(text)](const MetricsConfig&) { return text; };
}

// A metric held in one field of Result: its getter and setter from one accessor, a generic lambda
// returning the field (const for the getter).
template <class Access>
MetricDef field(std::string key, std::string unit, std::function<std::string(const MetricsConfig&)> definition,
                Access access) {
  MetricDef m;
  m.key = std::move(key), m.unit = std::move(unit), m.definition = std::move(definition);
  m.get = [access](const Result& r) {
    const auto& v = access(r);
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, Eigen::Vector2d>) return vec_json(v);
    else if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::optional<double>>) return optional_json(v);
    else return json(v);
  };
  m.set = [access](Result& r, const json& j) {
    auto& v = access(r);
    using V = std::decay_t<decltype(v)>;
    if constexpr (std::is_same_v<V, Eigen::Vector2d>) v = vec_from(j);
    else if constexpr (std::is_same_v<V, std::optional<double>>) v = json_number(j);
    else if constexpr (std::is_floating_point_v<V>) v = json_number(j);
    else v = j.get<V>();
  };
  return m;
}

MetricDef& shown(MetricDef& m, std::string column, std::string heading, bool ranked,
                 MeaningfulOn meaningful = MeaningfulOn::every_scene) {
  m.column = std::move(column), m.heading = std::move(heading), m.ranked = ranked, m.meaningful = meaningful;
  return m;
}

std::vector<MetricDef> build_catalog() {
  std::vector<MetricDef> c;
  const auto add = [&](MetricDef m) -> MetricDef& { return c.emplace_back(std::move(m)); };

  add(field("samples", "", fixed("the states the sampled metrics saw (every k-th step and the last)"),
            [](auto& r) -> auto& { return r.metrics.samples; }));

  // Energy (metrics/energy.h).
  add(field("energy.initial", "J",
            fixed("E0: E = sum m |v|^2 / 2 + I w^2 / 2 + m |g| h at the start, h measured from the container's floor "
                  "(from the lowest initial ball in open space), I = k m r^2 (the rotation term only for a scene that "
                  "rotates)"),
            [](auto& r) -> auto& { return r.metrics.energy.initial; }))
      .regress = kReal;
  add(field("energy.final", "J", fixed("E at the last sample"), [](auto& r) -> auto& { return r.metrics.energy.final; }))
      .regress = kReal;
  {
    MetricDef& m = add(field("energy.max_rel_drift", "",
                             fixed("max over samples of |E - E0| / E0 (none when E0 = 0). Restitution below 1 loses "
                                   "energy by design, so compare engines on the same scene, not against zero"),
                             [](auto& r) -> auto& { return r.metrics.energy.max_rel_drift; }));
    shown(m, "energy drift (max rel)", "E drift", false, MeaningfulOn::elastic_scenes).regress = kReal;
  }
  {
    MetricDef m;
    m.unit = "";
    m.definition = fixed("the energy left at the end, E final / E0");
    m.get = [](const Result& r) {
      const auto& e = r.metrics.energy;
      return e.initial > 0 ? json(e.final / e.initial) : json(nullptr);
    };
    shown(add(std::move(m)), "E final / E0", "", false, MeaningfulOn::inelastic_scenes);
  }
  add(field("energy.max_abs_drift", "J", fixed("max over samples of |E - E0|"),
            [](auto& r) -> auto& { return r.metrics.energy.max_abs_drift; }))
      .regress = kReal;
  add(field("energy.reference", "J/kg", fixed("-g . x_ref: the potential per unit mass at the height E is measured from"),
            [](auto& r) -> auto& { return r.metrics.energy.reference; }));

  // Momentum (metrics/momentum.h).
  add(field("momentum.initial", "kg m/s", fixed("P0: P = sum m v at the start"),
            [](auto& r) -> auto& { return r.metrics.momentum.initial; }));
  add(field("momentum.final", "kg m/s", fixed("P at the last sample"),
            [](auto& r) -> auto& { return r.metrics.momentum.final; }));
  {
    MetricDef& m = add(field("momentum.max_abs_drift", "kg m/s",
                             fixed("max over samples of |P - P0|. Conserved only in open space without gravity; walls "
                                   "and gravity change it"),
                             [](auto& r) -> auto& { return r.metrics.momentum.max_abs_drift; }));
    shown(m, "momentum drift (max abs)", "P drift", false, MeaningfulOn::open_space_without_gravity).regress = kReal;
  }
  add(field("angular_momentum.centre", "m",
            fixed("c, the fixed point angular momentum is taken about: the container's centre, or the initial centre "
                  "of mass in open space"),
            [](auto& r) -> auto& { return r.metrics.angular_momentum.centre; }));
  add(field("angular_momentum.initial", "kg m^2/s",
            fixed("L0: L = sum m (x - c) x v + I w at the start, orbital plus spin, counter-clockwise"),
            [](auto& r) -> auto& { return r.metrics.angular_momentum.initial; }))
      .regress = kReal;
  add(field("angular_momentum.final", "kg m^2/s", fixed("L at the last sample"),
            [](auto& r) -> auto& { return r.metrics.angular_momentum.final; }))
      .regress = kReal;
  {
    MetricDef& m = add(field("angular_momentum.max_abs_drift", "kg m^2/s",
                             fixed("max over samples of |L - L0|. Friction trades orbit for spin and keeps the sum: "
                                   "conserved in open space without gravity at any friction; walls and gravity change it"),
                             [](auto& r) -> auto& { return r.metrics.angular_momentum.max_abs_drift; }));
    shown(m, "angular momentum drift (max abs)", "L drift", false, MeaningfulOn::open_space_without_gravity).regress =
        kReal;
  }

  // Slip (metrics/slip.h): only for scenes that rotate and have walls.
  {
    MetricDef m;
    m.key = "slip.final_max", m.unit = "m/s";
    m.definition = [](const MetricsConfig& cfg) {
      return fmt::format("the largest slip |v . t - w r| (the speed of the contact point along the wall; t: the wall's "
                         "inward normal turned a quarter counter-clockwise) of a ball within r (1 + {:g}%) of a wall, "
                         "at the last sample: 0 when every such ball rolls. Scenes that rotate and have walls",
                         100 * cfg.contact_tolerance);
    };
    m.get = [](const Result& r) { return r.metrics.slip.measured ? json(r.metrics.slip.final_max) : json(nullptr); };
    m.set = [](Result& r, const json& j) { r.metrics.slip.measured = true, r.metrics.slip.final_max = json_number(j); };
    shown(add(std::move(m)), "slip at end (m/s)", "slip", true).regress = kReal;
  }
  {
    MetricDef m;
    m.key = "slip.time_to_roll", m.unit = "s";
    m.definition = [](const MetricsConfig& cfg) {
      return fmt::format("the time from which on no ball on a wall slips faster than {:g} m/s (none: the last sample "
                         "still slips)",
                         cfg.roll_tolerance);
    };
    m.get = [](const Result& r) {
      return r.metrics.slip.measured ? optional_json(r.metrics.slip.time_to_roll) : json(nullptr);
    };
    m.set = [](Result& r, const json& j) { r.metrics.slip.measured = true, r.metrics.slip.time_to_roll = json_number(j); };
    shown(add(std::move(m)), "time to roll (s)", "t.roll", false).regress = kReal;
  }

  // Tunnelling (metrics/tunnelling.h) and sticking (metrics/sticking.h): counts of events.
  shown(add(field("tunnelling.wall", "",
                  fixed("balls whose centre went from inside the box to beyond a wall between two samples"),
                  [](auto& r) -> auto& { return r.metrics.tunnelling_wall; })),
        "tunnelling wall", "tun.wall", true)
      .regress = kExact;
  shown(add(field("tunnelling.pair", "",
                  [](const MetricsConfig& cfg) {
                    return fmt::format(
                        "pairs apart in two consecutive samples whose relative motion, taken as a straight line between "
                        "them, came closer than {:.0f}% of their radius sum less (|dv_i| + |dv_j|) h / 4 (dv: each "
                        "ball's change of velocity between the samples, h: the time between them; a path bent once by "
                        "a collision strays at most that far from the straight line): they passed through each other. "
                        "A resolved bounce never counts; a ball that collides several times within one sample interval "
                        "can still fool the test, so `exact`'s count on a scene is the floor",
                        100 * (1 - cfg.contact_tolerance));
                  },
                  [](auto& r) -> auto& { return r.metrics.tunnelling_pair; })),
        "tunnelling pair", "tun.pair", true)
      .regress = kExact;
  const auto sticking = [](const char* what) {
    return [what](const MetricsConfig& cfg) {
      return fmt::format("{} overlapping deeper than {:.0f}% of its {} for more than {} consecutive samples, and not "
                         "moving out at a sample past that; one event per episode (a pair placed overlapping that is "
                         "moving apart is leaving, not stuck)",
                         what, 100 * cfg.contact_tolerance,
                         std::string(what) == "a pair" ? "radius sum" : "radius (in a wall)", cfg.stuck_samples);
    };
  };
  shown(add(field("sticking.wall", "", sticking("a ball"), [](auto& r) -> auto& { return r.metrics.sticking_wall; })),
        "sticking wall", "stk.wall", true)
      .regress = kExact;
  shown(add(field("sticking.pair", "", sticking("a pair"), [](auto& r) -> auto& { return r.metrics.sticking_pair; })),
        "sticking pair", "stk.pair", true)
      .regress = kExact;

  shown(add(field("penetration.max", "",
                  fixed("the deepest overlap over every contact in every sample, divided by the radius (the smaller "
                        "one for a pair)"),
                  [](auto& r) -> auto& { return r.metrics.penetration_max; })),
        "penetration max", "pen.max", true, MeaningfulOn::no_scene)
      .regress = kReal;
  shown(add(field("penetration.mean", "", fixed("the mean of the same over every overlapping contact in every sample"),
                  [](auto& r) -> auto& { return r.metrics.penetration_mean; })),
        "penetration mean", "", true, MeaningfulOn::no_scene)
      .regress = kReal;
  shown(add(field("penetration.initial", "",
                  fixed("penetration max of the first sample alone: how deep the placement starts overlapping, the "
                        "same for every engine"),
                  [](auto& r) -> auto& { return r.metrics.penetration_initial; })),
        "initial overlap", "", false, MeaningfulOn::no_scene);
  shown(add(field("penetration.after_start", "",
                  fixed("penetration max over every sample after the first: how deep the engine lets balls sink (the "
                        "accuracy spec's `overlap`)"),
                  [](auto& r) -> auto& { return r.metrics.penetration_after_start; })),
        "penetration after start", "", true);

  // Whole-run figures of the final state.
  add(field("jitter", "m/s",
            fixed("the RMS speed of the final state, for scenes with gravity and walls, where balls should come to "
                  "rest (a pile)"),
            [](auto& r) -> auto& { return r.jitter; }));
  // Asked for by a scene's [metrics] table (scenarios/README.md): none elsewhere.
  shown(add(field("rolling.speed", "m/s",
                  fixed("one ball on the floor (scenes that ask for `rolling`): its velocity along x in the final state, "
                        "to judge against the closed form"),
                  [](auto& r) -> auto& { return r.rolling.speed; })),
        "final speed (m/s)", "v.final", false)
      .regress = kReal;
  shown(add(field("rolling.expected_speed", "m/s",
            fixed("the closed form it must end at, rolling: v_roll = (v0 - k r w0) / (1 + k) for I = k m r^2 (its "
                  "angular momentum about the contact point is kept; slide to roll: v0 / (1 + k))"),
            [](auto& r) -> auto& { return r.rolling.expected_speed; })),
        "closed-form speed (m/s)", "", false)
      .regress = kReal;
  shown(add(field("rolling.expected_time_to_roll", "s",
            fixed("the closed form of the time it starts to roll: the slip u = v + w r after its first contact over "
                  "mu g (1 + 1 / k), the rate sliding friction takes it off (slide to roll: v0 k / ((1 + k) mu g)); "
                  "a drop with restitution 0 adds the fall and the impact's Coulomb impulse; none for a ball that "
                  "bounces"),
            [](auto& r) -> auto& { return r.rolling.expected_time_to_roll; })),
        "closed-form time to roll (s)", "", false)
      .regress = kReal;
  shown(add(field("angle_of_repose", "deg",
                  fixed(fmt::format(
                      "the slope of the final heap's flanks (scenes that ask for `angle_of_repose`): the floor cut "
                      "into columns one mean diameter wide, each column's height the top of its highest ball; on "
                      "each side of the highest column (height H), a least-squares line through the columns from it "
                      "outward whose height is within [{0:g} H, {1:g} H] (at least {2}; the walk stops at the first "
                      "column below {0:g} H), its angle atan |slope|; the mean over both flanks (none: neither had "
                      "{2} columns in the band). A heap spread flat measures near 0, or none",
                      kReposeBandLow, kReposeBandHigh, kReposeMinColumns)),
                  [](auto& r) -> auto& { return r.angle_of_repose; })),
        "angle of repose (deg)", "repose", false)
      .regress = kReal;
  add(field("speed_ks", "",
            fixed("the Kolmogorov-Smirnov statistic of the final speeds against the 2D Maxwell-Boltzmann (Rayleigh) "
                  "law, for elastic, gravity-free scenes of 100+ equal balls"),
            [](auto& r) -> auto& { return r.speed_ks; }));
  add(field("speed_ks_critical", "", fixed("the statistic's 1% critical value, 1.63 / sqrt(n)"),
            [](auto& r) -> auto& { return r.speed_ks_critical; }));
  return c;
}

// "a.b" -> "/a/b"
json::json_pointer pointer(const std::string& key) {
  std::string p = "/" + key;
  for (char& ch : p)
    if (ch == '.') ch = '/';
  return json::json_pointer(p);
}

}  // namespace

bool meaningful_on(MeaningfulOn where, const SceneFeatures& f) {
  switch (where) {
    case MeaningfulOn::every_scene: return true;
    case MeaningfulOn::elastic_scenes: return f.elastic;
    case MeaningfulOn::inelastic_scenes: return !f.elastic;
    case MeaningfulOn::open_space_without_gravity: return !f.walls && !f.gravity;
    case MeaningfulOn::no_scene: return false;
  }
  return true;
}

const std::vector<MetricDef>& metric_catalog() {
  static const std::vector<MetricDef> catalog = build_catalog();
  return catalog;
}

std::string metric_text(const json& v) {
  if (v.is_null()) return "-";
  if (v.is_number_integer()) return fmt::format("{}", v.get<long>());
  if (v.is_number()) return fmt::format("{:.3g}", v.get<double>());
  if (v.is_array() && v.size() == 2) return fmt::format("({}, {})", metric_text(v[0]), metric_text(v[1]));
  return json_text(v);
}

void put_metrics(const Result& r, json& j) {
  for (const MetricDef& m : metric_catalog())
    if (!m.key.empty()) j[pointer(m.key)] = r.measured() ? m.get(r) : json(nullptr);
}

void take_metrics(const json& j, Result& r) {
  for (const MetricDef& m : metric_catalog()) {
    if (m.key.empty() || !m.set) continue;
    const json::json_pointer p = pointer(m.key);
    if (!j.contains(p) || j.at(p).is_null()) continue;
    m.set(r, j.at(p));
  }
}

}  // namespace ballbench
