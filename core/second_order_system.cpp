#include "core/second_order_system.h"

namespace shockmap {

double ContactEnergy(const std::vector<PointContact>& contacts, const Eigen::VectorXd& x) {
  double e = 0.0;
  for (const auto& c : contacts) e += PenaltyEnergy(c, c.row.dot(x));
  return e;
}

bool AnyContactDamping(const std::vector<PointContact>& contacts) {
  for (const auto& c : contacts) {
    if (c.law.damping_n_s_per_m != 0.0) return true;
  }
  return false;
}

double ContactDampingPower(const std::vector<PointContact>& contacts, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& v) {
  double p = 0.0;
  for (const auto& c : contacts) {
    if (c.law.damping_n_s_per_m == 0.0) continue;
    const double u = c.row.dot(x);
    if (u >= c.gap_m) continue;
    // d/dt (kinetic + strain + spring) = -(F_e - F) w with F_e the elastic force: the damper's
    // share, c w^2 while the force is positive, and the whole spring power F_e w while it is
    // clamped at 0.
    const double w = c.row.dot(v);
    p += (c.law.ElasticForce(c.gap_m - u) - PenaltyForce(c, u, w)) * w;
  }
  return p;
}

}  // namespace shockmap
