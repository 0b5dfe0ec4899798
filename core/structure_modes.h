#pragma once
// Modes, static and residual flexibility of an FE structure (docs/structures.md): Lanczos
// (Spectra) on the flexibility K^-1 M in the symmetric standard form L^-1 M L^-T given by one
// sparse Cholesky factorization K = L L^T (shift-invert at zero shift), then Rayleigh-Ritz in
// the converged subspace, so that each omega^2 is a Rayleigh quotient phi^T K phi / phi^T M phi.

#include <Eigen/Dense>
#include <vector>

#include "core/fe_structure.h"
#include "core/modal_basis.h"

namespace shockmap {

// The modes of K phi = omega^2 M phi (paper eq. 6) with f <= f_trunc_hz, ascending,
// mass-normalized (phi^T M phi = I), signs as NormalizeModeSigns; repeated frequencies give a
// mass-orthonormal basis of their eigenspace (in no particular order). Their number is counted
// first by Sylvester's inertia of K - (2 pi f_trunc)^2 M (an LDL^T factorization).
// Throws InputError when K is not positive definite (the supports leave a rigid motion).
ModalBasis StructureModesBelow(const FeStructure& s, double f_trunc_hz);
// The `count` lowest modes (all the finite ones when count is larger), as above.
ModalBasis LowestStructureModes(const FeStructure& s, int count);

// The static flexibility (K^-1) restricted to the given rows (columns in the rows' order).
Eigen::MatrixXd StaticFlexibility(const FeStructure& s, const std::vector<int>& rows);
// The truncated modes' residual flexibility at those rows: (K^-1)_cc - sum phi_c phi_c^T /
// omega^2 over the modes of `basis` (what the static correction restores).
Eigen::MatrixXd ResidualFlexibility(const FeStructure& s, const ModalBasis& basis,
                                    const std::vector<int>& rows);

// The paper's K_bend at a node along a unit normal n (3D): 1 / (w^T K^-1 w) with
// w = s.NodeDirection(node, n), i.e. 1 / (n^T (K^-1)_cc n) over the node's translational DOFs (a
// missing DOF contributes nothing along its direction; copies are averaged). Throws InputError
// when the node has no free translational DOF along n.
double LocalStiffness(const FeStructure& s, int node, const Eigen::Vector3d& normal);

}  // namespace shockmap
