#include "core/modal_basis.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "core/shift_invert_modes.h"

namespace shockmap {
namespace {

// The lowest of `lambda` (ascending) above the round-off of a dense solve whose largest value is
// lambda_max, i.e. the first elastic eigenvalue when a beam has rigid-body modes; 0 when none.
double LowestElasticEigenvalue(const Eigen::VectorXd& lambda, double lambda_max) {
  const double noise = 10.0 * std::numeric_limits<double>::epsilon() * lambda_max;
  for (double l : lambda) {
    if (l > noise) return l;
  }
  return 0.0;
}

// The lowest `count` modes in flexibility form, shifted by minus half the lowest elastic
// eigenvalue so that rigid-body modes are found too and an elastic lambda = 1 / theta + shift
// keeps its digits. The dense estimate of that eigenvalue can be off by more than itself on a
// fine mesh: the solve is repeated with the shift its own result gives when that is smaller.
ModalBasis LowModesInFlexibilityForm(const FeBeamModel& model, int count, double dense_lowest,
                                     double lambda_max) {
  double shift = -0.5 * dense_lowest;
  ModalBasis low = LowestModesShiftInvert(model, count, shift);
  const double lowest = LowestElasticEigenvalue(low.omega_rad_s.array().square(), lambda_max);
  if (lowest > 0.0 && -shift > 0.5 * lowest * (1.0 + 1e-3)) {
    low = LowestModesShiftInvert(model, count, -0.5 * lowest);
  }
  return low;
}

// Replaces the first `low.NumModes()` modes of `all` by `low` and makes the others
// mass-orthonormal to them (their error along the low modes is that of the dense solve).
void SpliceLowModes(const FeBeamModel& model, const ModalBasis& low, ModalBasis& all) {
  const int k = low.NumModes();
  all.omega_rad_s.head(k) = low.omega_rad_s;
  all.shapes.leftCols(k) = low.shapes;
  const Eigen::MatrixXd m_low = model.mass * low.shapes;
  for (int j = k; j < all.NumModes(); ++j) {
    Eigen::VectorXd v = all.shapes.col(j);
    v -= low.shapes * (m_low.transpose() * v);
    all.shapes.col(j) = v / std::sqrt(v.dot(model.mass * v));
  }
}

// Each omega^2 as its shape's Rayleigh quotient in StiffnessForm: second order in the shape's
// error, and free of the cancellation of the assembled product.
void SetRayleighQuotients(const FeBeamModel& model, ModalBasis& basis) {
  for (int j = 0; j < basis.NumModes(); ++j) {
    const Eigen::VectorXd phi = basis.shapes.col(j);
    basis.omega_rad_s[j] = std::sqrt(StiffnessForm(model, phi) / phi.dot(model.mass * phi));
  }
}

// All eigenpairs of the generalized symmetric problem, ascending; eigenvectors M-normalized;
// the modes below kFlexibilityFormRatio omega_max from the flexibility form.
ModalBasis AllModes(const FeBeamModel& model) {
  const Eigen::MatrixXd k = model.stiffness;
  const Eigen::MatrixXd m = model.mass;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k, m);
  ModalBasis basis;
  basis.omega_rad_s = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  basis.shapes = solver.eigenvectors();
  NormalizeModeSigns(basis.shapes);
  const Eigen::VectorXd& lambda = solver.eigenvalues();
  const double split = kFlexibilityFormRatio * kFlexibilityFormRatio * lambda.maxCoeff();
  const int low = static_cast<int>((lambda.array() < split).count());
  const double lowest = LowestElasticEigenvalue(lambda, lambda.maxCoeff());
  if (low > 0 && low < model.Size() - 1 && lowest > 0.0) {
    SpliceLowModes(model, LowModesInFlexibilityForm(model, low, lowest, lambda.maxCoeff()), basis);
  }
  SetRayleighQuotients(model, basis);
  return basis;
}

}  // namespace

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
  return WithStaticCorrection(model.stiffness, model.mass, basis, force_rows);
}

ModalBasis WithStaticCorrection(const Eigen::SparseMatrix<double>& stiffness,
                                const Eigen::SparseMatrix<double>& mass, const ModalBasis& basis,
                                const std::vector<Eigen::VectorXd>& force_rows) {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> k(stiffness);
  std::vector<Eigen::VectorXd> columns;
  for (int j = 0; j < basis.NumModes(); ++j) columns.push_back(basis.shapes.col(j));
  for (const Eigen::VectorXd& row : force_rows) {
    Eigen::VectorXd psi = k.solve(row);
    const double initial = std::sqrt(psi.dot(mass * psi));
    // Mass-orthogonal to every column so far (twice: classical Gram-Schmidt loses it once).
    for (int pass = 0; pass < 2; ++pass) {
      for (const Eigen::VectorXd& c : columns) psi -= c.dot(mass * psi) * c;
    }
    const double left = std::sqrt(psi.dot(mass * psi));
    if (!(left > 1e-8 * initial)) continue;
    columns.push_back(psi / left);
  }
  Eigen::MatrixXd t(stiffness.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t j = 0; j < columns.size(); ++j) t.col(static_cast<Eigen::Index>(j)) = columns[j];
  // t is mass-orthonormal, so the reduced problem is a standard symmetric one.
  const Eigen::MatrixXd reduced = t.transpose() * (stiffness * t);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (reduced + reduced.transpose()));
  ModalBasis enriched;
  enriched.omega_rad_s = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  enriched.shapes = t * solver.eigenvectors();
  NormalizeModeSigns(enriched.shapes);
  return enriched;
}

}  // namespace shockmap
