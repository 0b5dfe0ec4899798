#pragma once
// The sparse Cholesky factorization of a symmetric matrix by CHOLMOD (SuiteSparse) with its
// fill-reducing ordering (METIS or AMD, whichever fills less): P A P^T = L L^T, supernodal, of a
// positive definite A (a 3D solid's stiffness, whose dense fronts it works on with BLAS), or
// P A P^T = L D L^T, simplicial and without pivoting, of an indefinite one whose inertia is
// wanted (docs/structures.md "Modes").

#include <Eigen/SparseCore>
#include <memory>

namespace shockmap {

class SparseCholesky {
 public:
  enum class Form { kLlt, kLdlt };

  // Factorizes A (both triangles stored; only the upper one is read). Never throws on a matrix
  // it cannot factorize (not positive definite for kLlt, a zero pivot for kLdlt): Succeeded() is
  // then false.
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& a, Form form = Form::kLlt);
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  int Size() const;
  bool Succeeded() const;
  // The row of A whose pivot stopped the factorization; -1 when it succeeded.
  int FailedRow() const;
  // Each pivot at its row of A: diag(L) for kLlt (the square root of the row's Schur
  // complement), diag(D) for kLdlt (the complement itself); NaN at the rows a failed
  // factorization did not reach.
  Eigen::VectorXd PivotsByRow() const;

  // A^-1 rhs, column by column.
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const;
  // For kLlt: L^-1 P x, and P^T L^-T x, the two halves of A^-1 = (P^T L^-T)(L^-1 P).
  Eigen::MatrixXd SolveLowerPermuted(const Eigen::MatrixXd& x) const;
  Eigen::MatrixXd SolveUpperPermuted(const Eigen::MatrixXd& x) const;

 private:
  struct Factor;  // CHOLMOD's workspace and factor
  Form form_ = Form::kLlt;
  std::unique_ptr<Factor> factor_;
};

}  // namespace shockmap
