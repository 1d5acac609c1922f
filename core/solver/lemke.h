#pragma once
// Lemke's complementary pivoting for the linear complementarity problem
//   w = A lambda + b >= 0,  lambda >= 0,  lambda . w = 0
// (Cottle, Pang and Stone, "The Linear Complementarity Problem", section 4.4): exact up to
// round-off where projected Gauss-Seidel stalls (exact's cluster settling: contact normals nearly
// opposite, in wedges and arches). Plain arrays in and out; the tableau lives in caller-owned
// scratch, so a warm caller allocates nothing.
#include <vector>

namespace ballbench {

enum class LcpOutcome {
  satisfied,  // b >= 0 already: lambda = 0, left untouched
  solved,     // lambda holds the solution
  failed,     // a ray or the pivot limit: no solution found, lambda untouched
};

struct LemkeScratch {
  std::vector<double> tableau;  // m rows of [I | -A | -1 | b]
  std::vector<int> basis;       // each row's basic variable: w_k (k < m), z_k (m + k), z0 (2 m)
};

// A: m x m, row-major; b: m; lambda: m (written only when solved).
LcpOutcome solve_lcp_lemke(int m, const double* A, const double* b, double* lambda, LemkeScratch& scratch);

}  // namespace ballbench
