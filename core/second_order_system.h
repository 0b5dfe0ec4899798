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

// A contact's tangential side at one step (SecondOrderSystem::Tangential).
struct TangentialSample {
  double sliding_speed_m_s = std::numeric_limits<double>::quiet_NaN();
  double force_n = 0.0;  // |F_t| (N): 0 without friction.
  bool sticks = false;   // Friction holds the two sides together (they do not slide).
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

  // The tangential side of contact `contact` (index into LastContactForces) at velocity v,
  // after the last solve: its sliding speed, the relative velocity of the two sides less its
  // normal part (m/s, >= 0; NaN when the model does not carry the tangential motion of that
  // contact, the default, and in scenes the zones that bend in one plane: its wear work rate is
  // then unavailable), and with friction its tangential force and whether it sticks.
  virtual TangentialSample Tangential(int /*contact*/, const Eigen::VectorXd& /*v*/) const {
    return {};
  }
  // True when the contact has friction (its tangential force and stick state then matter).
  virtual bool HasFriction(int /*contact*/) const { return false; }
  // The rate of a contact's penetration at velocity v (m/s, > 0 closing; NaN when unknown).
  virtual double PenetrationRate(int /*contact*/, const Eigen::VectorXd& /*v*/) const {
    return std::numeric_limits<double>::quiet_NaN();
  }

  virtual Energies EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const = 0;

  // True when the system declares structural or contact damping; otherwise the dissipated power
  // is identically zero.
  virtual bool Dissipates() const = 0;

  // True when time-dependent loads act (base motion, forces); the energy balance then counts
  // their work.
  virtual bool HasExternalLoads() const { return false; }

  // The powers the energy balance integrates, at time t_s and state (x, v): what structural and
  // contact damping take out (W, >= 0; 0 unless Dissipates()) and what the loads feed in (W; 0
  // unless HasExternalLoads()). One call, so that a system may sum both in one pass.
  struct Powers {
    double dissipated_w = 0.0;
    double external_w = 0.0;
  };
  virtual Powers PowersAt(double t_s, const Eigen::VectorXd& x, const Eigen::VectorXd& v) const = 0;
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
