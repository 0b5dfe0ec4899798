#pragma once
// The static equilibrium of a scene's modal model whose zones start closed (a negative gap: a
// preloaded contact, as in a bundle at the end of its life; docs/physics.md §5). Without it the
// run would start from the undeformed state with every preloaded spring compressed, and the
// preload would act as a step load at t = 0.

#include <Eigen/Dense>

#include "core/scene_system.h"

namespace shockmap {

// True when some zone of the model has a negative gap.
bool HasPreloadedZones(const SceneModalSystem& system);

// The modal state x of static equilibrium under the zones alone: with r_z the zone's row
// (n . (phi_a - phi_b) at its height, so that its penetration is r_z . x - g_z) and A the set
// of zones in contact, (diag(omega^2) + sum_{z in A} k_z r_z r_z^T) x = sum_{z in A} k_z g_z r_z,
// A starting as the zones with g_z < 0 and updated to {z : r_z . x > g_z} until it holds: Newton's
// method on the energy of the penalty springs, damped so that the energy always decreases.
// Throws InputError when the model has a rigid-body mode the contacts do not hold, or when no
// equilibrium is found within 100 steps. With linear laws on a model without rigid-body modes,
// the closed set is found by steps solved in the closed zones' space and the equilibrium then
// solved once in the modes' space: the vector PreloadEquilibriumBySparseSteps returns, bit for
// bit, at one sparse factorization instead of one per step.
Eigen::VectorXd PreloadEquilibrium(const SceneModalSystem& system);

// The same Newton's method with every step a sparse LDLT of the modes' matrix above (what
// PreloadEquilibrium does for power laws); the same exceptions.
Eigen::VectorXd PreloadEquilibriumBySparseSteps(const SceneModalSystem& system);

}  // namespace shockmap
