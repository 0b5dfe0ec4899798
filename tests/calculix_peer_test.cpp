// CalculiX (ccx) as an independent FE code on the same structures as shockmap (docs/fidelity.md
// "Structures from an FE code"). Every test skips, saying why, where ccx is absent.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <numbers>

#include "core/beam_properties.h"
#include "core/structure_modes.h"
#include "formats/calculix_job.h"
#include "tests/calculix_decks.h"
#include "tests/calculix_runner.h"
#include "tests/temp_dir.h"

namespace shockmap::testing {
namespace {

#define SKIP_WITHOUT_CALCULIX() \
  if (!FindCalculix()) GTEST_SKIP() << CalculixMissingMessage()

class CalculixPeer : public TempDirTest {
 protected:
  // Writes `deck` as dir/jobname.inp, runs ccx on it, fails the test unless ccx completed.
  CalculixRun Run(const std::string& jobname, const std::string& deck) {
    WriteDeck(dir_ / (jobname + ".inp"), deck);
    const CalculixRun run = RunCalculix(dir_, jobname);
    EXPECT_TRUE(run.Completed()) << run.Describe();
    return run;
  }
  std::filesystem::path Dat(const std::string& jobname) const { return dir_ / (jobname + ".dat"); }
};

// ccx 2.20 refuses a support on a node set the deck does not define with "*ERROR" and exit
// code 201 (measured).
TEST_F(CalculixPeer, RunnerReportsADeckCcxRefusesWithItsLog) {
  SKIP_WITHOUT_CALCULIX();
  std::string deck = StaticDeck(ClampedPlate({}, 2, 2), {0.0, 0.0, 1.0});
  deck.replace(deck.find("CLAMP, 1, 3"), 5, "NOSUCHSET");
  WriteDeck(dir_ / "bad.inp", deck);
  const CalculixRun run = RunCalculix(dir_, "bad");
  EXPECT_EQ(run.status, CalculixRun::Status::kFailed) << run.Describe();
  EXPECT_NE(run.exit_code, 0) << run.Describe();
  EXPECT_NE(run.Describe().find("NOSUCHSET"), std::string::npos) << run.Describe();
  EXPECT_EQ(run.log, dir_ / "bad.log");
}

TEST_F(CalculixPeer, RunnerSaysWhenCcxIsMissing) {
  ::setenv("SHOCKMAP_CCX", (dir_ / "no_ccx_here").c_str(), 1);
  const CalculixRun run = RunCalculix(dir_, "any");
  ::unsetenv("SHOCKMAP_CCX");
  EXPECT_EQ(run.status, CalculixRun::Status::kNotFound);
  EXPECT_NE(run.Describe().find("apt-get install calculix-ccx"), std::string::npos)
      << run.Describe();
}

TEST_F(CalculixPeer, RunnerKillsAJobPastItsTimeLimit) {
  SKIP_WITHOUT_CALCULIX();
  // A plate's transient of 20000 steps runs for minutes; the limit stops it after one second.
  TransientStep step;
  step.dt_s = 1e-6;
  step.end_s = 0.02;
  step.stop.normal = {0.0, 0.0, -1.0};
  WriteDeck(dir_ / "long.inp", TransientDeck(ClampedPlate({}, 8, 6), step));
  const CalculixRun run =
      RunCalculix(dir_, "long", {.threads = 1, .time_limit = std::chrono::seconds(1)});
  EXPECT_EQ(run.status, CalculixRun::Status::kTimedOut) << run.Describe();
  EXPECT_LT(run.wall_seconds, 5.0);
}

// The paper's cantilever in 20 C3D20R bricks: ccx's frequencies are the analytic clamped-free
// ones within the mesh's and the section's (shear) discretization, measured -2.3e-4 for f1 and
// -1.6e-3 for the second bending mode in the plane; the bending across the plane (width twice
// the depth) is at twice f1, measured -9.3e-4 (the shear of the wider side).
TEST_F(CalculixPeer, SolidCantileverFrequenciesAreTheAnalyticOnes) {
  SKIP_WITHOUT_CALCULIX();
  const BeamProperties beam;
  Run("solid", FrequencyDeck(SolidCantilever(beam, {}, 20), {.modes = 4}));
  const std::vector<double> hz = ReadEigenfrequenciesHz(Dat("solid"));
  ASSERT_EQ(hz.size(), 4u);
  const double f1 = FirstClampedFreeFrequencyHz(beam);
  const double f2 = f1 * std::pow(4.6940911329741745 / kClampedFreeB1, 2);
  EXPECT_NEAR(hz[0] / f1 - 1.0, 0.0, 5e-4);
  EXPECT_NEAR(hz[1] / (2.0 * f1) - 1.0, 0.0, 1.5e-3);
  EXPECT_NEAR(hz[2] / f2 - 1.0, 0.0, 3e-3);
}

// ccx expands B32R beams into C3D20R bricks of the section's shape: the beam deck has the brick
// deck's frequencies (measured equal to all 7 printed digits).
TEST_F(CalculixPeer, BeamElementsAreExpandedIntoTheSameBricks) {
  SKIP_WITHOUT_CALCULIX();
  const BeamProperties beam;
  Run("beam", FrequencyDeck(BeamCantilever(beam, {}, 20), {.modes = 4}));
  Run("solid", FrequencyDeck(SolidCantilever(beam, {}, 20), {.modes = 4}));
  const std::vector<double> beam_hz = ReadEigenfrequenciesHz(Dat("beam"));
  const std::vector<double> solid_hz = ReadEigenfrequenciesHz(Dat("solid"));
  ASSERT_EQ(beam_hz.size(), solid_hz.size());
  for (std::size_t i = 0; i < beam_hz.size(); ++i)
    EXPECT_NEAR(beam_hz[i] / solid_hz[i], 1.0, 1e-6) << "mode " << i + 1;
}

// The GAPUNI element at the observed node closes when the node moves along the stop's normal,
// with the stop's stiffness in series with none (both in parallel on the node): under a force F
// along n the node moves F / (K_bend + k); against n it moves F / K_bend. Only in a nonlinear
// step (NLGEOM), as TransientDeck writes it.
TEST_F(CalculixPeer, GapStopClosesAlongItsNormalOnly) {
  SKIP_WITHOUT_CALCULIX();
  const DeckModel plate = ClampedPlate({}, 4, 3);
  const Eigen::Vector3d n(0.0, 0.0, -1.0);
  Run("free", StaticDeck(plate, 10.0 * n));
  const double free_u =
      HistoryAlong(ReadNodeBlocks(Dat("free"), "displacements", "OBSERVED"), plate.observed_node, n)
          .value.at(0);
  const double k_bend = 10.0 / free_u;
  const double k_stop = 100.0 * k_bend;
  for (const double sign : {1.0, -1.0}) {
    std::string deck = StaticDeck(plate, sign * 10.0 * n);
    const int stop = StopNodeOf(plate);
    const Eigen::Vector3d at = plate.nodes.at(plate.observed_node);
    const std::string gap = "*NODE, NSET=STOP\n" + std::to_string(stop) + ", " +
                            std::to_string(at.x()) + ", " + std::to_string(at.y()) + ", " +
                            std::to_string(at.z()) + "\n*ELEMENT, TYPE=GAPUNI, ELSET=EGAP\n9999, " +
                            std::to_string(plate.observed_node) + ", " + std::to_string(stop) +
                            "\n*GAP, ELSET=EGAP\n0, 0, 0, -1, , " + std::to_string(k_stop) +
                            "\n*BOUNDARY\nSTOP, 1, 3\n*STEP, NLGEOM\n";
    deck.replace(deck.find("*STEP\n"), 6, gap);
    Run("gap", deck);
    const double u = HistoryAlong(ReadNodeBlocks(Dat("gap"), "displacements", "OBSERVED"),
                                  plate.observed_node, n)
                         .value.at(0);
    const double expected = sign * 10.0 / (sign > 0 ? k_bend + k_stop : k_bend);
    EXPECT_NEAR(u / expected, 1.0, 1e-3) << "force along " << sign << " n";
  }
}

// The plate (not a beam) imported through ccx's matrix storage: its modes are ccx's own
// *FREQUENCY on the same deck (to the 7 digits ccx prints), and its local stiffness at the
// corner along the stop's normal, the paper's K_bend that a zone's R_k divides, is ccx's own
// static compliance there (a force on the node, its displacement).
TEST_F(CalculixPeer, ImportedPlateHasCcxsFrequenciesAndCornerStiffness) {
  SKIP_WITHOUT_CALCULIX();
  const DeckModel plate = ClampedPlate({}, 4, 3);
  const int modes = 6;
  Run("plate", FrequencyDeck(plate, {.modes = modes}));
  const std::vector<double> ccx_hz = ReadEigenfrequenciesHz(Dat("plate"));
  ASSERT_EQ(ccx_hz.size(), static_cast<std::size_t>(modes));
  const FeStructure imported = ImportCalculixDeck(dir_ / "plate.inp");
  const ModalBasis basis = LowestStructureModes(imported, modes);
  ASSERT_EQ(basis.omega_rad_s.size(), static_cast<Eigen::Index>(modes));
  for (int i = 0; i < modes; ++i)
    EXPECT_NEAR(basis.omega_rad_s[i] / (2.0 * std::numbers::pi * ccx_hz[i]), 1.0, 2e-6)
        << "mode " << i + 1;

  const Eigen::Vector3d n(0.0, 0.0, -1.0);
  Run("corner", StaticDeck(plate, 1.0 * n));
  const double compliance = HistoryAlong(ReadNodeBlocks(Dat("corner"), "displacements", "OBSERVED"),
                                         plate.observed_node, n)
                                .value.at(0);
  EXPECT_NEAR(LocalStiffness(imported, plate.observed_node, n) * compliance, 1.0, 2e-6);
}

// The shipped decks run in ccx as they are, and import with ccx's own frequencies: the plate
// (scenes/clamped_plate.inp) to the 7 digits ccx prints; the non-uniform pin
// (scenes/fuel_pin.inp: B32R beams 450 times longer than wide, four materials, a point mass)
// only to 1.0e-3 for its two lowest modes and 3e-5 for the next ones (measured, with or without
// the point mass). Which of the two eigensolutions is the more accurate is not settled: the
// expanded slender beam's K is ill-conditioned, and ccx's own eigensolver has its tolerance.
TEST_F(CalculixPeer, ShippedDecksImportWithCcxsFrequencies) {
  SKIP_WITHOUT_CALCULIX();
  const std::map<std::string, double> tolerance = {{"clamped_plate", 2e-6}, {"fuel_pin", 2e-3}};
  for (const auto& [name, relative] : tolerance) {
    std::filesystem::copy_file(
        std::filesystem::path(SHOCKMAP_SOURCE_DIR) / "scenes" / (name + ".inp"),
        dir_ / (name + ".inp"));
    const CalculixRun run = RunCalculix(dir_, name);
    ASSERT_TRUE(run.Completed()) << run.Describe();
    const std::vector<double> ccx_hz = ReadEigenfrequenciesHz(Dat(name));
    ASSERT_EQ(ccx_hz.size(), 10u) << name;
    const ModalBasis basis = LowestStructureModes(ImportCalculixDeck(dir_ / (name + ".inp")), 10);
    ASSERT_EQ(basis.omega_rad_s.size(), 10) << name;
    for (int i = 0; i < 10; ++i)
      EXPECT_NEAR(basis.omega_rad_s[i] / (2.0 * std::numbers::pi * ccx_hz[i]), 1.0, relative)
          << name << " mode " << i + 1;
  }
}

// ccx's own direct transient (NLGEOM, ALPHA=0, a GAPUNI stop) of the 4 x 3 plate released from
// rest under 20 N at its corner (about 1e-4 m, away from the stop) onto a stop of 2e7 N/m
// (about 95 times the corner's K_bend) over 12 ms, at halving steps: the stop's total impulse
// converges at first order (measured 8.2014e-2, 8.1811e-2, 8.1711e-2 N s at 4e-5, 2e-5, 1e-5 s:
// order 1.04, the last two 1.2e-3 apart; docs/fidelity.md "Structures from an FE code").
class CalculixPeerLong : public CalculixPeer {};

TEST_F(CalculixPeerLong, PlateTransientConvergesInItsOwnStep) {
  SKIP_WITHOUT_CALCULIX();
  const DeckModel plate = ClampedPlate({}, 4, 3);
  const Eigen::Vector3d up(0.0, 0.0, 1.0);
  std::vector<double> impulse;
  for (const double dt : {4e-5, 2e-5, 1e-5}) {
    TransientStep step;
    step.dt_s = dt;
    step.end_s = 0.012;
    step.stop.normal = -up;
    step.stop.stiffness_n_per_m = 2e7;
    step.release_force_n = 20.0 * up;
    const std::string job = "plate" + std::to_string(impulse.size());
    Run(job, TransientDeck(plate, step));
    const History force =
        HistoryAlong(ReadNodeBlocks(Dat(job), "forces", "STOP"), StopNodeOf(plate), up);
    ASSERT_EQ(force.t.size(), static_cast<std::size_t>(std::lround(0.012 / dt))) << job;
    impulse.push_back(ContactImpulse(force, dt));
  }
  const double order =
      std::log2(std::abs(impulse[0] - impulse[1]) / std::abs(impulse[1] - impulse[2]));
  EXPECT_GT(order, 0.5) << impulse[0] << " " << impulse[1] << " " << impulse[2];
  EXPECT_NEAR(impulse[2] / impulse[1], 1.0, 2.5e-3);
}

}  // namespace
}  // namespace shockmap::testing
