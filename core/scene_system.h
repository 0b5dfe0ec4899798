#pragma once
// The modal model of a scene (paper §3): one mass-normalized modal basis per beam and bending
// direction, contact forces from the physical displacements at the zones projected back on
// each beam's basis (paper eq. 7). Assembled from the declared effects only: an undeclared
// effect has no member here and costs nothing per step.

#include <optional>
#include <vector>

#include "core/scene.h"
#include "core/second_order_system.h"

namespace shockmap {

// One zone in modal coordinates. Offsets are the first coordinate of each beam's block in y
// and z (-1 when absent: planar scenes, or a stop instead of beam b).
struct ZoneTerm {
  int a_y = -1, a_z = -1, b_y = -1, b_z = -1;
  std::vector<double> phi_a, phi_b;  // Mode shapes at the zone's height (1/sqrt(kg)).
  double normal_y = 1.0, normal_z = 0.0;
  double gap_m = 0.0, stiffness_n_per_m = 0.0, damping_n_s_per_m = 0.0;
};

// A time-dependent generalized force shape * amplitude(t), for base motion and point forces.
struct TimeLoad {
  Eigen::VectorXd shape;
  const BaseMotionEffect* base = nullptr;          // amplitude = -a_base(t), or
  const StaticForceEffect* point_force = nullptr;  // amplitude = F(t).
  double Amplitude(double t_s) const;
};

// Explicit only (beta = 0), as the paper's central differences; modal damping enters through
// gamma_dt, contact damping uses the predicted velocity.
class SceneModalSystem final : public SecondOrderSystem {
 public:
  SceneModalSystem(Eigen::VectorXd omega_rad_s, std::optional<Eigen::VectorXd> modal_damping,
                   std::vector<ZoneTerm> zones, std::vector<TimeLoad> loads);

  int Size() const override { return static_cast<int>(omega_squared_.size()); }
  bool SolveAcceleration(double t_s, double beta_dt2, double gamma_dt,
                         const Eigen::VectorXd& x_pred, const Eigen::VectorXd& v_pred,
                         Eigen::VectorXd& a) override;
  std::span<const double> LastContactForces() const override { return forces_; }
  // |t . (v_a - v_b)| at the zone's height, t = (-n_z, n_y) the in-plane tangent: for zones
  // whose beam a bends in both planes; NaN otherwise (planar scenes).
  double SlidingSpeed(int contact, const Eigen::VectorXd& v) const override;
  Energies EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;
  bool Dissipates() const override;
  double DissipatedPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;
  bool HasExternalLoads() const override { return !loads_.empty(); }
  double ExternalPower(double t_s, const Eigen::VectorXd& v) const override;

  // The largest eigenvalue of diag(omega^2) + sum_z k_z r_z r_z^T (every zone closed), by power
  // iteration on the operator: the sharp central-difference bound is 2 / sqrt of it.
  double StiffestOmegaSquared() const;
  const std::vector<ZoneTerm>& Zones() const { return zones_; }
  const Eigen::VectorXd& OmegaSquared() const { return omega_squared_; }

 private:
  // Normal displacement (and velocity) of a zone: n . (u_a - u_b) at its height.
  double Normal(const ZoneTerm& z, const Eigen::VectorXd& x) const;
  void AddZoneForce(const ZoneTerm& z, double force, Eigen::VectorXd& a) const;

  Eigen::VectorXd omega_squared_;
  std::optional<Eigen::VectorXd> modal_damping_;
  std::vector<ZoneTerm> zones_;
  std::vector<TimeLoad> loads_;
  std::vector<double> forces_;
};

}  // namespace shockmap
