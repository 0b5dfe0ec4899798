#include "reference/rotating_modal_sum.h"

#include <cmath>

namespace shockmap {
namespace {

constexpr Eigen::Index kLanes = 4;

Eigen::ArrayXd Padded(const Eigen::VectorXd& v) {
  Eigen::ArrayXd p = Eigen::ArrayXd::Zero((v.size() + kLanes - 1) / kLanes * kLanes);
  p.head(v.size()) = v.array();
  return p;
}

// Returns sum_i re_i, then sets z_i = z_i r_i; n is a multiple of kLanes. Lane l sums the modes
// i = l mod kLanes, so that the AVX2 clone and the default one (SSE2) perform the same
// operations in the same order; neither may contract into fused multiply-adds, which AVX2
// alone does not offer.
__attribute__((target_clones("avx2", "default"))) double SumThenRotate(
    double* __restrict re, double* __restrict im, const double* __restrict rotation_re,
    const double* __restrict rotation_im, Eigen::Index n) {
  double lane_sum[kLanes] = {0.0, 0.0, 0.0, 0.0};
  for (Eigen::Index i = 0; i < n; i += kLanes) {
    for (Eigen::Index l = 0; l < kLanes; ++l) {
      const double a = re[i + l], b = im[i + l];
      lane_sum[l] += a;
      re[i + l] = a * rotation_re[i + l] - b * rotation_im[i + l];
      im[i + l] = a * rotation_im[i + l] + b * rotation_re[i + l];
    }
  }
  return (lane_sum[0] + lane_sum[1]) + (lane_sum[2] + lane_sum[3]);
}

}  // namespace

RotatingModalSum::RotatingModalSum(const Eigen::VectorXd& omega_rad_s, double decay_per_s,
                                   double step_s)
    : omega_(Padded(omega_rad_s)), decay_per_s_(decay_per_s), step_s_(step_s) {
  const double shrink = std::exp(-decay_per_s * step_s);
  rotation_re_ = shrink * (omega_ * step_s).cos();
  rotation_im_ = shrink * (omega_ * step_s).sin();
}

void RotatingModalSum::Start(const Eigen::VectorXd& cos_weight, const Eigen::VectorXd& sin_weight,
                             double tau0_s) {
  weight_re_ = Padded(cos_weight);
  weight_im_ = -Padded(sin_weight);
  tau0_s_ = tau0_s;
  k_ = 0;
  Anchor();
}

void RotatingModalSum::Anchor() {
  const double tau = tau0_s_ + static_cast<double>(k_) * step_s_;
  const double decay = std::exp(-decay_per_s_ * tau);
  z_re_.resize(omega_.size());
  z_im_.resize(omega_.size());
  for (Eigen::Index i = 0; i < omega_.size(); ++i) {
    const double w = omega_[i] * tau;
    const double c = std::cos(w), s = std::sin(w);  // One sincos.
    z_re_[i] = decay * (weight_re_[i] * c - weight_im_[i] * s);
    z_im_[i] = decay * (weight_re_[i] * s + weight_im_[i] * c);
  }
}

void RotatingModalSum::Skip(long samples) {
  k_ += samples;
  Anchor();
}

double RotatingModalSum::Next() {
  const double u = SumThenRotate(z_re_.data(), z_im_.data(), rotation_re_.data(),
                                 rotation_im_.data(), z_re_.size());
  if (++k_ % kAnchorEvery == 0) Anchor();
  return u;
}

}  // namespace shockmap
