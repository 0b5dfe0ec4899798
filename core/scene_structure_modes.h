#pragma once
// The modal block of one FE structure in a scene (paper eq. 7, docs/scenes.md "Structures from an
// FE code"): its modes up to its truncation, enriched with static correction modes at its
// contact nodes when asked, and the rows that read or load it at a node along a direction.

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "core/fe_structure.h"
#include "core/modal_basis.h"

namespace shockmap {

struct SceneStructureModes {
  std::shared_ptr<const FeStructure> fe;
  ModalBasis basis;
  double f1_hz = 0.0;       // The structure's lowest frequency.
  double f_trunc_hz = 0.0;  // Its truncation.

  int N() const { return basis.NumModes(); }
  // Phi^T f, f = d on the node's translational DOFs (a DOF that is not free contributes
  // nothing): the node's motion along d is row . q, and a force F along d loads q with F row.
  Eigen::VectorXd AtNode(int node, const std::array<double, 3>& d) const;
  // Phi^T M r, r = d on every translational DOF and 0 on the rotations: the rigid-body
  // influence vector of a unit motion of the structure's support along d.
  Eigen::VectorXd Participation(const std::array<double, 3>& d) const;
};

// The force vector f = d on the node's translational DOFs (size s.Size()).
Eigen::VectorXd NodeForce(const FeStructure& s, int node, const std::array<double, 3>& d);

// The structure's modes below f_trunc_hz, or below ratio times its lowest frequency (exactly
// one of them given), with a static correction mode per translational DOF of each of
// `static_nodes` (code_aster's ENRI_STAT, as a beam's at its zones' heights). At least one
// mode is kept. Throws InputError when K is not positive definite (no support).
SceneStructureModes MakeStructureModes(std::shared_ptr<const FeStructure> fe,
                                       std::optional<double> f_trunc_hz, double ratio,
                                       const std::vector<int>& static_nodes);

}  // namespace shockmap
