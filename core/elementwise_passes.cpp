#include "core/elementwise_passes.h"

#include <algorithm>
#include <cassert>

namespace shockmap {
namespace {

using Index = Eigen::Index;

__attribute__((target_clones("avx2", "default"))) void Predict(double* __restrict x,
                                                               double* __restrict v,
                                                               const double* __restrict a, Index n,
                                                               double dt, double cx, double cv) {
  for (Index i = 0; i < n; ++i) {
    x[i] += dt * v[i] + cx * a[i];
    v[i] += cv * a[i];
  }
}

__attribute__((target_clones("avx2", "default"))) void AddScaled(double* __restrict v, double c,
                                                                 const double* __restrict a,
                                                                 Index n) {
  for (Index i = 0; i < n; ++i) v[i] += c * a[i];
}

__attribute__((target_clones("avx2", "default"))) void Negative(const double* __restrict w,
                                                                const double* __restrict x,
                                                                double* __restrict out, Index n) {
  for (Index i = 0; i < n; ++i) out[i] = -(w[i] * x[i]);
}

__attribute__((target_clones("avx2", "default"))) void NegativePlusScaled(
    const double* __restrict w, const double* __restrict x, double c, const double* __restrict s,
    double* __restrict out, Index n) {
  for (Index i = 0; i < n; ++i) out[i] = -(w[i] * x[i]) + c * s[i];
}

__attribute__((target_clones("avx2", "default"))) void Damp(double* __restrict a,
                                                            const double* __restrict d,
                                                            const double* __restrict v,
                                                            const double* __restrict divisor,
                                                            Index n) {
  for (Index i = 0; i < n; ++i) a[i] = (a[i] - d[i] * v[i]) / divisor[i];
}

__attribute__((target_clones("avx2", "default"))) void RaiseToMax(double* __restrict m,
                                                                  const double* __restrict v,
                                                                  Index n) {
  for (Index i = 0; i < n; ++i) m[i] = std::max(m[i], v[i]);
}

}  // namespace

void RaiseToMaxInPlace(std::span<double> largest, std::span<const double> values) {
  assert(values.size() == largest.size());
  RaiseToMax(largest.data(), values.data(), static_cast<Index>(largest.size()));
}

void DampInPlace(Eigen::VectorXd& a, const Eigen::VectorXd& d, const Eigen::VectorXd& v,
                 const Eigen::VectorXd& divisor) {
  assert(d.size() == a.size() && v.size() == a.size() && divisor.size() == a.size());
  Damp(a.data(), d.data(), v.data(), divisor.data(), a.size());
}

void PredictInPlace(Eigen::VectorXd& x, Eigen::VectorXd& v, const Eigen::VectorXd& a, double dt,
                    double cx, double cv) {
  assert(v.size() == x.size() && a.size() == x.size());
  Predict(x.data(), v.data(), a.data(), x.size(), dt, cx, cv);
}

void AddScaledInPlace(Eigen::VectorXd& v, double c, const Eigen::VectorXd& a) {
  assert(a.size() == v.size());
  AddScaled(v.data(), c, a.data(), v.size());
}

void NegativeProduct(const Eigen::VectorXd& w, const Eigen::VectorXd& x, Eigen::VectorXd& out) {
  assert(x.size() == w.size());
  out.resize(w.size());
  Negative(w.data(), x.data(), out.data(), w.size());
}

void NegativeProductPlusScaled(const Eigen::VectorXd& w, const Eigen::VectorXd& x, double c,
                               const Eigen::VectorXd& s, Eigen::VectorXd& out) {
  assert(x.size() == w.size() && s.size() == w.size());
  out.resize(w.size());
  NegativePlusScaled(w.data(), x.data(), c, s.data(), out.data(), w.size());
}

}  // namespace shockmap
