#pragma once
// A damped modal sum sampled on a uniform grid by rotation (docs/performance.md, "References
// and study points"):
//   u(tau) = sum_i e^{-d tau} (c_i cos(omega_i tau) + s_i sin(omega_i tau)),
//   tau = tau0 + k h, k = 0, 1, 2, ...
// Each term is Re(z_i) with z_i(tau) = (c_i - j s_i) e^{(-d + j omega_i) tau}, and
// z_i(tau + h) = z_i(tau) r_i with r_i = e^{(-d + j omega_i) h}: one complex multiplication per
// mode per sample instead of a cosine and a sine, four modes per instruction where the CPU has
// AVX2 (the same operations in the same order otherwise, so the sums are equal bit for bit on
// any x86-64). Rounding grows by about one ulp per multiplication, so every kAnchorEvery
// samples z is set again from exact trigonometry at tau0 + k h: the sum stays within ~1e-13
// of the exact one relative to sum_i |c_i - j s_i|.

#include <Eigen/Dense>
#include <cstddef>
#include <new>
#include <vector>

namespace shockmap {

// Allocates on 64-byte boundaries (a cache line): the walk's four-lane loads and stores then
// never straddle two lines, which a double's or Eigen's 16-byte alignment leaves to chance.
template <typename T>
struct CacheLineAllocator {
  using value_type = T;
  static constexpr std::align_val_t kAlignment{64};
  CacheLineAllocator() = default;
  template <typename U>
  CacheLineAllocator(const CacheLineAllocator<U>&) {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlignment)); }
  void deallocate(T* p, std::size_t) { ::operator delete(p, kAlignment); }
  template <typename U>
  bool operator==(const CacheLineAllocator<U>&) const {
    return true;
  }
};

class RotatingModalSum {
 public:
  static constexpr int kAnchorEvery = 512;

  // omega_rad_s: the terms' angular frequencies; decay_per_s: d >= 0; step_s: h > 0.
  RotatingModalSum(const Eigen::VectorXd& omega_rad_s, double decay_per_s, double step_s);

  // Starts the walk at tau0_s with the weights c (of the cosines) and s (of the sines), both of
  // the size of omega_rad_s.
  void Start(const Eigen::VectorXd& cos_weight, const Eigen::VectorXd& sin_weight, double tau0_s);

  // u at the current sample; then moves to the next one.
  double Next();

  // Fills out[0 .. count) as `count` calls of Next() would, equal bit for bit, walking two
  // anchored blocks of kAnchorEvery samples side by side (two chains of additions, not one).
  void NextInto(double* out, long count);

  // Moves `samples` (>= 0) samples on without summing them: the next Next() returns u at the
  // sample that many further, set from exact trigonometry (one sine and cosine per mode).
  void Skip(long samples);

 private:
  void Anchor();
  // z at sample k from exact trigonometry, into (re, im).
  using Lanes = std::vector<double, CacheLineAllocator<double>>;
  void AnchorAt(long k, Lanes& re, Lanes& im) const;

  // Every array holds the modes, then zeros up to a multiple of four (kLanes).
  Eigen::ArrayXd omega_;
  Lanes rotation_re_, rotation_im_;
  double decay_per_s_ = 0.0, step_s_ = 0.0;
  Eigen::ArrayXd weight_re_, weight_im_;  // c_i - j s_i
  Lanes z_re_, z_im_;
  Lanes second_re_, second_im_;  // NextInto's second block.
  double tau0_s_ = 0.0;
  long k_ = 0;
};

}  // namespace shockmap
