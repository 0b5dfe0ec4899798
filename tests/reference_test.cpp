// Verification of the semi-analytical reference: analytic modes against known roots and limits,
// orthogonality, boundary conditions, exactness without contact, transitions on the gap.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

#include "core/input_error.h"
#include "reference/analytic_basis.h"
#include "reference/analytic_modes.h"
#include "reference/rank_one_update.h"
#include "reference/reference_cost.h"
#include "reference/reference_solver.h"
#include "reference/tip_modes.h"

namespace shockmap {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(CharacteristicRoots, ClampedFreeMatchesTabulatedRoots) {
  const std::vector<double> expected = {1.87510407, 4.69409113, 7.85475744, 10.99554073};
  const auto roots = CharacteristicRoots(0.0, 11.0, 4);
  ASSERT_GE(roots.size(), 4u);
  for (std::size_t n = 0; n < expected.size(); ++n) EXPECT_NEAR(roots[n], expected[n], 1e-8);
}

TEST(CharacteristicRoots, ClampedFreeApproachesOddHalfPiWithoutLossOfAccuracy) {
  const auto roots = CharacteristicRoots(0.0, 0.0, 40);
  ASSERT_EQ(roots.size(), 40u);
  // b_n = (2n - 1) pi / 2 + O(e^-b_n): below rounding from n = 12 on.
  for (int n = 12; n <= 40; ++n) EXPECT_NEAR(roots[n - 1], (2 * n - 1) * kPi / 2, 1e-12) << n;
  // And each root satisfies the undivided equation's sign structure: cos b_n ~ -1 / cosh b_n.
  EXPECT_NEAR(std::cos(roots[5]), -1.0 / std::cosh(roots[5]), 1e-14);
}

TEST(CharacteristicRoots, StiffSpringTendsToClampedPinned) {
  constexpr double kClampedPinnedB1 = 3.92660231;
  double previous_gap = 1.0;
  for (double kappa : {1e3, 1e5, 1e7, 1e9}) {
    const double b1 = CharacteristicRoots(kappa, 0.0, 1).front();
    const double gap = std::abs(b1 - kClampedPinnedB1);
    EXPECT_LT(gap, previous_gap) << "kappa = " << kappa;
    EXPECT_LT(b1, kClampedPinnedB1 + 1e-8);
    previous_gap = gap;
  }
  EXPECT_LT(previous_gap, 1e-6);
}

TEST(CharacteristicRoots, SoftSpringTendsToClampedFree) {
  EXPECT_NEAR(CharacteristicRoots(1e-9, 0.0, 1).front(), kClampedFreeB1, 1e-9);
  EXPECT_NEAR(CharacteristicRoots(1e-3, 0.0, 1).front(), kClampedFreeB1, 1e-3);
  // A spring always stiffens the first mode.
  EXPECT_GT(CharacteristicRoots(1.0, 0.0, 1).front(), kClampedFreeB1);
}

class ModeShapeBoundaryConditions : public ::testing::TestWithParam<double> {};

TEST_P(ModeShapeBoundaryConditions, HoldForFortyModes) {
  const double kappa = GetParam();
  const auto roots = CharacteristicRoots(kappa, 0.0, 40);
  for (std::size_t n = 0; n < roots.size(); ++n) {
    const ModeShape w(roots[n]);
    const double b = roots[n];
    // Amplitude of the shape is O(1) (cos z and sin z terms), so absolute checks are relative.
    EXPECT_NEAR(w.Derivative(0, 0.0), 0.0, 1e-12) << n;  // u(0) = 0
    EXPECT_NEAR(w.Derivative(1, 0.0), 0.0, 1e-12) << n;  // u'(0) = 0
    EXPECT_NEAR(w.Derivative(2, 1.0), 0.0, 1e-9) << n;   // no moment at the tip
    // Shear at the tip: W''' b^3 = kappa W (EI u''' = k_s u).
    const double shear = w.Derivative(3, 1.0) * b * b * b;
    const double spring = kappa * w.Value(1.0);
    EXPECT_NEAR(shear, spring, 1e-7 * std::max({1.0, std::abs(spring), b * b * b})) << n;
  }
}

INSTANTIATE_TEST_SUITE_P(ClampedFreeAndSpring, ModeShapeBoundaryConditions,
                         ::testing::Values(0.0, 9000.0, 3e6), [](const auto& info) {
                           return "kappa_" + std::to_string(static_cast<long>(info.param));
                         });

class AnalyticBasisOrthogonality : public ::testing::TestWithParam<double> {};

TEST_P(AnalyticBasisOrthogonality, FortyModesAreMassOrthonormal) {
  const BeamProperties beam;
  const double kappa = GetParam();
  const double b40 = CharacteristicRoots(kappa, 0.0, 40).back();
  const auto quad = MakeBeamQuadrature(b40 + 1.0);
  const double f40 = beam.OmegaOf(b40) / (2 * kPi);
  const AnalyticBasis basis = MakeAnalyticBasis(beam, kappa, f40 * (1 + 1e-12), quad);
  ASSERT_EQ(basis.NumModes(), 40);
  const Eigen::MatrixXd gram = MassProjection(beam, basis, basis, quad);
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(40, 40)).cwiseAbs().maxCoeff(), 1e-10);
}

INSTANTIATE_TEST_SUITE_P(ClampedFreeAndSpring, AnalyticBasisOrthogonality,
                         ::testing::Values(0.0, 9000.0), [](const auto& info) {
                           return "kappa_" + std::to_string(static_cast<long>(info.param));
                         });

TEST(AnalyticBasis, ClampedFreeTipIsTwoOverRootMass) {
  // With the classical normalization, integral of W^2 over [0, L] is L and |W(L)| = 2, so a
  // mass-normalized clamped-free mode has |phi(L)| = 2 / sqrt(m).
  const BeamProperties beam;
  const auto quad = MakeBeamQuadrature(60.0);
  const AnalyticBasis basis = MakeAnalyticBasis(beam, 0.0, 1000.0 * 19.3, quad);
  for (int i = 0; i < basis.NumModes(); ++i) {
    EXPECT_NEAR(std::abs(basis.tip[i]), 2.0 / std::sqrt(beam.Mass()), 1e-10) << i;
  }
}

CantileverImpact PaperProblem() { return CantileverImpact{}; }

TEST(ReferenceSolver, IsExactWithoutContact) {
  CantileverImpact p = PaperProblem();
  p.gap_m = -2.0 * p.initial_tip_m;  // The stop is out of reach.
  ReferenceOptions o;
  o.end_time_s = 0.2;
  const ReferenceSolution ref = SolveReference(p, o);
  EXPECT_EQ(ref.Summary().n_transitions, 0);
  const double w1 = p.beam.OmegaOf(kClampedFreeB1);
  for (double t = 0.0; t <= 0.2; t += 0.2 / 97) {
    EXPECT_NEAR(ref.TipDisplacement(t), p.initial_tip_m * std::cos(w1 * t),
                1e-12 * p.initial_tip_m);
    EXPECT_EQ(ref.ContactForce(t), 0.0);
  }
}

TEST(ReferenceSolver, MassProportionalDampingDecaysAsAnalytic) {
  CantileverImpact p = PaperProblem();
  p.gap_m = -2.0 * p.initial_tip_m;
  p.mass_damping_per_s = 5.0;
  ReferenceOptions o;
  o.end_time_s = 0.2;
  const ReferenceSolution ref = SolveReference(p, o);
  const double w1 = p.beam.OmegaOf(kClampedFreeB1);
  const double h = p.mass_damping_per_s / 2;
  const double wd = std::sqrt(w1 * w1 - h * h);
  for (double t = 0.0; t <= 0.2; t += 0.2 / 97) {
    const double exact =
        p.initial_tip_m * std::exp(-h * t) * (std::cos(wd * t) + h / wd * std::sin(wd * t));
    EXPECT_NEAR(ref.TipDisplacement(t), exact, 1e-12 * p.initial_tip_m);
  }
}

TEST(ReferenceSolver, RefusesDampingItCannotRepresent) {
  CantileverImpact p = PaperProblem();
  p.contact_damping_n_s_per_m = 10.0;
  ReferenceOptions o;
  o.end_time_s = 0.01;
  try {
    SolveReference(p, o);
    FAIL() << "contact damping was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contact_damping_n_s_per_m"), std::string::npos);
  }
  p.contact_damping_n_s_per_m = 0.0;
  p.mass_damping_per_s = 1e3;  // alpha / 2 = 500 > omega_1 = 121 rad/s
  EXPECT_THROW(SolveReference(p, o), InputError);
}

TEST(ReferenceSolver, TransitionsLieOnTheGapAndDenseSamplingAgreesWithPhases) {
  for (double gap : {0.0, 2e-4}) {
    CantileverImpact p = PaperProblem();
    p.gap_m = gap;
    ReferenceOptions o;
    o.end_time_s = 0.06;
    const ReferenceSolution ref = SolveReference(p, o);
    ASSERT_GT(ref.Summary().n_transitions, 4) << "gap " << gap;
    const double amplitude = p.initial_tip_m;
    for (std::size_t i = 1; i < ref.Phases().size(); ++i) {
      EXPECT_NEAR(ref.TipDisplacement(ref.Phases()[i].start_s), gap, 1e-6 * amplitude) << i;
    }
    // Between transitions the tip stays on its phase's side of the gap (to the projection's
    // truncation error): no crossing was missed.
    const double step = ref.Summary().shortest_period_s / 64;
    for (double t = 0.0; t < o.end_time_s; t += step) {
      const double u = ref.TipDisplacement(t);
      const bool contact = ref.ContactForce(t) > 0.0 || u < gap - 1e-5 * amplitude;
      if (contact) {
        EXPECT_LT(u, gap + 1e-5 * amplitude) << "t = " << t;
      } else {
        EXPECT_GT(u, gap - 1e-5 * amplitude) << "t = " << t;
      }
    }
  }
}

TEST(ReferenceSolver, PhaseEnergyIsKeptExactlyAcrossTransitions) {
  // Undamped, g = 0: both phases live on the same modes, so a transition loses nothing.
  for (double r_k : {3000.0, 1e6}) {
    CantileverImpact p = PaperProblem();
    p.r_k = r_k;
    ReferenceOptions o;
    o.end_time_s = 0.06;
    const ReferenceSolution ref = SolveReference(p, o);
    ASSERT_GT(ref.Phases().size(), 10u);
    const double e0 = ref.PhaseEnergy(0);
    for (std::size_t i = 0; i < ref.Phases().size(); ++i) {
      EXPECT_NEAR(ref.PhaseEnergy(i) / e0, 1.0, 1e-10) << "R_k = " << r_k << ", phase " << i;
    }
  }
}

// The tip modes' residual flexibility is the beam's static tip flexibility less the kept modes'
// share: for none kept, L^3 / (3 EI); for n kept, the same less sum phi_n(L)^2 / omega_n^2.
TEST(TipModes, ResidualFlexibilityCompletesTheStaticTipFlexibility) {
  const BeamProperties beam;
  const double static_flexibility = 1.0 / beam.TipBendingStiffness();
  EXPECT_NEAR(ResidualTipFlexibility(beam, 0) / static_flexibility, 1.0, 1e-14);
  for (double r_fref : {1.0, 100.0, 3e4}) {
    const TipModes m = ClampedFreeTipModes(beam, r_fref * FirstClampedFreeFrequencyHz(beam));
    const double kept = (m.tip.array().square() / m.omega_rad_s.array().square()).sum();
    EXPECT_NEAR((kept + m.residual_flexibility_m_per_n) / static_flexibility, 1.0, 1e-13) << r_fref;
    for (int i = 0; i < m.tip.size(); ++i) {
      EXPECT_NEAR(std::abs(m.tip[i]), 2.0 / std::sqrt(beam.Mass()), 1e-12) << i;
    }
  }
}

// diag(d) + rho z z^T against a dense solve, for sizes where dlaed9 takes its three paths.
TEST(RankOneUpdate, MatchesADenseSolveAndIsOrthonormal) {
  for (int n : {1, 2, 7, 60}) {
    Eigen::VectorXd d(n), z(n);
    for (int i = 0; i < n; ++i) {
      d[i] = std::pow(i + 1.0, 4) * (1.0 + 1e-3 * std::sin(i));
      z[i] = (i % 2 == 0 ? 1.0 : -1.0) * (1.0 + 0.5 * std::cos(3.0 * i));
    }
    const double rho = 1e3;
    const RankOneEigen e = EigenOfRankOneUpdate(d, z, rho);
    const Eigen::MatrixXd a = Eigen::MatrixXd(d.asDiagonal()) + rho * z * z.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> dense(a);
    for (int i = 0; i < n; ++i) {
      // The dense solve is accurate to eps times the largest eigenvalue.
      EXPECT_NEAR(e.values[i], dense.eigenvalues()[i], 1e-13 * e.values.maxCoeff()) << n << i;
    }
    EXPECT_LT(
        (e.vectors.transpose() * e.vectors - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(),
        1e-12);
    EXPECT_LT((a * e.vectors - e.vectors * e.values.asDiagonal()).cwiseAbs().maxCoeff() /
                  e.values.maxCoeff(),
              1e-13);
  }
}

// On the spring the reference's modes tend to the analytic clamped-spring ones as f_ref grows
// (the residual flexibility makes the lowest converge fast): the first three, at R_k = 1e4.
TEST(ReferenceSolver, SpringModesTendToTheAnalyticClampedSpringModes) {
  const BeamProperties beam;
  const double kappa = 3.0 * 1e4;
  const std::vector<double> roots = CharacteristicRoots(kappa, 0.0, 3);
  const TipModes m = ClampedFreeTipModes(beam, 3e4 * FirstClampedFreeFrequencyHz(beam));
  const double k_s = 1e4 * beam.TipBendingStiffness();
  const double k_eff = k_s / (1.0 + k_s * m.residual_flexibility_m_per_n);
  const RankOneEigen e =
      EigenOfRankOneUpdate(m.omega_rad_s.array().square().matrix(), m.tip, k_eff);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(std::sqrt(e.values[i]) / beam.OmegaOf(roots[i]), 1.0, 1e-9) << "mode " << i + 1;
  }
}

// The estimate a reference is refused by, against references solved: its modes within two of
// each configuration's, its output samples an upper bound within a factor 2, from R_k = 1 to
// 1e6; the shipped studies' largest reference fits the budget, a 1e9 truncation does not.
TEST(ReferenceCost, EstimateBoundsTheSolvedReference) {
  for (const auto& [r_k, r_fref] : {std::pair{1.0, 2000.0}, {3000.0, 3000.0}, {1e6, 30000.0}}) {
    CantileverImpact problem;
    problem.r_k = r_k;
    ReferenceOptions options;
    options.r_fref = r_fref;
    options.end_time_s = 0.06;
    const ReferenceCost cost = EstimateReferenceCost(problem, options, options.end_time_s);
    const ReferenceSolution solved = SolveReference(problem, options);
    const ReferenceSummary& s = solved.Summary();
    EXPECT_NEAR(cost.modes, s.n_modes_free, 2.0) << "R_k = " << r_k;
    const double samples = options.end_time_s / solved.OutputStep() + 1.0;
    EXPECT_GE(cost.samples, samples) << "R_k = " << r_k;
    EXPECT_LT(cost.samples, 2.0 * samples) << "R_k = " << r_k;
    EXPECT_EQ(ReferenceBudgetExcess(problem, options, options.end_time_s), "") << "R_k = " << r_k;
  }
  CantileverImpact problem;
  ReferenceOptions huge;
  huge.r_fref = 1e9;
  huge.end_time_s = 0.06;
  const std::string excess = ReferenceBudgetExcess(problem, huge, huge.end_time_s);
  EXPECT_NE(excess.find("at most 2 GB and 1e+11 mode-samples"), std::string::npos) << excess;
}

}  // namespace
}  // namespace shockmap
