#include "core/modal_contact_system.h"

#include <cassert>

namespace shockmap {

ModalContactSystem::ModalContactSystem(Eigen::VectorXd omega_rad_s,
                                       std::optional<Eigen::VectorXd> modal_damping,
                                       std::vector<PointContact> contacts)
    : omega_squared_(omega_rad_s.array().square().matrix()),
      modal_damping_(std::move(modal_damping)),
      contacts_(std::move(contacts)),
      forces_(contacts_.size(), 0.0) {
  assert(!modal_damping_ || modal_damping_->size() == omega_squared_.size());
}

bool ModalContactSystem::SolveAcceleration(double /*t_s*/, double beta_dt2, double gamma_dt,
                                           const Eigen::VectorXd& x_pred,
                                           const Eigen::VectorXd& v_pred, Eigen::VectorXd& a) {
  assert(beta_dt2 == 0.0 && "the modal system is integrated explicitly");
  (void)beta_dt2;
  a.noalias() = -omega_squared_.cwiseProduct(x_pred);
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const PointContact& c = contacts_[i];
    forces_[i] = PenaltyForce(c, c.row.dot(x_pred), c.row.dot(v_pred));
    if (forces_[i] != 0.0) a.noalias() += forces_[i] * c.row;
  }
  if (modal_damping_) {
    const auto& d = *modal_damping_;
    a = (a - d.cwiseProduct(v_pred)).cwiseQuotient((1.0 + gamma_dt * d.array()).matrix());
  }
  return true;
}

Energies ModalContactSystem::EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  return {0.5 * v.squaredNorm(), 0.5 * omega_squared_.dot(x.cwiseProduct(x)),
          ContactEnergy(contacts_, x)};
}

bool ModalContactSystem::Dissipates() const {
  return modal_damping_.has_value() || AnyContactDamping(contacts_);
}

double ModalContactSystem::DissipatedPower(const Eigen::VectorXd& x,
                                           const Eigen::VectorXd& v) const {
  const double structural = modal_damping_ ? modal_damping_->dot(v.cwiseProduct(v)) : 0.0;
  return structural + ContactDampingPower(contacts_, x, v);
}

}  // namespace shockmap
