#include "solver/lemke.h"

#include <algorithm>
#include <cstddef>

#include "solver/contact.h"

namespace ballbench {

LcpOutcome solve_lcp_lemke(int m, const double* A, const double* b, double* lambda, LemkeScratch& scratch) {
  if (m == 0) return LcpOutcome::satisfied;
  const int cols = 2 * m + 2;  // w (m), z (m), z0, right-hand side
  std::vector<double>& tableau = scratch.tableau;
  auto T = [&](int r, int c) -> double& { return tableau[static_cast<size_t>(r) * cols + c]; };
  tableau.assign(static_cast<size_t>(m) * cols, 0.0);
  double bmin = 0;
  int r = -1;
  for (int c = 0; c < m; ++c) {
    T(c, c) = 1;
    for (int d = 0; d < m; ++d) T(c, m + d) = -A[static_cast<size_t>(c) * m + d];
    T(c, 2 * m) = -1;
    T(c, 2 * m + 1) = b[c];
    if (b[c] < bmin) bmin = b[c], r = c;
  }
  if (r < 0) return LcpOutcome::satisfied;
  std::vector<int>& basis = scratch.basis;
  basis.resize(m);
  for (int c = 0; c < m; ++c) basis[c] = c;
  auto pivot = [&](int row, int col) {
    const double p = T(row, col);
    for (int c = 0; c < cols; ++c) T(row, c) /= p;
    for (int i = 0; i < m; ++i) {
      if (i == row || T(i, col) == 0) continue;
      const double f = T(i, col);
      for (int c = 0; c < cols; ++c) T(i, c) -= f * T(row, c);
    }
    basis[row] = col;
  };
  pivot(r, 2 * m);       // z0 enters at the most violated row
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
    if (leave < 0) return LcpOutcome::failed;  // a ray
    const int left = basis[leave];
    pivot(leave, entering);
    if (left == 2 * m) {  // z0 left: complementary and feasible
      std::fill(lambda, lambda + m, 0.0);
      for (int i = 0; i < m; ++i)
        if (basis[i] >= m && basis[i] < 2 * m) lambda[basis[i] - m] = std::max(0.0, T(i, 2 * m + 1));
      return LcpOutcome::solved;
    }
    entering = left < m ? left + m : left - m;
  }
  return LcpOutcome::failed;
}

}  // namespace ballbench
