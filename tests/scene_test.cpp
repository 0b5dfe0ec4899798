// Verification of the scene engine (core/scene_*): analytic modal solutions, effects that are
// absent cost nothing and change nothing, conservation across beam-to-beam contact, base motion
// against the static solution, and the stability bound of large scenes.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "core/preload_equilibrium.h"
#include "core/scene_model.h"
#include "core/transient_run.h"

namespace shockmap {
namespace {

constexpr double kB1 = 1.8751040687119611;  // Clamped-free roots of 1 + cosh b cos b = 0.
constexpr double kB2 = 4.6940911329741746;

SceneBeam Cantilever(const std::string& name) {
  SceneBeam b;
  b.name = name;
  b.length_m = 1.0;
  b.ei_n_m2 = 1.5e5;
  b.rho_a_kg_per_m = 127.0;
  b.n_elements = 55;
  return b;
}

double OmegaOf(const SceneBeam& b, double root) {
  return root * root * std::sqrt(b.ei_n_m2 / (b.rho_a_kg_per_m * std::pow(b.length_m, 4)));
}

ObservedPoint Tip(int beam, double height_m) { return {"tip", beam, height_m, 0}; }

TransientResult Integrate(const Scene& scene, SceneModel& model, double dt_s, bool energy = false) {
  TransientOptions options;
  options.end_time_s = scene.solver.end_time_s;
  options.dt_s = dt_s;
  options.record_energy = energy;
  options.record_contact_forces = !scene.zones.empty();
  options.observed_rows = model.observed_rows;
  return RunTransient(*model.system, NewmarkParameters::CentralDifference(), model.x0, model.v0,
                      options);
}

TEST(SceneEngine, WithoutContactTheTipFollowsTheAnalyticModes) {
  Scene scene;
  scene.beams = {Cantilever("beam")};
  scene.initial_state = {{.beam = 0, .mode = 1, .tip_m = 1e-3},
                         {.beam = 0, .mode = 2, .tip_m = 2e-4}};
  scene.solver.end_time_s = 0.1;
  scene.outputs.displacements = {Tip(0, 1.0)};
  SceneModel model = BuildSceneModel(scene);
  EXPECT_FALSE(model.system->Dissipates());
  EXPECT_FALSE(model.system->HasExternalLoads());
  const TransientResult r = Integrate(scene, model, 0.1 * model.bounds.dt_sharp_s);
  ASSERT_EQ(r.summary.status, RunStatus::kOk);

  const double w1 = OmegaOf(scene.beams[0], kB1), w2 = OmegaOf(scene.beams[0], kB2);
  const UniformSignal& tip = r.displacement_m[0];
  double worst = 0.0;
  for (std::size_t i = 0; i < tip.values.size(); ++i) {
    const double t = tip.TimeAt(i);
    worst = std::max(worst,
                     std::abs(tip.values[i] - 1e-3 * std::cos(w1 * t) - 2e-4 * std::cos(w2 * t)));
  }
  // Phase error of central differences over 0.1 s, (w dt)^2 w t / 24, is 6e-5 rad on mode 2.
  EXPECT_LT(worst, 2e-8);
}

TEST(SceneEngine, AZoneWhoseGapNeverClosesChangesNothing) {
  Scene without;
  without.beams = {Cantilever("beam")};
  without.initial_state = {{.beam = 0, .mode = 1, .tip_m = 1e-3}};
  without.solver.end_time_s = 0.05;
  without.outputs.displacements = {Tip(0, 1.0), Tip(0, 0.5)};
  Scene with = without;
  with.zones = {{.name = "far",
                 .beam_a = 0,
                 .height_m = 1.0,
                 .normal_y = -1.0,
                 .gap_m = 0.5,
                 .stiffness_n_per_m = 1e9,
                 .damping_n_s_per_m = 1e3}};
  SceneModel a = BuildSceneModel(without), b = BuildSceneModel(with);
  const double dt = 0.1 * a.bounds.dt_sharp_s;  // The same absolute step for both.
  const TransientResult ra = Integrate(without, a, dt), rb = Integrate(with, b, dt);
  ASSERT_EQ(ra.summary.steps_taken, rb.summary.steps_taken);
  for (std::size_t p = 0; p < ra.displacement_m.size(); ++p) {
    EXPECT_EQ(ra.displacement_m[p].values, rb.displacement_m[p].values);
    EXPECT_EQ(ra.velocity_m_s[p].values, rb.velocity_m_s[p].values);
  }
  ASSERT_EQ(rb.contact_force_n.size(), 1u);
  for (double f : rb.contact_force_n[0].values) ASSERT_EQ(f, 0.0);
}

// Two free-free beams side by side, one thrown at the other: contact forces are equal and
// opposite, so the total momentum (carried by the rigid-body modes) is conserved to rounding;
// the undamped energy returns to its initial value once they separate, to the scheme's order.
struct Collision {
  Scene scene;
  Collision() {
    for (const char* name : {"a", "b"}) {
      SceneBeam b = Cantilever(name);
      b.at_zero = EndCondition::kFree;
      b.n_elements = 20;
      scene.beams.push_back(b);
    }
    for (double h : {0.1, 0.5, 0.9}) {
      scene.zones.push_back({.name = "z",
                             .beam_a = 0,
                             .beam_b = 1,
                             .height_m = h,
                             .normal_y = 1.0,
                             .gap_m = 1e-4,
                             .stiffness_n_per_m = 1e8});
    }
    scene.initial_state = {{.beam = 0, .velocity_m_s = 0.1}};
    scene.solver.r_ftrunc = 30.0;
    scene.solver.end_time_s = 0.02;
  }
};

TEST(SceneEngine, TwoFreeBeamsInContactConserveMomentumAndEnergy) {
  Collision c;
  SceneModel model = BuildSceneModel(c.scene);
  ASSERT_EQ(model.momentum_rows.size(), 1u);
  const double p0 = model.momentum_rows[0].dot(model.v0);
  EXPECT_NEAR(p0, 0.1 * 127.0, 1e-9);  // m v of beam a: the rigid translation is in its basis.

  double drift[4] = {0, 0, 0, 0};
  for (int refine = 0; refine < 4; ++refine) {
    const double dt = 0.2 * model.bounds.dt_sharp_s / (1 << refine);
    NewmarkIntegrator integrator(NewmarkParameters::CentralDifference(), *model.system);
    integrator.Init(model.x0, model.v0, 0.0);
    const double e0 = model.system->EnergyAt(model.x0, model.v0).Total();
    bool touched = false;
    double worst_momentum = 0.0;
    while (integrator.T() < c.scene.solver.end_time_s) {
      integrator.Step(dt);
      for (double f : model.system->LastContactForces()) touched = touched || f > 0.0;
      worst_momentum =
          std::max(worst_momentum, std::abs(model.momentum_rows[0].dot(integrator.V()) - p0) / p0);
    }
    ASSERT_TRUE(touched);
    // Exact in exact arithmetic; the eigenvectors' round-off leaves ~5e-10 (measured), the
    // same at every dt: no accumulation over the steps.
    EXPECT_LT(worst_momentum, 1e-9);
    bool open = true;
    for (double f : model.system->LastContactForces()) open = open && f == 0.0;
    ASSERT_TRUE(open) << "the beams should have separated by the end";
    drift[refine] =
        std::abs(model.system->EnergyAt(integrator.X(), integrator.V()).Total() - e0) / e0;
  }
  // The energy error of a penalty contact depends on where the steps fall around each switch,
  // so successive ratios scatter (measured 2.7, 5.0, 12); over the 8x refinement the error falls
  // at least as fast as dt^2 (measured slope 2.4).
  EXPECT_LT(drift[0], 1e-2);
  for (int i = 1; i < 4; ++i) EXPECT_LT(drift[i], drift[i - 1]);
  EXPECT_GT(std::log(drift[0] / drift[3]) / std::log(8.0), 1.9);
}

TEST(SceneEngine, ConstantBaseAccelerationSettlesOnTheStaticDeflection) {
  Scene scene;
  scene.beams = {Cantilever("beam")};
  BaseMotionEffect base;
  base.table_t_s = {0.0, 10.0};
  base.table_a_m_s2 = {9.81, 9.81};
  scene.base_motion = base;
  scene.modal_damping = ModalDampingEffect{.ratios = {0.2}};
  scene.solver.r_ftrunc = 30.0;
  scene.solver.end_time_s = 0.6;
  scene.outputs.displacements = {Tip(0, 1.0)};
  SceneModel model = BuildSceneModel(scene);
  EXPECT_TRUE(model.system->HasExternalLoads());
  const TransientResult r = Integrate(scene, model, 0.5 * model.bounds.dt_sharp_s, true);
  ASSERT_EQ(r.summary.status, RunStatus::kOk);
  // Relative to its support, the beam carries the inertial load -rho A a: q L^4 / (8 EI).
  const SceneBeam& b = scene.beams[0];
  const double expected = -b.rho_a_kg_per_m * 9.81 * std::pow(b.length_m, 4) / (8.0 * b.ei_n_m2);
  // Mode 1 decays as exp(-0.2 w1 t) = 5e-7 by 0.6 s; 4 modes hold the static shape to 1e-4.
  EXPECT_NEAR(r.displacement_m[0].values.back(), expected, 2e-4 * std::abs(expected));
  // Energy balance with the work of the base: kinetic + strain + dissipated = external work.
  const EnergyHistory& e = r.energy;
  const double total =
      e.kinetic_j.values.back() + e.strain_j.values.back() + e.dissipated_j.values.back();
  EXPECT_NEAR(total, e.external_work_j.values.back(), 1e-3 * e.external_work_j.values.back());
}

// A tip force on a cantilever truncated to its first mode: the static deflection in the basis
// misses the higher modes' share; with static correction at the tip it is F L^3 / (3 EI) (exact
// for Hermite cubics at a node) and the retained mode is unchanged.
TEST(SceneEngine, StaticCorrectionMakesTheContactPointStaticResponseExact) {
  Scene scene;
  scene.beams = {Cantilever("beam")};
  scene.zones = {
      {.name = "tip", .height_m = 1.0, .normal_y = -1.0, .gap_m = 0.5, .stiffness_n_per_m = 1e9}};
  scene.initial_state = {{.beam = 0, .tip_m = 0.0, .static_force_n = 100.0, .height_m = 1.0}};
  scene.solver.r_ftrunc = 2.0;  // f2 = 6.27 f1: one mode.
  scene.outputs.displacements = {Tip(0, 1.0)};
  const SceneBeam& b = scene.beams[0];
  const double exact = 100.0 * std::pow(b.length_m, 3) / (3.0 * b.ei_n_m2);

  const SceneModel truncated = BuildSceneModel(scene);
  ASSERT_EQ(truncated.modes_per_beam[0], 1);
  const double one_mode = truncated.observed_rows[0].dot(truncated.x0);
  EXPECT_GT(std::abs(one_mode - exact), 0.02 * exact);  // The first mode carries ~97 %.

  scene.solver.static_correction = true;
  const SceneModel corrected = BuildSceneModel(scene);
  ASSERT_EQ(corrected.modes_per_beam[0], 2);
  EXPECT_NEAR(corrected.observed_rows[0].dot(corrected.x0), exact, 1e-9 * exact);
  // The first frequency is unchanged (strain energy of a unit modal coordinate: omega^2 / 2) to
  // the accuracy of the eigensolver (measured 7.5e-9: the enlarged Ritz space even lowers it);
  // the static mode sits above the truncation, and the paper's bound follows it.
  auto omega_squared = [](const SceneModel& m, int k) {
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(m.system->Size());
    unit[k] = 1.0;
    return 2.0 * m.system->EnergyAt(unit, Eigen::VectorXd::Zero(unit.size())).strain_j;
  };
  EXPECT_NEAR(omega_squared(corrected, 0), omega_squared(truncated, 0),
              2e-8 * omega_squared(truncated, 0));
  const double f1 = OmegaOf(b, kB1) / (2.0 * std::numbers::pi);
  EXPECT_GT(std::sqrt(omega_squared(corrected, 1)) / (2.0 * std::numbers::pi), 2.0 * f1);
  EXPECT_LT(corrected.bounds.dt_paper_s, truncated.bounds.dt_paper_s);
}

// A cantilever preloaded against a stop at its tip (gap -g): with static correction the tip's
// static stiffness is exactly 3 EI / L^3 = k_b, so the equilibrium force is k k_b g / (k + k_b);
// the run starts there and, without loads, stays at rest with that force. A second stop with a
// gap the equilibrium does not close stays open.
TEST(SceneEngine, PreloadedZonesStartAtTheirStaticEquilibrium) {
  Scene scene;
  scene.beams = {Cantilever("beam")};
  const double g = 1e-3, k = 1e6;
  scene.zones = {
      {.name = "preloaded", .height_m = 1.0, .normal_y = 1.0, .gap_m = -g, .stiffness_n_per_m = k},
      {.name = "open", .height_m = 0.5, .normal_y = -1.0, .gap_m = 1e-3, .stiffness_n_per_m = k}};
  scene.solver.r_ftrunc = 10.0;
  scene.solver.static_correction = true;
  scene.solver.end_time_s = 0.05;
  scene.outputs.displacements = {Tip(0, 1.0)};
  const SceneBeam& b = scene.beams[0];
  const double k_beam = 3.0 * b.ei_n_m2 / std::pow(b.length_m, 3);
  const double force = k * k_beam * g / (k + k_beam);

  SceneModel model = BuildSceneModel(scene);
  EXPECT_NEAR(model.observed_rows[0].dot(model.x0), -force / k_beam, 1e-9 * force / k_beam);
  const TransientResult r = Integrate(scene, model, 0.1 * model.bounds.dt_sharp_s);
  ASSERT_EQ(r.summary.status, RunStatus::kOk);
  for (double f : r.contact_force_n[0].values) EXPECT_NEAR(f, force, 1e-6 * force);
  for (double f : r.contact_force_n[1].values) EXPECT_EQ(f, 0.0);
}

// The local bending stiffness the advice divides a zone's stiffness by: 3 EI / h^3 on a
// clamped-free beam at a node (Hermite cubics are exact for a nodal load), larger with an end
// spring.
TEST(SceneEngine, LocalBendingStiffnessIsThreeEiOverHCubedOnACantilever) {
  SceneBeam b = Cantilever("beam");
  for (const double h : {0.2, 0.6, 1.0}) {
    const double expected = 3.0 * b.ei_n_m2 / std::pow(h, 3);
    EXPECT_NEAR(LocalBendingStiffness(b, h), expected, 1e-9 * expected) << "h = " << h;
  }
  const double free_tip = LocalBendingStiffness(b, 1.0);
  b.spring_at_length_n_per_m = 1e5;
  EXPECT_NEAR(LocalBendingStiffness(b, 1.0), free_tip + 1e5, 1e-9 * (free_tip + 1e5));
}

// A 19-pin bundle in a wrapper, both planes, its neighbours in contact at three heights each,
// the zones between pins i and j with the gap `gap(i, j)`; pin 9 at the centre.
Scene NineteenPinBundle(const std::function<double(std::size_t, std::size_t)>& gap) {
  Scene scene;
  scene.planes = BendingPlanes::kBoth;
  scene.beams.push_back(Cantilever("wrapper"));
  const double pitch = 0.01;
  std::vector<std::pair<double, double>> cells;
  for (int q = -2; q <= 2; ++q) {
    for (int s = -2; s <= 2; ++s) {
      if (std::abs(q + s) <= 2)
        cells.emplace_back(pitch * (q + s / 2.0), pitch * s * std::sqrt(3.0) / 2);
    }
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    SceneBeam pin = Cantilever("pin" + std::to_string(i));
    pin.ei_n_m2 = 5.0, pin.rho_a_kg_per_m = 0.15, pin.n_elements = 30;
    pin.y_m = cells[i].first, pin.z_m = cells[i].second;
    scene.beams.push_back(pin);
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    for (std::size_t j = i + 1; j < cells.size(); ++j) {
      const double dy = cells[j].first - cells[i].first, dz = cells[j].second - cells[i].second;
      const double d = std::hypot(dy, dz);
      if (d > 1.01 * pitch) continue;
      for (double h : {0.3, 0.6, 0.9}) {
        scene.zones.push_back({.name = "pair",
                               .beam_a = static_cast<int>(i) + 1,
                               .beam_b = static_cast<int>(j) + 1,
                               .height_m = h,
                               .normal_y = dy / d,
                               .normal_z = dz / d,
                               .gap_m = gap(i, j),
                               .stiffness_n_per_m = 1e6});
      }
    }
  }
  return scene;
}

TEST(SceneEngine, PowerIterationBoundAgreesWithTheDenseOne) {
  // 400 coordinates, under the dense limit, so the model's bound is the dense one.
  Scene scene = NineteenPinBundle([](std::size_t, std::size_t) { return 0.0; });
  scene.solver.r_ftrunc = 300.0;
  const SceneModel model = BuildSceneModel(scene);
  ASSERT_LE(model.system->Size(), 600);
  const double dense = model.bounds.omega_max_rad_s * model.bounds.omega_max_rad_s;
  const double iterated =
      model.system->StiffestOmegaSquared(model.system->Contacts().BoundStiffnesses());
  EXPECT_LE(iterated, dense * (1 + 1e-12));
  EXPECT_GT(iterated, dense * (1 - 1e-3));
}

// A bundle swollen at its centre: the centre pin's wires preloaded, by 40 um and 5 um by turns,
// push the first ring onto the second, whose wires have a gap of 0.1 um. With linear laws the
// closed set is found in the zones' space and the equilibrium solved once: the same vector, bit for
// bit, as when every Newton step is a sparse factorization of the modes' matrix.
TEST(SceneEngine, PreloadedBundleEquilibriumIsTheSparseStepsOneBitForBit) {
  Scene scene = NineteenPinBundle([](std::size_t i, std::size_t j) {
    if (i != 9 && j != 9) return 1e-7;
    return (i + j) % 2 == 0 ? -4e-5 : -5e-6;
  });
  scene.solver.r_ftrunc = 300.0;
  const SceneModel model = BuildSceneModel(scene);
  const Eigen::VectorXd sparse_steps = PreloadEquilibriumBySparseSteps(*model.system);
  EXPECT_TRUE(model.x0 == sparse_steps) << (model.x0 - sparse_steps).cwiseAbs().maxCoeff();

  int preloaded_opened = 0, gapped_closed = 0;
  for (const ZoneTerm& z : model.system->Zones()) {
    const double u = ZoneRow(z, model.system->Size(), z.normal_y, z.normal_z).dot(model.x0);
    preloaded_opened += z.gap_m < 0.0 && u <= z.gap_m;
    gapped_closed += z.gap_m > 0.0 && u > z.gap_m;
  }
  EXPECT_GT(preloaded_opened, 0);
  EXPECT_GT(gapped_closed, 0);
}

}  // namespace
}  // namespace shockmap
