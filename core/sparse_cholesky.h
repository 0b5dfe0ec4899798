#pragma once
// The supernodal sparse Cholesky factorization P A P^T = L L^T of a symmetric positive definite
// matrix, by CHOLMOD (SuiteSparse) with its fill-reducing ordering (METIS or AMD, whichever
// fills less): the factor of a 3D solid's stiffness, whose dense fronts it works on with BLAS
// (docs/structures.md "Modes").

#include <Eigen/SparseCore>
#include <memory>

namespace shockmap {

class SparseCholesky {
 public:
  // Factorizes A (both triangles stored; only the upper one is read). Never throws on a matrix
  // that is not positive definite: Succeeded() is then false.
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& a);
  ~SparseCholesky();
  SparseCholesky(SparseCholesky&&) noexcept;
  SparseCholesky& operator=(SparseCholesky&&) noexcept;

  int Size() const { return size_; }
  // False when a pivot was not positive (A not positive definite to the factorization's eyes).
  bool Succeeded() const;
  // diag(L) with each entry at its row of A: L's pivot of that row, sqrt of its Schur complement.
  Eigen::VectorXd PivotsByRow() const;

  // A^-1 rhs, column by column.
  Eigen::MatrixXd Solve(const Eigen::MatrixXd& rhs) const;
  // L^-1 P x, and P^T L^-T x: the two halves of A^-1 = (P^T L^-T)(L^-1 P).
  Eigen::MatrixXd SolveLowerPermuted(const Eigen::MatrixXd& x) const;
  Eigen::MatrixXd SolveUpperPermuted(const Eigen::MatrixXd& x) const;

 private:
  struct Factor;  // CHOLMOD's workspace and factor
  int size_ = 0;
  std::unique_ptr<Factor> factor_;
};

}  // namespace shockmap
