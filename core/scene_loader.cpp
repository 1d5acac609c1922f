#include "scene_loader.h"

#include "project_scene.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string_view>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "input_error.h"
#include "interrupt.h"
#include "progress.h"
#include "overlap.h"
#include "toml_table_reader.h"

namespace ballbench {
namespace {

// The most steps a scene may ask for: beyond this a typo (dt = 1e-12) would look like a hang.
constexpr double kMaxSteps = 1e9;
// The largest scene file read: explicit [[ball]] tables of a few hundred thousand balls; more
// balls are placed by [random] or [lattice].
constexpr long long kMaxSceneBytes = 16ll << 20;
// The smallest radius (m): below it differences of positions lose every digit a contact needs
// (and engines with a minimum contact distance never finish a step).
constexpr double kMinRadius = 1e-9;
// The most balls a scene may hold: beyond this the state alone would not fit in memory here.
constexpr int64_t kMaxBalls = 50'000'000;
// The largest |value| of a coordinate, velocity, gravity component, radius or mass (m, m/s, m/s^2,
// kg). Far beyond any ball scene; it keeps differences, squares and sums of these finite (a box
// from -1e308 to 1e308 has an infinite width) so every later computation sees finite numbers.
constexpr double kMaxMagnitude = 1e12;
// How far from the origin a ball may start, in its own radii. The spatial hashes index cells of
// about a radius with 64-bit integers multiplied by hash primes (core/overlap.h); 1e9 cells keeps
// that product far from overflow, and a scene this spread out is a unit typo.
constexpr double kMaxRadiiFromOrigin = 1e9;

// Uniform double in [lo, hi) from 53 random bits: the mapping is ours, so a seed gives the same
// scene with every standard library (std::uniform_real_distribution's is implementation-defined).
double uniform(std::mt19937_64& rng, double lo, double hi) {
  const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

struct BallList {
  std::vector<Eigen::Vector2d> pos, vel;
  std::vector<double> radius, mass, spin;
  std::vector<int> line;  // where each ball was declared, for messages
  void add(Eigen::Vector2d p, Eigen::Vector2d v, double r, double m, double w, int at) {
    pos.push_back(p), vel.push_back(v), radius.push_back(r), mass.push_back(m), spin.push_back(w), line.push_back(at);
  }
  // Room for `n` balls up front: growing by doubling would copy millions of balls at once, twice the memory.
  void reserve(size_t n) {
    pos.reserve(n), vel.reserve(n), radius.reserve(n), mass.reserve(n), spin.reserve(n), line.reserve(n);
  }
};

void check_positive(const TableReader& r, const char* key, double v) {
  if (!(v > 0)) r.fail(r.node(key), key, fmt::format("must be positive, got {}", v));
}

// A radius or a mass: positive and at most kMaxMagnitude; a radius at least kMinRadius.
void check_size(const TableReader& r, const char* key, double v) {
  check_positive(r, key, v);
  if (std::string_view(key) == "radius" && v < kMinRadius)
    r.fail(r.node(key), key, fmt::format("must be at least {:g} m, got {}", kMinRadius, v));
  if (v > kMaxMagnitude) r.fail(r.node(key), key, fmt::format("must be at most {:g}, got {}", kMaxMagnitude, v));
}

// A ball (or a corner of a random placement box) at p is not too many radii from the origin.
void check_spread(const TableReader& r, const char* key, const Eigen::Vector2d& p, double radius) {
  if (p.cwiseAbs().maxCoeff() > kMaxRadiiFromOrigin * radius)
    r.fail(r.node(key), key,
           fmt::format("({}, {}) is more than {:g} radii ({}) from the origin: check the units", p.x(), p.y(),
                       kMaxRadiiFromOrigin, radius));
}

// A spin (rad/s): finite and at most kMaxMagnitude, as a velocity.
void check_spin(const TableReader& r, const char* key, double w) {
  if (!(std::abs(w) <= kMaxMagnitude))
    r.fail(r.node(key), key, fmt::format("must be a finite angular velocity of at most {:g} rad/s, got {}", kMaxMagnitude, w));
}

// spin_min and spin_max of a [random] or [lattice] table: each ball's spin is drawn uniformly
// between them. Without either key nothing is drawn, so the placements of scenes without spin
// stay those of the seed.
struct SpinRange {
  bool drawn = false;
  double min = 0, max = 0;
  double draw(std::mt19937_64& rng) const { return drawn ? uniform(rng, min, max) : 0.0; }
};

SpinRange read_spin_range(const TableReader& r) {
  SpinRange s;
  s.drawn = r.has("spin_min") || r.has("spin_max");
  s.min = r.number_or("spin_min", 0.0), s.max = r.number_or("spin_max", 0.0);
  check_spin(r, "spin_min", s.min);
  check_spin(r, "spin_max", s.max);
  if (s.min > s.max) r.fail(r.node("spin_min"), "spin_min", fmt::format("must not exceed spin_max ({} > {})", s.min, s.max));
  return s;
}

bool inside(const Container& c, const Eigen::Vector2d& p, double radius) {
  if (c.kind == ContainerKind::None) return true;
  return (p.array() - radius >= c.min.array()).all() && (p.array() + radius <= c.max.array()).all();
}

void read_explicit_balls(const toml::node& node, const std::string& source, const Container& container,
                         BallList& balls) {
  const toml::array* arr = node.as_array();
  const auto fail = [&](const toml::node& at, const std::string& field, const std::string& why) {
    throw InputError(fmt::format("{}:{}: {}: {}", source, at.source().begin.line, field, why));
  };
  if (node.is_table()) fail(node, "ball", "expected [[ball]] tables (double brackets), got a single [ball] table");
  if (!arr) fail(node, "ball", fmt::format("expected [[ball]] tables, got {}", node_type_name(node)));
  if (arr->empty()) fail(node, "ball", "expected [[ball]] tables, got an empty array");
  for (size_t i = 0; i < arr->size(); ++i)
    if (!arr->get(i)->is_table())
      fail(*arr->get(i), fmt::format("ball[{}]", i),
           fmt::format("expected a table of pos, vel, radius, mass, got {}", node_type_name(*arr->get(i))));
  if (static_cast<int64_t>(arr->size()) > kMaxBalls)
    fail(node, "ball", fmt::format("at most {} balls are supported", kMaxBalls));
  for (size_t i = 0; i < arr->size(); ++i) {
    const toml::table& t = *arr->get(i)->as_table();
    TableReader r(t, source, fmt::format("ball[{}]", i));
    r.check_keys({"pos", "vel", "radius", "mass", "spin"});
    const Eigen::Vector2d p = r.vec2("pos", kMaxMagnitude);
    const double radius = r.number("radius");
    const double mass = r.number_or("mass", 1.0);
    check_size(r, "radius", radius);
    check_size(r, "mass", mass);
    check_spread(r, "pos", p, radius);
    if (!inside(container, p, radius))
      r.fail(r.node("pos"), "pos",
             fmt::format("ball at ({}, {}) with radius {} is not inside the container", p.x(), p.y(), radius));
    const double spin = r.number_or("spin", 0.0);
    check_spin(r, "spin", spin);
    balls.add(p, r.vec2_or("vel", kMaxMagnitude, {0, 0}), radius, mass, spin, static_cast<int>(t.source().begin.line));
  }
}

// [random]: `count` balls drawn uniformly from the position and velocity boxes. Without
// allow_overlap a drawn position that overlaps an earlier ball is drawn again.
// [lattice]: `count` balls on a square lattice of `spacing`, row by row from `origin` (default:
// the box's lower-left corner plus half a spacing), each with a velocity drawn uniformly from the
// velocity box. For packings random placement cannot reach (a square lattice holds up to pi / 4).
void read_lattice_balls(const toml::table& t, const std::string& source, const Container& container, BallList& balls) {
  TableReader r(t, source, "lattice");
  r.check_keys({"count", "radius", "mass", "spacing", "origin", "columns", "vel_min", "vel_max", "spin_min", "spin_max",
                "seed"});
  const int64_t count = r.integer("count", -1);
  if (count < 0) r.fail(r.node("count"), "count", "missing or negative (a whole number of balls is required)");
  if (count > kMaxBalls) r.fail(r.node("count"), "count", fmt::format("at most {} balls are supported", kMaxBalls));
  const double radius = r.number("radius"), mass = r.number_or("mass", 1.0), spacing = r.number("spacing");
  check_size(r, "radius", radius);
  check_positive(r, "mass", mass);
  if (spacing < 2 * radius) r.fail(r.node("spacing"), "spacing", fmt::format("must be at least the diameter {}", 2 * radius));
  if (container.kind != ContainerKind::Box && (!r.has("origin") || !r.has("columns")))
    r.fail(nullptr, "origin", "origin and columns are required in open space");
  const Eigen::Vector2d origin =
      r.vec2_or("origin", kMaxMagnitude, container.min.array() + 0.5 * spacing);
  int64_t columns = 0;
  if (r.has("columns")) {
    columns = r.integer("columns", 0);
    if (columns <= 0) r.fail(r.node("columns"), "columns", fmt::format("must be at least 1, got {}", columns));
  } else {
    columns = static_cast<int64_t>(std::floor((container.max.x() - radius - origin.x()) / spacing)) + 1;
  }
  if (columns <= 0) r.fail(r.node("origin"), "origin", "no column fits in the container");
  const Eigen::Vector2d vel_min = r.vec2_or("vel_min", kMaxMagnitude, {0, 0}), vel_max = r.vec2_or("vel_max", kMaxMagnitude, {0, 0});
  const SpinRange spin = read_spin_range(r);
  std::mt19937_64 rng(static_cast<uint64_t>(r.integer("seed", 1)));
  const int line = static_cast<int>(t.source().begin.line);
  balls.reserve(balls.pos.size() + static_cast<size_t>(count));
  for (int64_t k = 0; k < count; ++k) {
    if ((k & 0xffff) == 0 && interrupt_signal()) throw Interrupted{fmt::format("placing {} balls", count)};
    const Eigen::Vector2d p = origin + spacing * Eigen::Vector2d(static_cast<double>(k % columns), static_cast<double>(k / columns));
    if (!inside(container, p, radius))
      r.fail(r.node("count"), "count", fmt::format("ball {} at ({:.4g}, {:.4g}) is outside the container: only {} fit", k,
                                                   p.x(), p.y(), k));
    const Eigen::Vector2d v{uniform(rng, vel_min.x(), vel_max.x()), uniform(rng, vel_min.y(), vel_max.y())};
    balls.add(p, v, radius, mass, spin.draw(rng), line);
  }
}

// What a [random] table draws: `count` balls uniformly in the position and velocity boxes.
struct RandomDraw {
  int64_t count;
  double radius, mass;
  Eigen::Vector2d pos_min, pos_max, vel_min, vel_max;
  SpinRange spin;
  int64_t seed;
  int line;  // the table's, for messages
};

// Each ball draws x, y, vx, vy (and w, with a spin range) in that order; without `allow_overlap` a
// position that overlaps an earlier ball (any, of any table) is drawn again. An interrupt is looked
// for every 65536 draws, redrawn ones included (a nearly full region redraws most of them).
void place_random_balls(const TableReader& r, const RandomDraw& d, const std::string& what, bool allow_overlap,
                        BallList& balls) {
  std::mt19937_64 rng(static_cast<uint64_t>(d.seed));
  double reach = d.radius;  // the largest radius already placed, so the hash cell covers every pair
  for (double r0 : balls.radius) reach = std::max(reach, r0);
  const size_t first = balls.pos.size();
  balls.reserve(first + static_cast<size_t>(d.count));
  OverlapIndex placed(d.radius + reach, allow_overlap ? 0 : first + static_cast<size_t>(d.count));
  if (!allow_overlap)
    for (const auto& p : balls.pos) placed.insert(p);
  constexpr int kAttempts = 1000;  // per ball; a region this full is effectively packed
  Progress progress(what);
  uint64_t draws = 0;
  for (int64_t k = 0; k < d.count; ++k) {
    Eigen::Vector2d p;
    int attempt = 0;
    do {
      if ((draws++ & 0xffff) == 0) {
        if (interrupt_signal()) throw Interrupted{fmt::format("placing {} balls", d.count)};
        progress.update(double(k) / double(d.count));
      }
      if (++attempt > kAttempts)
        r.fail(r.node("count"), "count",
               fmt::format("only {} of {} balls fit without overlap in [pos_min, pos_max] "
                           "(set allow_overlap = true to let them overlap)",
                           balls.pos.size() - first, d.count));
      p = {uniform(rng, d.pos_min.x(), d.pos_max.x()), uniform(rng, d.pos_min.y(), d.pos_max.y())};
    } while (!allow_overlap && placed.overlaps(p, d.radius, balls.pos, balls.radius));
    const Eigen::Vector2d v{uniform(rng, d.vel_min.x(), d.vel_max.x()), uniform(rng, d.vel_min.y(), d.vel_max.y())};
    const double w = d.spin.draw(rng);
    if (!allow_overlap) placed.insert(p);
    balls.add(p, v, d.radius, d.mass, w, d.line);
  }
}

void read_random_balls(const toml::table& t, const std::string& source, const std::string& prefix,
                       const Container& container, bool allow_overlap, BallList& balls) {
  TableReader r(t, source, prefix);
  r.check_keys({"count", "radius", "mass", "pos_min", "pos_max", "vel_min", "vel_max", "spin_min", "spin_max", "seed"});
  const int64_t count = r.integer("count", -1);
  if (count < 0) r.fail(r.node("count"), "count", "missing or negative (a whole number of balls is required)");
  if (count > kMaxBalls - static_cast<int64_t>(balls.pos.size()))
    r.fail(r.node("count"), "count", fmt::format("at most {} balls are supported (in all)", kMaxBalls));
  const double radius = r.number("radius");
  const double mass = r.number_or("mass", 1.0);
  check_size(r, "radius", radius);
  check_size(r, "mass", mass);
  Eigen::Vector2d lo_default{0, 0}, hi_default{0, 0};
  if (container.kind == ContainerKind::Box) {
    const Eigen::Vector2d size = container.max - container.min;
    if (2 * radius > size.minCoeff())
      r.fail(r.node("radius"), "radius",
             fmt::format("balls of radius {} do not fit in the {} x {} container", radius, size.x(), size.y()));
    lo_default = container.min.array() + radius;
    hi_default = container.max.array() - radius;
  } else if (!r.has("pos_min") || !r.has("pos_max")) {
    r.fail(nullptr, "pos_min", "pos_min and pos_max are required in open space");
  }
  const Eigen::Vector2d pos_min = r.vec2_or("pos_min", kMaxMagnitude, lo_default), pos_max = r.vec2_or("pos_max", kMaxMagnitude, hi_default);
  const Eigen::Vector2d vel_min = r.vec2_or("vel_min", kMaxMagnitude, {0, 0}), vel_max = r.vec2_or("vel_max", kMaxMagnitude, {0, 0});
  if ((pos_min.array() > pos_max.array()).any()) r.fail(r.node("pos_min"), "pos_min", "must not exceed pos_max");
  if ((vel_min.array() > vel_max.array()).any()) r.fail(r.node("vel_min"), "vel_min", "must not exceed vel_max");
  const SpinRange spin = read_spin_range(r);
  if (!inside(container, pos_min, radius) || !inside(container, pos_max, radius))
    r.fail(r.node("pos_min"), "pos_min",
           "the box [pos_min, pos_max] must keep balls of this radius inside the container");
  check_spread(r, "pos_min", pos_min, radius);
  check_spread(r, "pos_max", pos_max, radius);
  const RandomDraw draw{count, radius, mass, pos_min, pos_max, vel_min, vel_max, spin, r.integer("seed", 1),
                        static_cast<int>(t.source().begin.line)};
  place_random_balls(r, draw, fmt::format("placing {} balls ({} in {})", count, prefix, source), allow_overlap, balls);
}

// [accuracy]: the scene's own spec terms (accuracy_spec.h), each a bound or false (drops the term
// its class would bound).
void read_accuracy(const toml::node& node, const std::string& source, Scene& s) {
  if (!node.is_table())
    throw InputError(fmt::format("{}:{}: accuracy: expected a table [accuracy], got {}", source,
                                 node.source().begin.line, node_type_name(node)));
  const toml::table& t = *node.as_table();
  TableReader r(t, source, "accuracy");
  std::vector<std::string> keys;
  for (const SpecTermDef& d : spec_terms()) keys.push_back(d.key);
  for (const auto& [k, v] : t) {
    const std::string key(k.str());
    const auto term = spec_term_named(key);
    if (!term) r.fail(&v, key, "unknown key" + did_you_mean(key, keys));
    const int i = static_cast<int>(*term);
    s.accuracy.set[i] = true;
    if (v.is_boolean() && !v.as_boolean()->get()) continue;  // dropped
    if (!v.is_number()) r.fail(&v, key, fmt::format("expected a number (or false to drop it), got {}", node_type_name(v)));
    const double bound = v.value<double>().value_or(-1);
    try {
      check_spec_bound(*term, bound, source);
    } catch (const InputError&) {
      r.fail(&v, key, fmt::format("must be a finite number >= 0{}, got {}",
                                  *term == SpecTerm::tunnelling || *term == SpecTerm::sticking ? " and whole" : "", bound));
    }
    s.accuracy.bound[i] = bound;
  }
}

Scene parse_scene_text(const std::string& toml_text, const std::string& source, int64_t seed_offset);

}  // namespace

Scene parse_scene(const std::string& toml_text, const std::string& source, int64_t seed_offset) {
  try {
    return parse_scene_text(toml_text, source, seed_offset);
  } catch (const InputError& e) {
    // Messages quote what the file says (key names, strings), which may hold control characters
    // ("a\nb" is a valid quoted key): escaped, so every message stays one line.
    throw InputError(printable(e.what(), 100000));
  }
}

namespace {

// Adds `offset` to the seed (default 1) of each table that draws balls; returns how many there are.
int offset_seeds(toml::table& doc, int64_t offset) {
  int tables = 0;
  const auto shift = [&](toml::table* t) {
    if (!t) return;
    ++tables;
    if (offset == 0) return;
    const auto* seed = t->get("seed");
    const int64_t base = seed && seed->is_integer() ? seed->as_integer()->get() : 1;
    if (!seed || seed->is_integer()) t->insert_or_assign("seed", base + offset);  // another type: reported as written
  };
  shift(doc["lattice"].as_table());
  if (toml::node* rnd = doc.get("random")) {
    if (rnd->is_table()) shift(rnd->as_table());
    else if (toml::array* a = rnd->as_array())
      for (auto& e : *a) shift(e.as_table());
  }
  return tables;
}

// [metrics]: what a scene asks for beyond every run's metrics, each checked against what it needs
// (read after the balls, the container and gravity it is checked against).
void read_requested_metrics(const toml::node& node, const std::string& source, Scene& s) {
  if (!node.is_table())
    throw InputError(fmt::format("{}:{}: metrics: expected a table [metrics], got {}", source, node.source().begin.line,
                                 node_type_name(node)));
  TableReader r(*node.as_table(), source, "metrics");
  std::vector<const char*> keys;
  for (const RequestedMetricKey& m : kRequestedMetricKeys) keys.push_back(m.key);
  r.check_keys(keys);
  // Each measures against a floor: the box's bottom wall, with gravity straight down onto it.
  const bool floor = s.container.kind == ContainerKind::Box && s.gravity.x() == 0 && s.gravity.y() < 0;
  for (const RequestedMetricKey& m : kRequestedMetricKeys) {
    s.metrics.*m.flag = r.boolean(m.key, false);
    if (s.metrics.*m.flag && !floor)
      r.fail(r.node(m.key), m.key, "needs a floor: a box container and gravity straight down [0, -g]");
  }
  if (s.metrics.rolling && !(s.friction > 0))
    r.fail(r.node("rolling"), "rolling", "needs friction above 0 (a frictionless ball never rolls)");
}

// Without allow_overlap no two balls may start overlapping. Only the first `unchecked` balls (the
// [[ball]] and [lattice] ones) are searched: each [random] ball was drawn clear of every ball
// before it, so the first overlapping pair, if any, is among them. Millions of them take a second
// or more: an interrupt is looked for on either side.
void check_start_overlaps(const Scene& s, const BallList& balls, int unchecked) {
  if (s.allow_overlap) return;
  if (interrupt_signal()) throw Interrupted{fmt::format("placing {} balls", s.n())};
  const auto pair = unchecked == s.n()
                        ? first_overlapping_pair(s.initial.pos, s.radius)
                        : first_overlapping_pair(s.initial.pos.topRows(unchecked), s.radius.head(unchecked));
  if (interrupt_signal()) throw Interrupted{fmt::format("checking {} balls for overlaps", s.n())};
  if (!pair) return;
  const auto [i, j] = *pair;
  throw InputError(fmt::format("{}:{}: ball: balls {} and {} (declared at lines {} and {}) overlap at the start "
                               "(set allow_overlap = true if that is intended)",
                               s.source, balls.line[j], i, j, balls.line[i], balls.line[j]));
}

Scene parse_scene_text(const std::string& toml_text, const std::string& source, int64_t seed_offset) {
  toml::table doc;
  try {
    doc = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}: TOML syntax error: {}", source, e.source().begin.line, e.description()));
  }
  const bool random_placement = offset_seeds(doc, seed_offset) > 0;
  if (doc.empty())
    throw InputError(fmt::format("{}:1: scene: the file is empty (a scene needs dt, duration and balls)", source));
  TableReader top(doc, source, "");
  top.check_keys({"name", "description", "use_case", "dt", "duration", "gravity", "restitution", "friction", "inertia",
                  "allow_overlap", "animated", "container", "ball", "random", "lattice", "metrics", "accuracy", "settings"});

  Scene s;
  s.source = source;
  s.random_placement = random_placement;
  s.seed_offset = seed_offset;
  s.name = top.string("name", std::filesystem::path(source).stem().string());
  s.use_case = top.string("use_case", "");
  // The name is used in default output paths (`sweep` writes sweep-NAME.json) and in reports: it
  // must stay one file name in the working folder.
  if (top.node("name")) {
    const bool plain = !s.name.empty() && s.name.front() != '.' &&
                       std::none_of(s.name.begin(), s.name.end(), [](unsigned char c) {
                         return c == '/' || c == '\\' || std::iscntrl(c);
                       });
    if (!plain)
      top.fail(top.node("name"), "name",
               fmt::format("'{}' cannot name a file (no '/', '\\', control characters or leading '.')", s.name));
  }
  s.dt = top.number("dt");
  check_positive(top, "dt", s.dt);
  s.duration = top.number("duration");
  check_positive(top, "duration", s.duration);
  if (s.duration / s.dt > kMaxSteps)
    top.fail(top.node("duration"), "duration", fmt::format("duration / dt is more than {:.0e} steps", kMaxSteps));
  s.gravity = top.vec2_or("gravity", kMaxMagnitude, {0, 0});
  s.restitution = top.number_or("restitution", 1.0);
  if (s.restitution < 0 || s.restitution > 1)
    top.fail(top.node("restitution"), "restitution", fmt::format("must be in [0, 1], got {}", s.restitution));
  s.friction = top.number_or("friction", 0.0);
  if (s.friction < 0) top.fail(top.node("friction"), "friction", fmt::format("must be >= 0, got {}", s.friction));
  if (top.has("inertia")) {
    const std::string inertia = top.string("inertia", "disk");
    if (inertia == "sphere") s.inertia = Inertia::sphere;
    else if (inertia != "disk")
      top.fail(top.node("inertia"), "inertia",
               fmt::format("unknown inertia '{}' (use \"disk\", I = m r^2 / 2, or \"sphere\", I = 2/5 m r^2){}", inertia,
                           did_you_mean(inertia, std::vector<std::string>{"disk", "sphere"})));
  }
  s.allow_overlap = top.boolean("allow_overlap", false);
  s.animated = top.boolean("animated", false);

  if (const toml::node* c = top.node("container")) {
    if (!c->is_table()) top.fail(c, "container", "expected a table [container]");
    TableReader cr(*c->as_table(), source, "container");
    cr.check_keys({"kind", "min", "max"});
    const std::string kind = cr.string("kind", "box");
    if (kind == "box") {
      s.container.kind = ContainerKind::Box;
      s.container.min = cr.vec2("min", kMaxMagnitude);
      s.container.max = cr.vec2("max", kMaxMagnitude);
      if ((s.container.min.array() >= s.container.max.array()).any())
        cr.fail(cr.node("max"), "max", "must be greater than min in both x and y");
    } else if (kind == "none") {
      s.container.kind = ContainerKind::None;
      if (cr.has("min") || cr.has("max")) cr.fail(cr.node("min"), "min", "a container of kind \"none\" has no bounds");
    } else {
      cr.fail(cr.node("kind"), "kind",
              fmt::format("unknown container kind '{}' (use \"box\" or \"none\"){}", kind,
                          did_you_mean(kind, std::vector<std::string>{"box", "none"})));
    }
  }

  BallList balls;
  if (const toml::node* b = top.node("ball")) read_explicit_balls(*b, source, s.container, balls);
  if (const toml::node* lat = top.node("lattice")) {
    if (!lat->is_table()) top.fail(lat, "lattice", "expected a table [lattice]");
    read_lattice_balls(*lat->as_table(), source, s.container, balls);
  }
  const int unchecked = static_cast<int>(balls.pos.size());  // the [random] balls are drawn clear of every earlier one
  if (const toml::node* rnd = top.node("random")) {
    if (const toml::table* t = rnd->as_table()) {
      read_random_balls(*t, source, "random", s.container, s.allow_overlap, balls);
    } else if (const toml::array* a = rnd->as_array(); a && a->is_array_of_tables()) {
      for (size_t i = 0; i < a->size(); ++i)
        read_random_balls(*a->get(i)->as_table(), source, fmt::format("random[{}]", i), s.container,
                          s.allow_overlap, balls);
    } else {
      top.fail(rnd, "random", "expected a table [random] or tables [[random]]");
    }
  }
  if (balls.pos.empty()) top.fail(nullptr, "ball", "the scene has no balls (add [[ball]] or [random])");

  const int n = static_cast<int>(balls.pos.size());
  s.radius = Eigen::Map<Eigen::VectorXd>(balls.radius.data(), n);
  s.mass = Eigen::Map<Eigen::VectorXd>(balls.mass.data(), n);
  const bool spins = std::any_of(balls.spin.begin(), balls.spin.end(), [](double w) { return w != 0.0; });
  s.initial.resize(n, s.friction > 0 || spins);
  for (int i = 0; i < n; ++i) s.initial.pos.row(i) = balls.pos[i], s.initial.vel.row(i) = balls.vel[i];
  if (s.initial.rotates()) {
    s.initial.w = Eigen::Map<Eigen::VectorXd>(balls.spin.data(), n);
    s.initial.angle.setZero();
  }

  check_start_overlaps(s, balls, unchecked);

  if (const toml::node* m = top.node("metrics")) read_requested_metrics(*m, source, s);
  if (const toml::node* a = top.node("accuracy")) read_accuracy(*a, source, s);

  if (const toml::node* st = top.node("settings")) {
    if (!st->is_table()) top.fail(st, "settings", "expected tables [settings.ENGINE]");
    s.engine_settings = nlohmann::json::object();
    for (const auto& [engine, tbl] : *st->as_table()) {
      if (!tbl.is_table()) top.fail(&tbl, "settings." + std::string(engine.str()), "expected a table of settings");
      nlohmann::json obj = nlohmann::json::object();
      for (const auto& [k, v] : *tbl.as_table()) {
        const std::string key(k.str());
        if (v.is_boolean()) obj[key] = v.as_boolean()->get();
        else if (v.is_integer()) obj[key] = v.as_integer()->get();
        else if (v.is_floating_point()) obj[key] = v.as_floating_point()->get();
        else if (v.is_string()) obj[key] = v.as_string()->get();
        else top.fail(&v, "settings." + std::string(engine.str()) + "." + key, "expected a number, string or boolean");
        s.setting_lines[std::string(engine.str()) + "." + key] = static_cast<int>(v.source().begin.line);
      }
      s.engine_settings[std::string(engine.str())] = obj;
    }
  }
  return s;
}

}  // namespace

Scene load_scene_file(const std::string& path, int64_t seed_offset) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))  // ec: a reason other than absence (a loop of links, a folder not searchable)
    throw InputError(ec ? fmt::format("{}: cannot read the scene file: {}", path, ec.message())
                        : fmt::format("{}: scene file not found", path));
  if (std::filesystem::is_directory(path, ec)) throw InputError(fmt::format("{}: is a directory, not a scene file", path));
  // Checked before opening: a FIFO without a writer would block the open, a device (/dev/zero)
  // would never end.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputError(fmt::format("{}: cannot read the scene file: {}", path, std::strerror(errno)));
  if (!S_ISREG(st.st_mode))
    throw InputError(fmt::format("{}: cannot read the scene file: not a regular file (a {})", path,
                                 S_ISFIFO(st.st_mode) ? "FIFO" : S_ISSOCK(st.st_mode) ? "socket" : "device"));
  if (st.st_size > kMaxSceneBytes)
    throw InputError(fmt::format("{}: cannot read the scene file: {} bytes, above the limit of {} MiB (place many balls "
                                 "with [random] or [lattice])",
                                 path, static_cast<long long>(st.st_size), kMaxSceneBytes >> 20));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot read the scene file: {}", path, std::strerror(errno)));
  std::string text(static_cast<size_t>(kMaxSceneBytes) + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<size_t>(in.gcount()));
  if (text.size() > static_cast<size_t>(kMaxSceneBytes))
    throw InputError(fmt::format("{}: cannot read the scene file: above the limit of {} MiB", path, kMaxSceneBytes >> 20));
  if (in.bad()) throw InputError(fmt::format("{}: reading the scene file failed: {}", path, std::strerror(errno)));
  return parse_scene(text, path, seed_offset);
}

std::string scenario_dir() {
  if (const char* env = std::getenv("BALLBENCH_SCENARIOS"); env && *env) return env;
  return BALLBENCH_SCENARIO_DIR;
}

Scene load_project_scene(const std::string& name) {
  return load_scene_file(std::string(BALLBENCH_SCENARIO_DIR) + "/" + name + ".toml");
}

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(scenario_dir(), ec))
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

Scene load_scene(const std::string& name_or_path, int64_t seed_offset) {
  // A path by its spelling ('/' or .toml); a built-in's name is the built-in even where the working
  // folder holds a file or folder of that name; anything else is a path if it exists.
  const auto names = builtin_scene_names();
  const bool builtin = std::find(names.begin(), names.end(), name_or_path) != names.end();
  const bool looks_like_path = name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".toml") ||
                               (!builtin && std::filesystem::exists(name_or_path));
  if (looks_like_path) return load_scene_file(name_or_path, seed_offset);
  if (!builtin)
    throw InputError(fmt::format("--scene: unknown scene '{}'{} (built-in scenes: {}; or give a path to a .toml file)",
                                 name_or_path, did_you_mean(name_or_path, names), fmt::join(names, ", ")));
  return load_scene_file((std::filesystem::path(scenario_dir()) / (name_or_path + ".toml")).string(), seed_offset);
}

}  // namespace ballbench
