#pragma once
// Euler-Bernoulli beam finite elements: Hermite cubic deflection, consistent mass (paper eq. 4).

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

#include "core/beam_properties.h"
#include "core/end_condition.h"

namespace shockmap {

// Assembled beam with the constrained degrees of freedom removed. Nodes are equally spaced on
// [0, L]; node j carries deflection w_j (m) and rotation theta_j (rad). Unknowns are the free
// degrees of freedom in node order.
struct FeBeamModel {
  BeamProperties beam;
  int n_elements = 0;
  Eigen::SparseMatrix<double> mass;       // kg (and kg m, kg m^2 for rotational terms)
  Eigen::SparseMatrix<double> stiffness;  // N/m (and N, N m)
  std::vector<int> global_dof;            // unknown index -> global dof 2*node + {0: w, 1: theta}

  int Size() const { return static_cast<int>(global_dof.size()); }
  // Row r with r . u = deflection at abscissa x (m), from the Hermite shape functions.
  // Precondition: 0 <= x <= L.
  Eigen::VectorXd DeflectionRow(double x_m) const;
};

FeBeamModel AssembleBeam(const BeamProperties& beam, int n_elements, EndCondition at_zero,
                         EndCondition at_length);

}  // namespace shockmap
