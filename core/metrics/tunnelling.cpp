#include "metrics/tunnelling.h"

#include <algorithm>
#include <cmath>

namespace ballbench {

bool beyond_wall(const Eigen::Vector2d& p, const Container& box) {
  return box.kind == ContainerKind::Box && ((p.array() < box.min.array()).any() || (p.array() > box.max.array()).any());
}

int wall_escapes(const State& prev, const State& cur, const Container& box) {
  if (box.kind != ContainerKind::Box) return 0;
  int count = 0;
  for (int i = 0; i < cur.n(); ++i)
    if (!beyond_wall(prev.pos.row(i).transpose(), box) && beyond_wall(cur.pos.row(i).transpose(), box)) ++count;
  return count;
}

Eigen::Vector2d wall_crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Container& box) {
  double s = 1;
  for (int k = 0; k < 2; ++k) {
    if (b[k] < box.min[k] && a[k] >= box.min[k]) s = std::min(s, (box.min[k] - a[k]) / (b[k] - a[k]));
    if (b[k] > box.max[k] && a[k] <= box.max[k]) s = std::min(s, (box.max[k] - a[k]) / (b[k] - a[k]));
  }
  return a + s * (b - a);
}

namespace {

// clamp(-d.w / |w|^2, 0, 1): how far along w from d the line comes closest to 0, without squaring
// |w| where that overflows (a finite step beyond ~1e154).
double fraction_from(const Eigen::Vector2d& d, const Eigen::Vector2d& w) {
  const double ww = w.squaredNorm();
  if (std::isinf(ww) && w.allFinite()) {
    const double len = std::hypot(w.x(), w.y());
    return std::clamp(-d.dot(w / len) / len, 0.0, 1.0);
  }
  return ww > 0 ? std::clamp(-d.dot(w) / ww, 0.0, 1.0) : 0.0;
}

}  // namespace

double closest_approach_fraction(const Eigen::Vector2d& d0, const Eigen::Vector2d& d1) {
  return fraction_from(d0, d1 - d0);
}

double closest_approach(const Eigen::Vector2d& d0, const Eigen::Vector2d& d1) {
  const Eigen::Vector2d w = d1 - d0;
  const double f = fraction_from(d0, w);
  if (f <= 0.5) return (d0 + f * w).norm();
  // Nearer the end: measured back from it, so that a far start (a ball sent 1e150 m away and back)
  // whose rounding swallowed the pair's offset does not move the closest point to the end.
  return (d1 - fraction_from(d1, -w) * w).norm();
}

bool passes_through(const State& prev, const State& cur, int i, int j, double rs, double tolerance) {
  const Eigen::Vector2d d0 = (prev.pos.row(i) - prev.pos.row(j)).transpose();
  const Eigen::Vector2d d1 = (cur.pos.row(i) - cur.pos.row(j)).transpose();
  if (d0.squaredNorm() < rs * rs || d1.squaredNorm() < rs * rs) return false;  // overlapping: sticking's business
  const double h = cur.t - prev.t;
  const double bend =
      0.25 * h * ((cur.vel.row(i) - prev.vel.row(i)).norm() + (cur.vel.row(j) - prev.vel.row(j)).norm());
  return closest_approach(d0, d1) < (1.0 - tolerance) * rs - bend;
}

namespace {

// Filters drop a pair only when it misses by more than this share of r_i + r_j: far above the
// rounding of the quantities they compare for coordinates up to ~10^8 radii.
constexpr double kMargin = 1e-6;

// Does a step from a to b leave the disc of squared radius a2 around the reference r? Both ends
// decide: the disc is convex. (NaN coordinates count as outside.)
bool leaves_allowance(double ax, double ay, double bx, double by, double rx, double ry, double a2) {
  const double ex = ax - rx, ey = ay - ry, fx = bx - rx, fy = by - ry;
  return !(std::max(ex * ex + ey * ey, fx * fx + fy * fy) <= a2);
}

}  // namespace

TunnellingCheck::TunnellingCheck(const Eigen::VectorXd& radius, const Container& box, double tolerance, int threads)
    : radius_(radius),
      box_(box),
      tolerance_(tolerance),
      pool_(ForkJoin::threads_for(static_cast<int>(radius.size()), kParallelBalls, threads)),
      parts_(pool_.parts()) {
  if (radius_.size() > 0) {
    r_min_ = radius_.minCoeff(), r_max_ = radius_.maxCoeff();
    equal_radii_ = r_min_ == r_max_;
  }
  never_ = !(tolerance < 1.0);  // then (1 - tolerance) rs - bend <= 0 <= any closest approach
  reach_ = std::max(1.0, 1.0 - tolerance) * (1.0 + kMargin);
  // A straight relative path that starts and ends at least rs apart but comes within
  // (1 - tolerance) rs of contact crosses that circle along a chord at least 2 s rs long,
  // s = sqrt(1 - (1 - tolerance)^2): the relative step |w| is at least that long. Without a
  // positive tolerance there is no such bound (s = 0).
  const double s = tolerance > 0 && tolerance < 1 ? std::sqrt(1.0 - (1.0 - tolerance) * (1.0 - tolerance)) : 0.0;
  const double chord = std::max(0.0, 2.0 * s - kMargin);
  chord2_ = chord * chord;
  close2_ = (1.0 - tolerance + kMargin) * (1.0 - tolerance + kMargin);
  line_filter_ = tolerance > 0;
  // |w| <= |d_i| + |d_j| and rs >= 2 r_min: one of the pair stepped at least s rs >= 2 s r_min.
  mover2_ = (chord * r_min_) * (chord * r_min_);
}

void TunnellingCheck::set_tuning(double allowance_radii, double rebuild_share) {
  allowance_radii_ = allowance_radii, rebuild_share_ = rebuild_share;
  built_ = false;
}

double* TunnellingCheck::records() {
  // 32 bytes per ball, 32-byte aligned: one cache line per ball's record.
  const auto misalign = reinterpret_cast<uintptr_t>(rec_.data()) % 32;
  return rec_.data() + (misalign ? (32 - misalign) / sizeof(double) : 0);
}

StepTunnelling TunnellingCheck::step(const State& prev, const State& cur) {
  const int n = cur.n();
  const bool listed = built_ && ref_.rows() == n;
  if (static_cast<int>(rec_.size()) < 4 * n + 4) rec_.resize(4 * n + 4);
  if (static_cast<int>(is_escaped_.size()) < n) is_escaped_.assign(n, 0);
  wall_hits_.clear(), pair_hits_.clear();
  const Sweep sw = sweep(prev, cur, listed);
  if (!sw.finite) return {false, sw.contained, 0, 0};
  StepTunnelling out;
  out.contained = sw.contained;
  out.wall = sw.wall;
  // Which balls escaped: a second look, on the rare steps with an escape, spares the sweep a branch
  // per ball. In ball order, as many as the sweep counted (the same test).
  if (sw.wall > 0)
    for (int i = 0; i < n; ++i)
      if (!beyond_wall(prev.pos.row(i).transpose(), box_) && beyond_wall(cur.pos.row(i).transpose(), box_))
        wall_hits_.push_back(i);
  if (n < 2 || never_ || sw.step2_max < mover2_) return out;  // no step long enough for a pass-through
  if (!listed || static_cast<double>(escaped_.size()) > rebuild_share_ * n) {
    rebuild(prev, cur, std::sqrt(sw.step2_sum / n));
  }
  for (int e : escaped_) is_escaped_[e] = 1;
  pool_.run([&](int p) { parts_[p].pairs = count_listed(prev, cur, parts_[p]); });
  out.pair = count_escaped(prev, cur);
  for (const Part& part : parts_) {
    out.pair += part.pairs;
    pair_hits_.insert(pair_hits_.end(), part.hits.begin(), part.hits.end());
  }
  for (int e : escaped_) is_escaped_[e] = 0;
  // Which part found a pair depends on the number of parts: sorted, the list does not.
  if (!pair_hits_.empty()) {
    for (auto& h : pair_hits_)
      if (h[0] > h[1]) std::swap(h[0], h[1]);
    std::sort(pair_hits_.begin(), pair_hits_.end());
  }
  return out;
}

// The parts' escaped balls, in ball order (each part's range follows the one before).
void TunnellingCheck::gather_escaped() {
  escaped_.clear();
  for (const Part& part : parts_) escaped_.insert(escaped_.end(), part.escaped.begin(), part.escaped.end());
}

TunnellingCheck::Sweep TunnellingCheck::sweep(const State& prev, const State& cur, bool contained) {
  const int n = cur.n(), parts = pool_.parts();
  double* rec = records();
  pool_.run([&](int p) {
    // Locals, not the closure's references: the loop's push_back may call out, after which every
    // captured value would be loaded again, each ball.
    const double *px = prev.pos.col(0).data(), *py = prev.pos.col(1).data();
    const double *cx = cur.pos.col(0).data(), *cy = cur.pos.col(1).data();
    const double *vx = cur.vel.col(0).data(), *vy = cur.vel.col(1).data();
    const bool box = box_.kind == ContainerKind::Box;
    const double x0 = box_.min.x(), y0 = box_.min.y(), x1 = box_.max.x(), y1 = box_.max.y();
    const double far = 2.0 * r_max_;  // beyond the box by more than this: the ball has left it
    const double *rx = ref_.col(0).data(), *ry = ref_.col(1).data();
    const double a2 = a_ * a_;
    Part& part = parts_[p];
    // Every sum and flag below is carried from ball to ball: kept to one cheap operation each (an
    // integer AND, one add, one max), since a chain of four dependent adds per ball (the
    // finiteness sum this sweep had) set its pace.
    int finite = 1;
    int outside = 0;
    int wall = 0;
    double m2max = 0, m2sum = 0;
    part.escaped.clear();
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long i = b; i < e; ++i) {
      const double ax = px[i], ay = py[i], bx = cx[i], by = cy[i];
      // x - x is 0 for a finite x, NaN otherwise.
      finite &= ((bx - bx) + (by - by)) + ((vx[i] - vx[i]) + (vy[i] - vy[i])) == 0;
      const bool in_before = !(ax < x0 || ay < y0 || ax > x1 || ay > y1);
      const bool out_after = bx < x0 || by < y0 || bx > x1 || by > y1;
      wall += box && in_before && out_after;
      outside |= box && (bx < x0 - far || by < y0 - far || bx > x1 + far || by > y1 + far);
      const double dx = bx - ax, dy = by - ay, m2 = dx * dx + dy * dy;
      m2max = std::max(m2max, m2);
      m2sum += m2;
      double* r = rec + 4 * i;
      r[0] = ax, r[1] = ay, r[2] = dx, r[3] = dy;
      if (contained && leaves_allowance(ax, ay, bx, by, rx[i], ry[i], a2)) part.escaped.push_back(static_cast<int>(i));
    }
    part.sweep = {finite != 0, outside == 0, wall, m2max, m2sum};
  });
  gather_escaped();
  Sweep all;  // in part order: the same sums for a given number of parts
  for (const Part& part : parts_) {
    all.finite = all.finite && part.sweep.finite;
    all.contained = all.contained && part.sweep.contained;
    all.wall += part.sweep.wall;
    all.step2_max = std::max(all.step2_max, part.sweep.step2_max);
    all.step2_sum += part.sweep.step2_sum;
  }
  return all;
}

void TunnellingCheck::rebuild(const State& prev, const State& cur, double step_rms) {
  const int n = cur.n(), parts = pool_.parts();
  ++rebuilds_;
  built_ = true;
  // A few radii, or two typical steps where balls step further (then a ball keeps its place in the
  // list for a few steps); capped so that one far jump cannot make every pair a candidate.
  a_ = std::clamp(2.0 * step_rms, allowance_radii_ * r_max_, 4.0 * allowance_radii_ * r_max_);
  const double a2 = a_ * a_;
  // References at the midpoints of this step, which is then contained for every ball whose half
  // step is within a.
  ref_.resize(n, 2);
  double *rx = ref_.col(0).data(), *ry = ref_.col(1).data();
  const double *px = prev.pos.col(0).data(), *py = prev.pos.col(1).data();
  const double *cx = cur.pos.col(0).data(), *cy = cur.pos.col(1).data();
  pool_.run([&](int p) {
    Part& part = parts_[p];
    part.escaped.clear();
    const long b = ForkJoin::range_begin(n, p, parts), e = ForkJoin::range_begin(n, p + 1, parts);
    for (long i = b; i < e; ++i) {
      rx[i] = 0.5 * (px[i] + cx[i]), ry[i] = 0.5 * (py[i] + cy[i]);
      if (leaves_allowance(px[i], py[i], cx[i], cy[i], rx[i], ry[i], a2)) part.escaped.push_back(static_cast<int>(i));
    }
  });
  gather_escaped();
  grid_.build(ref_, 2.0 * reach_ * r_max_ + 2.0 * a_);
  const std::vector<int>& ball = grid_.order();
  slots_.resize(n);
  pool_.run([&](int p) {
    slots_.gather(ball.data(), ref_, radius_, ForkJoin::range_begin(n, p, parts),
                  ForkJoin::range_begin(n, p + 1, parts));
  });
  // Listed: references closer than c (r_i + r_j) + 2 a, so in the same or adjacent cells. Appended
  // without a branch: the distance test's outcome is random, and mispredictions cost more than it.
  // Each part lists the pairs whose first slot lies in its rows of cells.
  const double twice_a = 2.0 * a_;
  const int rows = grid_.rows();
  pool_.run([&](int p) {
    Part& part = parts_[p];
    // Locals (pointers reloaded only after a resize): through the closure's references the
    // compiler loaded every one of them again for each candidate.
    const double *sx = slots_.x.data(), *sy = slots_.y.data(), *sr = slots_.r.data(), reach = reach_;
    const int* order = ball.data();
    std::array<int, 2>* list = part.list.data();
    size_t m = 0, capacity = part.list.size();
    const int row_begin = static_cast<int>(ForkJoin::range_begin(rows, p, parts));
    const int row_end = static_cast<int>(ForkJoin::range_begin(rows, p + 1, parts));
    grid_.for_each_forward_range(row_begin, row_end, [&](int a, int begin, int end) {
      if (capacity < m + (end - begin)) {
        part.list.resize(2 * (m + end - begin));
        list = part.list.data(), capacity = part.list.size();
      }
      const double x = sx[a], y = sy[a], r = sr[a];
      const int i = order[a];
      size_t k = m;
      for (int b = begin; b < end; ++b) {
        const double dx = x - sx[b], dy = y - sy[b], range = reach * (r + sr[b]) + twice_a;
        list[k] = {i, order[b]};
        k += dx * dx + dy * dy < range * range;
      }
      m = k;
    });
    part.listed = m;
  });
}

// Necessary conditions for a pass-through from the step records (see the constructor).
inline bool TunnellingCheck::may_pass(int i, int j, double rs) const {
  const double* rec = records();
  const double *p = rec + 4 * i, *q = rec + 4 * j;
  const double wx = p[2] - q[2], wy = p[3] - q[3], ww = wx * wx + wy * wy, rs2 = rs * rs;
  if (ww < chord2_ * rs2) return false;
  if (std::isfinite(ww)) {
    const double d0x = p[0] - q[0], d0y = p[1] - q[1];
    const double t = ww > 0 ? std::clamp(-(d0x * wx + d0y * wy) / ww, 0.0, 1.0) : 0.0;
    const double qx = d0x + t * wx, qy = d0y + t * wy;
    if (qx * qx + qy * qy < close2_ * rs2) return true;
    if (t <= 0.5) return false;
  }
  // Nearer the end of a long step, or one too long to square: measured from both ends, as
  // closest_approach does (a far start's rounding must not hide a pass on the way back).
  const Eigen::Vector2d d0(p[0] - q[0], p[1] - q[1]);
  const Eigen::Vector2d d1((p[0] + p[2]) - (q[0] + q[2]), (p[1] + p[3]) - (q[1] + q[3]));
  return closest_approach(d0, d1) < std::sqrt(close2_) * rs;
}

inline bool TunnellingCheck::judge(const State& prev, const State& cur, int i, int j, double rs) const {
  return may_pass(i, j, rs) && passes_through(prev, cur, i, j, rs, tolerance_);
}

int TunnellingCheck::count_listed(const State& prev, const State& cur, Part& part) {
  // First the chord filter over every listed pair, without a branch (its outcome is random), then
  // the rest on the few that pass.
  const size_t listed = part.listed;
  if (part.survivors.size() < listed) part.survivors.resize(listed);
  const double* rec = records();
  const std::array<int, 2>* list = part.list.data();
  int* survivors = part.survivors.data();
  const double equal_rs = 2.0 * r_max_;
  size_t m = 0;
  constexpr size_t kAhead = 16;  // records fetched ahead: the partners lie at random in memory
  for (size_t k = 0; k < listed; ++k) {
    if (k + kAhead < listed) {
      __builtin_prefetch(rec + 4 * list[k + kAhead][0]);
      __builtin_prefetch(rec + 4 * list[k + kAhead][1]);
    }
    const int i = list[k][0], j = list[k][1];
    const double *p = rec + 4 * i, *q = rec + 4 * j;
    const double wx = p[2] - q[2], wy = p[3] - q[3], d0x = p[0] - q[0], d0y = p[1] - q[1];
    const double rs = equal_radii_ ? equal_rs : radius_[i] + radius_[j], rs2 = rs * rs;
    const double ww = wx * wx + wy * wy, dw = d0x * wx + d0y * wy;
    survivors[m] = static_cast<int>(k);
    // The chord, and the line through both samples passing within (1 - tolerance) rs: its distance
    // squared is |d0|^2 - (d0.w)^2 / |w|^2, no nearer than the closest approach (exact for a
    // positive tolerance; without one, every pair goes on).
    m += !line_filter_ || (ww >= chord2_ * rs2 && (d0x * d0x + d0y * d0y) * ww - dw * dw < close2_ * rs2 * ww);
  }
  part.hits.clear();
  for (size_t k = 0; k < m; ++k) {
    const int i = list[survivors[k]][0], j = list[survivors[k]][1];
    // A pair with an escaped ball is judged by count_escaped() instead. The survivors passed this
    // loop's filters already: the definition decides.
    if (!is_escaped_[i] && !is_escaped_[j] && passes_through(prev, cur, i, j, radius_[i] + radius_[j], tolerance_))
      part.hits.push_back({i, j});
  }
  return static_cast<int>(part.hits.size());
}

int TunnellingCheck::count_escaped(const State& prev, const State& cur) {
  const int m = static_cast<int>(escaped_.size());
  if (m == 0) return 0;
  const double* rec = records();
  const std::vector<int>& ball = grid_.order();
  const double *sx = slots_.x.data(), *sy = slots_.y.data(), *sr = slots_.r.data();
  int count = 0;
  // Against contained balls: their references lie within c (r_e + r_j) + a of e's segment, so
  // within c (r_e + r_j) + a + |d_e| / 2 of its midpoint.
  double dmax = 0;
  for (int e : escaped_) {
    const double* r = rec + 4 * e;
    const double step = std::hypot(r[2], r[3]);  // finite for any finite step
    dmax = std::max(dmax, step);
    const double mx = r[0] + 0.5 * r[2], my = r[1] + 0.5 * r[3], re = radius_[e], slack = a_ + 0.5 * step;
    auto against = [&](int begin, int end) {
      for (int b = begin; b < end; ++b) {
        // The bound with room for rounding: at a step of 1e150 m the radii vanish in its sum.
        const double dx = mx - sx[b], dy = my - sy[b], near = (reach_ * (re + sr[b]) + slack) * (1 + 1e-9);
        const double d2 = dx * dx + dy * dy, near2 = near * near;
        if (std::isfinite(near2) ? d2 >= near2 : std::hypot(dx, dy) >= near) continue;  // too far from e's path
        const int j = ball[b];
        if (!is_escaped_[j] && judge(prev, cur, e, j, re + radius_[j])) pair_hits_.push_back({e, j}), ++count;
      }
    };
    grid_.for_each_within_range(mx, my, reach_ * (re + r_max_) + slack, against);
  }
  // Among themselves: segments that come within c (r_i + r_j) have midpoints within
  // c (r_i + r_j) + (|d_i| + |d_j|) / 2, so in adjacent cells of that size.
  if (m <= 32) {
    for (int a = 0; a < m; ++a)
      for (int b = a + 1; b < m; ++b) {
        const int i = escaped_[a], j = escaped_[b];
        if (judge(prev, cur, i, j, radius_[i] + radius_[j])) pair_hits_.push_back({i, j}), ++count;
      }
    return count;
  }
  escaped_mid_.resize(m, 2);
  for (int a = 0; a < m; ++a) {
    const double* r = rec + 4 * escaped_[a];
    escaped_mid_(a, 0) = r[0] + 0.5 * r[2], escaped_mid_(a, 1) = r[1] + 0.5 * r[3];
  }
  escaped_grid_.build(escaped_mid_, 2.0 * reach_ * r_max_ + dmax);
  escaped_grid_.for_each_candidate_pair([&](int a, int b) {
    const int i = escaped_[a], j = escaped_[b];
    if (judge(prev, cur, i, j, radius_[i] + radius_[j])) pair_hits_.push_back({i, j}), ++count;
  });
  return count;
}

}  // namespace ballbench
