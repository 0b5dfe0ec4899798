#include "reference/rotating_modal_sum.h"

#include <cmath>
#include <cstring>

namespace shockmap {
namespace {

constexpr Eigen::Index kLanes = 4;

Eigen::ArrayXd Padded(const Eigen::VectorXd& v) {
  Eigen::ArrayXd p = Eigen::ArrayXd::Zero((v.size() + kLanes - 1) / kLanes * kLanes);
  p.head(v.size()) = v.array();
  return p;
}

// kLanes doubles side by side (GCC and Clang vector extension: lane-wise IEEE arithmetic, two
// SSE2 instructions where the target has no 256-bit register).
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));

// One walk over lanes [i, i + kLanes) of its z: the lanes added to its sums, then rotated. The
// lanes are copied in and out (unaligned moves, which the arrays' cache-line alignment keeps
// within one line), and vectors pass by reference only: none crosses by value from one clone's
// target to another's.
[[gnu::always_inline]] inline void SumThenRotateLanes(double* re, double* im,
                                                      const double* rotation_re,
                                                      const double* rotation_im, Lanes& sums) {
  Lanes a, b, rr, ri;
  std::memcpy(&a, re, sizeof a);
  std::memcpy(&b, im, sizeof b);
  std::memcpy(&rr, rotation_re, sizeof rr);
  std::memcpy(&ri, rotation_im, sizeof ri);
  sums += a;
  const Lanes rotated_re = a * rr - b * ri, rotated_im = a * ri + b * rr;
  std::memcpy(re, &rotated_re, sizeof rotated_re);
  std::memcpy(im, &rotated_im, sizeof rotated_im);
}

// The lanes' sums folded in pairs.
[[gnu::always_inline]] inline double Fold(const Lanes& sums) {
  return (sums[0] + sums[1]) + (sums[2] + sums[3]);
}

// Returns sum_i re_i, then sets z_i = z_i r_i; n is a multiple of kLanes. Lane l sums the modes
// i = l mod kLanes, so that the AVX2 clone and the default one (SSE2) perform the same
// operations in the same order; neither may contract into fused multiply-adds, which AVX2
// alone does not offer.
__attribute__((target_clones("avx2", "default"))) double SumThenRotate(
    double* __restrict re, double* __restrict im, const double* __restrict rotation_re,
    const double* __restrict rotation_im, Eigen::Index n) {
  Lanes sums{};
  for (Eigen::Index i = 0; i < n; i += kLanes) {
    SumThenRotateLanes(re + i, im + i, rotation_re + i, rotation_im + i, sums);
  }
  return Fold(sums);
}

// SumThenRotate of two walks on the same rotations, side by side: each walk's sums and
// rotation are SumThenRotate's, so each result is equal bit for bit; two independent chains of
// additions instead of one (a single walk waits on its own sums' latency).
__attribute__((target_clones("avx2", "default"))) void SumThenRotateTwo(
    double* __restrict re_a, double* __restrict im_a, double* __restrict re_b,
    double* __restrict im_b, const double* __restrict rotation_re,
    const double* __restrict rotation_im, Eigen::Index n, double& sum_a, double& sum_b) {
  Lanes sums_a{}, sums_b{};
  for (Eigen::Index i = 0; i < n; i += kLanes) {
    SumThenRotateLanes(re_a + i, im_a + i, rotation_re + i, rotation_im + i, sums_a);
    SumThenRotateLanes(re_b + i, im_b + i, rotation_re + i, rotation_im + i, sums_b);
  }
  sum_a = Fold(sums_a);
  sum_b = Fold(sums_b);
}

}  // namespace

RotatingModalSum::RotatingModalSum(const Eigen::VectorXd& omega_rad_s, double decay_per_s,
                                   double step_s)
    : omega_(Padded(omega_rad_s)), decay_per_s_(decay_per_s), step_s_(step_s) {
  const double shrink = std::exp(-decay_per_s * step_s);
  const Eigen::ArrayXd re = shrink * (omega_ * step_s).cos();
  const Eigen::ArrayXd im = shrink * (omega_ * step_s).sin();
  rotation_re_.assign(re.begin(), re.end());
  rotation_im_.assign(im.begin(), im.end());
}

void RotatingModalSum::Start(const Eigen::VectorXd& cos_weight, const Eigen::VectorXd& sin_weight,
                             double tau0_s) {
  weight_re_ = Padded(cos_weight);
  weight_im_ = -Padded(sin_weight);
  tau0_s_ = tau0_s;
  k_ = 0;
  Anchor();
}

void RotatingModalSum::Anchor() { AnchorAt(k_, z_re_, z_im_); }

void RotatingModalSum::AnchorAt(long k, Lanes& re, Lanes& im) const {
  const double tau = tau0_s_ + static_cast<double>(k) * step_s_;
  const double decay = std::exp(-decay_per_s_ * tau);
  re.resize(static_cast<std::size_t>(omega_.size()));
  im.resize(static_cast<std::size_t>(omega_.size()));
  for (Eigen::Index i = 0; i < omega_.size(); ++i) {
    const double w = omega_[i] * tau;
    const double c = std::cos(w), s = std::sin(w);  // One sincos.
    re[static_cast<std::size_t>(i)] = decay * (weight_re_[i] * c - weight_im_[i] * s);
    im[static_cast<std::size_t>(i)] = decay * (weight_re_[i] * s + weight_im_[i] * c);
  }
}

void RotatingModalSum::Skip(long samples) {
  k_ += samples;
  Anchor();
}

double RotatingModalSum::Next() {
  const double u = SumThenRotate(z_re_.data(), z_im_.data(), rotation_re_.data(),
                                 rotation_im_.data(), omega_.size());
  if (++k_ % kAnchorEvery == 0) Anchor();
  return u;
}

void RotatingModalSum::NextInto(double* out, long count) {
  // Singly up to the next anchor, then pairs of anchored blocks side by side: the walk reaches
  // a block's first sample as AnchorAt sets it, so a block needs nothing of the one before.
  long done = 0;
  for (; done < count && k_ % kAnchorEvery != 0; ++done) out[done] = Next();
  for (; count - done >= 2 * kAnchorEvery; done += 2 * kAnchorEvery) {
    AnchorAt(k_ + kAnchorEvery, second_re_, second_im_);
    for (long j = 0; j < kAnchorEvery; ++j) {
      SumThenRotateTwo(z_re_.data(), z_im_.data(), second_re_.data(), second_im_.data(),
                       rotation_re_.data(), rotation_im_.data(), omega_.size(), out[done + j],
                       out[done + kAnchorEvery + j]);
    }
    k_ += 2 * kAnchorEvery;
    Anchor();
  }
  for (; done < count; ++done) out[done] = Next();
}

}  // namespace shockmap
