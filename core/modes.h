#pragma once
// A set of mass-normalized modes (paper eqs. 6-7) and the sign convention of their shapes: what
// every modal solve returns (core/modal_basis.h for a beam's truncation, core/shift_invert_modes.h
// for its lowest modes in flexibility form).

#include <Eigen/Dense>

namespace shockmap {

// Columns of `shapes` are the modes in ascending frequency, with shapes^T M shapes = I, so the
// modal mass is 1 and the modal stiffness is diag(omega^2) (paper eq. 7).
struct ModalBasis {
  Eigen::VectorXd omega_rad_s;
  Eigen::MatrixXd shapes;  // model.Size() x NumModes()

  int NumModes() const { return static_cast<int>(omega_rad_s.size()); }
  double HighestFrequencyHz() const;
};

// Flips each column's sign so that its largest component is positive.
void NormalizeModeSigns(Eigen::MatrixXd& shapes);

}  // namespace shockmap
