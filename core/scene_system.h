#pragma once
// The modal model of a scene (paper §3): one mass-normalized modal basis per beam and bending
// direction, contact forces from the physical displacements at the zones projected back on
// each beam's basis (paper eq. 7). Assembled from the declared effects only: an undeclared
// effect has no member here and costs nothing per step.

#include <optional>
#include <vector>

#include "core/contact_stations.h"
#include "core/scene.h"
#include "core/second_order_system.h"

namespace shockmap {

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
  std::span<const double> LastContactForces() const override { return contacts_.Forces(); }
  // |t . (v_a - v_b)| at the zone's height, t = (-n_z, n_y) the in-plane tangent, for zones
  // whose beam a bends in both planes or that lie in their own frame (a structure's node: t its
  // tangent), NaN otherwise (planar scenes), and the zone's friction force and state in the last
  // solve.
  TangentialSample Tangential(int contact, const Eigen::VectorXd& v) const override;
  bool HasFriction(int contact) const override { return contacts_.HasFriction(contact); }
  // n . (v_a - v_b) at the zone's height.
  double PenetrationRate(int contact, const Eigen::VectorXd& v) const override;
  Energies EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;
  bool Dissipates() const override;
  bool HasExternalLoads() const override { return !loads_.empty(); }
  // The modal damping's power and the first load's summed in one pass (core/fused_sums.h),
  // each equal bit for bit to its own dot product; then the contacts' damping, the other loads.
  Powers PowersAt(double t_s, const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;

  // The largest eigenvalue of diag(omega^2) + sum_z (k_z r_z r_z^T + k_t,z t_z t_z^T) (every
  // zone closed with normal stiffness k_z, zone order, and the tangential springs of its zones
  // with friction), by power iteration on the operator: the sharp central-difference bound is
  // 2 / sqrt of it.
  double StiffestOmegaSquared(std::span<const double> normal_stiffness) const;
  const std::vector<ZoneTerm>& Zones() const { return zones_; }
  // The zones as the step evaluates them: per-zone forces, relative displacements and
  // velocities (core/contact_stations.h).
  const ContactStations& Contacts() const { return contacts_; }
  const Eigen::VectorXd& OmegaSquared() const { return omega_squared_; }

 private:
  Eigen::VectorXd omega_squared_;
  std::optional<Eigen::VectorXd> modal_damping_;
  std::vector<ZoneTerm> zones_;  // As given; the step uses contacts_.
  ContactStations contacts_;
  std::vector<TimeLoad> loads_;
  // 1 + gamma_dt * damping, for the gamma_dt it was computed with.
  Eigen::VectorXd damping_divisor_;
  double divisor_gamma_dt_ = -1.0;
};

}  // namespace shockmap
