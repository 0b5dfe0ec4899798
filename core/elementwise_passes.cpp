#include "core/elementwise_passes.h"

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

}  // namespace

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

}  // namespace shockmap
