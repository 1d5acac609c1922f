#include "solver/exact.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "engine_settings.h"
#include "input_error.h"
#include "solver/contact.h"
#include "solver/rough_impact.h"

namespace ballbench {
namespace {

// Relative size of round-off in a normal velocity: touching bodies that approach more slowly than
// this fraction of their speeds are not approaching (a collision there would be one of noise).
constexpr double kVelocityNoise = 1e-12;
// Under gravity, approach speeds below this fraction of rest_velocity are not an approach now
// either: a cluster of balls settling at restitution 0 would otherwise refine its relative
// velocities towards round-off through thousands of zero-time collisions (the Gauss-Seidel
// iteration of a multi-contact impact, done one binary collision at a time).
constexpr double kRestSlop = 1e-2;
// A pair (or ball and wall) closing slower than the noise above may creep into overlap by at most
// this fraction of the radius sum (radius), then collides: the cascade is spread over time.
constexpr double kOverlapCap = 1e-9;
// A single contact carries a ball's weight only if its normal is within this angle of -g (rad):
// a ball perched off-centre on one ball must roll off, not sleep there.
constexpr double kSupportAngle = 1e-9;
// A relative acceleration presses a contact only if its normal part is above this fraction of its
// size: side-by-side balls differ in height by round-off, which must not count as pressing.
constexpr double kPressedFraction = 1e-9;
// Default contact_time and rest_velocity as fractions of the scene's time and speed scales.
constexpr double kAutoScale = 1e-2;
// Gap within which balls (or a ball and a wall) count as touching when a slow impact is settled,
// as a fraction of the radius sum (radius).
constexpr double kTouch = 1e-9;
// Projected Gauss-Seidel sweeps when settling a cluster: this many plus 4 per ball in it.
constexpr int kClusterSweeps = 64;
// Clusters with at most this many contacts are settled exactly (Lemke), larger by Gauss-Seidel.
constexpr size_t kMaxExactContacts = 48;
// Largest cluster settled at once (balls); beyond it, contacts are left to binary events.
constexpr size_t kMaxCluster = 4096;
// A slow ball in more collisions than this within contact_time is jammed (Exact::jammed).
constexpr int kJamEvents = 100;
// Default wake_velocity as a multiple of rest_velocity.
constexpr double kAutoWake = 10.0;
// Default grid: at most about this many cells per ball (plus a few), so sparse scenes stay small.
constexpr double kCellsPerBall = 4.0;
// Cells are this much wider than the largest diameter, so a ball that round-off leaves a hair
// outside its cell still finds every ball it can touch in the 3 x 3 block.
constexpr double kCellMargin = 1e-9;

// ----------------------------------------------------------------------------------------------
// |(x, y)|: plain sqrt, as every quantity here is far from overflow (std::hypot is several times
// slower for its care about it).
inline double norm2(double x, double y) { return std::sqrt(x * x + y * y); }

// ----------------------------------------------------------------------------------------------
// Roots. Every event is the first moment a "gap function" q(tau) >= 0 reaches zero while
// decreasing, tau >= 0 measured from now. A state with q(0) <= 0 is invalid (left by round-off):
// following Bannerman, Strobl, Formella & Poschel (Comput. Part. Mech. 1, 191, 2014) it is an
// event now if q is decreasing, and no event while q increases (touching and separating).

// q(tau) = q0 + q1 tau + q2 tau^2: a ball and a wall, or a coordinate and a cell face, under
// constant acceleration. `noise`: |q1| up to this counts as zero at q0 <= 0; such a slow
// closing may go on until q = -cap, where only closing slower than `fine` (round-off) is ignored.
double gap_closing_time(double q0, double q1, double q2, double noise, double fine, double cap) {
  if (q0 <= 0) {
    if (q1 < -noise) return 0;               // touching and closing
    if (q1 <= noise && q2 < 0) return 0;     // touching at rest and pushed in
    if (q1 < 0) return gap_closing_time(q0 + cap, q1, q2, fine, fine, 0);  // creeping: event at the cap
    if (q2 >= 0) return kNever;              // opening, or at rest with nothing pushing
    // Opening but pulled back (a bounce under gravity): the descending root.
    const double disc = q1 * q1 - 4 * q0 * q2;  // <= q1^2, as q0 q2 >= 0
    if (disc < 0) return q1 / (-2 * q2);        // turns back before it is clear: event at the turn
    return (q1 + std::sqrt(disc)) / (-2 * q2);
  }
  const double disc = q1 * q1 - 4 * q0 * q2;
  if (q1 < 0) {
    if (disc < 0) return kNever;                   // decelerates and turns back before contact
    return 2 * q0 / (-q1 + std::sqrt(disc));       // smaller root, free of cancellation
  }
  if (q2 < 0) return (q1 + std::sqrt(disc)) / (-2 * q2);  // moving away now, pulled back later
  return kNever;
}

// f(tau) = c0 + c1 tau + c2 tau^2 + c3 tau^3 + c4 tau^4, c4 > 0: |d + w tau + A tau^2 / 2|^2 - R^2
// for two balls whose accelerations differ by A (one resting on a wall or asleep, the other free).
struct Quartic {
  double c0, c1, c2, c3, c4;
  double f(double t) const { return (((c4 * t + c3) * t + c2) * t + c1) * t + c0; }
  double df(double t) const { return ((4 * c4 * t + 3 * c3) * t + 2 * c2) * t + c1; }
  double ddf(double t) const { return (12 * c4 * t + 6 * c3) * t + 2 * c2; }
};

// Roots of a t^2 + b t + c strictly inside (lo, hi), ascending. Returns how many.
int quadratic_roots_inside(double a, double b, double c, double lo, double hi, double out[2]) {
  double r[2];
  int k = 0;
  if (a == 0) {
    if (b != 0) r[k++] = -c / b;
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      if (q != 0) {
        r[k++] = q / a;
        r[k++] = c / q;
      } else {
        r[k++] = 0;
      }
    }
  }
  if (k == 2 && r[0] > r[1]) std::swap(r[0], r[1]);
  int m = 0;
  for (int i = 0; i < k; ++i)
    if (r[i] > lo && r[i] < hi) out[m++] = r[i];
  return m;
}

// The root of a function monotone on [lo, hi] with a sign change there (fn(lo) > 0 if
// `lo_positive`), by Newton steps kept inside the shrinking bracket, bisecting when Newton
// leaves it. Converges to the last few ulps; deterministic.
template <class F, class DF>
double bracketed_root(const F& fn, const DF& dfn, double lo, double hi, bool lo_positive) {
  double x = 0.5 * (lo + hi);
  for (int k = 0; k < 200; ++k) {
    const double fx = fn(x);
    if (fx == 0) return x;
    if ((fx > 0) == lo_positive) lo = x;
    else hi = x;
    const double d = dfn(x);
    double next = d != 0 ? x - fx / d : lo;
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
      if (next <= lo || next >= hi) return hi;  // the bracket is two adjacent doubles
    }
    if (std::abs(next - x) <= 4 * std::numeric_limits<double>::epsilon() * std::abs(x)) return next;
    x = next;
  }
  return x;
}

// First tau in [0, horizon] with f(tau) <= 0 and f decreasing (Bannerman et al. 2014, section 4:
// the event of a general overlap function). f is split at its critical points (roots of the cubic
// f', themselves isolated between the roots of f'') into monotone pieces; the first decreasing
// piece that reaches zero holds the event. `noise`: |f'(0)| up to this counts as zero; a touching
// pair (f(0) <= cap) closing no faster may creep on until f = -cap, where only `fine` (round-off)
// counts as zero. `pressed`: the relative acceleration pushes the pair together (Exact::pressed).
double first_contact(const Quartic& q, double horizon, double noise, double fine, bool pressed, double cap) {
  const bool slow = q.c1 >= -noise;
  const bool held = pressed && q.c1 <= fine && q.c2 < 0;  // at rest and pressed together
  if (q.c0 <= 0 && (!slow || held)) return 0;               // touching and approaching
  if (q.c0 <= cap && slow && !held && cap > 0) {
    Quartic capped = q;
    capped.c0 += cap;
    return first_contact(capped, horizon, fine, fine, pressed, 0);
  }
  const bool skip_first = q.c0 <= 0;  // a decrease within noise is not an approach
  // Cauchy's bound: every root of f, and so (Gauss-Lucas) of f', is below it; f > 0 beyond.
  const double bound = 1 + std::max({std::abs(q.c0), std::abs(q.c1), std::abs(q.c2), std::abs(q.c3)}) / q.c4;
  const double end = std::min(horizon, bound);
  if (!(end > 0)) return kNever;

  double edges[4];
  int ne = 0;
  edges[ne++] = 0;
  ne += quadratic_roots_inside(12 * q.c4, 6 * q.c3, 2 * q.c2, 0, end, edges + ne);
  edges[ne++] = end;
  double pts[5];
  int np = 0;
  pts[np++] = 0;
  for (int k = 0; k + 1 < ne; ++k) {
    const double ga = q.df(edges[k]), gb = q.df(edges[k + 1]);
    if ((ga < 0 && gb > 0) || (ga > 0 && gb < 0))
      pts[np++] = bracketed_root([&](double t) { return q.df(t); }, [&](double t) { return q.ddf(t); }, edges[k],
                                 edges[k + 1], ga > 0);
  }
  pts[np++] = end;
  for (int k = 0; k + 1 < np; ++k) {
    const double a = pts[k], b = pts[k + 1];
    if (!(b > a) || q.df(a + 0.5 * (b - a)) >= 0) continue;  // increasing piece
    if (k == 0 && skip_first) continue;
    if (q.f(a) <= 0) {
      // Overlapping (round-off) and starting to approach: an event now if the approach becomes
      // more than noise within this piece (f' is steepest at an end or at an inflection point).
      double steepest = std::min(q.df(b), q.df(a + 0.5 * (b - a)));
      for (int e = 1; e + 1 < ne; ++e)
        if (edges[e] > a && edges[e] < b) steepest = std::min(steepest, q.df(edges[e]));
      if (steepest < -noise) return a;
      continue;
    }
    if (q.f(b) > 0) continue;
    return bracketed_root([&](double t) { return q.f(t); }, [&](double t) { return q.df(t); }, a, b, true);
  }
  return kNever;
}

// ----------------------------------------------------------------------------------------------

// A ball's events (contact.h's Event, one per ball): a pair (j >= 0; cj, the partner's trajectory
// counter when predicted), a wall (wall_partner), or the ball crossing a face of its grid cell
// (cell_face: of axis 0 or 1, towards the lower (0) or upper (1) cell).
constexpr int cell_face(int axis, int up) { return -5 - (2 * axis + up); }
// A rough ball sliding on a wall whose slip reaches zero: it starts to roll (Exact::on_roll).
constexpr int kRollEvent = -9;
constexpr bool is_cell_face(int j) { return j <= -5 && j > kRollEvent; }

// A contact (contact.h) of a cluster being settled (Exact::settle_cluster); j < 0: a wall or a
// sleeping ball, held still.
struct ClusterContact : Contact {
  double target;  // normal separation speed wanted (m/s)
  bool firm;      // crept to the overlap cap, or pressed: even a slow closing is stopped
  double n(int axis) const { return axis == 0 ? nx : ny; }
};

// A ball's candidates at one time in a fixed order: balls by index, then walls, then cell faces,
// then the start of rolling.
int event_rank(int j) { return j >= 0 ? 0 : j == kRollEvent ? 3 : is_cell_face(j) ? 2 : 1; }
bool sooner(const PredictedEvent& a, const PredictedEvent& b) {
  if (a.t != b.t) return a.t < b.t;
  const int ra = event_rank(a.j), rb = event_rank(b.j);
  if (ra != rb) return ra < rb;
  return ra == 0 ? a.j < b.j : a.j > b.j;  // walls and faces by code, -1 - j and -5 - j
}

// Why `exact` cannot run a scene in closed form, or "". A rough ball alone under gravity is exact
// (flights, rough impacts, sliding and rolling on a wall: EXACT.md, "Friction"), and so are rough
// balls without gravity (every impact binary); rough balls under gravity come to rest on one another,
// a frictional multi-contact problem with no closed form (nor a unique hard-disk answer).
std::string exact_refusal(const Scene& scene) {
  if (scene.friction > 0 && scene.features().gravity && scene.n() > 1)
    return "rough balls resting on each other under gravity have no closed form (the reference is a converged run)";
  return "";
}

// exact's user settings, each declared once: reading, bounds, settings() and `ballbench list
// --settings exact` come from these rows. The scene-dependent checks stay in the factory.
const SettingsTable<ExactSettings>& exact_settings_table() {
  using S = ExactSettings;
  static const SettingsTable<S> table(
      "exact",
      {setting("contact_time", &S::contact_time, any_value, "s",
               "flight a supported ball keeps per collision; < 0: automatic"),
       setting("rest_velocity", &S::rest_velocity, any_value, "m/s", "impacts slower than this settle; < 0: automatic"),
       setting("sleep", &S::sleep, any_value, "", "a settled, supported ball sleeps"),
       setting("wake_velocity", &S::wake_velocity, any_value, "m/s",
               "impacts this fast wake a sleeping ball; < 0: 10 rest_velocity"),
       setting("support_gap", &S::support_gap, any_value, "m",
               "gap within which a support carries a ball; < 0: automatic"),
       setting("cell_size", &S::cell_size, any_value, "m", "neighbour grid's cell width; < 0: automatic"),
       setting("max_events_per_ball", &S::max_events_per_ball, at_least(1), "count",
               "more events per ball in one step fail the run")});
  return table;
}

class Exact final : public Engine {
 public:
  Exact(const Scene& scene, const ExactSettings& s)
      : s_(s),
        n_(scene.n()),
        e_(scene.restitution),
        mu_(scene.friction),
        k_(inertia_factor(scene.inertia)),
        g_{scene.gravity.x(), scene.gravity.y()},
        walls_(scene.container.kind == ContainerKind::Box),
        tc_(s.contact_time),
        v_rest_(s.rest_velocity),
        v_wake_(s.wake_velocity),
        support_gap_(s.support_gap) {
    gravity_ = g_[0] != 0 || g_[1] != 0;
    rot_ = scene.features().rotation;
    rough_walls_ = mu_ > 0 && gravity_ && walls_;
    if (walls_) {
      box_lo_[0] = scene.container.min.x(), box_lo_[1] = scene.container.min.y();
      box_hi_[0] = scene.container.max.x(), box_hi_[1] = scene.container.max.y();
    }
    r_.resize(n_), im_.resize(n_);
    for (int k = 0; k < 2; ++k) p_[k].resize(n_), v_[k].resize(n_), a_[k].resize(n_);
    for (int i = 0; i < n_; ++i) {
      r_[i] = scene.radius(i);
      im_[i] = 1.0 / scene.mass(i);
      for (int k = 0; k < 2; ++k) {
        p_[k][i] = scene.initial.pos(i, k);
        v_[k][i] = scene.initial.vel(i, k);
        a_[k][i] = g_[k];
      }
    }
    if (rot_) {
      w_.resize(n_), angle_.resize(n_);
      for (int i = 0; i < n_; ++i) {
        w_[i] = scene.spin(i);
        angle_[i] = scene.initial.angle.size() == n_ ? scene.initial.angle(i) : 0.0;
      }
      alpha_.assign(n_, 0.0);
      slip_.assign(n_, 0);
      hold_.assign(n_, 0);
    }
    tl_.assign(n_, 0.0);
    jam_start_.assign(n_, -kNever);
    jam_count_.assign(n_, 0);
    count_.assign(n_, 0);
    asleep_.assign(n_, 0);
    events_.assign(n_, 0);
    mark_.assign(n_, 0);
    cluster_mark_.assign(n_, 0);
    group_mark_.assign(n_, 0);
    cluster_pos_.assign(n_, 0);
    ev_.assign(n_, PredictedEvent{});
    build_grid(scene);
    heap_.resize(n_), slot_.resize(n_);
    for (int i = 0; i < n_; ++i) heap_[i] = i, slot_[i] = i;
    for (int i = 0; i < n_; ++i) predict(i);
  }

  void step(double dt) override {
    const double t_end = t_ + dt;
    std::fill(events_.begin(), events_.end(), 0);
    while (n_ > 0) {
      const int i = heap_[0];
      const PredictedEvent ev = ev_[i];
      if (!(ev.t <= t_end)) break;
      now_ = ev.t;
      if (ev.j >= 0 && count_[ev.j] != ev.cj) {
        predict(i);  // the partner changed course since: look again
        continue;
      }
      if (ev.j >= 0) {
        on_pair(i, ev.j);
      } else if (ev.j == kRollEvent) {
        on_roll(i);
      } else if (!is_cell_face(ev.j)) {
        on_wall(i, wall_axis(ev.j), wall_side(ev.j));
      } else {
        const int code = -5 - ev.j;
        on_cell(i, code >> 1, code & 1);
      }
    }
    now_ = t_end;
    for (int i = 0; i < n_; ++i) advance(i, t_end);
    t_ = t_end;
  }

  void read(State& out) const override {
    out.t = t_;
    out.resize(n_, rot_);
    for (int i = 0; i < n_; ++i)
      for (int k = 0; k < 2; ++k) out.pos(i, k) = p_[k][i], out.vel(i, k) = v_[k][i];
    if (rot_)
      for (int i = 0; i < n_; ++i) out.w(i) = w_[i], out.angle(i) = angle_[i];
  }

  nlohmann::json settings() const override { return exact_settings_table().json(s_); }

 private:
  // ---- the neighbour grid: cells at least one diameter wide, crossed by cell-face events ----

  void build_grid(const Scene& scene) {
    const double rmax = n_ > 0 ? scene.radius.maxCoeff() : 1.0;
    double cell = std::max(s_.cell_size > 0 ? s_.cell_size : 2 * rmax, 2 * rmax * (1 + kCellMargin));
    double lo[2], hi[2];
    if (walls_) {
      for (int k = 0; k < 2; ++k) lo[k] = box_lo_[k], hi[k] = box_hi_[k];
    } else {
      // Open space: the grid covers the start with room to spread; the border cells reach to
      // infinity (coordinates are clamped), so a ball far outside is still found, only slower.
      for (int k = 0; k < 2; ++k) {
        lo[k] = n_ > 0 ? scene.initial.pos.col(k).minCoeff() : 0.0;
        hi[k] = n_ > 0 ? scene.initial.pos.col(k).maxCoeff() : 0.0;
        const double pad = std::max(0.5 * (hi[k] - lo[k]), 4 * cell);
        lo[k] -= pad, hi[k] += pad;
      }
    }
    double nc[2];
    for (int k = 0; k < 2; ++k) nc[k] = std::max(1.0, std::floor((hi[k] - lo[k]) / cell));
    const double cap = kCellsPerBall * n_ + 16;
    if (s_.cell_size <= 0 && nc[0] * nc[1] > cap) {
      const double shrink = std::sqrt(nc[0] * nc[1] / cap);
      for (int k = 0; k < 2; ++k) nc[k] = std::max(1.0, std::floor(nc[k] / shrink));
    }
    if (nc[0] * nc[1] > 1e9) throw std::runtime_error("exact: the neighbour grid would need more than 1e9 cells");
    double used = kNever;
    for (int k = 0; k < 2; ++k) {
      n_cells_[k] = static_cast<int>(nc[k]);
      grid_lo_[k] = lo[k];
      width_[k] = (hi[k] - lo[k]) / nc[k];
      used = std::min(used, width_[k]);
    }
    s_.cell_size = used;
    head_.assign(static_cast<size_t>(n_cells_[0]) * n_cells_[1], -1);
    next_.assign(n_, -1), prev_.assign(n_, -1), cell_.assign(n_, 0);
    for (int i = 0; i < n_; ++i) {
      int c[2];
      for (int k = 0; k < 2; ++k) {
        const double f = std::floor((p_[k][i] - grid_lo_[k]) / width_[k]);
        c[k] = f < 0 ? 0 : f >= n_cells_[k] ? n_cells_[k] - 1 : static_cast<int>(f);
      }
      link(i, c[1] * n_cells_[0] + c[0]);
    }
  }

  void link(int i, int c) {
    cell_[i] = c;
    prev_[i] = -1;
    next_[i] = head_[c];
    if (head_[c] >= 0) prev_[head_[c]] = i;
    head_[c] = i;
  }

  void unlink(int i) {
    if (prev_[i] >= 0) next_[prev_[i]] = next_[i];
    else head_[cell_[i]] = next_[i];
    if (next_[i] >= 0) prev_[next_[i]] = prev_[i];
  }

  // Face of cell index `c` along `axis` (the lower face of c + 1 is the upper face of c: one formula).
  double face(int axis, int c) const { return grid_lo_[axis] + c * width_[axis]; }

  template <class F>
  void for_each_near(int i, F&& f) const {
    const int cx = cell_[i] % n_cells_[0], cy = cell_[i] / n_cells_[0];
    for (int y = std::max(cy - 1, 0); y <= std::min(cy + 1, n_cells_[1] - 1); ++y)
      for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, n_cells_[0] - 1); ++x)
        for (int j = head_[y * n_cells_[0] + x]; j >= 0; j = next_[j])
          if (j != i) f(j);
  }

  // ---- motion ----

  // Brings ball i along its parabola to time t (lazily: each ball keeps its own time), and its
  // angle with it: w changes at the constant rate alpha (friction while sliding on a wall, the
  // rolling constraint while rolling), 0 in flight.
  void advance(int i, double t) {
    const double h = t - tl_[i];
    if (h != 0) {
      for (int k = 0; k < 2; ++k) {
        p_[k][i] += (v_[k][i] + 0.5 * a_[k][i] * h) * h;
        v_[k][i] += a_[k][i] * h;
      }
      if (rot_) {
        angle_[i] += (w_[i] + 0.5 * alpha_[i] * h) * h;
        w_[i] += alpha_[i] * h;
      }
    }
    tl_[i] = t;
  }

  double speed(int i) const { return norm2(v_[0][i], v_[1][i]); }

  // Normal speeds up to this count as zero for bodies moving at `speeds` (the sum of their speeds).
  double velocity_noise(double speeds) const { return std::max(kVelocityNoise * speeds, kRestSlop * v_rest_); }

  // ---- prediction ----

  void predict(int i) {
    advance(i, now_);
    PredictedEvent best;
    auto offer = [&](const PredictedEvent& c) {
      if (sooner(c, best)) best = c;
    };
    if (!asleep_[i]) {
      const double noise = velocity_noise(speed(i)), fine = kVelocityNoise * speed(i);
      for (int k = 0; k < 2; ++k) {
        const double x = p_[k][i], v = v_[k][i], a = a_[k][i];
        if (walls_) {
          const double cap = kOverlapCap * r_[i];
          const double t0 = gap_closing_time(x - r_[i] - box_lo_[k], v, 0.5 * a, noise, fine, cap);
          if (t0 < kNever) offer({now_ + t0, i, wall_partner(k, 0)});
          const double t1 = gap_closing_time(box_hi_[k] - r_[i] - x, -v, -0.5 * a, noise, fine, cap);
          if (t1 < kNever) offer({now_ + t1, i, wall_partner(k, 1)});
        }
        const int c = k == 0 ? cell_[i] % n_cells_[0] : cell_[i] / n_cells_[0];
        if (c > 0) {
          const double t0 = gap_closing_time(x - face(k, c), v, 0.5 * a, 0.0, 0.0, 0.0);
          if (t0 < kNever) offer({now_ + t0, i, cell_face(k, 0)});
        }
        if (c < n_cells_[k] - 1) {
          const double t1 = gap_closing_time(face(k, c + 1) - x, -v, -0.5 * a, 0.0, 0.0, 0.0);
          if (t1 < kNever) offer({now_ + t1, i, cell_face(k, 1)});
        }
      }
      if (rough_walls_ && slip_[i] != 0) {
        const double t = roll_time(i);
        if (t < kNever) offer({now_ + t, i, kRollEvent});
      }
    }
    for_each_near(i, [&](int j) {
      if (asleep_[i] && asleep_[j]) return;
      const double t = pair_time(i, j, best.t);
      if (t < kNever) offer({t, i, j, 0, count_[j]});
    });
    ev_[i] = best;
    heap_update(i);
  }

  // When balls i (at now) and j first touch while approaching, or kNever; `horizon` (absolute)
  // only prunes.
  double pair_time(int i, int j, double horizon) const {
    const double h = now_ - tl_[j];
    double d[2], w[2], A[2];
    for (int k = 0; k < 2; ++k) {
      d[k] = p_[k][i] - (p_[k][j] + (v_[k][j] + 0.5 * a_[k][j] * h) * h);
      w[k] = v_[k][i] - (v_[k][j] + a_[k][j] * h);
      A[k] = a_[k][i] - a_[k][j];
    }
    const double R = r_[i] + r_[j];
    const double d2 = d[0] * d[0] + d[1] * d[1];
    const double b = d[0] * w[0] + d[1] * w[1];  // < 0: approaching
    const double c = d2 - R * R;                  // <= 0: touching or overlapping
    const double speeds = speed(i) + norm2(v_[0][i] - w[0], v_[1][i] - w[1]);  // |v_i| + |v_j|
    const double noise = velocity_noise(speeds), fine = kVelocityNoise * speeds;
    const double dist = std::sqrt(d2);
    const double cap = R * R - (R * (1 - kOverlapCap)) * (R * (1 - kOverlapCap));  // in units of c
    if (A[0] == 0 && A[1] == 0) {
      // Same acceleration: the relative motion is a straight line, the contact a quadratic root.
      if (b >= 0) return kNever;
      const double a = w[0] * w[0] + w[1] * w[1];
      double cc = c;
      if (c <= cap && b >= -noise * dist) {  // touching, closing slower than noise: creep to the cap
        if (b >= -fine * dist) return kNever;
        cc += cap;
      }
      if (cc <= 0) return now_;
      const double disc = b * b - a * cc;
      if (disc < 0) return kNever;
      return now_ + cc / (-b + std::sqrt(disc));
    }
    const double tau_max = horizon - now_;
    if (tau_max < kNever) {
      const double gap = dist - R;
      const double reach = (norm2(w[0], w[1]) + 0.5 * norm2(A[0], A[1]) * tau_max) * tau_max;
      if (gap > reach * (1 + 1e-12)) return kNever;  // cannot close the gap before the best so far
    }
    const Quartic q{c, 2 * b, w[0] * w[0] + w[1] * w[1] + d[0] * A[0] + d[1] * A[1], w[0] * A[0] + w[1] * A[1],
                    0.25 * (A[0] * A[0] + A[1] * A[1])};
    const double press = dist > 0 ? -(d[0] * A[0] + d[1] * A[1]) / dist : 0.0;
    const bool is_pressed = pressed(press, A[0], A[1], fine);
    const double tau = first_contact(q, tau_max, 2 * dist * noise, 2 * dist * fine, is_pressed, cap);
    return tau < kNever ? now_ + tau : kNever;
  }

  // ---- events ----

  // Counts an event of ball i against the per-step budget.
  void bump(int i) {
    if (++events_[i] > s_.max_events_per_ball)
      throw std::runtime_error(fmt::format(
          "exact: ball {} took part in more than {} events in one step at t = {} s (an inelastic collapse the "
          "rest rules did not resolve; see settings contact_time, rest_velocity, max_events_per_ball)",
          i, s_.max_events_per_ball, now_));
    if (now_ - jam_start_[i] > tc_) jam_start_[i] = now_, jam_count_[i] = 0;
    ++jam_count_[i];
  }

  // Jammed: a ball in more than kJamEvents collisions within t_c. Contacts that resolve this
  // badly are a wedge, an arch or a column clamped between supports (nearly opposite contact
  // normals, where the impulses that hold a ball are many times its momentum, and a micro-bounce
  // has no room): the ball is held there, and is put to sleep.
  bool jammed(int i) const { return jam_count_[i] > kJamEvents; }

  // Ball k's event was used up: predict it again once the event is processed.
  void requeue(int k) {
    if (mark_[k] != stamp_) {
      mark_[k] = stamp_;
      touched_.push_back(k);
    }
  }

  // Ball k's trajectory changed: every prediction made against it is stale, and it predicts anew.
  void touch(int k) {
    ++count_[k];
    requeue(k);
  }

  void repredict_touched() {
    for (size_t k = 0; k < touched_.size(); ++k) predict(touched_[k]);
    touched_.clear();
    ++stamp_;
  }

  void on_cell(int i, int axis, int up) {
    bump(i);
    int c[2] = {cell_[i] % n_cells_[0], cell_[i] / n_cells_[0]};
    c[axis] += up ? 1 : -1;
    unlink(i);
    link(i, c[1] * n_cells_[0] + c[0]);
    predict(i);  // same trajectory, new neighbours: predictions against i stay valid
  }

  void on_wall(int i, int axis, int side) {
    bump(i);
    advance(i, now_);
    touch(i);
    const double sign = side == 0 ? 1.0 : -1.0;  // wall normal, into the box
    // Put the ball exactly on the wall: the event is the contact, and this keeps round-off from
    // accumulating in the normal coordinate (bounce heights stay exact to the last bounce).
    p_[axis][i] = side == 0 ? box_lo_[axis] + r_[i] : box_hi_[axis] - r_[i];
    double& v = v_[axis][i];
    const double u = std::max(-v * sign, 0.0);  // approach speed
    if (jam_count_[i] > kJamEvents && u >= v_rest_) {
      settle_cluster(i, -1, true);
      return repredict_touched();
    }
    // The tangential impulse of a rough wall, from the slip at impact (the normal impulse leaves it).
    if (mu_ > 0) wall_friction(i, axis, sign, u < v_rest_ ? 0.0 : e_, u);
    if (u < v_rest_) {
      // Too slow to be a bounce: the normal motion stops. The ball sleeps if the walls and
      // sleeping balls it touches carry its weight; pressed against this wall by gravity it
      // slides along it (the axis is held: no normal velocity or acceleration).
      v = 0;
      if (-g_[axis] * sign > 0) {
        a_[axis][i] = 0;
        if (rough_walls_) hold_[i] |= static_cast<uint8_t>(1 << axis);
      }
      try_sleep(i);
      set_motion(i);
      return repredict_touched();
    }
    v = e_ * u * sign;
    set_motion(i);
    repredict_touched();
  }

  // The rough part of ball i's impact on the wall of `axis` with inward normal `sign` (approach
  // speed u, restitution e): rough_impact's tangential impulse against the slip u_t = v.t - w r
  // (the wall has infinite mass and does not turn). The normal part is on_wall's. Under gravity an
  // impulse along the other axis that drives the ball into a wall it touches there needs both walls
  // at once (a corner): no closed form, so the run fails with the reason. One that lifts it off a
  // wall it slides on frees it.
  void wall_friction(int i, int axis, double sign, double e, double u) {
    const int b = 1 - axis;
    const double ts = tangent_sign(axis, sign);
    const double r = r_[i], m = 1.0 / im_[i];
    const double u_t = v_[b][i] * ts - w_[i] * r;
    const RoughImpulse P = rough_impact(-u, u_t, e, mu_, m, tangent_mass(im_[i], 0.0, k_));
    v_[b][i] += P.tangent * ts * im_[i];
    w_[i] -= P.tangent * im_[i] / (k_ * r);  // r P_t / I with I = k m r^2
    if (!rough_walls_) return;
    const double noise = velocity_noise(speed(i));
    const double vb = v_[b][i];
    const int toward = vb < 0 ? 0 : 1;  // the wall on axis b the ball now moves towards
    const double gap = toward == 0 ? p_[b][i] - r - box_lo_[b] : box_hi_[b] - r - p_[b][i];
    if (std::abs(vb) > noise && gap <= kTouch * r)
      throw std::runtime_error(fmt::format(
          "exact: ball {} at t = {} s is struck by a rough wall into the wall it touches across it (a corner): two "
          "rough contacts at once have no closed form",
          i, now_));
    if (hold_[i] & (1 << b)) {
      if (std::abs(vb) > noise) {
        hold_[i] &= static_cast<uint8_t>(~(1 << b));  // lifted off
        a_[b][i] = g_[b];
      } else {
        v_[b][i] = 0;
      }
    }
  }

  // The wall of axis `ax` that gravity presses a ball against: its inward normal's sign along ax.
  double inward(int ax) const { return g_[ax] < 0 ? 1.0 : -1.0; }
  // The sign along the other axis of the tangent t = (-n_y, n_x) of a wall of axis `ax` whose
  // inward normal has sign `sign` (rough_impact.h's convention, the wall as partner j).
  static double tangent_sign(int ax, double sign) { return ax == 1 ? -sign : sign; }

  // Ball i's accelerations for its state on the walls (rough_walls_ only): free (gravity, w
  // constant), or held on one wall by gravity, where Coulomb friction mu N (N = m G, G the part of
  // gravity into the wall) acts at the contact point against the slip s = v_t - w r:
  //   sliding (s != 0): a_t = g_t - mu G sgn(s),  dw/dt = mu G sgn(s) / (k r),
  //     so ds/dt = g_t - mu G sgn(s) (1 + k) / k, linear in time (the roll event);
  //   rolling (s = 0, w = v_t / r): a_t = g_t / (1 + k), dw/dt = a_t / r, which needs the static
  //     friction m g_t k / (1 + k); beyond mu m G it slides in the direction of g_t.
  // (Newton's laws for the centre and the rotation about it, torque -r F for a force F t at the
  // contact point -r n; Goldstein, Classical Mechanics, ch. 1 and 5.) Held on both walls of a
  // corner it is at rest; spinning there it would need both walls' friction at once: the run fails.
  void set_motion(int i) {
    if (!rough_walls_) return;
    const int held = hold_[i];
    if (held == 0) {
      for (int k = 0; k < 2; ++k) a_[k][i] = g_[k];
      alpha_[i] = 0, slip_[i] = 0;
      return;
    }
    if (held == 3) {
      if (std::abs(w_[i]) * r_[i] > kRestSlop * v_rest_)
        throw std::runtime_error(fmt::format(
            "exact: ball {} at t = {} s rests in a corner spinning at {} rad/s: friction at two walls at once has no "
            "closed form",
            i, now_, w_[i]));
      w_[i] = 0, alpha_[i] = 0, slip_[i] = 0;
      return;
    }
    const int ax = held == 1 ? 0 : 1, b = 1 - ax;
    const double sign = inward(ax), ts = tangent_sign(ax, sign);
    const double G = -g_[ax] * sign, gt = g_[b] * ts, r = r_[i];
    const double vt = v_[b][i] * ts;
    const double slip = vt - w_[i] * r;
    const double noise = kVelocityNoise * (std::abs(vt) + std::abs(w_[i]) * r);
    double at, alpha;
    int s = 0;
    if (std::abs(slip) <= noise && std::abs(gt) * k_ <= mu_ * G * (1 + k_)) {
      w_[i] = vt / r;
      at = gt / (1 + k_);
      alpha = at / r;
    } else {
      s = std::abs(slip) <= noise ? (gt > 0 ? 1 : -1) : (slip > 0 ? 1 : -1);
      at = gt - mu_ * G * s;
      alpha = mu_ * G * s / (k_ * r);
    }
    a_[ax][i] = 0;
    a_[b][i] = at * ts;
    alpha_[i] = alpha, slip_[i] = static_cast<int8_t>(s);
    // Standing against a wall across the slide, pushed into it by friction alone: a corner.
    const double push = a_[b][i];
    if (push != 0 && std::abs(v_[b][i]) <= velocity_noise(speed(i))) {
      const int side = push < 0 ? 0 : 1;
      const double gap = side == 0 ? p_[b][i] - r - box_lo_[b] : box_hi_[b] - r - p_[b][i];
      const bool gravity_presses = side == 0 ? g_[b] < 0 : g_[b] > 0;  // then it is held there next
      if (gap <= kTouch * r && !gravity_presses)
        throw std::runtime_error(fmt::format(
            "exact: ball {} at t = {} s is driven by friction into the wall it touches across its slide (a corner): "
            "two rough contacts at once have no closed form",
            i, now_));
    }
  }

  // When ball i's slip on the wall it slides on reaches zero (s(tau) = s0 + (ds/dt) tau, set_motion),
  // or kNever. The rate is a sum of the closed-form terms, never a difference of nearly equal
  // velocities; s0 is the slip itself.
  double roll_time(int i) const {
    const int ax = hold_[i] == 1 ? 0 : 1, b = 1 - ax;
    const double sign = inward(ax), ts = tangent_sign(ax, sign);
    const double G = -g_[ax] * sign, gt = g_[b] * ts, s = slip_[i];
    const double s0 = (v_[b][i] * ts - w_[i] * r_[i]) * s;  // |slip| while it keeps its sign
    const double closing = mu_ * G * (1 + k_) / k_ - gt * s;  // -d|s|/dt
    if (!(closing > 0)) return kNever;
    return s0 <= 0 ? 0.0 : s0 / closing;
  }

  // The slip of a sliding ball reached zero: it rolls from here (set_motion decides whether static
  // friction can hold it; if not it slides on the other way).
  void on_roll(int i) {
    bump(i);
    advance(i, now_);
    touch(i);
    const int ax = hold_[i] == 1 ? 0 : 1, b = 1 - ax;
    w_[i] = v_[b][i] * tangent_sign(ax, inward(ax)) / r_[i];  // the event is the moment the slip is zero
    set_motion(i);
    repredict_touched();
  }

  void on_pair(int i, int j) {
    bump(i), bump(j);
    advance(i, now_), advance(j, now_);
    requeue(i), requeue(j);
    double n[2] = {p_[0][i] - p_[0][j], p_[1][i] - p_[1][j]};  // from j to i
    const double dist = norm2(n[0], n[1]);
    if (dist > 0) {
      n[0] /= dist, n[1] /= dist;
      const double wn = (v_[0][i] - v_[0][j]) * n[0] + (v_[1][i] - v_[1][j]) * n[1];  // < 0: approaching
      const double u = std::max(-wn, 0.0);
      if (asleep_[i] && u >= v_wake_) wake(i);
      if (asleep_[j] && u >= v_wake_) wake(j);
      if (u < v_rest_) {
        settle_cluster(i, j, false);
      } else if (jam_count_[i] > kJamEvents || jam_count_[j] > kJamEvents) {
        settle_cluster(i, j, true);
      } else if (!asleep_[i] || !asleep_[j]) {
        // A sleeping ball is a fixed obstacle: infinite mass, no acceleration.
        const double wi = asleep_[i] ? 0.0 : im_[i], wj = asleep_[j] ? 0.0 : im_[j];
        const double Ax = a_[0][i] - a_[0][j], Ay = a_[1][i] - a_[1][j];
        const double press = -(Ax * n[0] + Ay * n[1]);  // relative acceleration into the contact
        // Restitution on the normal component only (thesis eq. 11-12 generalised):
        // J = -(1 + e) vn / (1/m1 + 1/m2), written as the wanted separation speed `out`.
        double out = e_ * u;
        if (pressed(press, Ax, Ay, kVelocityNoise * (speed(i) + speed(j)))) out = std::max(out, 0.5 * press * tc_);
        const double J = (out - wn) / (wi + wj);
        if (J > 0) {
          if (mu_ > 0) pair_friction(i, j, n, wn, wi, wj);
          for (int k = 0; k < 2; ++k) v_[k][i] += J * wi * n[k], v_[k][j] -= J * wj * n[k];
          for (int b : {i, j})
            if (!asleep_[b]) touch(b), after_impulse(b);
        }
      }
    }
    for (int b : {i, j})
      if (jammed(b)) try_sleep(b);
    repredict_touched();
  }

  // The rough part of the impact of balls i and j (normal n from j to i, normal velocity wn < 0,
  // inverse masses wi, wj: 0 for a sleeping ball, which neither moves nor turns): rough_impact's
  // tangential impulse P_t t on i, -P_t t on j, against the slip u_t = (v_i - v_j).t - (w_i r_i +
  // w_j r_j). The normal impulse is on_pair's; normal and tangent decouple for disks.
  void pair_friction(int i, int j, const double* n, double wn, double wi, double wj) {
    const double t[2] = {-n[1], n[0]};
    const double u_t =
        (v_[0][i] - v_[0][j]) * t[0] + (v_[1][i] - v_[1][j]) * t[1] - (w_[i] * r_[i] + w_[j] * r_[j]);
    const double P = rough_impact(wn, u_t, e_, mu_, 1.0 / (wi + wj), tangent_mass(wi, wj, k_)).tangent;
    for (int k = 0; k < 2; ++k) v_[k][i] += P * wi * t[k], v_[k][j] -= P * wj * t[k];
    w_[i] -= P * wi / (k_ * r_[i]);  // r P_t / I with I = k m r^2
    w_[j] -= P * wj / (k_ * r_[j]);
  }

  // A slow impact (below rest_velocity) is a ball settling into contact, usually among others that
  // touch: resolved one binary collision at a time, such a contact network needs thousands of
  // zero-time collisions (the Gauss-Seidel iteration of one multi-contact impact, converging
  // slower the more nearly opposite the contact normals), so it is resolved at once instead, as
  // one simultaneous perfectly inelastic impact (Moreau's contact dynamics at one instant): the
  // balls touching the pair through awake balls, with their contacts among themselves and with
  // walls and sleeping balls, get the impulses that leave no contact closing (solve_cluster).
  // Then slow balls whose weight is carried fall asleep, and pressed contacts of the others get
  // their micro-bounce. Contacts closing faster than rest_velocity are left to the binary events
  // that follow at the same time.
  //
  // A ball in more than kJamEvents collisions within t_c (jammed: falling into a wedge, where
  // each binary collision takes only a sliver of its momentum along nearly opposite normals) has
  // its contacts settled the same way whatever their speed (`jammed`): a sustained multi-contact,
  // as in the TC model, here taken as perfectly inelastic.
  void settle_cluster(int i, int j, bool jammed) {
    if (mu_ > 0)
      throw std::runtime_error(fmt::format(
          "exact: ball {} at t = {} s needs a multi-contact settle ({}), where friction has no closed form", i, now_,
          jammed ? "the jam rule: many collisions within contact_time" : "an impact slower than rest_velocity"));
    ++cluster_stamp_;
    cluster_.clear();
    contacts_.clear();
    auto join = [&](int k) {
      if (asleep_[k] || cluster_mark_[k] == cluster_stamp_ || cluster_.size() >= kMaxCluster) return;
      cluster_mark_[k] = cluster_stamp_;
      cluster_pos_[k] = static_cast<int>(cluster_.size());
      advance(k, now_);
      cluster_.push_back(k);
      for (int d = 0; d < 2; ++d) v_old_[d].push_back(v_[d][k]);
    };
    for (int d = 0; d < 2; ++d) v_old_[d].clear();
    join(i);
    if (j >= 0) join(j);
    for (size_t q = 0; q < cluster_.size(); ++q) {
      const int k = cluster_[q];
      if (walls_)
        for (int d = 0; d < 2; ++d)
          for (int side = 0; side < 2; ++side) {
            const double gap = side == 0 ? p_[d][k] - r_[k] - box_lo_[d] : box_hi_[d] - r_[k] - p_[d][k];
            if (gap > kTouch * r_[k]) continue;
            ClusterContact c{{k, -1, 0, 0, 1 / im_[k], 0}, 0, gap < -0.5 * kOverlapCap * r_[k]};
            (d == 0 ? c.nx : c.ny) = side == 0 ? 1 : -1;
            if (std::abs(v_[d][k]) > v_rest_ && !jammed) continue;  // a real bounce (its own event), or parting
            contacts_.push_back(c);
          }
      for_each_near(k, [&](int m) {
        // Each pair once: from the first of the two to be scanned.
        if (!asleep_[m] && cluster_mark_[m] == cluster_stamp_ && cluster_pos_[m] < static_cast<int>(q)) return;
        advance(m, now_);
        double n[2] = {p_[0][k] - p_[0][m], p_[1][k] - p_[1][m]};
        const double dist = norm2(n[0], n[1]), rs = r_[k] + r_[m];
        if (dist == 0 || dist - rs > kTouch * rs) return;
        n[0] /= dist, n[1] /= dist;
        const double wn = (v_[0][k] - v_[0][m]) * n[0] + (v_[1][k] - v_[1][m]) * n[1];
        // Only slow contacts: a real impact (closing faster than rest_velocity) is a binary event
        // that follows at the same time, and a pair parting that fast is not in contact.
        if (std::abs(wn) > v_rest_ && !(jammed && wn < 0)) return;
        const double wm = asleep_[m] ? 0.0 : im_[m];
        const double Ax = a_[0][k] - a_[0][m], Ay = a_[1][k] - a_[1][m];
        const double press = -(Ax * n[0] + Ay * n[1]);
        const double target = pressed(press, Ax, Ay, kVelocityNoise * (speed(k) + speed(m))) ? 0.5 * press * tc_ : 0.0;
        // Crept to the overlap cap, or pressed together: even a slow closing must stop.
        const bool firm = dist < rs * (1 - 0.5 * kOverlapCap) || target > 0;
        contacts_.push_back({{k, asleep_[m] ? -1 : m, n[0], n[1], 1 / (im_[k] + wm), 0}, target, firm});
        if (!asleep_[m]) join(m);
      });
    }
    // First perfectly inelastic (every target 0); balls left slow and carried fall asleep.
    rebound_.resize(contacts_.size());
    bool bounce = false;
    for (size_t c = 0; c < contacts_.size(); ++c) {
      rebound_[c] = contacts_[c].target;
      bounce |= rebound_[c] > 0;
      contacts_[c].target = 0;
    }
    solve_cluster();
    for (const int k : cluster_) try_sleep(k);
    sleep_group();
    // Then the pressed contacts of balls still awake get their micro-bounce. Between nearly
    // opposite normals (a wedge) that could take a launch many times rest_velocity: then the
    // micro-bounce is dropped, and the ball is left to the jam rule.
    if (bounce) {
      for (int d = 0; d < 2; ++d) {
        v_mid_[d].resize(cluster_.size());
        for (size_t q = 0; q < cluster_.size(); ++q) v_mid_[d][q] = v_[d][cluster_[q]];
      }
      size_t kept = 0;
      for (size_t c = 0; c < contacts_.size(); ++c) {
        ClusterContact cc = contacts_[c];
        if (asleep_[cc.i] || (cc.j >= 0 && asleep_[cc.j])) continue;
        cc.target = rebound_[c], cc.impulse = 0;
        contacts_[kept++] = cc;
      }
      contacts_.resize(kept);
      solve_cluster();
      double jump = 0;
      for (size_t q = 0; q < cluster_.size(); ++q)
        jump = std::max(jump, norm2(v_[0][cluster_[q]] - v_mid_[0][q], v_[1][cluster_[q]] - v_mid_[1][q]));
      if (jump > v_rest_)
        for (size_t q = 0; q < cluster_.size(); ++q)
          for (int d = 0; d < 2; ++d) v_[d][cluster_[q]] = v_mid_[d][q];
    }
    for (size_t q = 0; q < cluster_.size(); ++q) {
      const int k = cluster_[q];
      if (!asleep_[k] && (v_[0][k] != v_old_[0][q] || v_[1][k] != v_old_[1][q])) touch(k), after_impulse(k);
    }
  }

  // The slow balls of a cluster that carry one another's weight, down to walls and sleeping balls,
  // fall asleep together (one at a time, none would: each rests on another that is awake). The
  // group starts as every slow awake ball and loses, until none is left to lose, each ball whose
  // weight walls, sleeping balls and the rest of the group do not carry.
  void sleep_group() {
    if (!s_.sleep || !gravity_) return;
    ++group_stamp_;
    group_.clear();
    for (const int k : cluster_)
      if (!asleep_[k] && speed(k) < v_rest_) group_mark_[k] = group_stamp_, group_.push_back(k);
    for (bool changed = true; changed && !group_.empty();) {
      changed = false;
      for (size_t q = 0; q < group_.size();) {
        const int k = group_[q];
        if (supported(k, true)) {
          ++q;
          continue;
        }
        group_mark_[k] = 0;
        group_[q] = group_.back();
        group_.pop_back();
        changed = true;
      }
    }
    std::sort(group_.begin(), group_.end());
    for (const int k : group_) {
      asleep_[k] = 1;
      for (int d = 0; d < 2; ++d) v_[d][k] = 0, a_[d][k] = 0;
      touch(k);
    }
  }

  // The simultaneous impact of the cluster: exact for one ball or a few contacts, else projected
  // Gauss-Seidel (Catto's sequential impulses) to the tolerance.
  void solve_cluster() {
    const double tolerance = kRestSlop * v_rest_;
    if (cluster_.size() == 1) {
      settle_one(cluster_[0], tolerance);
    } else if (contacts_.size() > kMaxExactContacts || !settle_exact()) {
      settle_many(tolerance);
    }
  }

  // One awake ball against fixed contacts: its new velocity is the exact projection of the old
  // one onto {v : v.n_c >= target_c} (a ball wedged between two nearly opposite supports would
  // take Gauss-Seidel millions of sweeps). In 2D at most two contacts are active: try the sets
  // of none, one and two, keep the nearest feasible velocity.
  void settle_one(int k, double tolerance) {
    const double v0[2] = {v_[0][k], v_[1][k]};
    const double fine = kVelocityNoise * (norm2(v0[0], v0[1]) + v_rest_);  // round-off of a projection
    auto feasible = [&](const double* v) {
      for (const ClusterContact& c : contacts_)
        if (v[0] * c.nx + v[1] * c.ny < c.target - fine) return false;
      return true;
    };
    // Already within the slack of every contact (the Gauss-Seidel tolerance for slow ones)?
    bool slack = true;
    for (const ClusterContact& c : contacts_)
      if (v0[0] * c.nx + v0[1] * c.ny < c.target - (c.firm || c.target > 0 ? fine : tolerance)) slack = false;
    if (slack || feasible(v0)) return;
    double best[2] = {v0[0], v0[1]}, best_d2 = kNever;
    auto offer = [&](double x, double y) {
      const double v[2] = {x, y};
      const double d2 = (x - v0[0]) * (x - v0[0]) + (y - v0[1]) * (y - v0[1]);
      if (d2 < best_d2 && feasible(v)) best[0] = x, best[1] = y, best_d2 = d2;
    };
    const int m = static_cast<int>(contacts_.size());
    for (int a = 0; a < m; ++a) {
      const ClusterContact& c = contacts_[a];
      const double push = c.target - (v0[0] * c.nx + v0[1] * c.ny);
      if (push > 0) offer(v0[0] + push * c.nx, v0[1] + push * c.ny);
    }
    for (int a = 0; a < m; ++a)
      for (int b = a + 1; b < m; ++b) {
        const ClusterContact &ca = contacts_[a], &cb = contacts_[b];
        const double det = ca.nx * cb.ny - ca.ny * cb.nx;
        if (std::abs(det) < 1e-12) continue;
        // v.n_a = t_a and v.n_b = t_b; then the impulses along n_a, n_b must both push.
        const double x = (ca.target * cb.ny - cb.target * ca.ny) / det;
        const double y = (ca.nx * cb.target - cb.nx * ca.target) / det;
        const double dx = x - v0[0], dy = y - v0[1];
        const double la = (dx * cb.ny - dy * cb.nx) / det, lb = (ca.nx * dy - ca.ny * dx) / det;
        if (la >= 0 && lb >= 0) offer(x, y);
      }
    if (best_d2 < kNever) v_[0][k] = best[0], v_[1][k] = best[1];
  }

  // A small cluster: the impulses lambda >= 0 solve the linear complementarity problem
  //   w = A lambda + b >= 0, lambda >= 0, lambda.w = 0,
  // A = J M^-1 J^T (the contacts' coupling through the balls' masses), b = J v - target (a
  // contact's normal velocity beyond its target), by Lemke's complementary pivoting (Cottle, Pang
  // & Stone, "The Linear Complementarity Problem", 1992): exact where Gauss-Seidel stalls on
  // wedges and arches (contact normals nearly opposite). False if it does not terminate.
  bool settle_exact() {
    const int m = static_cast<int>(contacts_.size());
    if (m == 0) return true;
    const int cols = 2 * m + 2;  // w (m), z (m), z0, right-hand side
    auto T = [&](int r, int c) -> double& { return tableau_[static_cast<size_t>(r) * cols + c]; };
    tableau_.assign(static_cast<size_t>(m) * cols, 0.0);
    double bmin = 0;
    int r = -1;
    for (int c = 0; c < m; ++c) {
      const ClusterContact& cc = contacts_[c];
      double wn = v_[0][cc.i] * cc.nx + v_[1][cc.i] * cc.ny;
      if (cc.j >= 0) wn -= v_[0][cc.j] * cc.nx + v_[1][cc.j] * cc.ny;
      const double b = wn - cc.target;
      T(c, c) = 1;
      for (int d = 0; d < m; ++d) T(c, m + d) = -coupling(cc, contacts_[d]);
      T(c, 2 * m) = -1;
      T(c, 2 * m + 1) = b;
      if (b < bmin) bmin = b, r = c;
    }
    if (r < 0) return true;  // nothing violated
    basis_.resize(m);
    for (int c = 0; c < m; ++c) basis_[c] = c;
    auto pivot = [&](int row, int col) {
      const double p = T(row, col);
      for (int c = 0; c < cols; ++c) T(row, c) /= p;
      for (int i = 0; i < m; ++i) {
        if (i == row || T(i, col) == 0) continue;
        const double f = T(i, col);
        for (int c = 0; c < cols; ++c) T(i, c) -= f * T(row, c);
      }
      basis_[row] = col;
    };
    pivot(r, 2 * m);  // z0 enters at the most violated contact
    int entering = m + r;  // the complement of w_r, which left
    for (int it = 0; it < 50 * m + 50; ++it) {
      int leave = -1;
      double best = kNever;
      for (int i = 0; i < m; ++i) {
        const double d = T(i, entering);
        if (d <= 1e-14) continue;
        const double ratio = T(i, 2 * m + 1) / d;
        if (ratio < best) best = ratio, leave = i;
      }
      if (leave < 0) return false;  // ray: no solution found
      const int left = basis_[leave];
      pivot(leave, entering);
      if (left == 2 * m) {
        lambda_.assign(m, 0.0);
        for (int i = 0; i < m; ++i)
          if (basis_[i] >= m && basis_[i] < 2 * m) lambda_[basis_[i] - m] = std::max(0.0, T(i, 2 * m + 1));
        for (int c = 0; c < m; ++c) {
          const ClusterContact& cc = contacts_[c];
          for (int d = 0; d < 2; ++d) {
            v_[d][cc.i] += lambda_[c] * im_[cc.i] * cc.n(d);
            if (cc.j >= 0) v_[d][cc.j] -= lambda_[c] * im_[cc.j] * cc.n(d);
          }
        }
        return true;
      }
      entering = left < m ? left + m : left - m;
    }
    return false;
  }

  // Normal velocity change of contact c per unit impulse at contact d: J_c M^-1 J_d^T.
  double coupling(const ClusterContact& c, const ClusterContact& d) const {
    const double dot = c.nx * d.nx + c.ny * d.ny;
    double k = 0;
    if (c.i == d.i) k += im_[c.i];
    if (c.j >= 0 && c.j == d.j) k += im_[c.j];
    if (d.j >= 0 && c.i == d.j) k -= im_[c.i];
    if (c.j >= 0 && c.j == d.i) k -= im_[c.j];
    return k * dot;
  }

  // Projected Gauss-Seidel on the accumulated impulses (each >= 0: contacts only push).
  void settle_many(double tolerance) {
    const int sweeps = kClusterSweeps + 4 * static_cast<int>(cluster_.size());
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      double worst = 0;
      for (ClusterContact& c : contacts_) {
        double wn = v_[0][c.i] * c.nx + v_[1][c.i] * c.ny;
        if (c.j >= 0) wn -= v_[0][c.j] * c.nx + v_[1][c.j] * c.ny;
        if (c.impulse == 0 && !c.firm && c.target == 0 && wn >= -tolerance) continue;  // closing within noise
        const double next = std::max(0.0, c.impulse + (c.target - wn) * c.mass);
        const double dJ = next - c.impulse;
        if (dJ == 0) continue;
        c.impulse = next;
        for (int d = 0; d < 2; ++d) {
          v_[d][c.i] += dJ * im_[c.i] * c.n(d);
          if (c.j >= 0) v_[d][c.j] -= dJ * im_[c.j] * c.n(d);
        }
        worst = std::max(worst, std::abs(dJ) / c.mass);
      }
      if (worst <= tolerance) break;
    }
  }

  // Does relative acceleration (Ax, Ay), with normal part `press` into the contact (m/s^2), hold a
  // touching pair together? Then a collision cannot leave them separating at restitution 0, only
  // at the TC micro-bounce speed press t_c / 2 (one flight of t_c: Luding & McNamara's contact
  // duration) instead of the infinitely many vanishing bounces of a body held against a support.
  // Pressing too weak for that speed to stand out of round-off (`fine`), or a tilt of side-by-side
  // balls, does not count.
  bool pressed(double press, double Ax, double Ay, double fine) const {
    return press > kPressedFraction * norm2(Ax, Ay) && 0.5 * press * tc_ > 4 * fine;
  }

  // Frees every axis (a woken ball).
  void release(int i) {
    for (int k = 0; k < 2; ++k) a_[k][i] = g_[k];
  }

  // A ball sliding on a wall (axis k held: a_k = 0 though g_k != 0) was struck. Struck away from
  // the wall it flies again; struck into it faster than rest_velocity it is freed, and the wall
  // event due now bounces it; otherwise the wall absorbs the normal part (the rest rule, applied
  // here rather than by a zero-time wall event) and it keeps sliding.
  void after_impulse(int i) {
    const double noise = velocity_noise(speed(i));
    for (int k = 0; k < 2; ++k) {
      if (a_[k][i] != 0 || g_[k] == 0) continue;
      const double away = g_[k] < 0 ? v_[k][i] : -v_[k][i];  // normal velocity off the wall
      if (away > noise || away < -v_rest_) a_[k][i] = g_[k];
      else v_[k][i] = 0;
    }
  }

  // After a slow impact: a ball now slower than rest_velocity whose weight the walls and sleeping
  // balls it touches carry goes to sleep.
  // A rough ball on a wall rolls on (exactly), so it never sleeps.
  void try_sleep(int i) {
    if (asleep_[i] || !s_.sleep || !gravity_ || mu_ > 0) return;
    if (!jammed(i) && (speed(i) >= v_rest_ || !supported(i))) return;
    asleep_[i] = 1;
    for (int k = 0; k < 2; ++k) v_[k][i] = 0, a_[k][i] = 0;
    touch(i);
  }

  // Wakes sleeping ball i and, transitively, every sleeping ball resting on one that woke.
  void wake(int i) {
    stack_.assign(1, i);
    while (!stack_.empty()) {
      const int k = stack_.back();
      stack_.pop_back();
      if (!asleep_[k]) continue;
      advance(k, now_);
      asleep_[k] = 0;
      release(k);
      touch(k);
      for_each_near(k, [&](int m) {
        if (!asleep_[m]) return;
        const double dx = p_[0][m] - p_[0][k], dy = p_[1][m] - p_[1][k];
        const bool above = dx * g_[0] + dy * g_[1] < 0;
        if (above && norm2(dx, dy) - r_[k] - r_[m] <= support_gap_) stack_.push_back(m);
      });
    }
  }

  // Do the walls and sleeping balls within support_gap of ball i carry its weight? Frictionless
  // contacts push along their normals, so -g must lie in the cone of the contact normals.
  // `with_group`: balls of the group being put to sleep together (group_mark_) count as well.
  bool supported(int i, bool with_group = false) const {
    if (!gravity_) return false;
    const double gn = norm2(g_[0], g_[1]);
    const double up[2] = {-g_[0] / gn, -g_[1] / gn};
    double nrm[16][2];
    int m = 0;
    auto add = [&](double x, double y) {
      if (m < 16) nrm[m][0] = x, nrm[m][1] = y, ++m;
    };
    if (walls_)
      for (int k = 0; k < 2; ++k) {
        if (p_[k][i] - r_[i] - box_lo_[k] <= support_gap_) add(k == 0 ? 1 : 0, k == 1 ? 1 : 0);
        if (box_hi_[k] - r_[i] - p_[k][i] <= support_gap_) add(k == 0 ? -1 : 0, k == 1 ? -1 : 0);
      }
    for_each_near(i, [&](int j) {
      if (!asleep_[j] && !(with_group && group_mark_[j] == group_stamp_)) return;
      const double dx = p_[0][i] - p_[0][j], dy = p_[1][i] - p_[1][j];
      const double d = norm2(dx, dy);
      if (d > 0 && d - r_[i] - r_[j] <= support_gap_) add(dx / d, dy / d);
    });
    auto cross = [](const double* a, const double* b) { return a[0] * b[1] - a[1] * b[0]; };
    for (int k = 0; k < m; ++k)
      if (nrm[k][0] * up[0] + nrm[k][1] * up[1] > 0 && std::abs(cross(nrm[k], up)) <= kSupportAngle) return true;
    for (int k = 0; k < m; ++k)
      for (int l = k + 1; l < m; ++l) {
        const double c = cross(nrm[k], nrm[l]);
        if (std::abs(c) < 1e-12) continue;
        const double alpha = cross(up, nrm[l]) / c, beta = cross(nrm[k], up) / c;  // up = alpha n_k + beta n_l
        if (alpha >= 0 && beta >= 0) return true;
      }
    return false;
  }

  // ---- the event queue: an indexed binary heap with one entry per ball, ordered by (time, ball) ----

  bool before(int a, int b) const {
    const double ta = ev_[a].t, tb = ev_[b].t;
    return ta < tb || (ta == tb && a < b);
  }

  void heap_update(int i) {
    int k = slot_[i];
    while (k > 0) {
      const int parent = (k - 1) / 2;
      if (!before(i, heap_[parent])) break;
      heap_[k] = heap_[parent], slot_[heap_[k]] = k;
      k = parent;
    }
    for (;;) {
      int child = 2 * k + 1;
      if (child >= n_) break;
      if (child + 1 < n_ && before(heap_[child + 1], heap_[child])) ++child;
      if (!before(heap_[child], i)) break;
      heap_[k] = heap_[child], slot_[heap_[k]] = k;
      k = child;
    }
    heap_[k] = i, slot_[i] = k;
  }

  ExactSettings s_;
  int n_;
  double e_;
  double mu_;  // Coulomb coefficient, ball-ball and ball-wall
  double k_;   // inertia factor: I = k m r^2
  double g_[2];
  bool gravity_ = false;
  bool walls_;
  double box_lo_[2] = {0, 0}, box_hi_[2] = {0, 0};
  double tc_, v_rest_, v_wake_, support_gap_;

  // Balls, structure of arrays. Each ball's state is exact at its own time tl_.
  std::vector<double> r_, im_;        // radius (m), 1 / mass (1/kg)
  std::vector<double> p_[2], v_[2], a_[2];  // position (m), velocity (m/s), acceleration (m/s^2) at tl_
  std::vector<double> tl_;            // the time each ball was last brought to (s)
  std::vector<uint32_t> count_;       // trajectory changes so far, to recognise stale predictions
  std::vector<uint8_t> asleep_;
  std::vector<int> events_;           // events this step, against the budget
  std::vector<double> jam_start_;     // start of each ball's current window of t_c (s)
  std::vector<int> jam_count_;        // its events in that window

  // Rotation, only for a scene that rotates (rot_); sliding and rolling, only with rough_walls_.
  bool rot_ = false;
  bool rough_walls_ = false;          // friction under gravity in a box: a ball on a wall slides, then rolls
  std::vector<double> w_, angle_, alpha_;  // angular velocity (rad/s), angle (rad), dw/dt (rad/s^2) at tl_
  std::vector<int8_t> slip_;          // sliding on a wall: the sign of the slip; 0: rolling (or not on a wall)
  std::vector<uint8_t> hold_;         // bit k: held on the wall of axis k that gravity presses it against

  // Grid: singly-indexed cells, intrusive doubly-linked lists of balls.
  double grid_lo_[2] = {0, 0}, width_[2] = {1, 1};
  int n_cells_[2] = {1, 1};
  std::vector<int> head_, next_, prev_, cell_;

  std::vector<ClusterContact> contacts_;     // of the cluster being settled
  std::vector<int> cluster_, cluster_pos_;
  std::vector<uint32_t> cluster_mark_, group_mark_;
  std::vector<int> group_;
  uint32_t group_stamp_ = 0;
  uint32_t cluster_stamp_ = 0;
  std::vector<double> v_old_[2];      // cluster velocities before settling
  std::vector<double> v_mid_[2];      // after the inelastic pass
  std::vector<double> rebound_;       // each contact's micro-bounce target
  std::vector<double> tableau_, lambda_;  // Lemke's method (settle_exact)
  std::vector<int> basis_;

  std::vector<PredictedEvent> ev_;             // each ball's earliest predicted event
  std::vector<int> heap_, slot_;      // heap of balls; slot_[i]: i's position in heap_
  std::vector<int> touched_, stack_;
  std::vector<uint32_t> mark_;
  uint32_t stamp_ = 1;

  double t_ = 0;    // time of the last completed step (s)
  double now_ = 0;  // time of the event being processed (s)
};

}  // namespace

EngineEntry exact_engine() {
  EngineInfo info;
  info.name = "exact";
  info.role = EngineRole::reference;
  info.version = "1.0";
  info.summary =
      "event-driven reference: exact parabolic flights, binary collisions in time order, rest rules for piles";
  info.caps.continuous_collision = true;
  info.caps.deterministic = true;
  info.caps.any_restitution = true;
  info.caps.friction = true;  // closed-form cases only: `refuses` names the rest
  info.refuses = exact_refusal;
  info.settings = exact_settings_table().describe();
  return {info, [](const Scene& scene, const std::string&, const nlohmann::json& overrides) {
            ExactSettings s;
            exact_settings_table().read(overrides, s);
            if (const std::string why = exact_refusal(scene); !why.empty()) throw SceneUnsupported("exact: " + why);
            const double rmin = scene.n() > 0 ? scene.radius.minCoeff() : 1.0;
            const double rmax = scene.n() > 0 ? scene.radius.maxCoeff() : 1.0;
            if (s.cell_size > 0 && s.cell_size < 2 * rmax)
              throw InputError(
                  fmt::format("settings.exact.cell_size: must be at least the largest diameter, {} m", 2 * rmax));
            // Resolve the automatic values (negative = automatic), so settings() shows those in force.
            const double g = scene.gravity.norm();
            const double v0 = scene.n() > 0 ? std::sqrt(scene.initial.vel.rowwise().squaredNorm().maxCoeff()) : 0.0;
            const double v_scale = std::max(std::sqrt(g * rmin), v0);  // speed scale of the scene (m/s)
            if (s.contact_time < 0) s.contact_time = v_scale > 0 ? kAutoScale * rmin / v_scale : 0.0;
            if (s.rest_velocity < 0) s.rest_velocity = g > 0 ? kAutoScale * v_scale : 0.0;
            if (s.wake_velocity < 0) s.wake_velocity = kAutoWake * s.rest_velocity;
            if (s.support_gap < 0)
              s.support_gap = std::max(g > 0 ? s.rest_velocity * s.rest_velocity / g : 0.0, 1e-9 * rmin);
            if (g > 0 && !(s.contact_time > 0))
              throw InputError("settings.exact.contact_time: must be > 0 under gravity (it ends resting contacts)");
            if (g > 0 && !(s.rest_velocity > 0))
              throw InputError(
                  "settings.exact.rest_velocity: must be > 0 under gravity (it ends bouncing on supports)");
            return std::unique_ptr<Engine>(std::make_unique<Exact>(scene, s));
          }};
}

}  // namespace ballbench
