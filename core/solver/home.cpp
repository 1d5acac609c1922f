#include "solver/home.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <variant>
#include <vector>

#include "accuracy_spec.h"
#include "engine_settings.h"
#include "fork_join.h"
#include "input_error.h"
#include "solver/home_broad_grid.h"
#include "solver/home_broad_list.h"
#include "solver/home_events.h"
#include "solver/home_grid.h"
#include "solver/home_method.h"
#include "solver/home_soft.h"
#include "solver/home_world.h"

namespace ballbench {
namespace {

// From this many balls the per-ball loops run on every core. A hand-over costs ~7 us and a step
// has about a dozen: two threads lose below 10^5 balls, break even there and win at 10^6
// (ballbench_home_benchmark's home/threads/; PERFORMANCE.md, "Threads").
constexpr int kParallelBalls = 100'000;
// Every this many steps the balls are renumbered in the grid's cell order, so that neighbours in
// space are neighbours in memory (home/reorder/ in ballbench_home_benchmark; PERFORMANCE.md,
// "Renumbering"). Balls drift by under a cell per step, so the order stays good for a while; read()
// maps back to the scene's order. Only from kReorderBalls balls, where it pays: renumbering
// changes the order of the contact solve, and so the trajectory of every scene in tests/ and the
// regression suite, all far below 10^4 balls.
constexpr int kReorderSteps = 16;
constexpr int kReorderBalls = 10'000;

int reorder_steps(int n, int requested) {
  if (requested >= 0) return requested;
  return n >= kReorderBalls ? kReorderSteps : 0;
}

// The shortcuts this scene allows among those `allow` permits.
HomeShortcuts shortcuts(const Scene& scene, const HomeShortcuts& allow, double rest_velocity) {
  const SceneFeatures f = scene.features();
  HomeShortcuts s;
  s.no_gravity = allow.no_gravity && !f.gravity;
  s.no_walls = allow.no_walls && !f.walls;
  s.equal_radii = allow.equal_radii && f.equal_radii && scene.n() > 0;
  s.equal_masses = allow.equal_masses && f.equal_masses && scene.n() > 0;
  s.no_pairs = allow.no_pairs && scene.n() < 2;
  // Restitution 1 with a resting speed of 0 (no gravity, rest_velocity left to its default or 0):
  // no impact is resting contact and no contact is speculative, so the contact pass would only hold
  // touching pairs that do not approach, which it leaves as they are (every impact is the event
  // loop's: make_contact).
  const bool no_rest = rest_velocity == 0 || (rest_velocity < 0 && !f.gravity);
  s.elastic = allow.elastic && f.elastic && no_rest;
  return s;
}

// The path a scene runs, chosen once: the soft step, or the events path on the grid or, in
// elastic scenes, on the neighbour list.
using HomePath = std::variant<SoftResting, EventPath<GridBroadPhase>, EventPath<ListBroadPhase>>;

// home's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings home` come from these rows. HomeSettings' internal fields are not here.
const SettingsTable<HomeSettings>& home_settings_table() {
  using S = HomeSettings;
  using Soft = SoftStepSettings;
  static const SettingsTable<S> table(
      "home",
      {setting("contact_iterations", &S::contact_iterations, at_least(0), "count",
               "most sweeps of the contact pass per step"),
       setting("rest_velocity", &S::rest_velocity, any_value, "m/s",
               "impacts slower than this are resting contact; < 0: 2 |g| dt"),
       setting("contact_slop", &S::contact_slop, above(0), "1",
               "gap that counts as touching, as a fraction of the radius sum"),
       setting("max_events_per_ball", &S::max_events_per_ball, at_least(1), "count",
               "more events per ball in one step fail the run"),
       choice("resting", &S::resting,
              {{RestingMethod::automatic, "auto"}, {RestingMethod::soft, "soft"}, {RestingMethod::events, "events"}},
              "resting contact under gravity: chosen from the scene and its spec, the soft step, or event-driven "
              "with cluster solves"),
       setting("overlap", &S::overlap,
               bound([](double x) { return x >= 0 && x < 1; }, "[0, 1)", "must be in [0, 1)"), "radii",
               "resting = auto: the largest overlap the soft step is built for; 0: the scene's spec's"),
       setting("substeps", &S::soft, &Soft::substeps, at_least(1), "count", "the soft step's substeps per step"),
       setting("substep_iterations", &S::soft, &Soft::substep_iterations, at_least(1), "count",
               "soft step: sweeps with the push, per substep"),
       setting("relax_iterations", &S::soft, &Soft::relax_iterations, at_least(0), "count",
               "soft step: sweeps without the push, per substep"),
       setting("max_stride", &S::max_stride, above(0), "radii",
               "a soft step's parts move the fastest ball at most this far"),
       setting("max_parts", &S::max_parts, at_least(1), "count", "most parts a soft step is cut into"),
       setting("contact_hertz", &S::soft, &Soft::contact_hertz, above(0), "Hz", "soft step: stiffness of the push-out"),
       setting("damping_ratio", &S::soft, &Soft::damping_ratio, at_least(0), "1", "soft step: damping of the push-out"),
       setting("push_speed", &S::soft, &Soft::push_speed, above(0), "m/s",
               "soft step: fastest an overlap is pushed out"),
       setting("sleep_speed", &S::sleep_speed, at_least(0), "m/s",
               "soft path: islands slower than this for sleep_time sleep; 0 never"),
       setting("sleep_time", &S::sleep_time, above(0), "s", "soft path: how long an island is slow before it sleeps")});
  return table;
}

class Home final : public Engine {
 public:
  Home(const Scene& scene, HomeSettings s)
      : s_(s),
        sc_(shortcuts(scene, s.allow, s.rest_velocity)),
        reorder_(reorder_steps(scene.n(), s.reorder_steps)),
        w_(scene, sc_.equal_radii, sc_.equal_masses),
        pool_(ForkJoin::threads_for(w_.n, kParallelBalls, s.threads)),
        path_(choose_path(scene)) {}

  void step(double dt) override {
    ++steps_;
    t_ += dt;
    const double v_rest = s_.rest_velocity >= 0 ? s_.rest_velocity : 2.0 * w_.g.norm() * dt;
    const bool due = renumber_due();
    const std::function<bool()> renumber = [&] { return renumber_if_due(); };
    std::visit(
        [&](auto& path) {
          if constexpr (std::is_same_v<std::decay_t<decltype(path)>, SoftResting>)
            path.step(w_, dt, v_rest, sc_.no_pairs, grid_, pool_, [&] { renumber_if_due(); });
          else
            path.step(dt, v_rest, t_, due, renumber);
        },
        path_);
  }

  // In the scene's order: a plain copy until the balls are first renumbered, then a gather through
  // the scene -> ball map, which writes the output front to back (scattering the writes through a
  // ball -> scene map instead cost 10-15% of a harness step at 10^5 balls).
  // A step whose final advance is left to the next step's start (the grid's end_step) gets its end
  // positions here, by the same expression (on_line): the same numbers.
  void read(State& out) const override {
    out.t = t_;
    out.resize(w_.n, w_.rotation);
    double end = 0;
    const double* __restrict tl = nullptr;
    std::visit(
        [&](const auto& path) {
          if constexpr (!std::is_same_v<std::decay_t<decltype(path)>, SoftResting>)
            end = path.unfinished(), tl = path.clocks();
        },
        path_);
    // The angles are brought to the step's end by the step itself (EventPath::end_angles).
    if (w_.rotation)
      for (int k = 0; k < w_.n; ++k) {
        const int i = renumbered_ ? w_.ball_of[k] : k;
        out.w(k) = w_.w(i), out.angle(k) = w_.angle(i);
      }
    if (!renumbered_ && end == 0) {
      out.pos = w_.p, out.vel = w_.v;
      return;
    }
    // A gather through the renumbering (random reads): on the step's threads, each part over its
    // own range of the scene's order.
    const int* at = renumbered_ ? w_.ball_of.data() : nullptr;
    const int parts = pool_.parts();
    pool_.run([&](int part) {
      const long b = ForkJoin::range_begin(w_.n, part, parts), e = ForkJoin::range_begin(w_.n, part + 1, parts);
      for (int c = 0; c < 2; ++c) {
        const double* __restrict p = w_.p.col(c).data();
        const double* __restrict v = w_.v.col(c).data();
        double* __restrict op = out.pos.col(c).data();
        double* __restrict ov = out.vel.col(c).data();
        if (end == 0)
          for (long k = b; k < e; ++k) op[k] = p[at[k]], ov[k] = v[at[k]];
        else
          for (long k = b; k < e; ++k) {
            const long i = at ? at[k] : k;
            op[k] = on_line(p[i], v[i], end, tl[i]), ov[k] = v[i];
          }
      }
    });
  }

  nlohmann::json settings() const override {
    return home_settings_table().json(s_);
  }

 private:
  // Resting contact by the soft step in scenes with gravity when `resting` says so; else the events
  // path, on a neighbour list in elastic scenes with pairs, on the grid otherwise.
  HomePath choose_path(const Scene& scene) {
    if (s_.resting == RestingMethod::soft && scene.features().gravity)
      return HomePath(std::in_place_type<SoftResting>, s_, w_.n);
    if (sc_.elastic && !sc_.no_pairs)
      return HomePath(std::in_place_type<EventPath<ListBroadPhase>>, w_, grid_, pool_, s_, sc_);
    return HomePath(std::in_place_type<EventPath<GridBroadPhase>>, w_, grid_, pool_, s_, sc_);
  }

  // Renumbering in cell order (reorder_by_cell) right after a grid's build at the start of a step:
  // at the first, then when reorder_ steps have passed since the last. Returns whether it did.
  bool renumber_due() const { return reorder_ > 0 && !(renumbered_ && steps_ - renumbered_at_ < reorder_); }
  bool renumber_if_due() {
    if (!renumber_due() || grid_.balls() != w_.n) return false;
    reorder_by_cell();
    renumbered_ = true, renumbered_at_ = steps_;
    return true;
  }

  // Renumbers the balls in the cell order of the grid just built (slot s becomes ball s). Everything
  // indexed by ball moves with them; what the path stores by ball number is re-keyed. Positions and
  // velocities are gathered in slot order one column at a time (in parallel, through column_); the
  // other per-ball arrays are permuted in place along the permutation's cycles.
  void reorder_by_cell() {
    const int* id = grid_.id();
    const int parts = pool_.parts();
    column_.resize(w_.n);
    double* column_in_order = column_.data();
    for (double* column : {w_.p.col(0).data(), w_.p.col(1).data(), w_.v.col(0).data(), w_.v.col(1).data()}) {
      pool_.run([&](int p) {
        const long b = ForkJoin::range_begin(w_.n, p, parts), e = ForkJoin::range_begin(w_.n, p + 1, parts);
        for (long s = b; s < e; ++s) column_in_order[s] = column[id[s]];
      });
      pool_.run([&](int p) {
        const long b = ForkJoin::range_begin(w_.n, p, parts), e = ForkJoin::range_begin(w_.n, p + 1, parts);
        std::copy(column_in_order + b, column_in_order + e, column + b);
      });
    }
    placed_.resize(w_.n);
    uint8_t* placed = placed_.data();
    auto permute = [&](auto* a) {
      std::fill(placed, placed + w_.n, 0);
      for (int s = 0; s < w_.n; ++s) {
        if (placed[s]) continue;
        const auto first = a[s];  // the cycle s <- id[s] <- id[id[s]] ... back to s
        int k = s;
        for (; id[k] != s; k = id[k]) a[k] = a[id[k]], placed[k] = 1;
        a[k] = first, placed[k] = 1;
      }
    };
    if (w_.r.size()) permute(w_.r.data());
    if (w_.inv_m.size()) permute(w_.inv_m.data());
    if (w_.rotation) permute(w_.w.data()), permute(w_.angle.data());
    std::visit([&](auto& path) { path.permute_per_ball(permute); }, path_);
    grid_.renumbered([&](const int* new_number) {
      for (int& b : w_.ball_of) b = new_number[b];
      std::visit([&](auto& path) { path.renumbered(new_number); }, path_);
    });
  }

  HomeSettings s_;
  HomeShortcuts sc_;       // the shortcuts taken, fixed at construction
  int reorder_;            // renumber the balls in cell order every this many steps (0: never)
  HomeWorld w_;            // the balls and the scene's constants
  mutable ForkJoin pool_;  // mutable: read() gathers on it too
  HomeGrid grid_;          // the cells every path builds its broad phase on, and renumbers by
  double t_ = 0;           // simulated time (s)
  bool renumbered_ = false;  // ever renumbered
  long renumbered_at_ = 0;   // the step of the last renumbering
  long steps_ = 0;           // steps taken
  // Renumbering's scratch: one column of the state in the new order, and the slots whose
  // permutation cycle is done.
  std::vector<double> column_;
  std::vector<uint8_t> placed_;
  HomePath path_;  // last: it holds references to the world, the thread team and the grid
};

// resting = "auto": the method for this scene (home_method.h), at the overlap asked or the scene's
// spec's; settings given explicitly win.
void resolve_auto(const Scene& scene, const nlohmann::json& overrides, HomeSettings& s) {
  if (s.overlap == 0) s.overlap = scene_spec(scene)[SpecTerm::overlap].value_or(0.01);
  const HomeMethod m = choose_home_method(scene, scene.dt, s.overlap);
  s.resting = m.soft ? RestingMethod::soft : RestingMethod::events;
  if (!m.soft) return;
  if (!overrides.contains("substeps")) s.soft.substeps = m.substeps;
  if (!overrides.contains("contact_hertz")) s.soft.contact_hertz = m.contact_hertz;
}

}  // namespace

EngineEntry home_engine() {
  EngineInfo info;
  info.name = "home";
  info.role = EngineRole::ours;
  info.version = "0.1";
  info.limits =
      "double; impacts slower than rest_velocity (2 |g| dt) are resting contact (restitution 0); contacts within "
      "contact_slop (1e-6 of the radius sum) count as touching";
  info.summary = "our solver: symplectic Euler, resting-contact solve, exact event-driven motion within each step";
  // default: the method chosen from the scene and its accuracy spec (resting = "auto"); events and
  // soft force one.
  info.profiles = {"default", "events", "soft"};
  info.caps.continuous_collision = true;
  // Coulomb friction at impacts (the rough-disk impulse law) and in resting contacts (sequential
  // impulses in the friction cone); the soft path solves it in its soft step.
  // Sweeps of the resting-contact solve (default: motion between contacts is exact at any
  // setting), and the soft step's substeps (soft).
  info.sweep_knobs = {{"overlap", {0.005, 0.0025, 0.001}, {"default"}},
                      {"contact_iterations", {4, 16, 200}, {"events"}},
                      {"substeps", {2, 8, 16}, {"soft"}}};
  info.settings = home_settings_table().describe();
  // The scaling target takes the gas and bowl to 10^6. The soft profile has no gas or bowl rows
  // (it refuses the gas, which has no gravity; the bowl early in its pour is the default profile's
  // case): its rows are the piles', a settled pile to 10^6.
  info.bench.sizes = {.free_balls = 1'000'000, .fluid_balls = 100'000, .settled_balls = 10'000};
  info.bench.profile_sizes["soft"] = {.free_balls = 0, .fluid_balls = 100'000, .settled_balls = 1'000'000};
  return {info, [](const Scene& scene, const std::string& profile, const nlohmann::json& overrides) {
            HomeSettings s;
            if (profile == "default") s.resting = RestingMethod::automatic;
            if (profile == "soft") {
              // Without gravity nothing rests on anything: the default profile runs such a scene.
              if (!scene.features().gravity)
                throw SceneUnsupported("home (soft): the soft step is for scenes with gravity; without it home runs "
                                       "event-driven, as its default profile");
              s.resting = RestingMethod::soft;
            }
            home_settings_table().read(overrides, s);
            if (s.resting == RestingMethod::automatic) resolve_auto(scene, overrides, s);
            return make_home(scene, s);
          }, {}};
}

std::unique_ptr<Engine> make_home(const Scene& scene, const HomeSettings& settings) {
  return std::make_unique<Home>(scene, settings);
}

}  // namespace ballbench
