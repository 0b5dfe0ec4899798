#pragma once
// Mass-normalized modal basis of a finite-element beam, truncated at f_trunc (paper eqs. 6-7).

#include <Eigen/Dense>

#include "core/beam_fe.h"

namespace shockmap {

// Columns of `shapes` are the modes in ascending frequency, with shapes^T M shapes = I, so the
// modal mass is 1 and the modal stiffness is diag(omega^2) (paper eq. 7).
struct ModalBasis {
  Eigen::VectorXd omega_rad_s;
  Eigen::MatrixXd shapes;  // model.Size() x NumModes()

  int NumModes() const { return static_cast<int>(omega_rad_s.size()); }
  double HighestFrequencyHz() const;
};

// Solves (K - omega^2 M) phi = 0 (paper eq. 6) and keeps the modes with f <= f_trunc_hz.
// Each kept mode's sign makes its largest deflection component positive.
ModalBasis ComputeModalBasis(const FeBeamModel& model, double f_trunc_hz);

// The first `n` modes regardless of frequency (all of them when n exceeds the model size).
ModalBasis ComputeLowestModes(const FeBeamModel& model, int n);

}  // namespace shockmap
