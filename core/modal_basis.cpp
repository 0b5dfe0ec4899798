#include "core/modal_basis.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace shockmap {
namespace {

// Each mode's sign makes its largest component positive.
void NormalizeSigns(Eigen::MatrixXd& shapes) {
  for (int j = 0; j < shapes.cols(); ++j) {
    Eigen::Index at = 0;
    shapes.col(j).cwiseAbs().maxCoeff(&at);
    if (shapes(at, j) < 0.0) shapes.col(j) *= -1.0;
  }
}

// All eigenpairs of the generalized symmetric problem, ascending; eigenvectors M-normalized.
ModalBasis AllModes(const FeBeamModel& model) {
  const Eigen::MatrixXd k = model.stiffness;
  const Eigen::MatrixXd m = model.mass;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k, m);
  ModalBasis basis;
  basis.omega_rad_s = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  basis.shapes = solver.eigenvectors();
  NormalizeSigns(basis.shapes);
  return basis;
}

}  // namespace

double ModalBasis::HighestFrequencyHz() const {
  return NumModes() == 0 ? 0.0 : omega_rad_s[NumModes() - 1] / (2.0 * std::numbers::pi);
}

EigenCost DenseEigenCost(int unknowns) {
  const double n = unknowns;
  return {4.0 * n * n * sizeof(double), 10.0 * n * n * n};
}

std::string EigenBudgetExcess(const std::vector<int>& unknowns, int solves_each) {
  const double budget = DenseEigenCost(BeamUnknowns(kEigenBudgetElements)).flops;
  EigenCost total;
  for (int n : unknowns) {
    const EigenCost one = DenseEigenCost(n);
    total.bytes = std::max(total.bytes, one.bytes);  // Solved one after the other.
    total.flops += solves_each * one.flops;
  }
  if (total.flops <= budget) return "";
  char text[200];
  std::snprintf(text, sizeof text,
                "the modal bases would need about %.2g GB and %.2g flops; at most %.2g flops "
                "(one eigenproblem of a %d-element beam) are allowed",
                total.bytes / 1e9, total.flops, budget, kEigenBudgetElements);
  return text;
}

ModalBasis ComputeModalBasis(const FeBeamModel& model, double f_trunc_hz) {
  return ModesBelow(AllModes(model), f_trunc_hz);
}

ModalBasis ComputeLowestModes(const FeBeamModel& model, int n) {
  ModalBasis all = AllModes(model);
  if (n >= all.NumModes()) return all;  // Moved, not copied.
  return FirstModes(all, n);
}

ModalBasis ModesBelow(const ModalBasis& basis, double f_trunc_hz) {
  const double omega_trunc = 2.0 * std::numbers::pi * f_trunc_hz;
  int n = 0;
  while (n < basis.NumModes() && basis.omega_rad_s[n] <= omega_trunc) ++n;
  return FirstModes(basis, n);
}

ModalBasis FirstModes(const ModalBasis& basis, int n) {
  const int kept = std::min(n, basis.NumModes());
  return {basis.omega_rad_s.head(kept), basis.shapes.leftCols(kept)};
}

}  // namespace shockmap

namespace shockmap {

ModalBasis WithStaticCorrection(const FeBeamModel& model, const ModalBasis& basis,
                                const std::vector<Eigen::VectorXd>& force_rows) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> k(model.stiffness);
  std::vector<Eigen::VectorXd> columns;
  for (int j = 0; j < basis.NumModes(); ++j) columns.push_back(basis.shapes.col(j));
  for (const Eigen::VectorXd& row : force_rows) {
    Eigen::VectorXd psi = k.solve(row);
    const double initial = std::sqrt(psi.dot(model.mass * psi));
    // Mass-orthogonal to every column so far (twice: classical Gram-Schmidt loses it once).
    for (int pass = 0; pass < 2; ++pass) {
      for (const Eigen::VectorXd& c : columns) psi -= c.dot(model.mass * psi) * c;
    }
    const double left = std::sqrt(psi.dot(model.mass * psi));
    if (!(left > 1e-8 * initial)) continue;
    columns.push_back(psi / left);
  }
  Eigen::MatrixXd t(model.Size(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) t.col(static_cast<Eigen::Index>(j)) = columns[j];
  // t is mass-orthonormal, so the reduced problem is a standard symmetric one.
  const Eigen::MatrixXd reduced = t.transpose() * (model.stiffness * t);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (reduced + reduced.transpose()));
  ModalBasis enriched;
  enriched.omega_rad_s = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  enriched.shapes = t * solver.eigenvectors();
  NormalizeSigns(enriched.shapes);
  return enriched;
}

}  // namespace shockmap
