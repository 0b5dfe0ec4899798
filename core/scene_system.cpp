#include "core/scene_system.h"

#include <cassert>
#include <cmath>
#include <limits>

#include "core/elementwise_passes.h"
#include "core/fused_sums.h"

namespace shockmap {

double TimeLoad::Amplitude(double t_s) const {
  return base != nullptr ? -base->At(t_s) : point_force->At(t_s);
}

SceneModalSystem::SceneModalSystem(Eigen::VectorXd omega_rad_s,
                                   std::optional<Eigen::VectorXd> modal_damping,
                                   std::vector<ZoneTerm> zones, std::vector<TimeLoad> loads)
    : omega_squared_(omega_rad_s.array().square().matrix()),
      modal_damping_(std::move(modal_damping)),
      zones_(std::move(zones)),
      contacts_(zones_),
      loads_(std::move(loads)) {}

bool SceneModalSystem::SolveAcceleration(double t_s, double beta_dt2, double gamma_dt,
                                         const Eigen::VectorXd& x_pred,
                                         const Eigen::VectorXd& v_pred, Eigen::VectorXd& a) {
  assert(beta_dt2 == 0.0 && "the scene's modal model is integrated explicitly");
  (void)beta_dt2;
  NegativeProduct(omega_squared_, x_pred, a);
  for (const auto& load : loads_) AddScaledInPlace(a, load.Amplitude(t_s), load.shape);
  contacts_.AddForces(t_s, x_pred, v_pred, a);
  if (modal_damping_) {
    const auto& d = *modal_damping_;
    if (gamma_dt != divisor_gamma_dt_) {
      damping_divisor_ = (1.0 + gamma_dt * d.array()).matrix();
      divisor_gamma_dt_ = gamma_dt;
    }
    DampInPlace(a, d, v_pred, damping_divisor_);
  }
  return true;
}

TangentialSample SceneModalSystem::Tangential(int contact, const Eigen::VectorXd& v) const {
  const ZoneTerm& z = zones_[static_cast<std::size_t>(contact)];
  if (z.a_y < 0 || z.a_z < 0) return {};
  const auto [w_y, w_z] = contacts_.RelativeVelocity(contact, v);
  return {std::abs(-z.normal_z * w_y + z.normal_y * w_z),
          std::abs(contacts_.TangentialForce(contact)), contacts_.Sticks(contact)};
}

double SceneModalSystem::PenetrationRate(int contact, const Eigen::VectorXd& v) const {
  const ZoneTerm& z = zones_[static_cast<std::size_t>(contact)];
  const auto [w_y, w_z] = contacts_.RelativeVelocity(contact, v);
  return z.normal_y * w_y + z.normal_z * w_z;
}

Energies SceneModalSystem::EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  const auto [v_squared, omega_x_squared] = KineticAndStrainSums(v, omega_squared_, x);
  return {0.5 * v_squared, 0.5 * omega_x_squared, contacts_.ContactEnergy(x)};
}

bool SceneModalSystem::Dissipates() const { return modal_damping_ || contacts_.AnyDamping(); }

double SceneModalSystem::DissipatedPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  const double p = modal_damping_ ? modal_damping_->dot(v.cwiseProduct(v)) : 0.0;
  return contacts_.AddDampingPower(x, v, p);
}

double SceneModalSystem::ExternalPower(double t_s, const Eigen::VectorXd& v) const {
  double p = 0.0;
  for (const auto& load : loads_) p += load.Amplitude(t_s) * load.shape.dot(v);
  return p;
}

double SceneModalSystem::StiffestOmegaSquared(std::span<const double> normal_stiffness) const {
  // Power iteration from a vector touching every coordinate. The Rayleigh quotients rise towards
  // the largest eigenvalue from below; 300 iterations bring them within 1e-3 of it on the
  // bundles shipped (checked against the dense solver in the tests).
  Eigen::VectorXd x = Eigen::VectorXd::Ones(Size()).normalized();
  Eigen::VectorXd y(Size());
  double lambda = omega_squared_.size() > 0 ? omega_squared_.maxCoeff() : 0.0;
  for (int iter = 0; iter < 300; ++iter) {
    y = omega_squared_.cwiseProduct(x);
    contacts_.AddClosedStiffness(x, normal_stiffness, y);
    lambda = std::max(lambda, x.dot(y));
    const double norm = y.norm();
    if (norm == 0.0) break;
    x = y / norm;
  }
  return lambda;
}

}  // namespace shockmap
