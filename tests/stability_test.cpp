// The numerical hard cases (ctest -L stability): stiff, grazing, chattering and initial
// contacts, zero and tiny gaps, long runs, high truncations, fine meshes, heavy damping. Each
// asserts finite results, bounded undamped energy without secular growth, the expected status
// on either side of the stability bound, and a reference that misses no contact transition.
// Measured values are quoted beside each bound; the closing note of issue 6 tabulates them.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

#include "core/cantilever_impact.h"
#include "core/input_error.h"
#include "core/scene_model.h"
#include "core/transient_run.h"
#include "reference/reference_solver.h"
#include "validation/shock_segmentation.h"

namespace shockmap {

void PrintTo(RunStatus s, std::ostream* os) { *os << ToString(s); }

namespace {

// "R300" for r_ftrunc = 300.
std::string RFtruncName(const testing::TestParamInfo<double>& info) {
  return "R" + std::to_string(static_cast<int>(info.param));
}

// ---------------------------------------------------------------------------------------------
// 1. What the sharp bound guarantees on the canonical problem.

std::string CaseName(std::string name) {
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
      '_');
  return name;
}

// Linear check first: with the contact always closed the structure is linear with stiffness
// Omega^2 + k phi phi^T, and dt_sharp is the exact limit of central differences on it.
class ClosedContactStabilityTest : public testing::TestWithParam<double> {};

TEST_P(ClosedContactStabilityTest, SharpBoundIsTheExactLimit) {
  const CantileverImpact problem;
  const ImpactModel model = BuildImpactModel(problem, Scheme::kExplicitModal, GetParam());
  const auto& modal = dynamic_cast<const SceneModalSystem&>(*model.system);
  const ZoneTerm& contact = modal.Zones().at(0);
  const Eigen::Map<const Eigen::VectorXd> row(contact.phi_a.data(), modal.Size());
  Eigen::MatrixXd k = modal.OmegaSquared().asDiagonal();
  k += contact.law.normal.stiffness * row * row.transpose();
  // Integrate in the eigenbasis of the closed-contact stiffness: decoupled oscillators.
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k);
  const Eigen::VectorXd omega = eig.eigenvalues().cwiseSqrt();
  EXPECT_NEAR(2.0 / omega.maxCoeff(), model.bounds.dt_sharp_s, 1e-12 * model.bounds.dt_sharp_s);
  SceneModalSystem closed(omega, std::nullopt, {}, {});
  const Eigen::VectorXd x0 = Eigen::VectorXd::Ones(omega.size());
  TransientOptions options;
  options.end_time_s = 5000 * model.bounds.dt_sharp_s;

  options.dt_s = 0.95 * model.bounds.dt_sharp_s;
  TransientResult r = RunTransient(closed, NewmarkParameters::CentralDifference(), x0,
                                   Eigen::VectorXd::Zero(omega.size()), options);
  EXPECT_EQ(r.summary.status, RunStatus::kOk) << r.summary.message;
  // Bounded by the invariant: E / E0 <= 1 / (1 - c / 4), c = (omega_max dt)^2.
  EXPECT_LE(r.summary.max_energy_ratio, 1.0 / (1.0 - 0.95 * 0.95));

  options.dt_s = 1.05 * model.bounds.dt_sharp_s;
  r = RunTransient(closed, NewmarkParameters::CentralDifference(), x0,
                   Eigen::VectorXd::Zero(omega.size()), options);
  EXPECT_EQ(r.summary.status, RunStatus::kDiverged);
  EXPECT_LT(r.summary.steps_taken, r.summary.steps_requested);
}

INSTANTIATE_TEST_SUITE_P(RFtrunc, ClosedContactStabilityTest, testing::Values(10.0, 300.0),
                         RFtruncName);

// The canonical impact (R_k = 3000). Central differences on a unilateral penalty contact can
// gain energy at each switch even below dt_sharp (measured: a 1-dof bilinear oscillator grows at
// 0.8 dt_sharp), so the bound is necessary but not sufficient; the table records where each
// scheme stands.
struct StabilityCase {
  std::string name;
  Scheme scheme;
  double r_ftrunc;
  double dt_factor;
  DtRule rule;
  double end_s;
  RunStatus expected;
  double max_energy_ratio;  // Checked for kOk cases.
};

void PrintTo(const StabilityCase& c, std::ostream* os) { *os << c.name; }

class CanonicalStabilityTest : public testing::TestWithParam<StabilityCase> {};

TEST_P(CanonicalStabilityTest, EndsWithExpectedStatus) {
  const StabilityCase& c = GetParam();
  const CantileverImpact problem;
  ImpactModel model = BuildImpactModel(problem, c.scheme, c.r_ftrunc);
  TransientOptions options;
  options.end_time_s = c.end_s;
  options.record_energy = false;
  options.dt_s =
      c.dt_factor * (c.rule == DtRule::kSharp ? model.bounds.dt_sharp_s : model.bounds.dt_paper_s);
  const TransientResult r =
      RunTransient(*model.system, NewmarkParametersOf(c.scheme), model.x0, model.v0, options);
  ASSERT_EQ(r.summary.status, c.expected)
      << r.summary.message << " (max energy ratio " << r.summary.max_energy_ratio << ")";
  if (c.expected == RunStatus::kOk) {
    EXPECT_EQ(r.summary.steps_taken, r.summary.steps_requested);
    EXPECT_LT(r.summary.max_energy_ratio, c.max_energy_ratio);
  } else {
    // Stopped while running, not just flagged at the end.
    EXPECT_LT(r.summary.steps_taken, r.summary.steps_requested);
    EXPECT_FALSE(r.summary.message.empty());
  }
}

// Energy ratios on this problem are sensitive: the cascade into high modes through micro-impacts
// (docs/physics.md §2) makes them vary with dt by a percent. The bounds below hold for dt * {0.99,
// 1, 1.01} and initial amplitudes 0.7 to 3.7 mm (measured spread in the comments); the statuses are
// the same for all of those.
const StabilityCase kStabilityCases[] = {
    // Just below the bound at R_ftrunc = 300: kOk over the first 0.3 s, with ratio 1.39 at
    // 0.95 dt_sharp but 3.1 at 0.94 and 11 at 0.96; it diverges by ~1.7 s.
    {"Explicit_R300_0p95Sharp_0p3s", Scheme::kExplicitModal, 300, 0.95, DtRule::kSharp, 0.3,
     RunStatus::kOk, 20},
    // Just below the bound at R_ftrunc = 10 the contact switching pumps energy (ratio 233 at
    // 0.3 s) and the run diverges at step ~1150 (0.24 s).
    {"Explicit_R10_0p95Sharp_1s", Scheme::kExplicitModal, 10, 0.95, DtRule::kSharp, 1.0,
     RunStatus::kDiverged, 0},
    // Above the bound: diverges within the first impacts (steps 704 / 1260 and 256 / 4353).
    {"Explicit_R10_1p1Sharp", Scheme::kExplicitModal, 10, 1.1, DtRule::kSharp, 0.3,
     RunStatus::kDiverged, 0},
    {"Explicit_R300_1p1Sharp", Scheme::kExplicitModal, 300, 1.1, DtRule::kSharp, 0.3,
     RunStatus::kDiverged, 0},
    // docs/physics.md §3: the paper's 1 / (4 f_trunc) is 6 dt_sharp at R_ftrunc = 10 (step 64 /
    // 231).
    {"Explicit_R10_PaperBound", Scheme::kExplicitModal, 10, 1.0, DtRule::kPaper, 0.3,
     RunStatus::kDiverged, 0},
    // The studies' default factor 0.1: bounded over 3 s, ~58 periods of f1 and hundreds of
    // impacts (ratios 1.00 to 1.07).
    {"Explicit_R10_0p1Sharp_3s", Scheme::kExplicitModal, 10, 0.1, DtRule::kSharp, 3.0,
     RunStatus::kOk, 1.2},
    {"Explicit_R300_0p1Sharp_3s", Scheme::kExplicitModal, 300, 0.1, DtRule::kSharp, 3.0,
     RunStatus::kOk, 1.2},
    // Average acceleration is unconditionally stable only while linear: with the penalty
    // contact unresolved (omega_contact dt >> 1) it gains energy at impacts. At dt_sharp on the
    // 55-element model it stays bounded over 3 s (ratios 1.00 to 1.98)...
    {"Implicit_R300_1Sharp_3s", Scheme::kImplicitFull, 300, 1.0, DtRule::kSharp, 3.0,
     RunStatus::kOk, 3},
    // ...at 5 dt_sharp it is still kOk after 0.3 s (ratios 4.7 to 42) but diverges by 3 s.
    {"Implicit_R300_5Sharp_0p3s", Scheme::kImplicitFull, 300, 5.0, DtRule::kSharp, 0.3,
     RunStatus::kOk, 100},
    {"Implicit_R300_5Sharp_3s", Scheme::kImplicitFull, 300, 5.0, DtRule::kSharp, 3.0,
     RunStatus::kDiverged, 0},
    {"Implicit_R10_5Sharp_3s", Scheme::kImplicitFull, 10, 5.0, DtRule::kSharp, 3.0,
     RunStatus::kDiverged, 0},
};

INSTANTIATE_TEST_SUITE_P(Cases, CanonicalStabilityTest, testing::ValuesIn(kStabilityCases),
                         [](const testing::TestParamInfo<StabilityCase>& info) {
                           return CaseName(info.param.name);
                         });

// ---------------------------------------------------------------------------------------------
// 2. Hard cases of the canonical problem.

struct Outcome {
  TransientResult result;
  double dt_sharp_s = 0.0;
  // Largest |E + D - E0| / E0 over the first and the last tenth of the run (secular growth
  // shows as the second far above the first).
  double early_drift = 0.0, late_drift = 0.0;
  bool finite = true;
};

Outcome Integrate(const CantileverImpact& problem, Scheme scheme, double r_ftrunc, double dt_factor,
                  double end_s, int n_elements = 0, int energy_stride = 16) {
  const ImpactModel model = BuildImpactModel(problem, scheme, r_ftrunc, n_elements);
  TransientOptions options;
  options.end_time_s = end_s;
  options.dt_s = dt_factor * model.bounds.dt_sharp_s;
  options.record_stride = energy_stride;
  options.record_contact_forces = true;
  options.observed_rows = {model.tip_row};
  Outcome o;
  o.dt_sharp_s = model.bounds.dt_sharp_s;
  o.result = RunTransient(*model.system, NewmarkParametersOf(scheme), model.x0, model.v0, options);
  const EnergyHistory& e = o.result.energy;
  const std::size_t n = e.kinetic_j.values.size();
  const double e0 = e.kinetic_j.values[0] + e.strain_j.values[0] + e.contact_j.values[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double total = e.kinetic_j.values[i] + e.strain_j.values[i] + e.contact_j.values[i] +
                         e.dissipated_j.values[i];
    o.finite =
        o.finite && std::isfinite(total) && std::isfinite(o.result.displacement_m[0].values[i]);
    const double drift = std::abs(total - e0) / e0;
    if (i < n / 10) o.early_drift = std::max(o.early_drift, drift);
    if (i >= n - n / 10) o.late_drift = std::max(o.late_drift, drift);
  }
  for (double f : o.result.contact_force_n[0].values) o.finite = o.finite && std::isfinite(f);
  return o;
}

void Report(const std::string& name, const Outcome& o) {
  const RunSummary& s = o.result.summary;
  std::printf("[measured] %s: %s, %lld steps, max energy ratio %.4g, drift early %.3g late %.3g\n",
              name.c_str(), ToString(s.status).c_str(), static_cast<long long>(s.steps_taken),
              s.max_energy_ratio, o.early_drift, o.late_drift);
}

class StiffContact : public testing::TestWithParam<double> {};

TEST_P(StiffContact, StableAtATenthOfTheBoundDivergesAboveIt) {
  CantileverImpact problem;
  problem.r_k = GetParam();
  const Outcome below = Integrate(problem, Scheme::kExplicitModal, 300, 0.1, 0.06);
  Report("stiff below " + std::to_string(problem.r_k), below);
  EXPECT_EQ(below.result.summary.status, RunStatus::kOk);
  EXPECT_TRUE(below.finite);
  EXPECT_LT(below.result.summary.max_energy_ratio, 1.1);  // Measured 1.000 to 1.002.
  EXPECT_LT(below.late_drift, 0.01);                      // Measured 5e-4 to 2.3e-3.
  // Above the bound the energy grows at each impact only (free flight is stable), so the
  // divergence limit (1e3 E0) is crossed after a few impacts, not within the first two.
  const Outcome above = Integrate(problem, Scheme::kExplicitModal, 300, 1.5, 2.0, 0, 1024);
  Report("stiff above " + std::to_string(problem.r_k), above);
  EXPECT_EQ(above.result.summary.status, RunStatus::kDiverged);
  EXPECT_LT(above.result.summary.steps_taken, above.result.summary.steps_requested);
  const Outcome implicit = Integrate(problem, Scheme::kImplicitFull, 300, 1.0, 0.06);
  Report("stiff implicit " + std::to_string(problem.r_k), implicit);
  EXPECT_EQ(implicit.result.summary.status, RunStatus::kOk);
  EXPECT_TRUE(implicit.finite);
  // Average acceleration gains energy at unresolved switches: 1.03, 1.17, 1.67, 2.17.
  EXPECT_LT(implicit.result.summary.max_energy_ratio, 3.0);
}

INSTANTIATE_TEST_SUITE_P(Rk, StiffContact, testing::Values(1e5, 1e6, 1e7, 1e8),
                         [](const testing::TestParamInfo<double>& info) {
                           return "Rk1e" +
                                  std::to_string(static_cast<int>(std::log10(info.param) + 0.5));
                         });

// Once inside its side of the gap, every phase of the reference stays there when sampled far
// more densely than its crossing search (64 samples per shortest period against 16): a missed
// transition shows as a sample on the wrong side. (A phase may start a hair on the wrong side:
// the truncated projection at a transition moves the tip by up to 2e-5 of the amplitude at
// R_k = 1e6, and the reference waits for the tip to come inside or ends the phase as a graze.)
// Returns the samples on the wrong side.
int MissedTransitions(const CantileverImpact& problem, const ReferenceSolution& ref, double end_s) {
  const auto& phases = ref.Phases();
  const double dt = ref.Summary().shortest_period_s / 64.0;
  const double tolerance = 1e-9 * problem.initial_tip_m;
  int missed = 0;
  const ReferencePhase* current = nullptr;
  bool inside = false;
  for (double t = 0.0; t <= end_s; t += dt) {
    const auto next =
        std::upper_bound(phases.begin(), phases.end(), t,
                         [](double x, const ReferencePhase& p) { return x < p.start_s; });
    const ReferencePhase& phase = *std::prev(next);
    if (&phase != current) current = &phase, inside = false;
    const double u = ref.TipDisplacement(t) - problem.gap_m;
    const double wrong_side = phase.in_contact ? u : -u;
    if (wrong_side < 0.0) inside = true;
    if (inside && wrong_side > tolerance) ++missed;
  }
  return missed;
}

ReferenceSolution Reference(const CantileverImpact& problem, double end_s) {
  ReferenceOptions options;
  options.r_fref = std::max(3000.0, 10.0 * std::sqrt(problem.r_k));
  options.end_time_s = end_s;
  return SolveReference(problem, options);
}

double LargestForce(const Outcome& o) {
  const auto& f = o.result.contact_force_n[0].values;
  return *std::max_element(f.begin(), f.end());
}

// The tip released from +a just reaches the stop at -a (1 - 1e-3): a contact of 1e-3 a.
TEST(HardCases, GrazingContactIsFoundByBothSolvers) {
  CantileverImpact problem;
  problem.gap_m = -problem.initial_tip_m * (1.0 - 1e-3);
  const ReferenceSolution ref = Reference(problem, 0.06);
  EXPECT_GE(ref.Summary().n_transitions, 2);
  EXPECT_EQ(MissedTransitions(problem, ref, 0.06), 0);
  const Outcome o = Integrate(problem, Scheme::kExplicitModal, 300, 0.1, 0.06);
  Report("grazing", o);
  EXPECT_EQ(o.result.summary.status, RunStatus::kOk);
  EXPECT_TRUE(o.finite);
  EXPECT_GT(LargestForce(o), 0.0);
  EXPECT_LT(o.result.summary.max_energy_ratio, 1.01);
}

// ...and at -a (1 + 1e-6) it misses: no transition, no force (central differences keep a pure
// mode's amplitude exactly when released from rest).
TEST(HardCases, NearMissMakesNoContact) {
  CantileverImpact problem;
  problem.gap_m = -problem.initial_tip_m * (1.0 + 1e-6);
  const ReferenceSolution ref = Reference(problem, 0.06);
  EXPECT_EQ(ref.Summary().n_transitions, 0);
  EXPECT_EQ(MissedTransitions(problem, ref, 0.06), 0);
  const Outcome o = Integrate(problem, Scheme::kExplicitModal, 300, 0.1, 0.06);
  EXPECT_EQ(LargestForce(o), 0.0);
}

// A stiff stop makes the first shock a burst of micro-impacts; neither solver loses one.
TEST(HardCases, ChatteringIsResolved) {
  CantileverImpact problem;
  problem.r_k = 1e6;
  const ReferenceSolution ref = Reference(problem, 0.03);
  std::printf("[measured] chattering reference: %d transitions\n", ref.Summary().n_transitions);
  EXPECT_GE(ref.Summary().n_transitions, 10);
  EXPECT_EQ(MissedTransitions(problem, ref, 0.03), 0);
  const Outcome o = Integrate(problem, Scheme::kExplicitModal, 300, 0.1, 0.03, 0, 1);
  ShockSegmentationOptions shocks;
  shocks.rest_duration_s = 0.1 / problem.F1Hz();
  const auto segmented = SegmentShocks(o.result.contact_force_n[0], shocks, 0.03);
  ASSERT_FALSE(segmented.empty());
  std::printf("[measured] chattering explicit: %d contacts in the first shock\n",
              segmented.front().n_contacts);
  EXPECT_GE(segmented.front().n_contacts, 5);
  EXPECT_TRUE(o.finite);
  EXPECT_LT(o.result.summary.max_energy_ratio, 1.01);
}

TEST(HardCases, ATinyGapBehavesAsNoGap) {
  CantileverImpact zero, tiny;
  tiny.gap_m = 1e-12;
  const Outcome a = Integrate(zero, Scheme::kExplicitModal, 300, 0.1, 0.06);
  const Outcome b = Integrate(tiny, Scheme::kExplicitModal, 300, 0.1, 0.06);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.result.displacement_m[0].values.size(); ++i) {
    worst = std::max(worst, std::abs(a.result.displacement_m[0].values[i] -
                                     b.result.displacement_m[0].values[i]));
  }
  std::printf("[measured] tiny gap: largest tip difference %.3g m\n", worst);
  EXPECT_LT(worst, 1e-9);  // 1e-6 of the amplitude for a 1e-9 relative change of the gap.
  EXPECT_EQ(MissedTransitions(tiny, Reference(tiny, 0.06), 0.06), 0);
}

// Released 1 mm inside the stop (gap +2 mm, tip +1 mm): in contact from the first step.
TEST(HardCases, ContactAtTheFirstStep) {
  CantileverImpact problem;
  problem.gap_m = 2e-3;
  const ReferenceSolution ref = Reference(problem, 0.06);
  ASSERT_FALSE(ref.Phases().empty());
  EXPECT_TRUE(ref.Phases().front().in_contact);
  EXPECT_EQ(MissedTransitions(problem, ref, 0.06), 0);
  const Outcome o = Integrate(problem, Scheme::kExplicitModal, 300, 0.1, 0.06);
  Report("initial contact", o);
  EXPECT_GT(o.result.contact_force_n[0].values.front(), 0.0);
  EXPECT_EQ(o.result.summary.status, RunStatus::kOk);
  EXPECT_TRUE(o.finite);
  EXPECT_LT(o.result.summary.max_energy_ratio, 1.01);
}

// A million steps (R_ftrunc = 10 at 0.1 dt_sharp: 21.7 s, ~420 periods, hundreds of impacts):
// the energy error stays bounded, with no secular growth. Past the first impacts the rattling is
// chaotic, so the error of a single run is a random walk whose end depends on rounding. With the
// release scaled by 1 + j 1e-12 (j = -4 .. 4), Newmark's form gave late drifts of 0.044 to 0.156
// (median 0.070) and largest energy ratios up to 1.111; the increment form 0.031 to 0.179
// (median 0.074) and up to 1.138 (docs/performance.md, "The explicit step in increment form").
// The median drift is judged, and every run's growth.
TEST(HardCases, AMillionStepsKeepTheEnergy) {
  const CantileverImpact nominal;
  const ImpactModel model = BuildImpactModel(nominal, Scheme::kExplicitModal, 10);
  const double end = 1e6 * 0.1 * model.bounds.dt_sharp_s;
  std::vector<double> late;
  for (int j = -4; j <= 4; ++j) {
    CantileverImpact problem = nominal;
    problem.initial_tip_m *= 1.0 + j * 1e-12;
    const Outcome o = Integrate(problem, Scheme::kExplicitModal, 10, 0.1, end, 0, 1000);
    Report("million steps, release x (1 + " + std::to_string(j) + "e-12)", o);
    EXPECT_EQ(o.result.summary.steps_taken, 1'000'000);
    EXPECT_EQ(o.result.summary.status, RunStatus::kOk);
    EXPECT_TRUE(o.finite);
    EXPECT_LT(o.result.summary.max_energy_ratio, 1.25);
    late.push_back(o.late_drift);
  }
  std::ranges::nth_element(late, late.begin() + 4);
  EXPECT_LT(late[4], 0.1) << "median late drift";
}

TEST(HardCases, HighTruncationAndFineMeshStayStable) {
  const CantileverImpact problem;
  const Outcome high = Integrate(problem, Scheme::kExplicitModal, 3000, 0.1, 0.06);
  Report("R_ftrunc 3000", high);
  EXPECT_EQ(high.result.summary.status, RunStatus::kOk);
  EXPECT_LT(high.result.summary.max_energy_ratio, 1.01);
  const Outcome fine = Integrate(problem, Scheme::kExplicitModal, 300, 0.1, 0.06, 400);
  Report("400 elements explicit", fine);
  EXPECT_EQ(fine.result.summary.status, RunStatus::kOk);
  EXPECT_LT(fine.result.summary.max_energy_ratio, 1.01);
  const Outcome implicit = Integrate(problem, Scheme::kImplicitFull, 300, 1.0, 0.06, 400);
  Report("400 elements implicit", implicit);
  EXPECT_EQ(implicit.result.summary.status, RunStatus::kOk);
  EXPECT_TRUE(implicit.finite);
  EXPECT_LT(implicit.result.summary.max_energy_ratio, 3.0);
}

// Mass-proportional damping at and far above critical on mode 1 (xi_1 = alpha / (2 omega_1)):
// the numerical solver stays stable and dissipates; the reference, whose modes would be
// overdamped, refuses with the parameter named.
TEST(HardCases, HeavyDampingIsStableOrRefused) {
  for (double xi : {1.05, 10.0}) {
    CantileverImpact problem;
    problem.mass_damping_per_s = 2.0 * xi * 2.0 * M_PI * problem.F1Hz();
    const Outcome o = Integrate(problem, Scheme::kExplicitModal, 300, 0.1, 0.06);
    Report("damping xi " + std::to_string(xi), o);
    EXPECT_EQ(o.result.summary.status, RunStatus::kOk);
    EXPECT_TRUE(o.finite);
    EXPECT_LT(o.result.summary.max_energy_ratio, 1.001);
    // The mechanical energy only decreases (overdamped, the tip creeps: at xi = 10 half of it
    // is left after 0.06 s, measured 0.113 of 0.232 J).
    const EnergyHistory& e = o.result.energy;
    double previous = std::numeric_limits<double>::infinity(), e0 = 0.0;
    for (std::size_t i = 0; i < e.kinetic_j.values.size(); ++i) {
      const double now = e.kinetic_j.values[i] + e.strain_j.values[i] + e.contact_j.values[i];
      if (i == 0) e0 = now;
      ASSERT_LE(now, previous + 1e-9 * e0) << "energy grew at sample " << i;
      previous = now;
    }
    EXPECT_LT(previous, 0.6 * e0);
    try {
      Reference(problem, 0.06);
      ADD_FAILURE() << "the reference accepted xi = " << xi;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("mass_damping_per_s"), std::string::npos);
    }
  }
  CantileverImpact damped_contact;
  damped_contact.contact_damping_n_s_per_m = 1e3;
  EXPECT_THROW(Reference(damped_contact, 0.06), InputError);
}

// Modal damping ratios of 1 and 5 on every mode of the canonical scene, with its contact.
TEST(HardCases, OvercriticalModalDampingInASceneIsStable) {
  for (double xi : {1.0, 5.0}) {
    Scene scene;
    SceneBeam beam;
    beam.ei_n_m2 = 1.5e5, beam.rho_a_kg_per_m = 127.0, beam.n_elements = 55;
    scene.beams = {beam};
    scene.zones = {{.name = "tip", .height_m = 1.0, .normal_y = -1.0, .stiffness_n_per_m = 1.35e9}};
    scene.initial_state = {{.beam = 0, .tip_m = 1e-3}};
    scene.modal_damping = ModalDampingEffect{.ratios = {xi}};
    SceneModel model = BuildSceneModel(scene);
    TransientOptions options;
    options.end_time_s = 0.06;
    options.dt_s = 0.1 * model.bounds.dt_sharp_s;
    const TransientResult r = RunTransient(*model.system, NewmarkParameters::CentralDifference(),
                                           model.x0, model.v0, options);
    EXPECT_EQ(r.summary.status, RunStatus::kOk);
    EXPECT_LT(r.summary.max_energy_ratio, 1.001) << xi;
    EXPECT_TRUE(std::isfinite(r.energy.kinetic_j.values.back()));
  }
}

}  // namespace
}  // namespace shockmap
