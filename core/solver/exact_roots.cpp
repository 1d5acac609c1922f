#include "solver/exact_roots.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace ballbench {
namespace {

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

}  // namespace

// f is split at its critical points (roots of the cubic f', themselves isolated between the roots
// of f'') into monotone pieces; the first decreasing piece that reaches zero holds the event.
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

}  // namespace ballbench
