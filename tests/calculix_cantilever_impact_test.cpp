// Peer check 2 (docs/fidelity.md "Structures from an FE code"): the paper's impact on the paper's
// cantilever meshed by CalculiX and imported through its matrix storage, scored against
// shockmap's own semi-analytical reference as the native Euler-Bernoulli beam is. Skips, saying
// why, where ccx is absent.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/comparison.h"
#include "compare/reference_run.h"
#include "compare/scene_run.h"
#include "core/cantilever_impact.h"
#include "formats/calculix_job.h"
#include "formats/scene_file.h"
#include "formats/structure_files.h"
#include "tests/calculix_decks.h"
#include "tests/calculix_runner.h"
#include "tests/temp_dir.h"
#include "validation/scores.h"

namespace shockmap::testing {
namespace {

using Json = nlohmann::json;

class CalculixCantileverImpact : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    if (!FindCalculix()) GTEST_SKIP() << CalculixMissingMessage();
    WriteDeck(dir_ / "cantilever.inp", FrequencyDeck(solid_, {.modes = 1}));
    std::filesystem::create_directories(dir_ / "rod");
    WriteMatrixMarketStructure(ImportCalculixDeck(dir_ / "cantilever.inp"), Path("rod"));
    reference_ = std::make_shared<ReferenceRun>(WithTipSpectrum(
        ComputeReferenceRun(problem_, options_.reference, options_.window_s, Shocks()),
        options_.psd, options_.window_s));
  }

  ShockSegmentationOptions Shocks() const { return options_.Shocks(problem_.F1Hz()); }

  // Every registered score of a run's tip and stop force against the reference.
  ScoreValues Score(const SceneRun& run) const {
    const UniformSignal& tip = run.result.displacement_m.at(0);
    const UniformSignal& force = run.result.contact_force_n.at(0);
    const std::vector<Shock> shocks = SegmentShocks(force, Shocks(), options_.window_s);
    return ComputeScores({.displacement = tip,
                          .reference_displacement = reference_->tip_m,
                          .reference_spectrum = &reference_->tip_spectrum->psd,
                          .psd = options_.psd,
                          .end_s = options_.window_s,
                          .force = force,
                          .shocks = shocks,
                          .reference_force = reference_->force_n,
                          .reference_shocks = reference_->shocks,
                          .srf_definition = options_.srf_definition,
                          .segmentation = Shocks()});
  }

  // The native beam of `elements` elements (the canonical problem as a scene).
  ScoreValues Beam(double r_ftrunc, double dt, int elements) const {
    Scene scene = CanonicalScene(problem_, r_ftrunc, elements);
    scene.solver.dt.dt_s = dt;
    scene.solver.end_time_s = options_.window_s;
    return Score(RunScene(scene));
  }

  // The imported solid: the stop at its tip node (on the face y = 0, mid-width) along -y, of the
  // problem's stiffness; its first mode (bending in y) released with the tip 1 mm away.
  ScoreValues Imported(double r_ftrunc, double dt) const {
    const int tip = solid_.observed_node;
    const Json scene = {
        {"name", "imported"},
        {"structures",
         {{{"name", "rod"},
           {"matrix_market",
            {{"stiffness", "rod/stiffness.mtx"},
             {"mass", "rod/mass.mtx"},
             {"dofs", "rod/dofs.csv"},
             {"nodes", "rod/nodes.csv"}}}}}},
        {"zones",
         {{{"name", "tip"},
           {"structure", "rod"},
           {"node", tip},
           {"normal", {0, -1, 0}},
           {"stiffness_n_per_m", problem_.SpringStiffness()}}}},
        {"effects",
         {{"initial_state",
           {{{"structure", "rod"},
             {"node", tip},
             {"direction", {0, 1, 0}},
             {"mode", 1},
             {"amplitude_m", problem_.initial_tip_m}}}}}},
        {"solver",
         {{"r_ftrunc", r_ftrunc}, {"dt", {{"seconds", dt}}}, {"end_time_s", options_.window_s}}},
        {"outputs",
         {{"displacements",
           {{{"name", "tip"}, {"structure", "rod"}, {"node", tip}, {"direction", {0, 1, 0}}}}},
          {"contact_forces", true}}}};
    const SceneRun run = RunScene(ParseScene(scene, Path("imported.json")));
    EXPECT_EQ(run.result.summary.status, RunStatus::kOk) << run.result.summary.message;
    return Score(run);
  }

  const CantileverImpact problem_;  // The paper's: R_k 3000, the first mode released 1 mm away.
  const ComparisonOptions options_;
  const DeckModel solid_ = SolidCantilever(problem_.beam, {}, 20, "C3D20");
  std::shared_ptr<const ReferenceRun> reference_;
};

// The paper's impact (R_k 3000, 0.06 s) at rising R_ftrunc, dt 1e-6 s, on the native beam at its
// converged mesh (DefaultElementCount), on the native beam of 20 elements and on ccx's 20 C3D20
// bricks imported. Measured (Err, SRf):
//   R_ftrunc   beam, converged mesh   beam, 20 elements     imported solid
//   10         0.48977  0.84398       the same (20)         0.48976  0.84392
//   30         0.26656  0.92679       the same (20)         0.26810  0.92560
//   100        0.22833  0.94104       0.22831  0.94103      0.23055  0.94068
//   300        0.02876  0.99339       0.03705  0.99196      0.00985  0.99765
// Up to R_ftrunc 100 the imported solid scores as the beam to 1e-2 of Err and 1.2e-3 of SRf:
// more than the beam's own mesh changes them (2e-5), by the solid's own physics (its second
// bending frequency lies 1.6e-3 below Euler-Bernoulli's in ccx, docs/fidelity.md). At 300 the
// solid's Err is 1.9e-2 below the converged beam's and its SRf 4.3e-3 above, 2.3 and 3.0 times
// what 20 elements change the beam's (8.3e-3 and 1.4e-3; asserted within 4 times): the solid
// keeps modes there that the Euler-Bernoulli beam does not have. Every verdict at the
// default thresholds (Err <= 0.1, SRf >= 0.8) is the beam's.
TEST_F(CalculixCantileverImpact, ImportedSolidScoresAsTheNativeBeam) {
  const auto thresholds = DefaultThresholds();
  const double dt = 1e-6;
  for (const double r : {10.0, 30.0, 100.0, 300.0}) {
    const ScoreValues beam = Beam(r, dt, 0), imported = Imported(r, dt);
    const double err = *beam["err"], srf = *beam["srf"];
    EXPECT_EQ(*imported["err"] <= thresholds.at("err"), err <= thresholds.at("err")) << r;
    EXPECT_EQ(*imported["srf"] >= thresholds.at("srf"), srf >= thresholds.at("srf")) << r;
    if (r <= 100.0) {
      EXPECT_NEAR(*imported["err"], err, 0.015 * err) << r;
      EXPECT_NEAR(*imported["srf"], srf, 2e-3) << r;
    } else {
      const ScoreValues beam20 = Beam(r, dt, 20);
      EXPECT_LT(std::abs(*imported["err"] - err), 4.0 * std::abs(*beam20["err"] - err));
      EXPECT_LT(std::abs(*imported["srf"] - srf), 4.0 * std::abs(*beam20["srf"] - srf));
    }
  }
}

}  // namespace
}  // namespace shockmap::testing
