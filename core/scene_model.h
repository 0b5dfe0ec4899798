#pragma once
// Builds the modal model of a scene: one FE model and modal basis per distinct beam (shared by
// identical beams), one modal block per structure after the beams' (block-diagonal, paper eq.
// 7), the zones in modal coordinates, the declared loads, the initial state, the
// observed points and both stability bounds.

#include <memory>
#include <span>
#include <vector>

#include "core/beam_fe.h"
#include "core/scene.h"
#include "core/scene_system.h"

namespace shockmap {

struct SceneModel {
  std::unique_ptr<SceneModalSystem> system;
  Eigen::VectorXd x0, v0;
  std::vector<Eigen::VectorXd> observed_rows;  // One per requested displacement output.
  // Per direction (y, then z): row . v is the momentum of all beams relative to the base
  // (kg m/s), exact whatever the truncation when the beams are free (rigid modes kept).
  std::vector<Eigen::VectorXd> momentum_rows;
  std::vector<int> beam_offset;     // First coordinate of each beam (y, then z).
  std::vector<int> modes_per_beam;  // Per direction.
  std::vector<int> modes_per_structure;
  int distinct_bases = 0;
  StabilityBounds bounds;  // paper: 1/(4 max f_trunc); sharp: every zone closed.
};

// The make-up of one scene beam: its sections (one when uniform) and point masses.
SectionedBeam SectionsOf(const SceneBeam& beam);

// The FE model of one scene beam: its sections, point masses, elements, ends and end springs.
FeBeamModel AssembleSceneBeam(const SceneBeam& beam);

// The static stiffness of the beam at a height (N/m): the force at that height over the
// deflection it causes there, 1 / (r . K^-1 r) with r the FE deflection row; 3 EI / h^3 on a
// uniform clamped-free beam, on sections the inverse of Mohr's integral of M m / EI.
// Precondition: the beam is supported (no rigid-body mode).
double LocalBendingStiffness(const SceneBeam& beam, double height_m);

// The largest eigenvalue of the modal stiffness with every zone closed, each with the normal
// stiffness given (zone order), and the tangential springs of the zones with friction: dense
// eigenvalues up to 600 coordinates, power iteration with a 1e-3 safety margin beyond. The
// sharp bound is 2 / sqrt of it.
double SharpOmegaSquared(const SceneModalSystem& system, std::span<const double> normal_stiffness);

// Preconditions: the scene was validated (indices in range, positive properties), and it
// outlives the model (the loads refer to its effects).
SceneModel BuildSceneModel(const Scene& scene);

}  // namespace shockmap
