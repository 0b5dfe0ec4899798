#include "core/modal_basis.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace shockmap {
namespace {

// All eigenpairs of the generalized symmetric problem, ascending; eigenvectors M-normalized.
ModalBasis AllModes(const FeBeamModel& model) {
  const Eigen::MatrixXd k = model.stiffness;
  const Eigen::MatrixXd m = model.mass;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(k, m);
  ModalBasis basis;
  basis.omega_rad_s = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  basis.shapes = solver.eigenvectors();
  for (int j = 0; j < basis.shapes.cols(); ++j) {
    Eigen::Index at = 0;
    basis.shapes.col(j).cwiseAbs().maxCoeff(&at);
    if (basis.shapes(at, j) < 0.0) basis.shapes.col(j) *= -1.0;
  }
  return basis;
}

ModalBasis FirstColumns(ModalBasis all, int n) {
  all.omega_rad_s.conservativeResize(n);
  all.shapes.conservativeResize(Eigen::NoChange, n);
  return all;
}

}  // namespace

double ModalBasis::HighestFrequencyHz() const {
  return NumModes() == 0 ? 0.0 : omega_rad_s[NumModes() - 1] / (2.0 * std::numbers::pi);
}

ModalBasis ComputeModalBasis(const FeBeamModel& model, double f_trunc_hz) {
  ModalBasis all = AllModes(model);
  const double omega_trunc = 2.0 * std::numbers::pi * f_trunc_hz;
  int n = 0;
  while (n < all.NumModes() && all.omega_rad_s[n] <= omega_trunc) ++n;
  return FirstColumns(std::move(all), n);
}

ModalBasis ComputeLowestModes(const FeBeamModel& model, int n) {
  ModalBasis all = AllModes(model);
  const int kept = std::min(n, all.NumModes());
  return FirstColumns(std::move(all), kept);
}

}  // namespace shockmap
