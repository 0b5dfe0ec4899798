#pragma once
// The comparison model: the whole finite-element beam, no reduction, contact solved implicitly.

#include <Eigen/SparseCholesky>
#include <memory>

#include "core/second_order_system.h"

namespace shockmap {

// M a + alpha M v + K x = sum_c r_c F_c(r_c . x, r_c . v), with mass-proportional damping
// alpha (1/s, 0 for none). SolveAcceleration factorizes A = (1 + gamma_dt alpha) M + beta_dt2 K
// once per (beta_dt2, gamma_dt) pair and solves the piecewise-linear contact exactly by an
// active-set iteration, each active set through a Woodbury update of A^-1 with the contact rows.
// Precondition: every contact's normal law is linear (the canonical problem's spring; a power
// law would need a Newton iteration inside each active set, which no model here asks for).
class FullFeContactSystem final : public SecondOrderSystem {
 public:
  FullFeContactSystem(Eigen::SparseMatrix<double> mass, Eigen::SparseMatrix<double> stiffness,
                      double mass_damping_per_s, std::vector<PointContact> contacts);
  ~FullFeContactSystem() override;

  int Size() const override { return static_cast<int>(mass_.rows()); }
  bool SolveAcceleration(double t_s, double beta_dt2, double gamma_dt,
                         const Eigen::VectorXd& x_pred, const Eigen::VectorXd& v_pred,
                         Eigen::VectorXd& a) override;
  std::span<const double> LastContactForces() const override { return forces_; }
  // -r . v: the penetration g - u grows as the point moves down.
  double PenetrationRate(int contact, const Eigen::VectorXd& v) const override {
    return -contacts_[static_cast<std::size_t>(contact)].row.dot(v);
  }
  Energies EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;
  bool Dissipates() const override;
  // Mass-proportional and contact damping; no time-dependent loads.
  Powers PowersAt(double t_s, const Eigen::VectorXd& x, const Eigen::VectorXd& v) const override;
  const std::vector<PointContact>& Contacts() const { return contacts_; }

  // Iterations of the active-set loop allowed per solve; the law is piecewise linear with
  // one kink per contact, so a consistent set is normally found in two or three.
  static constexpr int kMaxActiveSetIterations = 50;

 private:
  struct Factorization;
  const Factorization& FactorizationFor(double beta_dt2, double gamma_dt);

  Eigen::SparseMatrix<double> mass_;
  Eigen::SparseMatrix<double> stiffness_;
  double mass_damping_per_s_;
  std::vector<PointContact> contacts_;
  std::vector<double> forces_;
  std::unique_ptr<Factorization> factorization_;
};

}  // namespace shockmap
