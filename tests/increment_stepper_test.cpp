// The central-difference step in increment form (core/increment_stepper.h) against the discrete
// solution of the scheme and against Newmark's form of the same scheme.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/cantilever_impact.h"
#include "core/increment_stepper.h"
#include "core/newmark.h"
#include "core/scene_system.h"
#include "core/transient_run.h"

namespace shockmap {
namespace {

// One mode against a stop it never reaches: q_n = q0 cos(n theta), cos theta = 1 - (w dt)^2 / 2,
// the central-difference scheme's own solution from rest.
TEST(IncrementStepper, FreeModeFollowsTheSchemesDiscreteSolution) {
  const double omega = 2.0 * std::numbers::pi * 13.0, dt = 1e-3, q0 = 0.7;
  ZoneTerm stop;
  stop.a_y = 0;
  stop.phi_a = {1.0};
  stop.gap_m = 10.0;
  stop.law.normal.stiffness = 1e6;
  SceneModalSystem system(Eigen::VectorXd::Constant(1, omega), std::nullopt, {stop}, {});
  const std::vector<Eigen::VectorXd> observed{Eigen::VectorXd::Ones(1)};
  auto stepper = IncrementStepper::For(system, dt, observed);
  ASSERT_NE(stepper, nullptr);
  stepper->Init(Eigen::VectorXd::Constant(1, q0), Eigen::VectorXd::Zero(1));
  const int steps = 2000;
  std::vector<double> seen(steps), forces(steps);
  stepper->Advance(steps, seen.data(), forces.data());
  const double theta = std::acos(1.0 - 0.5 * omega * omega * dt * dt);
  for (int n = 1; n <= steps; ++n) {
    ASSERT_NEAR(seen[n - 1], q0 * std::cos(n * theta), 1e-12 * q0) << "step " << n;
    ASSERT_EQ(forces[n - 1], 0.0);
  }
  // v_n = -q0 sin(n theta) sin(theta) / dt (the scheme's velocity, (q_{n+1} - q_{n-1}) / 2dt).
  EXPECT_NEAR(stepper->V()[0], -q0 * std::sin(steps * theta) * std::sin(theta) / dt,
              1e-10 * q0 * omega);
  EXPECT_NEAR(stepper->T(), steps * dt, 1e-15);
}

// The paper's problem at R_k = 3000 over the Fig. 4 window: the increment form and Newmark's
// form are the same scheme, so their tip and force histories agree to rounding.
TEST(IncrementStepper, AgreesWithNewmarksFormOnThePapersProblem) {
  const CantileverImpact problem;
  const ImpactModel model = BuildImpactModel(problem, Scheme::kExplicitModal, 300.0);
  const double dt = 0.5 * model.bounds.dt_sharp_s;
  const std::vector<Eigen::VectorXd> observed{model.tip_row};
  auto stepper = IncrementStepper::For(*model.system, dt, observed);
  ASSERT_NE(stepper, nullptr);
  stepper->Init(model.x0, model.v0);
  NewmarkIntegrator newmark(NewmarkParameters::CentralDifference(), *model.system);
  ASSERT_TRUE(newmark.Init(model.x0, model.v0));
  const int steps = static_cast<int>(0.03 / dt);
  double largest_force = 0.0, tip_gap = 0.0, force_gap = 0.0;
  for (int n = 0; n < steps; ++n) {
    double tip = 0.0, force = 0.0;
    stepper->Advance(1, &tip, &force);
    ASSERT_TRUE(newmark.Step(dt));
    tip_gap = std::max(tip_gap, std::abs(tip - model.tip_row.dot(newmark.X())));
    force_gap = std::max(force_gap, std::abs(force - model.system->LastContactForces()[0]));
    largest_force = std::max(largest_force, force);
  }
  EXPECT_GT(largest_force, 0.0) << "the window holds shocks";
  EXPECT_LT(tip_gap, 1e-10 * problem.initial_tip_m);
  EXPECT_LT(force_gap, 1e-10 * largest_force);
  EXPECT_LT((stepper->V() - newmark.V()).norm(), 1e-9 * newmark.V().norm());
}

// What the increment form does not take runs Newmark's general step.
TEST(IncrementStepper, TakesOnlyUndampedLinearZonesWithoutLoads) {
  ZoneTerm stop;
  stop.a_y = 0;
  stop.phi_a = {1.0};
  stop.law.normal.stiffness = 1e6;
  const Eigen::VectorXd omega = Eigen::VectorXd::Constant(1, 10.0);
  const std::vector<Eigen::VectorXd> none;
  EXPECT_NE(IncrementStepper::For(SceneModalSystem(omega, std::nullopt, {stop}, {}), 1e-3, none),
            nullptr);
  EXPECT_EQ(IncrementStepper::For(
                SceneModalSystem(omega, Eigen::VectorXd::Constant(1, 0.1), {stop}, {}), 1e-3, none),
            nullptr)
      << "modal damping";
  ZoneTerm damped = stop, hertz = stop, rubbing = stop;
  damped.law.normal.damping_n_s_per_m = 10.0;
  hertz.law.normal.exponent = 1.5;
  rubbing.law.friction = FrictionLaw{0.3, 0.3, 1e5, 0.0};
  for (const ZoneTerm& z : {damped, hertz, rubbing}) {
    EXPECT_EQ(IncrementStepper::For(SceneModalSystem(omega, std::nullopt, {z}, {}), 1e-3, none),
              nullptr);
  }
  const std::vector<ZoneTerm> many(IncrementStepper::kMaxZones + 1, stop);
  EXPECT_EQ(IncrementStepper::For(SceneModalSystem(omega, std::nullopt, many, {}), 1e-3, none),
            nullptr);
}

// RunTransient takes the increment form for the paper's problem: its histories (every third
// step, velocities and energies included, a last block shorter than a check's) are Newmark's
// form's, stepped here by hand, to rounding.
TEST(IncrementStepper, ARunRecordsWhatNewmarksFormRecords) {
  CantileverImpact problem;
  problem.r_k = 1e4;
  const ImpactModel model = BuildImpactModel(problem, Scheme::kExplicitModal, 100.0);
  TransientOptions options;
  options.end_time_s = 0.03;
  options.dt_s = 0.3 * model.bounds.dt_sharp_s;
  options.record_stride = 3;
  options.observed_rows = {model.tip_row};
  const TransientResult run = RunTransient(*model.system, NewmarkParameters::CentralDifference(),
                                           model.x0, model.v0, options);
  ASSERT_EQ(run.summary.status, RunStatus::kOk) << run.summary.message;
  ASSERT_NE(run.summary.steps_taken % options.divergence_check_stride, 0);

  NewmarkIntegrator newmark(NewmarkParameters::CentralDifference(), *model.system);
  ASSERT_TRUE(newmark.Init(model.x0, model.v0));
  // The first mode's velocity amplitude.
  const double v_scale = 2.0 * std::numbers::pi * problem.F1Hz() * problem.initial_tip_m;
  std::size_t records = 0;
  for (std::int64_t n = 0; n <= run.summary.steps_taken; ++n) {
    if (n > 0) {
      ASSERT_TRUE(newmark.Step(run.summary.dt_used_s));
    }
    if (n % options.record_stride != 0) continue;
    const Energies e = model.system->EnergyAt(newmark.X(), newmark.V());
    ASSERT_NEAR(run.displacement_m[0].values[records], model.tip_row.dot(newmark.X()),
                1e-10 * problem.initial_tip_m)
        << "record " << records;
    ASSERT_NEAR(run.velocity_m_s[0].values[records], model.tip_row.dot(newmark.V()),
                1e-10 * v_scale);
    ASSERT_NEAR(run.contact_force_n[0].values[records], model.system->LastContactForces()[0],
                1e-9 * problem.SpringStiffness() * problem.initial_tip_m);
    ASSERT_NEAR(run.energy.kinetic_j.values[records] + run.energy.strain_j.values[records] +
                    run.energy.contact_j.values[records],
                e.Total(), 1e-10 * run.summary.initial_energy_j);
    ++records;
  }
  EXPECT_EQ(records, run.displacement_m[0].values.size());
}

}  // namespace
}  // namespace shockmap
