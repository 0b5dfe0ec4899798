#include "reference/rotating_modal_sum.h"

#include <cmath>

namespace shockmap {

RotatingModalSum::RotatingModalSum(const Eigen::VectorXd& omega_rad_s, double decay_per_s,
                                   double step_s)
    : omega_(omega_rad_s.array()), decay_per_s_(decay_per_s), step_s_(step_s) {
  const double shrink = std::exp(-decay_per_s * step_s);
  rotation_re_ = shrink * (omega_ * step_s).cos();
  rotation_im_ = shrink * (omega_ * step_s).sin();
}

void RotatingModalSum::Start(const Eigen::VectorXd& cos_weight, const Eigen::VectorXd& sin_weight,
                             double tau0_s) {
  weight_re_ = cos_weight.array();
  weight_im_ = -sin_weight.array();
  tau0_s_ = tau0_s;
  k_ = 0;
  Anchor();
}

void RotatingModalSum::Anchor() {
  const double tau = tau0_s_ + static_cast<double>(k_) * step_s_;
  const double decay = std::exp(-decay_per_s_ * tau);
  const Eigen::ArrayXd c = (omega_ * tau).cos(), s = (omega_ * tau).sin();
  z_re_ = decay * (weight_re_ * c - weight_im_ * s);
  z_im_ = decay * (weight_re_ * s + weight_im_ * c);
}

double RotatingModalSum::Next() {
  const double u = z_re_.sum();
  ++k_;
  if (k_ % kAnchorEvery == 0) {
    Anchor();
  } else {
    next_re_ = z_re_ * rotation_re_ - z_im_ * rotation_im_;
    z_im_ = z_re_ * rotation_im_ + z_im_ * rotation_re_;
    z_re_.swap(next_re_);
  }
  return u;
}

}  // namespace shockmap
