#include "core/structure_modes.h"

#include <Spectra/SymEigsSolver.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/input_error.h"
#include "core/stiffness_cholesky.h"
#include "core/structure_factorization.h"

namespace shockmap {
namespace {

// Spectra's operator: the flexibility's symmetric standard form (StiffnessCholesky), whose
// largest eigenvalues are the lowest modes' 1 / omega^2. Lanczos on it keeps the Euclidean
// inner product, so it needs no product with M beyond the operator's own.
class FlexibilityOperator {
 public:
  using Scalar = double;
  explicit FlexibilityOperator(const StiffnessCholesky& k) : k_(k) {}
  Eigen::Index rows() const { return k_.Size(); }
  Eigen::Index cols() const { return k_.Size(); }
  void perform_op(const double* x, double* y) const { k_.ApplyFlexibilityForm(x, y); }

 private:
  const StiffnessCholesky& k_;
};

// Ritz values are converged to this relative residual; Rayleigh-Ritz then squares the error.
constexpr double kFlexibilityLanczosTolerance = 1e-12;
constexpr int kFlexibilityLanczosIterations = 1000;
// Structures this small are solved densely: Lanczos needs count < size / 2 to be worth it.
constexpr int kDenseSize = 400;
// Modes whose 1 / omega^2 is below this share of the largest are taken as the infinite
// frequencies of a singular mass (its null combinations), never as modes.
constexpr double kFiniteShare = 1e-13;

// Rayleigh-Ritz in the span of `shapes`: the best omega^2 and a mass-orthonormal basis of
// each cluster, ascending.
ModalBasis RayleighRitz(const FeStructure& s, const Eigen::MatrixXd& shapes) {
  const Eigen::MatrixXd k = shapes.transpose() * (s.stiffness * shapes);
  const Eigen::MatrixXd m = shapes.transpose() * (s.mass * shapes);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> small(
      k.selfadjointView<Eigen::Lower>(), m.selfadjointView<Eigen::Lower>());
  ModalBasis basis;
  basis.shapes = shapes * small.eigenvectors();
  NormalizeModeSigns(basis.shapes);
  basis.omega_rad_s = small.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return basis;
}

// The lowest `count` modes' shapes from the dense problem in flexibility form,
// M phi = (1 / omega^2) K phi (K positive definite, M only semi-definite), at most as many as
// M's rank: the largest 1 / omega^2, in descending order.
Eigen::MatrixXd DenseLowestShapes(const FeStructure& s, int count) {
  const Eigen::MatrixXd k(s.stiffness), m(s.mass);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> dense(m, k);
  const Eigen::VectorXd& flexibility = dense.eigenvalues();  // ascending
  const double largest = flexibility.maxCoeff();
  const int finite = static_cast<int>((flexibility.array() > kFiniteShare * largest).count());
  count = std::min(count, finite);
  return dense.eigenvectors().rightCols(count).rowwise().reverse();
}

Eigen::MatrixXd LanczosLowestShapes(const FeStructure& s, const StiffnessCholesky& k, int count) {
  FlexibilityOperator op(k);
  const int subspace = std::min(s.Size(), std::max(2 * count + 1, count + 20));
  Spectra::SymEigsSolver<FlexibilityOperator> solver(op, count, subspace);
  solver.init();
  solver.compute(Spectra::SortRule::LargestAlge, kFlexibilityLanczosIterations,
                 kFlexibilityLanczosTolerance, Spectra::SortRule::LargestAlge);
  if (solver.info() != Spectra::CompInfo::Successful) {
    throw std::runtime_error("structure '" + s.name +
                             "': the Lanczos iteration did not converge on its modes");
  }
  return k.ShapesOf(solver.eigenvectors());
}

ModalBasis LowestModes(const FeStructure& s, const StiffnessCholesky& k, int count) {
  count = std::min(count, s.Size());
  if (count <= 0) return {Eigen::VectorXd(0), Eigen::MatrixXd(s.Size(), 0)};
  const bool dense = s.Size() <= kDenseSize || 2 * count + 1 > s.Size();
  if (dense && s.Size() > 4 * kDenseSize) {
    throw InputError("structure '" + s.name + "': " + std::to_string(count) + " modes of its " +
                     std::to_string(s.Size()) +
                     " DOFs are too many: at most half its DOFs may be asked for");
  }
  return RayleighRitz(s, dense ? DenseLowestShapes(s, count) : LanczosLowestShapes(s, k, count));
}

double Omega2(double f_hz) { return std::pow(2.0 * std::numbers::pi * f_hz, 2); }

}  // namespace

ModalBasis LowestStructureModes(const FeStructure& s, int count) {
  return LowestModes(s, StiffnessCholesky(s), count);
}

ModalBasis StructureModesBelow(const FeStructure& s, double f_trunc_hz) {
  const StiffnessCholesky stiffness(s);
  const int count = ShiftedFactorization(s, Omega2(f_trunc_hz)).NegativePivots();
  return ModesBelow(LowestModes(s, stiffness, count), f_trunc_hz);
}

Eigen::MatrixXd StaticFlexibility(const FeStructure& s, const std::vector<int>& rows) {
  const StiffnessCholesky factor(s);
  Eigen::MatrixXd flexibility(rows.size(), rows.size());
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const Eigen::VectorXd column = factor.Solve(Eigen::VectorXd::Unit(s.Size(), rows[j]));
    for (std::size_t i = 0; i < rows.size(); ++i) flexibility(i, j) = column[rows[i]];
  }
  return flexibility;
}

Eigen::MatrixXd ResidualFlexibility(const FeStructure& s, const ModalBasis& basis,
                                    const std::vector<int>& rows) {
  Eigen::MatrixXd residual = StaticFlexibility(s, rows);
  for (int k = 0; k < basis.NumModes(); ++k) {
    Eigen::VectorXd phi(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) phi[i] = basis.shapes(rows[i], k);
    residual -= phi * phi.transpose() / std::pow(basis.omega_rad_s[k], 2);
  }
  return residual;
}

double LocalStiffness(const FeStructure& s, int node, const Eigen::Vector3d& normal) {
  assert(std::abs(normal.norm() - 1.0) < 1e-9);
  const Eigen::VectorXd w = s.NodeDirection(node, normal);
  if (w.isZero(0.0)) {
    throw InputError("structure '" + s.name + "': node " + std::to_string(node) +
                     " has no free translation along the normal");
  }
  return 1.0 / w.dot(StiffnessCholesky(s).Solve(w));
}

}  // namespace shockmap
