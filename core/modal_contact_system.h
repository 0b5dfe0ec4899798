#pragma once
// The paper's reduced model (eq. 7): decoupled modal oscillators, contact forces computed from
// the physical displacement at each contact point and projected back on the modes.

#include <optional>

#include "core/second_order_system.h"

namespace shockmap {

// q'' + 2 xi Omega q' + Omega^2 q = sum_c phi_c F_c(phi_c . q, phi_c . q'), with unit modal
// masses (mass-normalized basis). Contact rows are the mode shapes at the contact points.
// Only explicit Newmark (beta = 0) is supported: the contact force is evaluated at the
// predicted state, as central differences do. Modal damping enters through gamma_dt and stays
// unconditionally consistent; contact damping uses the predicted velocity.
class ModalContactSystem final : public SecondOrderSystem {
 public:
  // modal_damping: 2 xi_i Omega_i per mode (1/s), or nullopt for an undamped structure, which
  // then computes no damping term at all.
  ModalContactSystem(Eigen::VectorXd omega_rad_s, std::optional<Eigen::VectorXd> modal_damping,
                     std::vector<PointContact> contacts);

  int Size() const override { return static_cast<int>(omega_squared_.size()); }
  bool SolveAcceleration(double t_s, double beta_dt2, double gamma_dt,
                         const Eigen::VectorXd& x_pred, const Eigen::VectorXd& v_pred,
                         Eigen::VectorXd& a) override;
  std::span<const double> LastContactForces() const override { return forces_; }
  Energies EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;
  bool Dissipates() const override;
  double DissipatedPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;
  const std::vector<PointContact>& Contacts() const { return contacts_; }

  const Eigen::VectorXd& OmegaSquared() const { return omega_squared_; }

 private:
  Eigen::VectorXd omega_squared_;
  std::optional<Eigen::VectorXd> modal_damping_;
  std::vector<PointContact> contacts_;
  std::vector<double> forces_;
};

}  // namespace shockmap
