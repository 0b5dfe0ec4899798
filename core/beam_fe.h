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
  // Grounded springs on deflections (AddDeflectionSpring), already in `stiffness`.
  struct Spring {
    int unknown = 0;
    double stiffness_n_per_m = 0.0;
  };
  std::vector<Spring> springs;

  int Size() const { return static_cast<int>(global_dof.size()); }
  // Row r with r . u = deflection at abscissa x (m), from the Hermite shape functions.
  // Precondition: 0 <= x <= L.
  Eigen::VectorXd DeflectionRow(double x_m) const;
};

FeBeamModel AssembleBeam(const BeamProperties& beam, int n_elements, EndCondition at_zero,
                         EndCondition at_length);

// Adds a grounded spring of stiffness k (N/m) on the deflection of `node`, when k != 0 and the
// deflection is not constrained.
void AddDeflectionSpring(FeBeamModel& model, int node, double k_n_per_m);

// u^T K u, summed element by element in the chord-relative rotations a = theta_1 - psi,
// c = theta_2 - psi (psi = (w_2 - w_1) / h) as (EI / h)(3 (a + c)^2 + (a - c)^2), plus the
// springs' k w^2: a sum of non-negative terms, accurate to about eps n_elements^2 where the
// assembled product loses eps |K| |u| to cancellation (the lowest modes of a fine mesh).
double StiffnessForm(const FeBeamModel& model, const Eigen::VectorXd& u);

}  // namespace shockmap
