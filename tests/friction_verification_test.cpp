// Verification of the friction conventions (core/contact_law.h, docs/physics.md §7.2) against
// code_aster's DIS_CHOC friction case in a modal transient (DYNA_VIBRA, BASE_CALCUL='GENE') and
// against rigid Coulomb's closed form.
//
// code_aster's case, astest/sdnd100a.comm ("cas-test de frottement à 1 ddl"): a mass M = 1 kg
// on a spring K = 1e4 N/m (DIS_T, K_T_D_N), constrained to move along (1, 1, 0)/sqrt(2)
// (LIAISON_DDL DX = DY, DZ = 0), pressed on a PLAN_Z obstacle (JEU 0.5, RIGI_NOR 20: N = 10 N
// = M g), released at rest from U0 = 0.85 mm along its line (ETAT_INIT DEPL, DX = DY = U0 cos 45°)
// against COULOMB = 0.1 (FROTTEMENT='COULOMB': COULOMB_STAT = COULOMB_DYNA), RIGI_TAN = 4e5 N/m,
// no AMOR_TAN, SCHEMA='DIFF_CENTRE', PAS = 5e-4 s, AMOR_REDUIT = 0. Rigid Coulomb's decay: the
// amplitude loses 2 C, C = mu M g / K, every half-period pi / omega: TEST_RESU on DY (=
// the line's displacement times cos 45°, REST_GENE_PHYS INTERPOL='LIN') at T1..T4 = k pi /
// omega, VALE_REFE -4.596e-4, 3.182e-4, -1.768e-4, 3.536e-5 m (REFERENCE='ANALYTIQUE'),
// PRECISION 1e-3, 1e-3, 1e-3, 5e-3 (relative).
//
// Here the line's coordinate z carries the mode (omega = 100 rad/s, unit mode shape), and the
// normal coordinate y, free, is pressed by N = 10 N onto a stop of stiffness 20 N/m from its
// equilibrium penetration 0.5 m, so that N stays 10 N, as sdnd100a's fixed penetration gives.
// DIS_CHOC's friction is isotropic in the obstacle's plane, so along the line it is the scene's
// friction along the zone's tangent.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "core/contact_law.h"
#include "core/newmark.h"
#include "core/scene.h"
#include "core/scene_system.h"

namespace shockmap {
namespace {

constexpr double kPi = std::numbers::pi;

// sdnd100a's data.
constexpr double kMassKg = 1.0, kStiffnessNPerM = 1e4, kNormalForceN = 10.0;
constexpr double kCoulomb = 0.1, kRigiTanNPerM = 4e5, kStepS = 5e-4, kReleaseM = 0.85e-3;
constexpr double kRigiNorNPerM = 20.0;
const double kCos45 = std::cos(kPi / 4);
const double kOmega = std::sqrt(kStiffnessNPerM / kMassKg);

// The four half-periods T_k = k pi / omega, sdnd100a's VALE_REFE on DY and PRECISION.
constexpr int kHalfPeriods = 4;
constexpr std::array<double, kHalfPeriods> kValeRefe = {-4.596e-4, 3.182e-4, -1.768e-4, 3.536e-5};
constexpr std::array<double, kHalfPeriods> kPrecision = {1e-3, 1e-3, 1e-3, 5e-3};

FrictionLaw Law(FrictionConvention convention, double k_t) {
  FrictionLaw law;
  law.coefficient = kCoulomb;
  law.static_coefficient = kCoulomb;
  law.tangential_stiffness_n_per_m = k_t;
  law.convention = convention;
  return law;
}

// The line's displacement (m) at T_1..T_4 for a law and a step: the structure released at rest
// from kReleaseM, central differences, linear interpolation between the steps around each T_k.
std::array<double, kHalfPeriods> LineDisplacements(const FrictionLaw& law, double dt_s) {
  ZoneTerm zone;
  zone.a_y = 0;
  zone.a_z = 1;
  zone.phi_a = {1 / std::sqrt(kMassKg)};
  zone.law.normal = {kRigiNorNPerM};
  zone.law.friction = law;
  const StaticForceEffect press{0, 0.0, 1.0, 0.0, kNormalForceN};
  std::vector<TimeLoad> loads(1);
  loads[0].shape = Eigen::Vector2d(1.0, 0.0);
  loads[0].point_force = &press;
  SceneModalSystem system(Eigen::Vector2d(0.0, kOmega), std::nullopt, {zone}, std::move(loads));
  NewmarkIntegrator integrator(NewmarkParameters::CentralDifference(), system);
  const Eigen::Vector2d x0(kNormalForceN / kRigiNorNPerM, kReleaseM);
  EXPECT_TRUE(integrator.Init(x0, Eigen::Vector2d::Zero()));
  std::array<double, kHalfPeriods> at{};
  double t_before = 0.0, z_before = kReleaseM;
  for (int k = 0; k < kHalfPeriods;) {
    EXPECT_TRUE(integrator.Step(dt_s));
    const double t = integrator.T(), z = integrator.X()(1);
    while (k < kHalfPeriods && t >= (k + 1) * kPi / kOmega) {
      const double w = ((k + 1) * kPi / kOmega - t_before) / (t - t_before);
      at[k++] = (1 - w) * z_before + w * z;
    }
    t_before = t;
    z_before = z;
  }
  EXPECT_NEAR(system.Contacts().Forces()[0], kNormalForceN, 1e-9);  // N stayed M g.
  return at;
}

// Rigid Coulomb's extreme after k half-periods: (-1)^k (U0 - 2 k C), C = mu N / K.
double RigidCoulombExtreme(int k) {
  const double c = kCoulomb * kNormalForceN / kStiffnessNPerM;
  return (k % 2 == 0 ? 1.0 : -1.0) * (kReleaseM - 2 * k * c);
}

// sdnd100a's TEST_RESU: DY at T_k relative to VALE_REFE.
std::array<double, kHalfPeriods> RelativeToValeRefe(const std::array<double, kHalfPeriods>& u) {
  std::array<double, kHalfPeriods> e{};
  for (int k = 0; k < kHalfPeriods; ++k) {
    e[k] = (u[k] * kCos45 - kValeRefe[k]) / std::abs(kValeRefe[k]);
  }
  return e;
}

void Print(const char* name, const std::array<double, kHalfPeriods>& e) {
  std::printf("sdnd100a %-42s DY at T1..T4 relative to VALE_REFE: %+.2e %+.2e %+.2e %+.2e\n", name,
              e[0], e[1], e[2], e[3]);
}

// The analytic reference of sdnd100a is rigid Coulomb's (its VALE_REFE is R_k cos 45°, rounded
// to four digits).
TEST(FrictionVerification, Sdnd100aReferenceIsRigidCoulombDecay) {
  for (int k = 0; k < kHalfPeriods; ++k) {
    EXPECT_NEAR(RigidCoulombExtreme(k + 1) * kCos45 / kValeRefe[k], 1.0, 5e-4) << "T" << k + 1;
  }
}

// sdnd100a at code_aster's own data (RIGI_TAN 4e5 N/m, no AMOR_TAN, PAS 5e-4 s). Measured:
// code_aster's convention meets code_aster's PRECISION at T1 and T2 (+1.6e-4, +9.2e-4) and not
// at T3 and T4 (-3.4e-3, +3.8e-2), as the default convention (-5.9e-5, +1.1e-3, -3.6e-3,
// +3.8e-2): DIS_CHOC's ftang, as written, sticks at every reversal of the slip rate until the
// spring has unloaded 2 mu N / k_t, as the default law does, and that costs amplitude that
// rigid Coulomb does not lose (3.8 % at T4, 1 / k_t as FrictionVerification.RigidLimit
// shows). With a spring ten times stiffer, at the same step, all four meet the PRECISION.
TEST(FrictionVerification, Sdnd100aOneModeReleasedAtRestAgainstCoulomb) {
  const auto code_aster = RelativeToValeRefe(
      LineDisplacements(Law(FrictionConvention::kCodeAster, kRigiTanNPerM), kStepS));
  const auto default_law = RelativeToValeRefe(
      LineDisplacements(Law(FrictionConvention::kReturnMapping, kRigiTanNPerM), kStepS));
  const auto stiffer = RelativeToValeRefe(
      LineDisplacements(Law(FrictionConvention::kCodeAster, 10 * kRigiTanNPerM), kStepS));
  Print("code_aster convention, RIGI_TAN 4e5:", code_aster);
  Print("return_mapping convention, RIGI_TAN 4e5:", default_law);
  Print("code_aster convention, RIGI_TAN 4e6:", stiffer);
  for (int k = 0; k < 2; ++k) EXPECT_LE(std::abs(code_aster[k]), kPrecision[k]) << "T" << k + 1;
  for (int k = 0; k < kHalfPeriods; ++k) {
    EXPECT_LE(std::abs(stiffer[k]), kPrecision[k]) << "T" << k + 1;
  }
}

// The rigid limit: released at rest, both conventions tend to rigid Coulomb's decay as k_t
// grows (at a step of 1e-5 s, 2e-3 of the stiffest spring's stick period), the largest error
// over T1..T4 falling as 1 / k_t: the observed order between successive tenfold stiffenings
// lies within [0.9, 1.1], and at k_t = 4e8 N/m the error is below 1e-5 of U0.
TEST(FrictionVerification, RigidLimit) {
  const double dt_s = 1e-5;
  for (const FrictionConvention convention :
       {FrictionConvention::kCodeAster, FrictionConvention::kReturnMapping}) {
    double error_before = 0.0;
    for (const double k_t : {4e5, 4e6, 4e7, 4e8}) {
      const auto u = LineDisplacements(Law(convention, k_t), dt_s);
      double error = 0.0;
      for (int k = 0; k < kHalfPeriods; ++k) {
        error = std::max(error, std::abs(u[k] - RigidCoulombExtreme(k + 1)) / kReleaseM);
      }
      const char* name =
          convention == FrictionConvention::kCodeAster ? "code_aster" : "return_mapping";
      if (error_before > 0.0) {
        const double order = std::log10(error_before / error);
        std::printf("rigid limit, %-14s k_t %.0e N/m: error %.3e of U0, observed order %.3f\n",
                    name, k_t, error, order);
        EXPECT_GE(order, 0.9) << name << " k_t " << k_t;
        EXPECT_LE(order, 1.1) << name << " k_t " << k_t;
      } else {
        std::printf("rigid limit, %-14s k_t %.0e N/m: error %.3e of U0\n", name, k_t, error);
      }
      error_before = error;
    }
    EXPECT_LT(error_before, 1e-5);
  }
}

}  // namespace
}  // namespace shockmap
