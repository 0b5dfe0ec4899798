// core/sparse_cholesky.h against dense algebra on matrices whose factors are known.

#include "core/sparse_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

namespace shockmap {
namespace {

// The stiffness of n springs of stiffness k in a chain fixed at one end, plus a coupling
// between the ends that makes the ordering permute: symmetric positive definite.
Eigen::SparseMatrix<double> ChainWithCoupling(int n, double k) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    a(i, i) += k;
    if (i + 1 < n) {
      a(i, i) += k;
      a(i + 1, i) = a(i, i + 1) = -k;
    }
  }
  a(0, n - 1) = a(n - 1, 0) = 0.1 * k;
  return a.sparseView();
}

TEST(SparseCholesky, SolvesToRoundOffAndItsHalvesComposeTheInverse) {
  const int n = 60;
  const Eigen::SparseMatrix<double> a = ChainWithCoupling(n, 3e6);
  const SparseCholesky factor(a);
  ASSERT_TRUE(factor.Succeeded());
  EXPECT_EQ(factor.Size(), n);
  const Eigen::MatrixXd rhs = Eigen::MatrixXd::Random(n, 3);
  const Eigen::MatrixXd x = factor.Solve(rhs);
  const Eigen::MatrixXd dense_x = Eigen::MatrixXd(a).llt().solve(rhs);
  EXPECT_LT((x - dense_x).norm(), 1e-12 * dense_x.norm());
  // A^-1 = (P^T L^-T)(L^-1 P), and L^-1 P A P^T L^-T = I.
  EXPECT_LT((factor.SolveUpperPermuted(factor.SolveLowerPermuted(rhs)) - dense_x).norm(),
            1e-12 * dense_x.norm());
  const Eigen::MatrixXd identity = factor.SolveLowerPermuted(
      Eigen::MatrixXd(a) * factor.SolveUpperPermuted(Eigen::MatrixXd::Identity(n, n)));
  EXPECT_LT((identity - Eigen::MatrixXd::Identity(n, n)).norm(), 1e-10);
}

// An arrow matrix: row 0 couples to every other. A fill-reducing ordering eliminates it last,
// so row i >= 1 keeps its pivot sqrt(d_i) and row 0 gets sqrt(a_00 - sum 1 / d_i): each pivot
// must come back at its own row through the permutation.
TEST(SparseCholesky, PivotsAreReturnedAtTheirRows) {
  const int n = 40;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd expected(n);
  a(0, 0) = 2.0 * n;
  double schur = a(0, 0);
  for (int i = 1; i < n; ++i) {
    a(i, i) = 1.0 + i;
    a(0, i) = a(i, 0) = 1.0;
    expected[i] = std::sqrt(a(i, i));
    schur -= 1.0 / a(i, i);
  }
  expected[0] = std::sqrt(schur);
  const SparseCholesky factor(Eigen::SparseMatrix<double>(a.sparseView()));
  ASSERT_TRUE(factor.Succeeded());
  EXPECT_LT((factor.PivotsByRow() - expected).norm(), 1e-13 * expected.norm());
}

// Eigenvalues -1 and 3: the factorization breaks down and says so, without throwing.
TEST(SparseCholesky, AnIndefiniteMatrixIsReportedNotFactorized) {
  Eigen::MatrixXd a(2, 2);
  a << 1.0, 2.0, 2.0, 1.0;
  EXPECT_FALSE(SparseCholesky(Eigen::SparseMatrix<double>(a.sparseView())).Succeeded());
  // Only row 1 is negative: whatever the ordering, it is the row that stops L L^T.
  a << 1.0, 0.0, 0.0, -1.0;
  const SparseCholesky stopped(Eigen::SparseMatrix<double>(a.sparseView()));
  EXPECT_FALSE(stopped.Succeeded());
  EXPECT_EQ(stopped.FailedRow(), 1);
  EXPECT_TRUE(std::isnan(stopped.PivotsByRow()[1]));
}

// L D L^T of tridiag(-1, 2, -1) - sigma I: as many negative pivots as eigenvalues
// 2 - 2 cos(k pi / (n + 1)) below sigma (Sylvester's law of inertia).
TEST(SparseCholesky, LdltPivotsCountTheEigenvaluesBelowTheShift) {
  const int n = 50;
  for (const double sigma : {0.01, 0.5, 1.3, 2.05, 3.9}) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {
      a(i, i) = 2.0 - sigma;
      if (i + 1 < n) a(i + 1, i) = a(i, i + 1) = -1.0;
    }
    int below = 0;
    for (int k = 1; k <= n; ++k) below += 2.0 - 2.0 * std::cos(k * M_PI / (n + 1)) < sigma;
    const SparseCholesky factor(Eigen::SparseMatrix<double>(a.sparseView()),
                                SparseCholesky::Form::kLdlt);
    ASSERT_TRUE(factor.Succeeded()) << "sigma " << sigma;
    EXPECT_EQ((factor.PivotsByRow().array() < 0.0).count(), below) << "sigma " << sigma;
    EXPECT_GT(below, 0);
  }
}

}  // namespace
}  // namespace shockmap
