// Peer check 2 (docs/fidelity.md "Structures from an FE code"): the paper's impact on the paper's
// cantilever meshed by CalculiX and imported through its matrix storage, scored against
// shockmap's own semi-analytical reference as the native Euler-Bernoulli beam is. Skips, saying
// why, where ccx is absent.

#include <gtest/gtest.h>

#include <cmath>
#include <map>
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
    reference_ = std::make_shared<ReferenceRun>(WithTipSpectrum(
        ComputeReferenceRun(problem_, options_.reference, options_.window_s, Shocks()),
        options_.psd, options_.window_s));
  }

  // The cantilever in `elements` C3D20 bricks along its length (one across its section),
  // imported once into the folder rod<elements>; returns its tip node.
  int ImportSolid(int elements) {
    if (const auto it = tips_.find(elements); it != tips_.end()) return it->second;
    const DeckModel solid = SolidCantilever(problem_.beam, {}, elements, "C3D20");
    const std::string name = "rod" + std::to_string(elements);
    WriteDeck(dir_ / (name + ".inp"), FrequencyDeck(solid, {.modes = 1}));
    std::filesystem::create_directories(dir_ / name);
    WriteMatrixMarketStructure(ImportCalculixDeck(dir_ / (name + ".inp")), Path(name));
    return tips_[elements] = solid.observed_node;
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

  // The imported solid of `elements` bricks: the stop at its tip node (on the face y = 0,
  // mid-width) along -y, of the problem's stiffness; its first mode (bending in y) released with
  // the tip 1 mm away.
  ScoreValues Imported(int elements, double r_ftrunc, double dt) {
    const int tip = ImportSolid(elements);
    const std::string rod = "rod" + std::to_string(elements);
    const Json scene = {
        {"name", "imported"},
        {"structures",
         {{{"name", "rod"},
           {"matrix_market",
            {{"stiffness", rod + "/stiffness.mtx"},
             {"mass", rod + "/mass.mtx"},
             {"dofs", rod + "/dofs.csv"},
             {"nodes", rod + "/nodes.csv"}}}}}},
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

  const CantileverImpact problem_{};  // The paper's: R_k 3000, the first mode released 1 mm away.
  const ComparisonOptions options_{};
  std::shared_ptr<const ReferenceRun> reference_;
  std::map<int, int> tips_;  // Tip node of each imported mesh, by its element count.
};

// The paper's impact (R_k 3000, 0.06 s) at dt 1e-6 s on the native beam at its converged mesh
// (DefaultElementCount) and on ccx's C3D20 bricks imported, 20, 40 and 80 along the span.
// Measured (Err, SRf):
//   R_ftrunc   beam                  solid, 20           solid, 40           solid, 80
//   10         0.48977  0.84398      0.48976  0.84392    0.48977  0.84391    0.48977  0.84392
//   30         0.26656  0.92679      0.26810  0.92560    0.28882  0.92438    0.28990  0.92428
//   100        0.22833  0.94104      0.23055  0.94068    0.18401  0.95234    0.17918  0.95429
//   300        0.02876  0.99339      0.00985  0.99765    0.11380  0.97286    0.12610  0.97015
// At R_ftrunc 10 the solid, at any of its meshes, scores as the beam (1.6e-5 of Err, 6e-5 of
// SRf). Above, the solid's scores converge with its mesh (the change from 40 to 80 bricks is 1/8
// to 1/19 of the change from 20 to 40) to values that are not the beam's: the difference from
// the beam is 8 to 21 times the last mesh change, so it is the solid's own model (it has modes
// below R_ftrunc f1 that the Euler-Bernoulli beam and its reference lack, docs/fidelity.md), and
// at 300 the solid's Err, 0.126, fails the default threshold 0.1 where the beam's passes.
TEST_F(CalculixCantileverImpact, ImportedSolidScoresAsTheBeamOnlyWhereItHasTheBeamsModes) {
  const double dt = 1e-6;
  const ScoreValues beam10 = Beam(10.0, dt, 0);
  for (const int elements : {20, 40, 80}) {
    const ScoreValues solid = Imported(elements, 10.0, dt);
    EXPECT_NEAR(*solid["err"], *beam10["err"], 1e-4 * *beam10["err"]) << elements;
    EXPECT_NEAR(*solid["srf"], *beam10["srf"], 2e-4) << elements;
  }
  for (const double r : {30.0, 100.0, 300.0}) {
    const ScoreValues beam = Beam(r, dt, 0);
    const ScoreValues s20 = Imported(20, r, dt), s40 = Imported(40, r, dt),
                      s80 = Imported(80, r, dt);
    const double coarse = std::abs(*s20["err"] - *s40["err"]);
    const double fine = std::abs(*s40["err"] - *s80["err"]);
    EXPECT_LT(fine, coarse / 4.0) << r;
    EXPECT_GT(std::abs(*s80["err"] - *beam["err"]), 5.0 * fine) << r;
  }
  const ScoreValues beam300 = Beam(300.0, dt, 0);
  EXPECT_LE(*beam300["err"], DefaultThresholds().at("err"));
  EXPECT_GT(*Imported(80, 300.0, dt)["err"], DefaultThresholds().at("err"));
}

}  // namespace
}  // namespace shockmap::testing
