// Lemke's method (core/solver/lemke.h) on small LCPs solved by hand:
//   w = A lambda + b >= 0, lambda >= 0, lambda . w = 0.
#include <gtest/gtest.h>

#include "solver/lemke.h"

namespace ballbench {
namespace {

constexpr double kTol = 1e-12;

// A = [[2, 1], [1, 2]], b = (-5, -6): both contacts push, w = 0, so A lambda = -b:
// 2 l1 + l2 = 5 and l1 + 2 l2 = 6 give l1 = 4/3, l2 = 7/3.
TEST(Lemke, BothContactsActiveSolveTheLinearSystem) {
  const double A[] = {2, 1, 1, 2}, b[] = {-5, -6};
  double lambda[2] = {-1, -1};
  LemkeScratch scratch;
  ASSERT_EQ(solve_lcp_lemke(2, A, b, lambda, scratch), LcpOutcome::solved);
  EXPECT_NEAR(lambda[0], 4.0 / 3.0, kTol);
  EXPECT_NEAR(lambda[1], 7.0 / 3.0, kTol);
}

// A = [[2, 1], [1, 2]], b = (-1, 3): only the first pushes: 2 l1 - 1 = 0, l1 = 1/2, and then
// w2 = l1 + 3 = 7/2 > 0 with l2 = 0.
TEST(Lemke, OneContactActiveLeavesTheOtherAtZero) {
  const double A[] = {2, 1, 1, 2}, b[] = {-1, 3};
  double lambda[2] = {-1, -1};
  LemkeScratch scratch;
  ASSERT_EQ(solve_lcp_lemke(2, A, b, lambda, scratch), LcpOutcome::solved);
  EXPECT_NEAR(lambda[0], 0.5, kTol);
  EXPECT_EQ(lambda[1], 0.0);
}

// One ball of unit inverse mass with contact normals (1, 0), (-1, 0) and (0, 1): A = J J^T, the
// opposite pair coupled with -1. b = (-1, 2, -2): w1 = l1 - l2 - 1, w2 = -l1 + l2 + 2, w3 = l3 - 2.
// l1 = 0 leaves w1 < 0, so l1 > 0, w1 = 0, l1 = 1 + l2, w2 = 1 > 0, l2 = 0: lambda = (1, 0, 2).
TEST(Lemke, OppositeContactsOfOneBall) {
  const double A[] = {1, -1, 0, -1, 1, 0, 0, 0, 1}, b[] = {-1, 2, -2};
  double lambda[3] = {-1, -1, -1};
  LemkeScratch scratch;
  ASSERT_EQ(solve_lcp_lemke(3, A, b, lambda, scratch), LcpOutcome::solved);
  EXPECT_NEAR(lambda[0], 1.0, kTol);
  EXPECT_EQ(lambda[1], 0.0);
  EXPECT_NEAR(lambda[2], 2.0, kTol);
}

TEST(Lemke, NothingViolatedLeavesLambdaUntouched) {
  const double A[] = {2, 1, 1, 2}, b[] = {0, 1};
  double lambda[2] = {-1, -1};
  LemkeScratch scratch;
  EXPECT_EQ(solve_lcp_lemke(2, A, b, lambda, scratch), LcpOutcome::satisfied);
  EXPECT_EQ(lambda[0], -1.0);
  EXPECT_EQ(lambda[1], -1.0);
}

// w = -lambda - 1 >= 0 has no solution with lambda >= 0: Lemke ends on a ray.
TEST(Lemke, InfeasibleProblemFails) {
  const double A[] = {-1}, b[] = {-1};
  double lambda[1] = {-1};
  LemkeScratch scratch;
  EXPECT_EQ(solve_lcp_lemke(1, A, b, lambda, scratch), LcpOutcome::failed);
  EXPECT_EQ(lambda[0], -1.0);
}

}  // namespace
}  // namespace ballbench
