#pragma once
// What a Newmark integrator needs from a structure: M a + C v + K x = f_contact(x, v).

#include <Eigen/Dense>
#include <limits>
#include <span>
#include <vector>

#include "core/point_contact.h"

namespace shockmap {

// Mechanical energies at one state (J).
struct Energies {
  double kinetic_j = 0.0;
  double strain_j = 0.0;
  double contact_j = 0.0;
  double Total() const { return kinetic_j + strain_j + contact_j; }
};

class SecondOrderSystem {
 public:
  virtual ~SecondOrderSystem() = default;

  virtual int Size() const = 0;

  // Newmark's equation for the new acceleration a at time t_s (as MFEM's ImplicitSolve):
  //   M a + C (v_pred + gamma_dt a) + K (x_pred + beta_dt2 a)
  //     = f(t) + f_contact(x_pred + beta_dt2 a, v_pred + gamma_dt a).
  // beta_dt2 = gamma_dt = 0 gives the acceleration at a known state.
  // Returns false when the contact iteration does not converge (a is then unspecified).
  virtual bool SolveAcceleration(double t_s, double beta_dt2, double gamma_dt,
                                 const Eigen::VectorXd& x_pred, const Eigen::VectorXd& v_pred,
                                 Eigen::VectorXd& a) = 0;

  // The force of each contact (N, >= 0) in the solution of the last SolveAcceleration: the
  // forces the integrator applied, recorded without computing them again.
  virtual std::span<const double> LastContactForces() const = 0;

  // The tangential sliding speed at contact `contact` (index into LastContactForces) at
  // velocity v (m/s, >= 0): the relative velocity of the two sides there, less its normal part.
  // NaN when the model does not carry the tangential motion of that contact (the default; in
  // scenes, zones that bend in one plane): its wear work rate is then unavailable.
  virtual double SlidingSpeed(int /*contact*/, const Eigen::VectorXd& /*v*/) const {
    return std::numeric_limits<double>::quiet_NaN();
  }

  virtual Energies EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const = 0;

  // True when the system declares structural or contact damping; otherwise DissipatedPower is
  // identically zero and callers skip it.
  virtual bool Dissipates() const = 0;

  // True when time-dependent loads act (base motion, forces); their power is then
  // ExternalPower, and the energy balance counts their work.
  virtual bool HasExternalLoads() const { return false; }
  virtual double ExternalPower(double /*t_s*/, const Eigen::VectorXd& /*v*/) const { return 0.0; }

  // Power dissipated by structural and contact damping at a state (W), >= 0.
  virtual double DissipatedPower(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const = 0;
};

// Sum over contacts of the penalty energy at state x.
double ContactEnergy(const std::vector<PointContact>& contacts, const Eigen::VectorXd& x);
bool AnyContactDamping(const std::vector<PointContact>& contacts);
// Power taken out of the mechanical energy (kinetic + strain + penalty spring) by contact
// damping, summed over contacts in contact (W): c w^2 while the force is positive, and the
// spring power k (g - u) w while the force is clamped at zero (the stop never pulls).
double ContactDampingPower(const std::vector<PointContact>& contacts, const Eigen::VectorXd& x,
                           const Eigen::VectorXd& v);

}  // namespace shockmap
