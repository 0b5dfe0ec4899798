#pragma once
// The central-difference step of a modal model with a few linear penalty zones, in increment
// form (docs/performance.md, "The explicit step in increment form"): with Δ_n = q_n - q_{n-1},
//   Δ_{n+1} = Δ_n + dt² a_n,   q_{n+1} = q_n + Δ_{n+1},   a_n = -ω² ⊙ q_n - Σ_z F_z,n r_z,
// F_z,n = k_z max(0, r_z · q_n - g_z) (paper eqs. 5 and 7, r_z the zone's normal row over the
// modal coordinates). It is Newmark's β = 0, γ = 1/2 (Δ_n = dt v_{n-1/2}) with other roundings:
// 5 flops per mode and step instead of 15.
//
// The forces' dependency chain holds one multiply-add and a maximum per step, not the modal
// pass: each step's pass also predicts the penetrations K = kLookahead steps ahead without the
// forces to come, and the forces add their effect through constants. With s = (q, Δ) per mode,
// s_{n+1} = A s_n + e F_n, A = [[1 - dt²ω², 1], [-dt²ω², 1]], e = -dt² r (on both), so
//   k_z (r_z · q_{n+1} - g_z) = P_z,{n+1-K} + Σ_{l<K} Σ_w μ_l,zw F_w,{n-l},
//   P_z,m = k_z (r_z · [A^K s_m]_q - g_z),   μ_l,zw = k_z r_z · [A^l e_w]_q,
// and F_z,{n+1} is the maximum of that and 0. Before the first step the state is continued
// backwards without forces (A is invertible), so the first K steps need no other formula.
//
// The pass is compiled for AVX-512, AVX2 with fused multiply-adds and baseline x86-64, the one
// the CPU supports chosen when the program loads; the first two fuse multiplies and adds, so
// their results differ from the baseline's in the last bits.
//
// A model qualifies (IncrementStepper::For) when it is a scene's modal model without modal
// damping or loads, with at most kMaxZones zones, each a linear penalty without damping or
// friction, and at most kMaxZones observed rows; the zones' rows are then dense over the modal
// coordinates.

#include <Eigen/Dense>
#include <memory>
#include <span>
#include <vector>

#include "core/scene_system.h"

namespace shockmap {

class IncrementStepper {
 public:
  static constexpr int kMaxZones = 8;
  // Steps between a prediction and its use: the chain of the pass and of its sums, about 50
  // cycles, spread over 8 steps.
  static constexpr int kLookahead = 4;

  // The stepper of `system` with step dt_s, recording the rows `observed` (row · q), or null
  // when the system does not qualify (above). An observed row equal to a zone's normal row,
  // or to its opposite, is read off that zone's penetration.
  static std::unique_ptr<IncrementStepper> For(const SecondOrderSystem& system, double dt_s,
                                               std::span<const Eigen::VectorXd> observed);

  // Sets the state at t = 0 (velocity v0).
  void Init(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0);
  // Advances `steps` steps; step s's observed values go to observed[s * Rows() + j], its zone
  // forces to forces[s * Zones() + z].
  void Advance(int steps, double* observed, double* forces);

  int Zones() const { return zones_; }
  int Rows() const { return static_cast<int>(row_zone_.size()); }
  double T() const { return static_cast<double>(steps_) * dt_; }
  // The state after the last step: q_n, and v_n = (Δ_n + dt² a_n / 2) / dt.
  const Eigen::VectorXd& X();
  const Eigen::VectorXd& V();
  // The zones' forces at the current state (N).
  std::span<const double> Forces() const { return {forces_.data(), std::size_t(zones_)}; }

 private:
  IncrementStepper(const SceneModalSystem& system, double dt_s,
                   std::span<const Eigen::VectorXd> observed);

  // Per-mode arrays padded with zeros to whole lanes.
  std::vector<double> Padded(const Eigen::VectorXd& v) const;
  // dt² a_n at the current state, unpadded, into `out` (resized only when its size differs).
  void DtSquaredAcceleration(Eigen::VectorXd& out) const;

  int modes_ = 0, padded_ = 0, zones_ = 0, dot_rows_ = 0;
  double dt_ = 0.0;
  long long steps_ = 0;
  Eigen::VectorXd one_c_, c_;          // 1 - dt²ω² and -dt²ω² per mode (unpadded).
  std::vector<Eigen::VectorXd> rows_;  // r_z per zone (unpadded).
  std::vector<double> k_, kg_;         // Per zone: k_z and k_z g_z.
  std::vector<double> c_padded_;
  // Padded, zone-major: -dt² r_z; k_z r_z α_K and k_z r_z β_K, (α_K, β_K) the first row of A^K.
  std::vector<double> b_, ra_, rb_;
  std::vector<double> mu_;  // μ_l,zw at [(l * zones + z) * zones + w].
  // Per observed row: the zone it is read off (-1: a dot product) and the scale and offset
  // that turn the zone's k (r . q - g) into it; the dot rows padded, row-major.
  std::vector<int> row_zone_;
  std::vector<double> row_scale_, row_offset_, dot_rows_padded_;
  std::vector<double> q_, d_;  // q_n and Δ_n, padded.
  // The last K predictions P_{n+1-K} .. P_n and forces F_n .. F_{n+1-K}, lag-major.
  std::vector<double> predictions_, forces_;
  Eigen::VectorXd x_, v_;  // X() and V() as last asked.
};

}  // namespace shockmap
