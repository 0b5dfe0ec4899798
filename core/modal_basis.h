#pragma once
// Mass-normalized modal basis of a finite-element beam, truncated at f_trunc (paper eqs. 6-7).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "core/beam_fe.h"
#include "core/modes.h"

namespace shockmap {

// Solves (K - omega^2 M) phi = 0 (paper eq. 6) and keeps the modes with f <= f_trunc_hz.
// Each kept mode's sign makes its largest deflection component positive. Every mode's
// frequency is within about 1e-14 of the exact eigenvalue of the mesh (docs/physics.md §3): a
// dense solve gives each omega^2 to about eps omega_max^2, so the modes below
// kFlexibilityFormRatio omega_max are solved again in flexibility form
// (LowestModesShiftInvert), the others made mass-orthogonal to them, and every omega^2 taken
// as its shape's Rayleigh quotient in StiffnessForm.
ModalBasis ComputeModalBasis(const FeBeamModel& model, double f_trunc_hz);

// Modes below this share of the highest frequency are solved in flexibility form: the dense
// solve's shapes are accurate above it (their omega^2 error eps (omega_max / omega)^2 is
// 1e-10 there).
inline constexpr double kFlexibilityFormRatio = 1e-3;

// The first `n` modes regardless of frequency (all of them when n exceeds the model size).
ModalBasis ComputeLowestModes(const FeBeamModel& model, int n);

// The same selections from a basis already solved for (one eigensolution serving several):
// the modes with f <= f_trunc_hz, and the first n (all of them when n exceeds its size).
// Only the kept modes are copied.
ModalBasis ModesBelow(const ModalBasis& basis, double f_trunc_hz);
ModalBasis FirstModes(const ModalBasis& basis, int n);

// What the dense generalized eigenproblem behind ComputeModalBasis and ComputeLowestModes costs
// on a model of `unknowns` unknowns: about four unknowns^2 matrices of doubles held at once and
// 10 unknowns^3 flops (measured on one core: 3000 unknowns, 250 MB and 30 s).
struct EigenCost {
  double bytes = 0.0;
  double flops = 0.0;
};
EigenCost DenseEigenCost(int unknowns);

// Unknowns of a beam of `n_elements` elements before its ends remove any: an upper bound.
inline int BeamUnknowns(int n_elements) { return 2 * n_elements + 2; }

// Elements of the largest beam whose one eigenproblem a run may solve: the budget of a run (a
// comparison, or all the distinct bases of a scene) is that problem's cost, under a minute on
// one core and a few hundred MB.
inline constexpr int kEigenBudgetElements = 1500;

// Empty when solving `solves_each` eigenproblems on each model of `unknowns` fits the budget;
// otherwise the estimate against the budget, e.g. "the modal bases would need about 1.2 GB and
// 2.2e+12 flops; at most 2.7e+11 flops (one eigenproblem of a 1500-element beam) are allowed".
std::string EigenBudgetExcess(const std::vector<int>& unknowns, int solves_each);

// Static correction (code_aster's ENRI_STAT): adds to `basis` the static deflections K^-1 r
// under a unit force along each of `force_rows` (e.g. DeflectionRow at the contact heights),
// then diagonalizes again, so that the result is still mass-orthonormal and stiffness-orthogonal
// with its modes below the truncation unchanged, and reproduces exactly the static response to
// forces at those points. Deflections the basis already spans (to 1e-8) add nothing.
// Precondition: the beam is supported (K nonsingular).
ModalBasis WithStaticCorrection(const FeBeamModel& model, const ModalBasis& basis,
                                const std::vector<Eigen::VectorXd>& force_rows);
// The same for any model of stiffness K (nonsingular) and mass M (an FE structure's).
ModalBasis WithStaticCorrection(const Eigen::SparseMatrix<double>& stiffness,
                                const Eigen::SparseMatrix<double>& mass, const ModalBasis& basis,
                                const std::vector<Eigen::VectorXd>& force_rows);

}  // namespace shockmap
