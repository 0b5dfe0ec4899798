// Contact laws (core/contact_law.h, docs/physics.md §7) against closed forms: the normal laws'
// energy and tangent stiffness, Hertz's impact of a mass on a half-space, Coulomb friction's
// stick then slip of a block on a plane and the energy it dissipates per cycle of a harmonic
// slide, a beam rubbing a stop under a base motion (energy balance), the stability bound with
// the tangential stiffness, and the static preload of a power-law zone.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/contact_law.h"
#include "core/newmark.h"
#include "core/preload_equilibrium.h"
#include "core/reached_bound.h"
#include "core/scene_model.h"
#include "core/scene_system.h"
#include "core/transient_run.h"

namespace shockmap {
namespace {

constexpr double kPi = std::numbers::pi;

// The elastic force is the derivative of the energy, and the tangent stiffness that of the
// force (central differences, relative 1e-7), for the linear law, Hertz and p = 2.3.
TEST(NormalLaw, EnergyForceAndTangentStiffnessAgree) {
  for (const NormalLaw law :
       {NormalLaw{2e6, 0.0, 1.0}, NormalLaw{3e9, 0.0, 1.5}, NormalLaw{7e12, 0.0, 2.3}}) {
    for (double d : {1e-6, 3e-5, 2e-4}) {
      const double h = 1e-4 * d;
      const double force = (law.Energy(d + h) - law.Energy(d - h)) / (2 * h);
      const double stiffness = (law.ElasticForce(d + h) - law.ElasticForce(d - h)) / (2 * h);
      EXPECT_NEAR(force / law.ElasticForce(d), 1.0, 1e-7) << law.exponent << " at " << d;
      EXPECT_NEAR(stiffness / law.TangentStiffness(d), 1.0, 1e-7) << law.exponent << " at " << d;
    }
    EXPECT_EQ(law.ElasticForce(-1e-6), 0.0);
    EXPECT_EQ(law.Energy(-1e-6), 0.0);
    EXPECT_EQ(law.Force(std::nan(""), 1.0), 0.0);
  }
  // Damping never makes the stop pull.
  const NormalLaw damped{1e6, 1e3};
  EXPECT_EQ(damped.Force(1e-6, -10.0), 0.0);
  EXPECT_DOUBLE_EQ(damped.Force(1e-3, 0.5), 1e3 + 500.0);
}

// One free mass m (a single mode of zero frequency, phi = 1 / sqrt(m)) thrown at v0 onto a stop
// of law F = k d^p. Energy gives its deepest penetration d_m = ((p + 1) m v0^2 / (2 k))^(1/(p+1))
// and peak k d_m^p; the contact lasts t_c = 2 (d_m / v0) int_0^1 (1 - x^(p+1))^(-1/2) dx, the
// integral Gamma(1 + 1/n) Gamma(1/2) / Gamma(1/2 + 1/n) with n = p + 1 (2.9432 d_m / v0 for
// Hertz).
struct PowerLawImpact {
  double mass, speed, stiffness, exponent;

  double DeepestM() const {
    return std::pow((exponent + 1) * mass * speed * speed / (2 * stiffness), 1 / (exponent + 1));
  }
  double PeakN() const { return stiffness * std::pow(DeepestM(), exponent); }
  double DurationS() const {
    const double n = exponent + 1;
    const double integral = std::tgamma(1 + 1 / n) * std::tgamma(0.5) / std::tgamma(0.5 + 1 / n);
    return 2 * DeepestM() / speed * integral;
  }
};

struct ImpactRun {
  TransientResult result;
  ReachedBound bound;
};

ImpactRun RunImpact(const PowerLawImpact& impact, double bound_penetration_m, int steps) {
  ZoneTerm zone;
  zone.a_y = 0;
  zone.phi_a = {1 / std::sqrt(impact.mass)};
  zone.gap_m = 1e-6;  // Reached at t = gap / v0.
  zone.law.normal = {impact.stiffness, 0.0, impact.exponent, bound_penetration_m};
  SceneModalSystem system(Eigen::VectorXd::Zero(1), std::nullopt, {zone}, {});
  TransientOptions options;
  options.dt_s = impact.DurationS() / steps;
  options.end_time_s = zone.gap_m / impact.speed + 1.5 * impact.DurationS();
  options.record_energy = false;
  options.track_impact_statistics = true;
  options.listed_impact_contacts = {0};
  ImpactRun run;
  run.result =
      RunTransient(system, NewmarkParameters::CentralDifference(), Eigen::VectorXd::Zero(1),
                   Eigen::VectorXd::Constant(1, impact.speed * std::sqrt(impact.mass)), options);
  run.bound = CheckReachedBound(system);
  return run;
}

class HertzImpact : public testing::TestWithParam<double> {};

// Duration and peak force within 1e-3 at 4000 steps per contact, for Hertz (p = 3/2) and the
// general power law (p = 1.2, 2.5); the run that went deeper than its bound penetration is
// flagged, with the bound at the penetration reached: 2 / sqrt(p k d_m^(p-1) / m).
TEST_P(HertzImpact, DurationAndPeakForceOfAMassOnAHalfSpace) {
  const PowerLawImpact impact{0.05, 0.3, GetParam() == 1.5 ? 2.2e9 : 5e8, GetParam()};
  const ImpactRun run = RunImpact(impact, 0.5 * impact.DeepestM(), 4000);
  ASSERT_EQ(run.result.summary.status, RunStatus::kOk) << run.result.summary.message;
  const ImpactStatistics& s = run.result.impact_statistics.at(0);
  ASSERT_EQ(s.impacts, 1);
  ASSERT_EQ(s.records.size(), 1u);
  const double duration_error = s.records[0].duration_s / impact.DurationS() - 1;
  const double peak_error = s.records[0].peak_force_n / impact.PeakN() - 1;
  std::printf("p = %.2f: contact %.6e s (closed form %.6e, error %.2e), peak %.6e N (%.6e, %.2e)\n",
              impact.exponent, s.records[0].duration_s, impact.DurationS(), duration_error,
              s.records[0].peak_force_n, impact.PeakN(), peak_error);
  EXPECT_LE(std::abs(duration_error), 1e-3);
  EXPECT_LE(std::abs(peak_error), 1e-3);
  EXPECT_NEAR(s.records[0].impact_speed_m_s / impact.speed, 1.0, 1e-3);
  ASSERT_TRUE(run.bound.exceeded);
  EXPECT_EQ(run.bound.deepest_zone, 0);
  EXPECT_NEAR(run.bound.largest_penetration_m / impact.DeepestM(), 1.0, 1e-4);
  const double tangent = impact.exponent * impact.stiffness *
                         std::pow(run.bound.largest_penetration_m, impact.exponent - 1);
  EXPECT_NEAR(run.bound.dt_sharp_reached_s / (2 / std::sqrt(tangent / impact.mass)), 1.0, 1e-12);
  // A bound penetration deeper than the impact's: not flagged.
  EXPECT_FALSE(RunImpact(impact, 2 * impact.DeepestM(), 400).bound.exceeded);
}

INSTANTIATE_TEST_SUITE_P(Exponents, HertzImpact, testing::Values(1.5, 1.2, 2.5));

// A block of mass m on a plane (two free coordinates, y normal and z tangential, unit mode
// shapes) pressed by N0 into a stop and pulled along it by a force rising slowly, F = beta t:
// it sticks while the friction force, the pull less m z'' (beta / omega_t^2 here, nothing), stays
// below mu_s N, then slides under mu N. The pull at the first sliding step is the transition
// force mu_s N within 1e-3.
TEST(Friction, BlockOnAPlaneSticksThenSlips) {
  const double normal_n = 100.0, mu = 0.3, mu_s = 0.4, k_t = 1e6;
  ZoneTerm zone;
  zone.a_y = 0;
  zone.a_z = 1;
  zone.phi_a = {1.0};
  zone.law.normal = {1e7};
  zone.law.friction = FrictionLaw{mu, mu_s, k_t, 2 * std::sqrt(k_t)};  // Critically damped.
  const StaticForceEffect press{0, 0.0, 1.0, 0.0, normal_n};
  const StaticForceEffect pull{0, 0.0, 0.0, 1.0, 60.0, 0.0, 10.0};  // beta = 6 N/s.
  std::vector<TimeLoad> loads(2);
  loads[0].shape = Eigen::Vector2d(1.0, 0.0);
  loads[0].point_force = &press;
  loads[1].shape = Eigen::Vector2d(0.0, 1.0);
  loads[1].point_force = &pull;
  SceneModalSystem system(Eigen::VectorXd::Zero(2), std::nullopt, {zone}, std::move(loads));
  NewmarkIntegrator integrator(NewmarkParameters::CentralDifference(), system);
  ASSERT_TRUE(integrator.Init(Eigen::Vector2d(normal_n / 1e7, 0.0), Eigen::Vector2d::Zero()));
  const double dt = 5e-5;
  double transition_n = -1.0, largest_stuck_error = 0.0;
  for (int n = 1; n <= 200000 && transition_n < 0; ++n) {
    ASSERT_TRUE(integrator.Step(dt));
    const double pull_n = pull.At(integrator.T());
    const double friction_n = system.Contacts().TangentialForce(0);
    if (system.Contacts().Sticks(0)) {
      // Sticking, the friction force balances the pull (after the first 10 ms of transient).
      if (integrator.T() > 0.01) {
        largest_stuck_error = std::max(largest_stuck_error, std::abs(friction_n + pull_n));
      }
    } else {
      transition_n = pull_n;
      EXPECT_NEAR(friction_n, -mu * system.Contacts().Forces()[0], 1e-12);
    }
  }
  const double expected = mu_s * normal_n;
  largest_stuck_error /= expected;
  std::printf(
      "stick-slip: transition at a pull of %.6f N (mu_s N = %.6f N, error %.2e); "
      "sticking, the friction force balanced the pull within %.2e of mu_s N\n",
      transition_n, expected, transition_n / expected - 1, largest_stuck_error);
  EXPECT_NEAR(transition_n / expected, 1.0, 1e-3);
  EXPECT_LT(largest_stuck_error, 1e-3);
}

// A Jenkins element (tangential spring k_t and a Coulomb slider mu N) driven through the slip
// s = U sin(omega t) dissipates 4 mu N (U - mu N / k_t) per cycle, the area of its
// parallelogram loop, in either convention (both stick at a reversal until the spring has
// unloaded 2 mu N / k_t). Sampled at 20000 points per cycle over a steady cycle, the work taken,
// the integral of -F ds, and the slider's work agree with it within 1e-3. code_aster's
// convention is sampled half a step off the reversals: at a sample on a reversal itself, the
// slip rate within the machine epsilon and the spring at mu N give ftang's zero force at rest,
// the spring relaxed, and the stick that follows unloads mu N / k_t only.
TEST(Friction, EnergyDissipatedPerCycleOfAHarmonicSlide) {
  for (const FrictionConvention convention :
       {FrictionConvention::kReturnMapping, FrictionConvention::kCodeAster}) {
    FrictionLaw law{0.25, 0.25, 2e5, 0.0};
    law.convention = convention;
    const double normal_n = 40.0, amplitude_m = 3e-4, omega = 2 * kPi * 5.0;
    const int samples = 20000;
    const double dt = 2 * kPi / omega / samples;
    FrictionState state = ClosingFrictionState(law, 0.0, false);
    double force = 0.0, work = 0.0, dissipated = 0.0, power_before = 0.0;
    auto slip = [&](double t) { return amplitude_m * std::sin(omega * t); };
    const double phase = convention == FrictionConvention::kCodeAster ? 0.5 : 0.0;
    for (int n = 0; n <= 2 * samples; ++n) {
      const double t = (n + phase) * dt, rate = amplitude_m * omega * std::cos(omega * t);
      const double next = FrictionForce(law, normal_n, slip(t), rate, state);
      const double power = FrictionDissipatedPower(law, state, dt, rate);
      if (n > samples) {  // The second cycle: steady.
        work += -0.5 * (force + next) * (slip(t) - slip(t - dt));
        dissipated += 0.5 * dt * (power_before + power);
      }
      force = next;
      power_before = power;
    }
    const double limit = law.coefficient * normal_n;
    const double expected = 4 * limit * (amplitude_m - limit / law.tangential_stiffness_n_per_m);
    std::printf(
        "harmonic slide (%s): per cycle, closed form %.8e J; slider's work error %.2e, work "
        "taken error %.2e\n",
        convention == FrictionConvention::kCodeAster ? "code_aster" : "return_mapping", expected,
        dissipated / expected - 1, work / expected - 1);
    EXPECT_NEAR(work / expected, 1.0, 1e-3);
    EXPECT_NEAR(dissipated / expected, 1.0, 1e-3);
  }
}

// code_aster's convention, update by update on a scripted slip, against DIS_CHOC's ftang worked
// by hand (N = 10 N, mu = 0.2, mu_s = 0.3, k_t = 1e4 N/m): a zone closed at the run's start
// slides at once (force 0 at rest, then -mu N sign(s')) where the default convention would
// stick; a reversal sticks from the last sliding force, OLDFT - k_t (s - OLDXLO); a sticking
// force beyond mu_s N slides under -mu N sign(s'); a slip rate at or below 1e-6 m/s ends a
// slide; AMOR_TAN adds -c_t s' while sticking.
TEST(Friction, CodeAsterConventionFollowsDisChocUpdateByUpdate) {
  FrictionLaw law{0.2, 0.3, 1e4, 0.0};
  law.convention = FrictionConvention::kCodeAster;
  const double n = 10.0;
  FrictionState state = ClosingFrictionState(law, 0.0, true);
  struct Update {
    double slip_m, rate_m_s, force_n;
    bool sliding;
  };
  const Update script[] = {
      {0.0, 0.0, 0.0, true},         // At rest: slides with no force, anchored there.
      {1e-4, 0.2, -2.0, true},       // Moving: -mu N sign(s'), though k_t s = 1 N < mu_s N.
      {2e-4, 0.2, -2.0, true},       // Keeps sliding: OLDFT = -2 N, OLDXLO = 2e-4 m.
      {1.5e-4, -0.1, -1.5, false},   // Reversal: -2 - 1e4 (1.5e-4 - 2e-4).
      {1e-4, -0.1, -1.0, false},     // Sticks: -2 - 1e4 (1e-4 - 2e-4).
      {-4e-4, -0.1, 2.0, true},      // -2 + 6 = 4 > mu_s N: slides, +mu N.
      {-5e-4, -0.1, 2.0, true},      // Keeps sliding: OLDFT = 2 N, OLDXLO = -5e-4 m.
      {-5.5e-4, -5e-7, 2.5, false},  // Too slow to slide: 2 - 1e4 (-5.5e-4 + 5e-4).
      {-5.5e-4, -0.1, 2.5, false},   // Stuck stays stuck while within mu_s N.
  };
  for (const Update& u : script) {
    const double force = FrictionForce(law, n, u.slip_m, u.rate_m_s, state);
    EXPECT_NEAR(force, u.force_n, 1e-12) << "slip " << u.slip_m;
    EXPECT_EQ(state.sliding, u.sliding) << "slip " << u.slip_m;
  }
  // The default convention sticks where code_aster's slid (k_t s = 1 N < mu_s N).
  FrictionLaw default_law{0.2, 0.3, 1e4, 0.0};
  FrictionState default_state = ClosingFrictionState(default_law, 0.0, true);
  FrictionForce(default_law, n, 0.0, 0.0, default_state);
  EXPECT_NEAR(FrictionForce(default_law, n, 1e-4, 0.2, default_state), -1.0, 1e-12);
  EXPECT_FALSE(default_state.sliding);
  // AMOR_TAN: sticking, -c_t s' joins the spring's force.
  law.tangential_damping_n_s_per_m = 5.0;
  state = ClosingFrictionState(law, 0.0, false);
  EXPECT_NEAR(FrictionForce(law, n, 1e-5, 1e-7, state), -1e4 * 1e-5 - 5.0 * 1e-7, 1e-12);
  EXPECT_FALSE(state.sliding);
}

// A cantilever bending in both planes, its tip preloaded against a stop along y with friction,
// shaken along z by its base: the tip sticks, then rubs. kinetic + strain + contact (normal and
// tangential springs) + dissipated equals the work of the base within 1e-3 of that work's
// magnitude at every record, and the friction dissipated some of it.
TEST(Friction, BeamRubbingAStopUnderABaseMotionBalancesItsEnergy) {
  Scene scene;
  scene.planes = BendingPlanes::kBoth;
  SceneBeam beam;
  beam.name = "beam";
  beam.ei_n_m2 = 1.5e4;
  beam.rho_a_kg_per_m = 12.7;
  scene.beams = {beam};
  SceneZone stop;
  stop.name = "stop";
  stop.height_m = 1.0;
  stop.normal_y = 1.0;
  stop.gap_m = -1e-4;  // Preloaded: the tip starts pressed on the stop.
  stop.stiffness_n_per_m = 1e6;
  stop.friction = FrictionLaw{0.3, 0.3, 5e5, 0.0};
  scene.zones = {stop};
  BaseMotionEffect base;
  base.dir_y = 0.0, base.dir_z = 1.0;
  base.amplitude_m_s2 = 40.0, base.duration_s = 0.02;
  scene.base_motion = base;
  scene.solver.r_ftrunc = 30;
  scene.solver.end_time_s = 0.2;
  scene.solver.dt.factor = 0.05;
  SceneModel model = BuildSceneModel(scene);
  TransientOptions options;
  options.end_time_s = scene.solver.end_time_s;
  options.dt_s = scene.solver.dt.Resolve(model.bounds);
  options.record_contact_forces = true;
  options.track_impact_statistics = true;
  const TransientResult r = RunTransient(*model.system, NewmarkParameters::CentralDifference(),
                                         model.x0, model.v0, options);
  ASSERT_EQ(r.summary.status, RunStatus::kOk) << r.summary.message;
  const EnergyHistory& e = r.energy;
  double largest_error = 0.0, largest_work = 0.0;
  for (std::size_t i = 0; i < e.kinetic_j.values.size(); ++i) {
    const double balance = e.kinetic_j.values[i] + e.strain_j.values[i] + e.contact_j.values[i] +
                           e.dissipated_j.values[i] - e.kinetic_j.values[0] - e.strain_j.values[0] -
                           e.contact_j.values[0] - e.external_work_j.values[i];
    largest_error = std::max(largest_error, std::abs(balance));
    largest_work = std::max(largest_work, std::abs(e.external_work_j.values[i]));
  }
  const ImpactStatistics& s = r.impact_statistics.at(0);
  std::printf(
      "rubbing beam: work of the base up to %.4e J, energy balance within %.2e of it; "
      "friction dissipated %.4e J, wear work rate %.4e W while sliding\n",
      largest_work, largest_error / largest_work, e.dissipated_j.values.back(), s.wear_work_rate_w);
  EXPECT_LT(largest_error, 1e-3 * largest_work);
  EXPECT_GT(e.dissipated_j.values.back(), 0.05 * largest_work);
  ASSERT_TRUE(s.wear_available);
  EXPECT_TRUE(s.sliding_only);
  EXPECT_GT(s.wear_work_rate_w, 0.0);
  // Sliding, the friction force is mu N: its power is mu times the wear work rate.
  EXPECT_NEAR(s.friction_power_w / (0.3 * s.wear_work_rate_w), 1.0, 1e-9);
}

// The sharp bound of a free block (omega = 0) on a stop with friction is set by the stiffer of
// the normal law (k_n phi^2) and the tangential spring (k_t phi^2).
TEST(Friction, SharpBoundIncludesTheTangentialStiffness) {
  ZoneTerm zone;
  zone.a_y = 0;
  zone.a_z = 1;
  zone.phi_a = {0.5};
  zone.law.normal = {1e6};
  zone.law.friction = FrictionLaw{0.3, 0.3, 4e6, 0.0};
  const SceneModalSystem system(Eigen::VectorXd::Zero(2), std::nullopt, {zone}, {});
  const std::vector<double> stiffness = system.Contacts().BoundStiffnesses();
  EXPECT_DOUBLE_EQ(SharpOmegaSquared(system, stiffness), 4e6 * 0.25);
  EXPECT_NEAR(system.StiffestOmegaSquared(stiffness) / (4e6 * 0.25), 1.0, 1e-9);
}

// One mode (omega, phi) held by a preloaded Hertz zone: the equilibrium balances the mode's
// stiffness against the law, omega^2 q = -phi k d^p with the penetration d = phi q - g > 0, to
// rounding.
TEST(PowerLaw, PreloadEquilibriumOfAHertzZone) {
  ZoneTerm zone;
  zone.a_y = 0;
  zone.phi_a = {0.8};
  zone.gap_m = -2e-4;
  zone.law.normal = {3e9, 0.0, 1.5, 1e-4};
  const SceneModalSystem system(Eigen::VectorXd::Constant(1, 300.0), std::nullopt, {zone}, {});
  const Eigen::VectorXd x = PreloadEquilibrium(system);
  const double d = 0.8 * x[0] - zone.gap_m;
  ASSERT_GT(d, 0.0);
  const double residual = 300.0 * 300.0 * x[0] + 0.8 * 3e9 * std::pow(d, 1.5);
  EXPECT_LT(std::abs(residual), 1e-9 * 3e9 * std::pow(d, 1.5));
}

}  // namespace
}  // namespace shockmap
