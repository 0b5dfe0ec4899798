#pragma once
// Newmark time integration (MFEM's NewmarkSolver form). Central differences and average
// acceleration are parameter choices of the same scheme, not two codes.

#include <optional>
#include <string>
#include <string_view>

#include "core/second_order_system.h"

namespace shockmap {

struct NewmarkParameters {
  double beta = 0.0;
  double gamma = 0.5;
  // beta = 0, gamma = 1/2: explicit, second order, stable for dt < 2 / omega_max.
  static NewmarkParameters CentralDifference() { return {0.0, 0.5}; }
  // beta = 1/4, gamma = 1/2: implicit, second order, unconditionally stable, no dissipation.
  static NewmarkParameters AverageAcceleration() { return {0.25, 0.5}; }
};

// Owns the state (x, v, a) of one system. Contract of Step(dt): from (x_n, v_n, a_n) at t_n,
//   x_pred = x_n + dt v_n + (1/2 - beta) dt^2 a_n,   v_pred = v_n + (1 - gamma) dt a_n,
//   a_{n+1} solves the system's SolveAcceleration(beta dt^2, gamma dt, x_pred, v_pred),
//   x_{n+1} = x_pred + beta dt^2 a_{n+1},           v_{n+1} = v_pred + gamma dt a_{n+1}.
class NewmarkIntegrator {
 public:
  NewmarkIntegrator(NewmarkParameters parameters, SecondOrderSystem& system);

  // Sets the state at time t0_s and computes the consistent initial acceleration. False if
  // that fails.
  bool Init(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0, double t0_s = 0.0);
  // Advances one step. False when the system's solve fails (the state is then unspecified).
  bool Step(double dt);

  const Eigen::VectorXd& X() const { return x_; }
  const Eigen::VectorXd& V() const { return v_; }
  const Eigen::VectorXd& A() const { return a_; }
  double T() const { return t_; }

 private:
  NewmarkParameters p_;
  SecondOrderSystem& system_;
  Eigen::VectorXd x_, v_, a_;
  double t_ = 0.0;
};

}  // namespace shockmap
