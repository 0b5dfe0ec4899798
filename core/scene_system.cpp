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
  if (loads_.empty()) {
    NegativeProduct(omega_squared_, x_pred, a);
  } else {
    NegativeProductPlusScaled(omega_squared_, x_pred, loads_.front().Amplitude(t_s),
                              loads_.front().shape, a);
  }
  for (std::size_t i = 1; i < loads_.size(); ++i)
    AddScaledInPlace(a, loads_[i].Amplitude(t_s), loads_[i].shape);
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
  if (!z.InFrame() && (z.a_y < 0 || z.a_z < 0)) return {};
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

SecondOrderSystem::Powers SceneModalSystem::PowersAt(double t_s, const Eigen::VectorXd& x,
                                                     const Eigen::VectorXd& v) const {
  double damping = 0.0, external = 0.0;
  std::size_t summed_loads = 0;
  if (modal_damping_ && !loads_.empty()) {
    const auto [d, s] = WeightedSquareAndDot(*modal_damping_, v, loads_.front().shape);
    damping = d;
    external += loads_.front().Amplitude(t_s) * s;
    summed_loads = 1;
  } else if (modal_damping_) {
    damping = modal_damping_->dot(v.cwiseProduct(v));
  }
  for (std::size_t i = summed_loads; i < loads_.size(); ++i)
    external += loads_[i].Amplitude(t_s) * loads_[i].shape.dot(v);
  return {contacts_.AddDampingPower(x, v, damping), external};
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
