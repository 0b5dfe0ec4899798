#include "core/full_fe_contact_system.h"

#include <algorithm>
#include <cassert>

namespace shockmap {

struct FullFeContactSystem::Factorization {
  double beta_dt2 = 0.0;
  double gamma_dt = 0.0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  Eigen::MatrixXd a_inv_rows;  // A^-1 r_c, one column per contact
};

FullFeContactSystem::FullFeContactSystem(Eigen::SparseMatrix<double> mass,
                                         Eigen::SparseMatrix<double> stiffness,
                                         double mass_damping_per_s,
                                         std::vector<PointContact> contacts)
    : mass_(std::move(mass)),
      stiffness_(std::move(stiffness)),
      mass_damping_per_s_(mass_damping_per_s),
      contacts_(std::move(contacts)),
      forces_(contacts_.size(), 0.0) {
  for ([[maybe_unused]] const PointContact& c : contacts_) {
    assert(c.law.IsLinear() && "the active set solves piecewise-linear laws exactly, no other");
  }
}

FullFeContactSystem::~FullFeContactSystem() = default;

const FullFeContactSystem::Factorization& FullFeContactSystem::FactorizationFor(double beta_dt2,
                                                                                double gamma_dt) {
  if (factorization_ && factorization_->beta_dt2 == beta_dt2 &&
      factorization_->gamma_dt == gamma_dt) {
    return *factorization_;
  }
  auto f = std::make_unique<Factorization>();
  f->beta_dt2 = beta_dt2;
  f->gamma_dt = gamma_dt;
  const Eigen::SparseMatrix<double> a =
      (1.0 + gamma_dt * mass_damping_per_s_) * mass_ + beta_dt2 * stiffness_;
  f->solver.compute(a);
  f->a_inv_rows.resize(Size(), static_cast<Eigen::Index>(contacts_.size()));
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    f->a_inv_rows.col(static_cast<Eigen::Index>(c)) = f->solver.solve(contacts_[c].row);
  }
  factorization_ = std::move(f);
  return *factorization_;
}

bool FullFeContactSystem::SolveAcceleration(double /*t_s*/, double beta_dt2, double gamma_dt,
                                            const Eigen::VectorXd& x_pred,
                                            const Eigen::VectorXd& v_pred, Eigen::VectorXd& a) {
  const Factorization& f = FactorizationFor(beta_dt2, gamma_dt);
  Eigen::VectorXd rhs = -(stiffness_ * x_pred);
  if (mass_damping_per_s_ != 0.0) rhs.noalias() -= mass_damping_per_s_ * (mass_ * v_pred);
  const Eigen::VectorXd a_free = f.solver.solve(rhs);
  if (f.solver.info() != Eigen::Success) return false;

  // Contact s, its linear law's k and c: F_s = F0_s - eff_s (r_s . a) while active (u < g and
  // F_s > 0).
  const auto n_c = static_cast<Eigen::Index>(contacts_.size());
  Eigen::VectorXd f0(n_c), eff(n_c);
  for (Eigen::Index s = 0; s < n_c; ++s) {
    const auto& c = contacts_[s];
    const double k = c.law.stiffness, damping = c.law.damping_n_s_per_m;
    f0[s] = k * (c.gap_m - c.row.dot(x_pred)) - damping * c.row.dot(v_pred);
    eff[s] = k * beta_dt2 + damping * gamma_dt;
  }
  auto active_at = [&](const Eigen::VectorXd& acc) {
    std::vector<Eigen::Index> set;
    for (Eigen::Index s = 0; s < n_c; ++s) {
      const auto& c = contacts_[s];
      const double ra = c.row.dot(acc);
      if (PenaltyForce(c, c.row.dot(x_pred) + beta_dt2 * ra, c.row.dot(v_pred) + gamma_dt * ra) >
          0.0) {
        set.push_back(s);
      }
    }
    return set;
  };

  a = a_free;
  std::vector<Eigen::Index> active = active_at(a);
  for (int iter = 0; iter < kMaxActiveSetIterations; ++iter) {
    // (I + D R_S^T Z_S) f_S = F0_S - D R_S^T a_free, then a = a_free + Z_S f_S.
    const auto m = static_cast<Eigen::Index>(active.size());
    Eigen::MatrixXd schur = Eigen::MatrixXd::Identity(m, m);
    Eigen::VectorXd rhs_s(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto& ci = contacts_[active[i]];
      for (Eigen::Index j = 0; j < m; ++j) {
        schur(i, j) += eff[active[i]] * ci.row.dot(f.a_inv_rows.col(active[j]));
      }
      rhs_s[i] = f0[active[i]] - eff[active[i]] * ci.row.dot(a_free);
    }
    const Eigen::VectorXd forces =
        m > 0 ? Eigen::VectorXd(schur.lu().solve(rhs_s)) : Eigen::VectorXd();
    a = a_free;
    for (Eigen::Index i = 0; i < m; ++i) a.noalias() += forces[i] * f.a_inv_rows.col(active[i]);
    std::vector<Eigen::Index> next = active_at(a);
    if (next == active) {
      std::ranges::fill(forces_, 0.0);
      for (Eigen::Index i = 0; i < m; ++i) forces_[active[i]] = forces[i];
      return true;
    }
    active = std::move(next);
  }
  return false;
}

Energies FullFeContactSystem::EnergyAt(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
  return {0.5 * v.dot(mass_ * v), 0.5 * x.dot(stiffness_ * x), ContactEnergy(contacts_, x)};
}

bool FullFeContactSystem::Dissipates() const {
  return mass_damping_per_s_ != 0.0 || AnyContactDamping(contacts_);
}

SecondOrderSystem::Powers FullFeContactSystem::PowersAt(double /*t_s*/, const Eigen::VectorXd& x,
                                                        const Eigen::VectorXd& v) const {
  return {mass_damping_per_s_ * v.dot(mass_ * v) + ContactDampingPower(contacts_, x, v), 0.0};
}

}  // namespace shockmap
