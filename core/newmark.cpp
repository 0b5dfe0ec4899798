#include "core/newmark.h"

#include "core/elementwise_passes.h"

namespace shockmap {

NewmarkIntegrator::NewmarkIntegrator(NewmarkParameters parameters, SecondOrderSystem& system)
    : p_(parameters), system_(system) {}

bool NewmarkIntegrator::Init(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double t0_s) {
  x_ = x0;
  v_ = v0;
  t_ = t0_s;
  a_.resize(x0.size());
  return system_.SolveAcceleration(t_, 0.0, 0.0, x_, v_, a_);
}

bool NewmarkIntegrator::Step(double dt) {
  const double dt2 = dt * dt;
  // x and v become the predictors in place, in one pass; a still holds a_n.
  const double cx = (0.5 - p_.beta) * dt2, cv = (1.0 - p_.gamma) * dt;
  PredictInPlace(x_, v_, a_, dt, cx, cv);
  t_ += dt;
  if (!system_.SolveAcceleration(t_, p_.beta * dt2, p_.gamma * dt, x_, v_, a_)) return false;
  if (p_.beta != 0.0) x_.noalias() += (p_.beta * dt2) * a_;
  AddScaledInPlace(v_, p_.gamma * dt, a_);
  return true;
}

}  // namespace shockmap
