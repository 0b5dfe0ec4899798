// Impact statistics of a zone (core/impact_statistics.h, docs/physics.md §6): closed forms of a
// one-mode beam bouncing on a stop, synthetic force sequences with known impacts, rebounds and
// wear, and the statistics of a scene run.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numbers>
#include <vector>

#include "compare/scene_run.h"
#include "core/code_aster_impact_counter.h"
#include "core/impact_statistics.h"
#include "core/input_error.h"
#include "core/scene_model.h"
#include "core/scene_system.h"
#include "core/transient_run.h"
#include "formats/scene_file.h"

namespace shockmap {
namespace {

constexpr double kPi = std::numbers::pi;

// One modal coordinate q (mass-normalized, circular frequency omega1) whose zone displacement
// is u = phi q, against a stop at gap g with stiffness k, released at rest from q = -amplitude.
// Free flight: q = amplitude cos(omega1 t + ...), out of contact while q < q_g = g / phi.
// In contact: q'' = -omega_c^2 q + k phi g, omega_c^2 = omega1^2 + k phi^2, an oscillation of
// amplitude B about q* = k phi g / omega_c^2, entered at q_g with the free-flight speed V.
struct Bounce {
  double omega1, phi, k, gap, amplitude;

  double OmegaC() const { return std::sqrt(omega1 * omega1 + k * phi * phi); }
  double Qg() const { return gap / phi; }
  double Yg() const { return Qg() - k * phi * gap / (OmegaC() * OmegaC()); }
  double EntrySpeed() const { return omega1 * std::sqrt(amplitude * amplitude - Qg() * Qg()); }
  double B() const { return std::hypot(Yg(), EntrySpeed() / OmegaC()); }
  // Contact from y = y_g out to B and back: 2 arccos(y_g / B) / omega_c (pi / omega_c if g = 0).
  double ContactS() const { return 2.0 * std::acos(Yg() / B()) / OmegaC(); }
  // Free flight from q_g down to -amplitude and back: (2 pi - 2 arccos(q_g / A)) / omega1.
  double FlightS() const { return (2.0 * kPi - 2.0 * std::acos(Qg() / amplitude)) / omega1; }
  double CycleS() const { return ContactS() + FlightS(); }
  double PeakForceN() const { return k * phi * (B() - Yg()); }
  // Integral of k phi (y - y_g) over one contact.
  double ImpulsePerImpactNs() const {
    const double half_angle = std::acos(Yg() / B());
    return k * phi * (2.0 * B() * std::sin(half_angle) / OmegaC() - Yg() * ContactS());
  }
};

class OneModeBounce : public testing::TestWithParam<double> {};

// 20 whole cycles from rest to rest, 400 steps per contact: every statistic against its
// closed form within 1e-3.
TEST_P(OneModeBounce, MatchesItsClosedForms) {
  const Bounce bounce{120.0, 0.2, 3e6, GetParam() * 0.2, 1.0};
  const int cycles = 20;
  ZoneTerm zone;
  zone.a_y = 0;
  zone.phi_a = {bounce.phi};
  zone.gap_m = bounce.gap;
  zone.law.normal.stiffness = bounce.k;
  SceneModalSystem system(Eigen::VectorXd::Constant(1, bounce.omega1), std::nullopt, {zone}, {});
  TransientOptions options;
  options.end_time_s = cycles * bounce.CycleS();
  options.dt_s = bounce.ContactS() / 400.0;
  options.record_energy = false;
  options.track_impact_statistics = true;
  options.impact_counting.rest_duration_s = 0.1 * 2.0 * kPi / bounce.omega1;
  const TransientResult result = RunTransient(system, NewmarkParameters::CentralDifference(),
                                              Eigen::VectorXd::Constant(1, -bounce.amplitude),
                                              Eigen::VectorXd::Zero(1), options);
  ASSERT_EQ(result.summary.status, RunStatus::kOk) << result.summary.message;
  ASSERT_EQ(result.impact_statistics.size(), 1u);
  const ImpactStatistics& s = result.impact_statistics[0];
  const double tolerance = 1e-3;
  std::printf(
      "gap %g m: relative errors: duration %.2e, impacts/s %.2e, time in contact %.2e, "
      "peak %.2e, impulse %.2e\n",
      bounce.gap, s.mean_impact_duration_s / bounce.ContactS() - 1.0,
      s.impacts_per_s * bounce.CycleS() - 1.0,
      s.contact_time_fraction / (bounce.ContactS() / bounce.CycleS()) - 1.0,
      s.max_force_n / bounce.PeakForceN() - 1.0,
      s.impulse_n_s / (cycles * bounce.ImpulsePerImpactNs()) - 1.0);
  EXPECT_EQ(s.impacts, cycles);
  EXPECT_EQ(s.contacts, cycles);
  EXPECT_EQ(s.rebounds_per_impact, 0.0);
  EXPECT_FALSE(s.truncated);
  EXPECT_NEAR(s.mean_impact_duration_s / bounce.ContactS(), 1.0, tolerance);
  EXPECT_NEAR(s.longest_impact_duration_s / bounce.ContactS(), 1.0, tolerance);
  EXPECT_NEAR(s.impacts_per_s * bounce.CycleS(), 1.0, tolerance);
  EXPECT_NEAR(s.contact_time_fraction / (bounce.ContactS() / bounce.CycleS()), 1.0, tolerance);
  EXPECT_NEAR(s.max_force_n / bounce.PeakForceN(), 1.0, tolerance);
  EXPECT_NEAR(s.impulse_n_s / (cycles * bounce.ImpulsePerImpactNs()), 1.0, tolerance);
  // The mean force over the whole time is the cumulative impulse over the time.
  EXPECT_NEAR(s.mean_force_n, s.impulse_n_s / options.end_time_s, 1e-12 * s.mean_force_n);
  EXPECT_NEAR(s.mean_force_in_contact_n * s.contact_time_fraction, s.mean_force_n,
              1e-9 * s.mean_force_n);
  // A planar zone carries no tangential motion: no wear work rate.
  EXPECT_FALSE(s.wear_available);
  EXPECT_TRUE(std::isnan(s.wear_work_rate_w));
}

// Gap 0 (contact half-period pi / omega_c, the canonical problem's) and q_g = A / 2.
INSTANTIATE_TEST_SUITE_P(Gaps, OneModeBounce, testing::Values(0.0, 0.5));

// Triangular pulses 0, F, 0 one step dt apart: no slope inside, so each contact runs from the
// middle of the step before its peak to the middle of the step after, dt long, with impulse
// F dt / 2. Peaks at steps 1, 5, 9 (gaps of 3 dt < rest 5 dt: one impact, two rebounds), 31
// (alone), 61 and 64 (one rebound).
TEST(ImpactAccumulator, CountsImpactsAndRebounds) {
  const double dt = 1e-3;
  std::vector<double> force(100, 0.0);
  for (int peak : {1, 5, 9, 31, 61, 64}) force[peak] = 10.0;
  ImpactAccumulator accumulator({0.0, 5 * dt});
  for (std::size_t i = 1; i < force.size(); ++i) accumulator.Add(force[i], 0.0, dt);
  const ImpactStatistics s = accumulator.Finish(99 * dt);
  EXPECT_EQ(s.impacts, 3);
  EXPECT_EQ(s.contacts, 6);
  EXPECT_DOUBLE_EQ(s.rebounds_per_impact, 1.0);
  // Impact spans: [0.5, 9.5] dt, [30.5, 31.5] dt, [60.5, 64.5] dt.
  EXPECT_NEAR(s.mean_impact_duration_s, (9 + 1 + 4) * dt / 3.0, 1e-15);
  EXPECT_NEAR(s.longest_impact_duration_s, 9 * dt, 1e-15);
  EXPECT_NEAR(s.contact_time_fraction, 6.0 / 99.0, 1e-12);
  EXPECT_NEAR(s.impulse_n_s, 6 * 5.0 * dt, 1e-15);
  EXPECT_DOUBLE_EQ(s.max_force_n, 10.0);
  // Trapezoids of F^2 on each half: 2 x (dt / 2) x 100 / 2 per contact.
  EXPECT_NEAR(s.rms_force_n, std::sqrt(6 * 50.0 * dt / (99 * dt)), 1e-12);
  EXPECT_FALSE(s.truncated);
  // Without a rest duration every contact is an impact.
  ImpactAccumulator ungrouped;
  for (std::size_t i = 1; i < force.size(); ++i) ungrouped.Add(force[i], 0.0, dt);
  EXPECT_EQ(ungrouped.Finish(99 * dt).impacts, 6);
}

// Forces 0, 2, 10, 4, 0: the opening continues the slope 8 / dt back to zero at 0.75 dt, the
// closing the slope -6 / dt forward to zero at (3 + 2/3) dt.
TEST(ImpactAccumulator, ReconstructsTheZeroCrossingsFromTheForceSlope) {
  const double dt = 1e-3;
  ImpactAccumulator accumulator;
  for (double f : {2.0, 10.0, 4.0, 0.0, 0.0}) accumulator.Add(f, 0.0, dt);
  const ImpactStatistics s = accumulator.Finish(5 * dt);
  EXPECT_EQ(s.impacts, 1);
  EXPECT_NEAR(s.mean_impact_duration_s, (3.0 + 2.0 / 3.0 - 0.75) * dt, 1e-15);
  // 0.25 dt x 2 / 2 + (2 + 10) dt / 2 + (10 + 4) dt / 2 + (2/3) dt x 4 / 2.
  EXPECT_NEAR(s.impulse_n_s, (0.25 + 6.0 + 7.0 + 4.0 / 3.0) * dt, 1e-15);
}

// Threshold F/2 on a pulse 0, F, 0: the pieces of the reconstructed triangle over
// [dt/2, 3 dt/2] cross it at 3 dt/4 and 5 dt/4, and the mean force over that time is 3 F / 4.
TEST(ImpactAccumulator, InterpolatesTheForceThreshold) {
  const double dt = 0.01;
  ImpactAccumulator accumulator({5.0, 0.0});
  for (double f : {0.0, 10.0, 0.0, 0.0}) accumulator.Add(f, 0.0, dt);
  const ImpactStatistics s = accumulator.Finish(4 * dt);
  EXPECT_EQ(s.impacts, 1);
  EXPECT_NEAR(s.mean_impact_duration_s, dt / 2, 1e-15);
  EXPECT_NEAR(s.contact_time_fraction, 0.125, 1e-12);
  EXPECT_NEAR(s.mean_force_in_contact_n, 7.5, 1e-12);
  EXPECT_NEAR(s.impulse_n_s, 5.0 * dt, 1e-15);  // The whole force, below threshold included.
}

// Preloaded from t = 0 and still in contact at the end: one impact spanning the run, cut.
TEST(ImpactAccumulator, FlagsContactsCutByTheRun) {
  ImpactAccumulator accumulator({0.0, 0.0}, 50.0);
  for (int i = 0; i < 10; ++i) accumulator.Add(50.0, 0.0, 0.1);
  const ImpactStatistics s = accumulator.Finish(1.0);
  EXPECT_EQ(s.impacts, 1);
  EXPECT_TRUE(s.truncated);
  EXPECT_NEAR(s.mean_impact_duration_s, 1.0, 1e-12);
  EXPECT_NEAR(s.contact_time_fraction, 1.0, 1e-12);
  EXPECT_NEAR(s.mean_force_n, 50.0, 1e-12);
}

// Archard's power: 100 N sliding at 0.2 m/s during the first half of the run, then open.
TEST(ImpactAccumulator, WearWorkRateOfAKnownForceAndSpeed) {
  const double dt = 1e-3;
  const int steps = 1000;
  ImpactAccumulator accumulator({0.0, 0.0}, 100.0, 0.2);
  for (int i = 1; i <= steps; ++i) {
    const bool closed = i < steps / 2;
    accumulator.Add(closed ? 100.0 : 0.0, closed ? 0.2 : 0.0, dt);
  }
  const ImpactStatistics s = accumulator.Finish(steps * dt);
  ASSERT_TRUE(s.wear_available);
  // 20 W over [0, 499 dt], then down to 0 over half the next step (no slope: its middle).
  const double expected = 20.0 * (499 + 0.25) * dt / (steps * dt);
  EXPECT_NEAR(s.wear_work_rate_w, expected, 1e-12);
  ImpactAccumulator unknown({0.0, 0.0}, 100.0, 0.2);
  unknown.Add(100.0, std::numeric_limits<double>::quiet_NaN(), dt);
  EXPECT_FALSE(unknown.Finish(dt).wear_available);
  EXPECT_TRUE(std::isnan(unknown.Finish(dt).wear_work_rate_w));
}

// A beam bending in both planes bounces in y on a stop while swinging freely in z: the zone's
// sliding speed is |phi v_z|, so the streamed statistics equal those of the recorded force and
// recorded |v_z| at the zone fed to an accumulator step by step afterwards.
TEST(ImpactStatisticsInRun, WearWorkRateOfABeamSlidingAcrossItsStop) {
  const double omega1 = 120.0, phi = 0.2;
  ZoneTerm zone;
  zone.a_y = 0;
  zone.a_z = 1;
  zone.phi_a = {phi};
  zone.law.normal.stiffness = 3e6;
  SceneModalSystem system(Eigen::Vector2d(omega1, 1.3 * omega1), std::nullopt, {zone}, {});
  TransientOptions options;
  options.end_time_s = 0.5;
  options.dt_s = 2e-5;
  options.record_energy = false;
  options.track_impact_statistics = true;
  options.observed_rows = {Eigen::Vector2d(0.0, phi)};
  const TransientResult result =
      RunTransient(system, NewmarkParameters::CentralDifference(), Eigen::Vector2d(-1.0, 0.0),
                   Eigen::Vector2d(0.0, 50.0), options);
  ASSERT_EQ(result.summary.status, RunStatus::kOk) << result.summary.message;
  const ImpactStatistics& s = result.impact_statistics[0];
  ASSERT_TRUE(s.wear_available);
  const std::vector<double>& force = result.contact_force_n[0].values;
  const std::vector<double>& speed = result.velocity_m_s[0].values;
  ImpactAccumulator replay({}, force[0], std::abs(speed[0]));
  for (std::size_t i = 1; i < force.size(); ++i) {
    replay.Add(force[i], std::abs(speed[i]), result.contact_force_n[0].dt_s);
  }
  const ImpactStatistics expected = replay.Finish(options.end_time_s);
  EXPECT_GT(expected.wear_work_rate_w, 0.0);
  EXPECT_NEAR(s.wear_work_rate_w, expected.wear_work_rate_w, 1e-12 * expected.wear_work_rate_w);
  // The run passes runs of zero force as one piece: the same statistics to rounding.
  EXPECT_EQ(s.impacts, expected.impacts);
  EXPECT_EQ(s.contacts, expected.contacts);
  EXPECT_GT(s.impacts, 5);
  for (const auto& [streamed, replayed] :
       {std::pair{s.mean_impact_duration_s, expected.mean_impact_duration_s},
        {s.longest_impact_duration_s, expected.longest_impact_duration_s},
        {s.contact_time_fraction, expected.contact_time_fraction},
        {s.impulse_n_s, expected.impulse_n_s},
        {s.rms_force_n, expected.rms_force_n},
        {s.mean_force_in_contact_n, expected.mean_force_in_contact_n}}) {
    EXPECT_NEAR(streamed, replayed, 1e-9 * replayed);
  }
}

// The paper's cantilever (scenes/cantilever_spring.json) kept to its first mode: the scene's
// impact statistics give the contact duration pi / sqrt(omega1^2 + k phi(L)^2), with omega1 and
// phi(L) from its modal model, and its impacts per second and time in contact.
TEST(ImpactStatisticsInRun, SceneOfTheCantileverOnItsSpring) {
  Scene scene = LoadScene(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json");
  scene.solver.r_ftrunc = 1.5;
  scene.solver.dt.factor = 0.004;
  scene.outputs = {};
  scene.outputs.impact_statistics = true;
  scene.outputs.impact_counting.rest_duration_s = 0.0052;
  const SceneModel model = BuildSceneModel(scene);
  ASSERT_EQ(model.system->Size(), 1);
  const double omega1 = std::sqrt(model.system->OmegaSquared()[0]);
  const double phi = model.system->Zones()[0].phi_a[0];
  const double k = scene.zones[0].stiffness_n_per_m;
  const double contact_s = kPi / std::sqrt(omega1 * omega1 + k * phi * phi);
  const double cycle_s = kPi / omega1 + contact_s;
  const int cycles = 10;
  scene.solver.end_time_s = cycles * cycle_s;
  const SceneRun run = RunScene(scene);
  ASSERT_EQ(run.result.summary.status, RunStatus::kOk) << run.result.summary.message;
  ASSERT_EQ(run.impact_statistics.size(), 1u);
  const ImpactStatistics& s = run.impact_statistics[0];
  std::printf(
      "cantilever, one mode: omega1 %.6g rad/s, phi(L) %.6g, contact %.6g s, measured "
      "%.6g s; impacts/s %.6g (closed form %.6g); time in contact %.6g (%.6g)\n",
      omega1, phi, contact_s, s.mean_impact_duration_s, s.impacts_per_s, 1.0 / cycle_s,
      s.contact_time_fraction, contact_s / cycle_s);
  EXPECT_EQ(s.impacts, cycles);
  EXPECT_NEAR(s.mean_impact_duration_s / contact_s, 1.0, 1e-3);
  EXPECT_NEAR(s.impacts_per_s * cycle_s, 1.0, 1e-3);
  EXPECT_NEAR(s.contact_time_fraction / (contact_s / cycle_s), 1.0, 1e-3);
  EXPECT_NEAR(s.mean_force_n * scene.solver.end_time_s, s.impulse_n_s, 1e-12 * s.impulse_n_s);
}

// The scene file's key: its settings reach the scene, and a wrong one is refused naming it.
TEST(ImpactStatisticsInRun, SceneFileKey) {
  nlohmann::json json = nlohmann::json::parse(
      std::ifstream(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json"));
  json["outputs"] = {
      {"impact_statistics", {{"rest_duration_s", 0.005}, {"force_threshold_n", 2.0}}}};
  const Scene scene = ParseScene(json, "scene.json");
  EXPECT_TRUE(scene.outputs.impact_statistics);
  EXPECT_EQ(scene.outputs.impact_counting.rest_duration_s, 0.005);
  EXPECT_EQ(scene.outputs.impact_counting.force_threshold_n, 2.0);
  auto refusal = [&](const nlohmann::json& impacts) {
    json["outputs"] = {{"impact_statistics", impacts}};
    try {
      ParseScene(json, "scene.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(refusal(nlohmann::json::object()).find("outputs.impact_statistics.rest_duration_s"),
            std::string::npos);
  EXPECT_NE(
      refusal({{"rest_duration_s", 0.005}, {"force_threshold_n", -1.0}}).find("force_threshold_n"),
      std::string::npos);
  EXPECT_NE(refusal({{"rest_duration_s", 0.005}, {"seuil", 1.0}}).find("seuil"), std::string::npos);
}

// code_aster's convention on a scripted force (1 ms samples, t_i = i ms), threshold 5 N, rest
// 2.5 ms (looking 3 samples ahead), window [2, 35] ms (samples 2 to 35, 34 of them):
//   i:  0  1  2  3  4  5  6  7  8  9 10 11 12 13 14 15-18 19 20 21 22 23-32 33 34 35 36 37 38-40
//   F:  8  8  0 10 20  4  0 12  0  0  0  0  6 30  5   0    7  0  0  7   0   15  0  0  0 11  0
// Samples 0 and 1 are in contact before the window: nothing. Contacts end (at their first sample
// at or below 5 N) at 5, 8, 14, 20, 23 and 34: 6 in the window. Impacts: [3, 8] (its gap 5-6
// is 2 samples: a rebound; the gap from 8 is longer than 3: it ends at 8), [12, 14], [19, 23]
// (gap 20-21: a rebound); the one from 33 gets a rebound at 37 (gap 34-36, read past the
// window) and does not end in it: uncounted, the statistics truncated. So 3 impacts of 5, 2 and
// 4 ms (11 ms), rebounds per impact int(6 / 3) = 2, impacts per second int(3 / 0.034) = 88, time
// in impacts int(100 x 11 / 34) = 32 %. Samples above 5 N in the window: 10, 20, 12, 6, 30, 7, 7,
// 15 (the 4 and the 5 are not): sum 107, squares 1903. Each impact's peak is its last sample of
// largest force (19 and 22 both 7: 22 ms).
std::vector<double> ScriptedForce() {
  std::vector<double> f(41, 0.0);
  for (const auto& [i, value] : std::vector<std::pair<int, double>>{{0, 8},
                                                                    {1, 8},
                                                                    {3, 10},
                                                                    {4, 20},
                                                                    {5, 4},
                                                                    {7, 12},
                                                                    {12, 6},
                                                                    {13, 30},
                                                                    {14, 5},
                                                                    {19, 7},
                                                                    {22, 7},
                                                                    {33, 15},
                                                                    {37, 11}}) {
    f[i] = value;
  }
  return f;
}

ImpactStatistics CountCodeAster(double rest_s, bool stick_at_13) {
  ImpactCounting counting{5.0, rest_s, ImpactConvention::kCodeAster, 2e-3, 35e-3};
  CodeAsterImpactCounter counter(counting, 1e-3, false, true);
  const std::vector<double> force = ScriptedForce();
  for (std::size_t i = 0; i < force.size(); ++i) {
    ZoneSample sample{force[i], 1.0};  // Sliding at 1 m/s throughout.
    sample.sticks = stick_at_13 && i == 13;
    sample.penetration_rate_m_s = 0.1 * static_cast<double>(i);
    counter.Add(sample);
  }
  return counter.Finish();
}

TEST(CodeAsterConvention, CountsAScriptedForceByHand) {
  const ImpactStatistics s = CountCodeAster(2.5e-3, false);
  EXPECT_EQ(s.convention, ImpactConvention::kCodeAster);
  EXPECT_DOUBLE_EQ(s.window_start_s, 2e-3);
  EXPECT_DOUBLE_EQ(s.window_end_s, 35e-3);
  EXPECT_EQ(s.impacts, 3);
  EXPECT_EQ(s.contacts, 6);
  EXPECT_EQ(s.rebounds_per_impact, 2.0);
  EXPECT_EQ(s.impacts_per_s, 88.0);
  EXPECT_NEAR(s.mean_impact_duration_s, 11e-3 / 3, 1e-15);
  EXPECT_NEAR(s.longest_impact_duration_s, 5e-3, 1e-15);
  EXPECT_EQ(s.contact_time_fraction, 0.32);
  // Contacts of 2, 1, 2, 1, 1 and 1 ms.
  EXPECT_NEAR(s.mean_contact_duration_s, 8e-3 / 6, 1e-15);
  EXPECT_NEAR(s.mean_force_n, 107.0 / 34, 1e-12);
  EXPECT_NEAR(s.mean_force_in_contact_n, 107.0 / 8, 1e-12);
  EXPECT_NEAR(s.rms_force_n, std::sqrt(1903.0 / 34), 1e-12);
  EXPECT_NEAR(s.rms_force_in_contact_n, std::sqrt(1903.0 / 8), 1e-12);
  EXPECT_EQ(s.max_force_n, 30.0);
  EXPECT_NEAR(s.impulse_n_s, 0.107, 1e-15);
  EXPECT_TRUE(s.truncated);
  // The wear work rate: trapezoids of F x 1 m/s over the window's 33 steps, every sample
  // inside it weighing one step (its end samples are 0): 116 N (the 4 and the 5 included).
  ASSERT_TRUE(s.wear_available);
  EXPECT_NEAR(s.wear_work_rate_w, 116.0 / 33, 1e-12);
  // Per impact: start, duration, peak and its time, impulse (sum of F dt above the threshold),
  // the penetration rate at its first sample, contacts.
  ASSERT_EQ(s.records.size(), 3u);
  const std::vector<std::array<double, 7>> expected = {{3e-3, 5e-3, 20, 4e-3, 0.042, 0.3, 2},
                                                       {12e-3, 2e-3, 30, 13e-3, 0.036, 1.2, 1},
                                                       {19e-3, 4e-3, 7, 22e-3, 0.014, 1.9, 2}};
  for (std::size_t k = 0; k < 3; ++k) {
    const ImpactRecord& r = s.records[k];
    EXPECT_NEAR(r.start_s, expected[k][0], 1e-15) << k;
    EXPECT_NEAR(r.duration_s, expected[k][1], 1e-15) << k;
    EXPECT_EQ(r.peak_force_n, expected[k][2]) << k;
    EXPECT_NEAR(r.peak_time_s, expected[k][3], 1e-15) << k;
    EXPECT_NEAR(r.impulse_n_s, expected[k][4], 1e-15) << k;
    EXPECT_NEAR(r.impact_speed_m_s, expected[k][5], 1e-12) << k;
    EXPECT_EQ(r.contacts, expected[k][6]) << k;
  }
}

// A rest duration of 0 (code_aster's default) looks one sample ahead, which ends an impact at
// every gap: the 6 contacts ending in the window are 6 impacts (the one from 33 ends at 34), and
// code_aster's integer rebounds per impact is int(6 / 6) = 1. A sample that sticks takes its
// pair out of the wear work rate: the pair (13, 14), (30 + 5) / 2 N.
TEST(CodeAsterConvention, RestZeroAndAStickingSample) {
  const ImpactStatistics s = CountCodeAster(0.0, true);
  EXPECT_EQ(s.impacts, 6);
  EXPECT_EQ(s.contacts, 6);
  EXPECT_EQ(s.rebounds_per_impact, 1.0);
  EXPECT_EQ(s.impacts_per_s, 176.0);  // int(6 / 0.034).
  // Impacts of 2, 1, 2, 1, 1, 1 ms: int(100 x 8 / 34) = 23 %.
  EXPECT_EQ(s.contact_time_fraction, 0.23);
  EXPECT_NEAR(s.wear_work_rate_w, (116.0 - 17.5) / 33, 1e-12);
  EXPECT_FALSE(s.records.back().truncated);
}

// The same force in shockmap's convention differs point by point (docs/physics.md §6.2): its
// contacts end where the force's line crosses the threshold, so the gap 20-21 runs from 19.14 to
// 21.86 ms (pieces 7 -> 0 and 0 -> 7, each from the step's middle), 2.71 ms: longer than the rest,
// a separate impact; the one from 33 started in the window and counts. Its rebounds per impact
// are (contacts - impacts) / impacts, its rates real-valued, and the threshold's samples enter
// the force's integrals.
TEST(CodeAsterConvention, DiffersFromShockmapsOnTheSameForce) {
  ImpactCounting counting{5.0, 2.5e-3};
  counting.window_start_s = 2e-3;
  ImpactAccumulator accumulator(counting, 0.0, 1.0);
  const std::vector<double> force = ScriptedForce();
  for (std::size_t i = 3; i <= 35; ++i) accumulator.Add(force[i], 1.0, 1e-3);
  const ImpactStatistics shockmap = accumulator.Finish(33e-3);
  const ImpactStatistics aster = CountCodeAster(2.5e-3, false);
  EXPECT_EQ(shockmap.impacts, 5);
  EXPECT_EQ(shockmap.contacts, 6);
  EXPECT_NE(shockmap.rebounds_per_impact, aster.rebounds_per_impact);
  EXPECT_NE(shockmap.impacts_per_s, std::floor(shockmap.impacts_per_s));
  EXPECT_NE(shockmap.mean_force_n, aster.mean_force_n);
}

TEST(ImpactCounting, RefusesNegativeOrNonFiniteSettings) {
  std::string error;
  EXPECT_TRUE((ImpactCounting{0.0, 0.0}).IsValid(&error));
  EXPECT_FALSE((ImpactCounting{-1.0, 0.0}).IsValid(&error));
  EXPECT_NE(error.find("force_threshold_n"), std::string::npos);
  EXPECT_FALSE((ImpactCounting{0.0, std::nan("")}).IsValid(&error));
  EXPECT_NE(error.find("rest_duration_s"), std::string::npos);
}

}  // namespace
}  // namespace shockmap
