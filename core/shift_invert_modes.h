#pragma once
// The lowest modes of a finite-element beam in flexibility form (docs/physics.md §3): Lanczos on
// (K - sigma M)^-1 M (Spectra's shift-invert solver), the factorization of K - sigma M in long
// double. A dense solve of K phi = omega^2 M phi is accurate to about eps omega_max^2 in every
// omega^2, so it loses the lowest modes' shapes as the mesh grows (omega_1 off by 2.5e-3 at
// 1500 elements); these shapes are accurate, and their Ritz values to about
// eps_long_double cond(K) (1e-8 at 1500 elements; ComputeModalBasis takes each omega^2 from the
// shape's Rayleigh quotient in StiffnessForm instead, to about 1e-15).

#include "core/beam_fe.h"
#include "core/modes.h"

namespace shockmap {

// The `count` lowest modes, ascending, mass-normalized, each signed as ModalBasis says.
// `shift` (rad^2/s^2) must lie below the lowest eigenvalue, e.g. minus half of it, so that
// K - shift M is positive definite even for a beam with rigid-body modes.
// Preconditions: 1 <= count < model.Size() - 1.
ModalBasis LowestModesShiftInvert(const FeBeamModel& model, int count, double shift);

}  // namespace shockmap
