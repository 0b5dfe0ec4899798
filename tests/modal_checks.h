#pragma once
// Checks a modal basis must pass whatever the mesh: Phi^T M Phi = I and Phi^T K Phi =
// diag(omega^2).

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/beam_fe.h"
#include "core/modal_basis.h"

namespace shockmap::testing {

// The basis `all` of every mode of `fe` is mass-orthonormal and diagonalizes the stiffness,
// each to 1e-10 (the stiffness relative to the largest omega^2).
inline void ExpectMassOrthonormalAndDiagonalizing(const FeBeamModel& fe, const ModalBasis& all) {
  const Eigen::MatrixXd m = fe.mass;
  const Eigen::MatrixXd k = fe.stiffness;
  const Eigen::MatrixXd modal_mass = all.shapes.transpose() * m * all.shapes;
  EXPECT_LT((modal_mass - Eigen::MatrixXd::Identity(fe.Size(), fe.Size())).cwiseAbs().maxCoeff(),
            1e-10);
  const Eigen::MatrixXd modal_stiffness = all.shapes.transpose() * k * all.shapes;
  const Eigen::MatrixXd omega2 = all.omega_rad_s.array().square().matrix().asDiagonal();
  EXPECT_LT((modal_stiffness - omega2).cwiseAbs().maxCoeff() / omega2.maxCoeff(), 1e-10);
}

}  // namespace shockmap::testing
