// Temporary: the canonical problem through the scene model against the retiring
// ModalContactSystem, same basis and state, over the comparison's window.

#include <gtest/gtest.h>

#include <cstdio>

#include "core/beam_fe.h"
#include "core/cantilever_impact.h"
#include "core/modal_basis.h"
#include "core/modal_contact_system.h"
#include "core/transient_run.h"

namespace shockmap {
namespace {

struct Old {
  std::unique_ptr<SecondOrderSystem> system;
  Eigen::VectorXd x0, tip_row;
};

Old OldModel(const CantileverImpact& problem, double r_ftrunc) {
  const int n_el = DefaultElementCount(r_ftrunc);
  const FeBeamModel fe =
      AssembleBeam(problem.beam, n_el, EndCondition::kClamped, EndCondition::kFree);
  ModalBasis basis = ComputeModalBasis(fe, r_ftrunc * problem.F1Hz());
  if (basis.NumModes() == 0) basis = ComputeLowestModes(fe, 1);
  Old o;
  o.tip_row = basis.shapes.transpose() * fe.DeflectionRow(problem.beam.length_m);
  const PointContact c{o.tip_row, problem.gap_m, problem.SpringStiffness(),
                       problem.contact_damping_n_s_per_m};
  std::optional<Eigen::VectorXd> damping;
  if (problem.mass_damping_per_s > 0.0)
    damping = Eigen::VectorXd::Constant(basis.NumModes(), problem.mass_damping_per_s);
  o.system = std::make_unique<ModalContactSystem>(basis.omega_rad_s, damping, std::vector{c});
  o.x0 = Eigen::VectorXd::Zero(basis.NumModes());
  o.x0[0] = problem.initial_tip_m / o.tip_row[0];
  return o;
}

double RelDiff(const UniformSignal& a, const UniformSignal& b) {
  EXPECT_EQ(a.values.size(), b.values.size());
  double d = 0.0, m = 0.0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    d = std::max(d, std::abs(a.values[i] - b.values[i]));
    m = std::max(m, std::abs(a.values[i]));
  }
  return m > 0.0 ? d / m : d;
}

TEST(ReducedModelParity, SceneModelReproducesModalContactSystem) {
  for (double rk : {1.0, 3000.0, 1e6}) {
    for (double rf : {10.0, 300.0, 1000.0}) {
      for (double alpha : {0.0, 40.0}) {
        for (double c : {0.0, 200.0}) {
          for (double gap : {0.0, -2e-4}) {
            CantileverImpact p;
            p.gap_m = gap;
            p.r_k = rk;
            p.mass_damping_per_s = alpha;
            p.contact_damping_n_s_per_m = c * std::sqrt(rk);
            const ImpactModel m = BuildImpactModel(p, Scheme::kExplicitModal, rf);
            Old o = OldModel(p, rf);
            ASSERT_EQ(o.x0.size(), m.x0.size());
            TransientOptions opt;
            opt.end_time_s = 0.06;
            opt.dt_s = 0.1 * m.bounds.dt_sharp_s;
            opt.observed_rows = {m.tip_row};
            const TransientResult n =
                RunTransient(*m.system, NewmarkParameters::CentralDifference(), m.x0, m.v0, opt);
            opt.observed_rows = {o.tip_row};
            const TransientResult r =
                RunTransient(*o.system, NewmarkParameters::CentralDifference(), o.x0, m.v0, opt);
            ASSERT_EQ(n.summary.status, r.summary.status);
            const double tip = RelDiff(r.displacement_m[0], n.displacement_m[0]);
            const double vel = RelDiff(r.velocity_m_s[0], n.velocity_m_s[0]);
            const double force = RelDiff(r.contact_force_n[0], n.contact_force_n[0]);
            const double kin = RelDiff(r.energy.kinetic_j, n.energy.kinetic_j);
            const double dis = RelDiff(r.energy.dissipated_j, n.energy.dissipated_j);
            std::printf(
                "gap %g rk %-6g rf %-5g alpha %-3g c %-7g modes %3d steps %7lld x0 %s tip %.3e vel "
                "%.3e "
                "force %.3e kin %.3e diss %.3e\n",
                p.gap_m, rk, rf, alpha, p.contact_damping_n_s_per_m, static_cast<int>(m.x0.size()),
                static_cast<long long>(n.summary.steps_taken), (o.x0 == m.x0 ? "==" : "!="), tip,
                vel, force, kin, dis);
            EXPECT_LE(tip, 1e-12);
            EXPECT_LE(force, 1e-12);
            EXPECT_EQ(RelDiff(r.energy.strain_j, n.energy.strain_j), 0.0);
            EXPECT_EQ(RelDiff(r.energy.contact_j, n.energy.contact_j), 0.0);
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace shockmap
