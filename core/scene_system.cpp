#include "core/scene_system.h"

#include <cassert>
#include <cmath>
#include <limits>

namespace shockmap {
namespace {

// phi . x[offset ...], summed in the order of Eigen's reduction of row.dot(x) on 2-wide packets
// (SSE2): two pairs of partial sums over blocks of four, folded, then the tail. A zone thus reads
// the same displacement as a row of the same values does (the observed outputs, the canonical
// problem's histories before it became a scene). Inlined: it runs for every zone at every step.
[[gnu::always_inline]] inline double Dot(const std::vector<double>& phi, const Eigen::VectorXd& x,
                                         int offset) {
  const std::size_t n = phi.size();
  const double* f = phi.data();
  const double* p = x.data() + offset;
  if (n < 2) return n == 1 ? f[0] * p[0] : 0.0;
  const std::size_t pairs_end = n & ~std::size_t{1}, quads_end = n & ~std::size_t{3};
  double s0 = f[0] * p[0], s1 = f[1] * p[1];
  if (pairs_end > 2) {
    double t0 = f[2] * p[2], t1 = f[3] * p[3];
    for (std::size_t i = 4; i < quads_end; i += 4) {
      s0 += f[i] * p[i];
      s1 += f[i + 1] * p[i + 1];
      t0 += f[i + 2] * p[i + 2];
      t1 += f[i + 3] * p[i + 3];
    }
    s0 += t0;
    s1 += t1;
    if (pairs_end > quads_end) {
      s0 += f[quads_end] * p[quads_end];
      s1 += f[quads_end + 1] * p[quads_end + 1];
    }
  }
  double s = s0 + s1;
  for (std::size_t i = pairs_end; i < n; ++i) s += f[i] * p[i];
  return s;
}

void Axpy(double alpha, const std::vector<double>& phi, Eigen::VectorXd& a, int offset) {
  double* p = a.data() + offset;
  for (std::size_t i = 0; i < phi.size(); ++i) p[i] += alpha * phi[i];
}

}  // namespace

double TimeLoad::Amplitude(double t_s) const {
  return base != nullptr ? -base->At(t_s) : point_force->At(t_s);
}

SceneModalSystem::SceneModalSystem(Eigen::VectorXd omega_rad_s,
                                   std::optional<Eigen::VectorXd> modal_damping,
                                   std::vector<ZoneTerm> zones, std::vector<TimeLoad> loads)
    : omega_squared_(omega_rad_s.array().square().matrix()),
      modal_damping_(std::move(modal_damping)),
      zones_(std::move(zones)),
      loads_(std::move(loads)),
      forces_(zones_.size(), 0.0) {}

double SceneModalSystem::Normal(const ZoneTerm& z, const Eigen::VectorXd& x) const {
  double u = 0.0;
  if (z.a_y >= 0) u += z.normal_y * Dot(z.phi_a, x, z.a_y);
  if (z.a_z >= 0) u += z.normal_z * Dot(z.phi_a, x, z.a_z);
  if (z.b_y >= 0) u -= z.normal_y * Dot(z.phi_b, x, z.b_y);
  if (z.b_z >= 0) u -= z.normal_z * Dot(z.phi_b, x, z.b_z);
  return u;
}

void SceneModalSystem::AddZoneForce(const ZoneTerm& z, double force, Eigen::VectorXd& a) const {
  if (z.a_y >= 0) Axpy(-force * z.normal_y, z.phi_a, a, z.a_y);
  if (z.a_z >= 0) Axpy(-force * z.normal_z, z.phi_a, a, z.a_z);
  if (z.b_y >= 0) Axpy(force * z.normal_y, z.phi_b, a, z.b_y);
  if (z.b_z >= 0) Axpy(force * z.normal_z, z.phi_b, a, z.b_z);
}

bool SceneModalSystem::SolveAcceleration(double t_s, double beta_dt2, double gamma_dt,
                                         const Eigen::VectorXd& x_pred,
                                         const Eigen::VectorXd& v_pred, Eigen::VectorXd& a) {
  assert(beta_dt2 == 0.0 && "the scene's modal model is integrated explicitly");
  (void)beta_dt2;
  a.noalias() = -omega_squared_.cwiseProduct(x_pred);
  for (const auto& load : loads_) a.noalias() += load.Amplitude(t_s) * load.shape;
  for (std::size_t i = 0; i < zones_.size(); ++i) {
    const ZoneTerm& z = zones_[i];
    const double penetration = Normal(z, x_pred) - z.gap_m;
    double force = 0.0;
    if (penetration > 0.0) {
      force = z.stiffness_n_per_m * penetration;
      if (z.damping_n_s_per_m != 0.0) {
        force = std::max(0.0, force + z.damping_n_s_per_m * Normal(z, v_pred));
      }
      AddZoneForce(z, force, a);
    }
    forces_[i] = force;
  }
  if (modal_damping_) {
    const auto& d = *modal_damping_;
    a = (a - d.cwiseProduct(v_pred)).cwiseQuotient((1.0 + gamma_dt * d.array()).matrix());
  }
  return true;
}

double SceneModalSystem::SlidingSpeed(int contact, const Eigen::VectorXd& v) const {
  const ZoneTerm& z = zones_[static_cast<std::size_t>(contact)];
  if (z.a_y < 0 || z.a_z < 0) return std::numeric_limits<double>::quiet_NaN();
  double w_y = Dot(z.phi_a, v, z.a_y), w_z = Dot(z.phi_a, v, z.a_z);
  if (z.b_y >= 0) w_y -= Dot(z.phi_b, v, z.b_y);
  if (z.b_z >= 0) w_z -= Dot(z.phi_b, v, z.b_z);
  return std::abs(-z.normal_z * w_y + z.normal_y * w_z);
}

Energies SceneModalSystem::EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  double contact = 0.0;
  for (const auto& z : zones_) {
    const double d = Normal(z, x) - z.gap_m;
    if (d > 0.0) contact += 0.5 * z.stiffness_n_per_m * d * d;
  }
  return {0.5 * v.squaredNorm(), 0.5 * omega_squared_.dot(x.cwiseProduct(x)), contact};
}

bool SceneModalSystem::Dissipates() const {
  if (modal_damping_) return true;
  for (const auto& z : zones_) {
    if (z.damping_n_s_per_m != 0.0) return true;
  }
  return false;
}

double SceneModalSystem::DissipatedPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  double p = modal_damping_ ? modal_damping_->dot(v.cwiseProduct(v)) : 0.0;
  for (const auto& z : zones_) {
    if (z.damping_n_s_per_m == 0.0) continue;
    const double d = Normal(z, x) - z.gap_m;
    if (d <= 0.0) continue;
    // d/dt (kinetic + strain + spring) = (k d - F) d': what leaves is (F - k d) d'.
    const double rate = Normal(z, v);
    const double force = std::max(0.0, z.stiffness_n_per_m * d + z.damping_n_s_per_m * rate);
    p += (force - z.stiffness_n_per_m * d) * rate;
  }
  return p;
}

double SceneModalSystem::ExternalPower(double t_s, const Eigen::VectorXd& v) const {
  double p = 0.0;
  for (const auto& load : loads_) p += load.Amplitude(t_s) * load.shape.dot(v);
  return p;
}

double SceneModalSystem::StiffestOmegaSquared() const {
  // Power iteration from a vector touching every coordinate. The Rayleigh quotients rise towards
  // the largest eigenvalue from below; 300 iterations bring them within 1e-3 of it on the
  // bundles shipped (checked against the dense solver in the tests).
  Eigen::VectorXd x = Eigen::VectorXd::Ones(Size()).normalized();
  Eigen::VectorXd y(Size());
  double lambda = omega_squared_.size() > 0 ? omega_squared_.maxCoeff() : 0.0;
  for (int iter = 0; iter < 300; ++iter) {
    y = omega_squared_.cwiseProduct(x);
    for (const auto& z : zones_) AddZoneForce(z, -z.stiffness_n_per_m * Normal(z, x), y);
    lambda = std::max(lambda, x.dot(y));
    const double norm = y.norm();
    if (norm == 0.0) break;
    x = y / norm;
  }
  return lambda;
}

}  // namespace shockmap
