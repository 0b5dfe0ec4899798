// Non-uniform beams (docs/scenes.md, "Non-uniform beams"): sections of their own EI and rho A
// and point masses, checked against analytic solutions (the clamped-free beam with a tip mass,
// Mohr's integral on a stepped beam); the basis cache telling sectioned beams apart; the
// reader's refusals, each with its key path and exit code 2.

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/input_error.h"
#include "core/modal_basis.h"
#include "core/scene_model.h"
#include "formats/scene_file.h"
#include "tests/run_command.h"
#include "tests/scene_refusal.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

constexpr double kB1 = 1.8751040687119611;  // Clamped-free roots of 1 + cosh b cos b = 0.
constexpr double kB2 = 4.6940911329741746;
constexpr double kB3 = 7.8547574382376126;
constexpr double kEi = 1.5e5, kRhoA = 127.0;  // The paper's beam (L = 1 m).

SceneBeam Uniform(int elements) {
  SceneBeam b;
  b.name = "uniform";
  b.length_m = 1.0;
  b.ei_n_m2 = kEi;
  b.rho_a_kg_per_m = kRhoA;
  b.n_elements = elements;
  return b;
}

// A beam of 1 m.
SceneBeam Sectioned(std::vector<BeamSection> sections, int elements,
                    std::vector<BeamPointMass> masses = {}) {
  SceneBeam b;
  b.name = "sectioned";
  b.length_m = 1.0;
  b.sections = std::move(sections);
  b.point_masses = std::move(masses);
  b.n_elements = elements;
  return b;
}

Eigen::VectorXd OmegasOf(const SceneBeam& b, int modes) {
  return ComputeLowestModes(AssembleSceneBeam(b), modes).omega_rad_s;
}

double UniformOmega(double root) { return root * root * std::sqrt(kEi / kRhoA); }

// The root in (0, kB1] of f, which changes sign there, by bisection to round-off.
double LowestRoot(const std::function<double(double)>& f) {
  double lo = 0.1, hi = kB1;
  EXPECT_LT(f(lo) * f(hi), 0.0) << "no sign change";
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(lo) * f(mid) <= 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// beta L of the clamped-free beam with a tip mass m = mu rho A L: the lowest root of
// 1 + cos b cosh b + mu b (cos b sinh b - sin b cosh b) = 0.
double TipMassRoot(double mu) {
  return LowestRoot([mu](double b) {
    return 1.0 + std::cos(b) * std::cosh(b) +
           mu * b * (std::cos(b) * std::sinh(b) - std::sin(b) * std::cosh(b));
  });
}

// beta L with a tip mass m = mu rho A L and rotary inertia J = eta rho A L^3: W = A (cosh bx -
// cos bx) + B (sinh bx - sin bx) (clamped at 0), and at the tip EI W''' + m w^2 W = 0 (shear)
// and EI W'' - J w^2 W' = 0 (moment), w^2 = b^4 EI / (rho A L^4): the lowest zero of the 2 x 2
// determinant, in units of L = 1.
double TipMassAndInertiaRoot(double mu, double eta) {
  return LowestRoot([mu, eta](double b) {
    const double ch = std::cosh(b), c = std::cos(b), sh = std::sinh(b), s = std::sin(b);
    const double b4 = b * b * b * b;
    // Rows: shear and moment conditions; columns: A, B.
    const double shear_a = b * b * b * (sh - s) + mu * b4 * (ch - c);
    const double shear_b = b * b * b * (ch + c) + mu * b4 * (sh - s);
    const double moment_a = b * b * (ch + c) - eta * b4 * b * (sh + s);
    const double moment_b = b * b * (sh + s) - eta * b4 * b * (ch - c);
    return shear_a * moment_b - shear_b * moment_a;
  });
}

// Mohr's integral: the deflection at `height_m` under a unit force there, the integral of
// (height - x)^2 / EI(x) from 0 to height over the sections.
double MohrFlexibility(const std::vector<BeamSection>& sections, double height_m) {
  double flexibility = 0.0, from = 0.0;
  for (const BeamSection& s : sections) {
    const double to = std::min(from + s.length_m, height_m);
    if (to > from) {
      flexibility +=
          (std::pow(height_m - from, 3) - std::pow(height_m - to, 3)) / (3.0 * s.ei_n_m2);
    }
    from += s.length_m;
  }
  return flexibility;
}

// A stepped cantilever: a stiff foot, a soft middle, a stiffer top (EI ratios 1 : 0.3 : 0.6).
const std::vector<BeamSection> kStepped = {{0.25, 2.0 * kEi, 2.0 * kRhoA},
                                           {0.5, 0.3 * 2.0 * kEi, 0.5 * kRhoA},
                                           {0.25, 0.6 * 2.0 * kEi, kRhoA}};

TEST(BeamSections, OneSectionIsTheUniformBeamBitForBit) {
  const SceneBeam uniform = Uniform(55);
  const SceneBeam one = Sectioned({{1.0, kEi, kRhoA}}, 55);
  const FeBeamModel a = AssembleSceneBeam(uniform), b = AssembleSceneBeam(one);
  EXPECT_EQ(Eigen::MatrixXd(a.stiffness), Eigen::MatrixXd(b.stiffness));
  EXPECT_EQ(Eigen::MatrixXd(a.mass), Eigen::MatrixXd(b.mass));
  EXPECT_EQ(a.DeflectionRow(0.731), b.DeflectionRow(0.731));
  EXPECT_EQ(OmegasOf(uniform, 10), OmegasOf(one, 10));
}

// Two sections of the paper's properties: at a split on the uniform mesh's nodes (0.4 m with 20
// elements) the mesh is the uniform one and so are the frequencies, to round-off; at a split
// between them (0.37 m) the mesh differs, and the frequencies are the analytic clamped-free ones
// within the Hermite elements' discretization (measured 6.5e-8, 2.4e-6, 1.6e-5 for the three
// lowest, the uniform mesh's 5.4e-8, 2.1e-6, 1.6e-5).
TEST(BeamSections, TwoIdenticalSectionsGiveTheUniformBeamsFrequencies) {
  const Eigen::VectorXd uniform = OmegasOf(Uniform(20), 6);
  const Eigen::VectorXd on_nodes =
      OmegasOf(Sectioned({{0.4, kEi, kRhoA}, {0.6, kEi, kRhoA}}, 20), 6);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(on_nodes[i] / uniform[i], 1.0, 1e-12) << "mode " << i + 1;

  const Eigen::VectorXd between =
      OmegasOf(Sectioned({{0.37, kEi, kRhoA}, {0.63, kEi, kRhoA}}, 20), 3);
  const double roots[3] = {kB1, kB2, kB3};
  const double tolerance[3] = {1e-7, 4e-6, 3e-5};
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(between[i] / UniformOmega(roots[i]), 1.0, tolerance[i]) << "mode " << i + 1;
    EXPECT_NEAR(uniform[i] / UniformOmega(roots[i]), 1.0, tolerance[i]) << "mode " << i + 1;
  }
}

// A tip mass half the beam's: f1 from 1 + cos bL cosh bL + mu bL (cos bL sinh bL - sin bL cosh
// bL) = 0, approached at the Hermite elements' fourth order as the mesh is halved (measured
// errors 5.1e-5, 3.5e-6, 2.2e-7, 1.4e-8 with 2, 4, 8, 16 elements: orders 3.87, 3.97, 3.99).
TEST(BeamSections, TipMassFirstFrequencyConvergesToTheTranscendentalRoot) {
  const double mu = 0.5;
  const double exact = UniformOmega(TipMassRoot(mu));
  std::vector<double> error;
  for (const int elements : {2, 4, 8, 16}) {
    const SceneBeam b = Sectioned({{1.0, kEi, kRhoA}}, elements, {{1.0, mu * kRhoA * 1.0, 0.0}});
    error.push_back(std::abs(OmegasOf(b, 1)[0] / exact - 1.0));
  }
  for (std::size_t i = 0; i + 1 < error.size(); ++i) {
    EXPECT_GT(std::log2(error[i] / error[i + 1]), 3.8) << error[i] << " " << error[i + 1];
  }
  EXPECT_LT(error.back(), 2e-8);
}

// The same with the mass's rotary inertia: the root of the 2 x 2 determinant of the tip's
// shear and moment conditions (at eta = 0 the transcendental equation above); measured errors
// 3.7e-5, 2.6e-6, 1.6e-7, 1.0e-8 with 2, 4, 8, 16 elements.
TEST(BeamSections, TipMassWithRotaryInertiaConvergesToItsRoot) {
  EXPECT_NEAR(TipMassAndInertiaRoot(0.5, 0.0), TipMassRoot(0.5), 1e-12);
  const double mu = 0.5, eta = 0.05;
  const double exact = UniformOmega(TipMassAndInertiaRoot(mu, eta));
  EXPECT_LT(exact, UniformOmega(TipMassRoot(mu)));
  std::vector<double> error;
  for (const int elements : {2, 4, 8, 16}) {
    const SceneBeam b = Sectioned({{1.0, kEi, kRhoA}}, elements, {{1.0, mu * kRhoA, eta * kRhoA}});
    error.push_back(std::abs(OmegasOf(b, 1)[0] / exact - 1.0));
  }
  for (std::size_t i = 0; i + 1 < error.size(); ++i) {
    EXPECT_GT(std::log2(error[i] / error[i + 1]), 3.8) << error[i] << " " << error[i + 1];
  }
  EXPECT_LT(error.back(), 2e-8);
}

// A point mass inside the beam gets a node of its own, and moves f1 as the Rayleigh quotient of
// the mode says to first order: a small mass dm at x lowers omega^2 by omega^2 phi(x)^2 dm.
TEST(BeamSections, APointMassInsideTheBeamSitsAtItsOwnNode) {
  const SceneBeam bare = Sectioned(kStepped, 30);
  const double x = 0.613;
  const SceneBeam loaded = Sectioned(kStepped, 30, {{x, 1e-4 * kRhoA, 0.0}});
  const std::vector<double> breaks = MeshBreaks(SectionsOf(loaded));
  EXPECT_EQ(std::count(breaks.begin(), breaks.end(), x), 1);
  const FeBeamModel fe = AssembleSceneBeam(loaded);
  int node = -1;
  for (int j = 0; j <= fe.n_elements; ++j) {
    if (fe.NodeHeightM(j) == x) node = j;
  }
  EXPECT_GE(node, 0);
  const ModalBasis modes = ComputeLowestModes(AssembleSceneBeam(bare), 1);
  const double phi = AssembleSceneBeam(bare).DeflectionRow(x).dot(modes.shapes.col(0));
  const double w2 = std::pow(modes.omega_rad_s[0], 2);
  const double shift = std::pow(OmegasOf(loaded, 1)[0], 2) - w2;
  EXPECT_NEAR(shift / (-w2 * phi * phi * 1e-4 * kRhoA), 1.0, 1e-3);
}

// The static tip deflection of a stepped cantilever under a tip force, as the FE model gives it
// (1 / K_bend at the tip), is Mohr's sum of the segments' contributions: exact at the nodes for
// Hermite cubics, whatever the mesh, to the factorization's round-off (measured 3.6e-12 with
// 20 elements). A point mass changes no static deflection.
TEST(BeamSections, SteppedBeamTipDeflectionIsMohrsIntegral) {
  const double exact = MohrFlexibility(kStepped, 1.0);
  for (const int elements : {4, 7, 20}) {
    const SceneBeam b = Sectioned(kStepped, elements, {{0.6, 5.0, 0.1}});
    EXPECT_NEAR(1.0 / LocalBendingStiffness(b, 1.0) / exact, 1.0, 2e-11) << elements;
  }
  EXPECT_GT(exact / MohrFlexibility({{1.0, 2.0 * kEi, kRhoA}}, 1.0), 1.5);  // The steps matter.
}

// The paper's K_bend at a height (what `advise` divides a zone's stiffness by, R_k = k_s /
// K_bend) on the stepped beam: at a section's end, a node, exactly Mohr's; inside an element
// it converges to Mohr's as the mesh is refined (measured 2.0e-4, 7.9e-5, 1.8e-6, 9.4e-7 with
// 6, 12, 24, 48 elements: the point's place inside its element changes with the mesh).
TEST(BeamSections, LocalStiffnessAtAHeightIsMohrsOnASteppedBeam) {
  for (const double height : {0.25, 0.75}) {
    const double exact = 1.0 / MohrFlexibility(kStepped, height);
    EXPECT_NEAR(LocalBendingStiffness(Sectioned(kStepped, 12), height) / exact, 1.0, 1e-12)
        << height;
  }
  const double inside = 0.6180339887;
  const double exact = 1.0 / MohrFlexibility(kStepped, inside);
  std::vector<double> error;
  for (const int elements : {6, 12, 24, 48}) {
    error.push_back(
        std::abs(LocalBendingStiffness(Sectioned(kStepped, elements), inside) / exact - 1.0));
  }
  EXPECT_LT(error.back(), 2e-6);
  EXPECT_LT(error.back(), error.front() / 100.0);
}

// With static correction, the initial state under a force at a zone's height on the stepped
// beam is the exact static deflection there (Mohr's), even with a single retained mode.
TEST(BeamSections, StaticCorrectionOfASteppedBeamIsExactAtItsZone) {
  Scene scene;
  scene.beams = {Sectioned(kStepped, 20, {{1.0, 2.0, 0.0}})};
  SceneZone stop;
  stop.name = "stop";
  stop.height_m = 0.6;
  stop.gap_m = 1.0;
  stop.stiffness_n_per_m = 1e6;
  scene.zones = {stop};
  scene.solver.r_ftrunc = 1.0;
  scene.solver.static_correction = true;
  scene.solver.end_time_s = 0.01;
  scene.initial_state = {{.beam = 0, .static_force_n = 10.0, .height_m = 0.6}};
  scene.outputs.displacements = {{"at_zone", 0, 0.6, 0}};
  const SceneModel model = BuildSceneModel(scene);
  const double deflection = model.observed_rows[0].dot(model.x0);
  const FeBeamModel fe = AssembleSceneBeam(scene.beams[0]);
  const Eigen::VectorXd row = fe.DeflectionRow(0.6);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> k(fe.stiffness);
  EXPECT_NEAR(deflection / (10.0 * row.dot(k.solve(row))), 1.0, 1e-9);
  EXPECT_NEAR(deflection / (10.0 * MohrFlexibility(kStepped, 0.6)), 1.0, 1e-5);
}

// The basis cache keys a model by everything it is built from: two beams that differ only in
// their sections (or only in a point mass) are two bases, each with its own frequencies, in
// one scene and from one scene to the next.
TEST(BeamSections, BeamsDifferingOnlyInSectionsHaveTheirOwnBases) {
  const SceneBeam soft = Sectioned({{0.5, kEi, kRhoA}, {0.5, 0.5 * kEi, kRhoA}}, 20);
  const SceneBeam stiff = Sectioned({{0.5, kEi, kRhoA}, {0.5, 2.0 * kEi, kRhoA}}, 20);
  const SceneBeam heavy =
      Sectioned({{0.5, kEi, kRhoA}, {0.5, 0.5 * kEi, kRhoA}}, 20, {{1.0, 10.0, 0.0}});
  Scene scene;
  scene.solver.end_time_s = 0.01;
  for (const SceneBeam* b : {&soft, &stiff, &heavy}) {
    scene.beams.push_back(*b);
    scene.beams.back().name = "beam" + std::to_string(scene.beams.size());
  }
  const SceneModel model = BuildSceneModel(scene);
  EXPECT_EQ(model.distinct_bases, 3);
  const Eigen::VectorXd w2 = model.system->OmegaSquared();
  int at = 0;
  for (int b = 0; b < 3; ++b) {
    const Eigen::VectorXd fresh = OmegasOf(scene.beams[b], model.modes_per_beam[b]);
    EXPECT_EQ(w2.segment(at, model.modes_per_beam[b]), fresh.array().square().matrix()) << b;
    at += model.modes_per_beam[b];
  }
  EXPECT_LT(w2[0], w2[model.modes_per_beam[0]]);  // soft's f1 below stiff's.

  // A scene of the stiff beam alone, after the soft one's was cached under the same mesh.
  Scene alone = scene;
  alone.beams = {stiff};
  EXPECT_EQ(BuildSceneModel(alone).system->OmegaSquared()[0], w2[model.modes_per_beam[0]]);
}

// Scene files: the keys read, and every mistake refused with its key path.
class BeamSectionFiles : public testing::TempDirTest {
 protected:
  // The canonical scene's beam with `change` applied (after its EI and rho A are removed when
  // `sectioned`), written to a file.
  std::string Variant(const std::function<void(Json&)>& change, bool sectioned = true) {
    std::ifstream in(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json");
    Json scene = Json::parse(in);
    Json& beam = scene["beams"][0];
    if (sectioned) {
      beam.erase("ei_n_m2");
      beam.erase("rho_a_kg_per_m");
      beam["sections"] =
          Json::array({{{"length_m", 0.3}, {"ei_n_m2", 2e5}, {"rho_a_kg_per_m", 130}},
                       {{"length_m", 0.7}, {"ei_n_m2", 1.5e5}, {"rho_a_kg_per_m", 127}}});
      beam["point_masses"] = Json::array({{{"height_m", 1.0}, {"mass_kg", 2.0}}});
    }
    change(beam);
    const std::string path = Path("variant.json");
    testing::WriteText(path, scene.dump(2));
    return path;
  }
};

TEST_F(BeamSectionFiles, SectionsAndPointMassesReachTheScene) {
  const Scene scene = LoadScene(Variant([](Json& b) {
    b["point_masses"].push_back(
        {{"height_m", 0.3}, {"mass_kg", 0.5}, {"rotary_inertia_kg_m2", 1e-3}});
  }));
  const SceneBeam& b = scene.beams[0];
  ASSERT_EQ(b.sections.size(), 2u);
  EXPECT_EQ(b.sections[0], (BeamSection{0.3, 2e5, 130.0}));
  EXPECT_EQ(b.sections[1], (BeamSection{0.7, 1.5e5, 127.0}));
  ASSERT_EQ(b.point_masses.size(), 2u);
  EXPECT_EQ(b.point_masses[1], (BeamPointMass{0.3, 0.5, 1e-3}));
  // The mass at 0.3 m sits on the section's end: two pieces, 55 elements.
  EXPECT_EQ(MeshBreaks(SectionsOf(b)), (std::vector<double>{0.0, 0.3, 1.0}));
  EXPECT_EQ(AssembleSceneBeam(b).n_elements, 55);
}

TEST_F(BeamSectionFiles, EveryMistakeIsNamedByItsKeyPath) {
  const std::vector<std::pair<std::function<void(Json&)>, std::vector<std::string>>> cases = {
      {[](Json& b) { b["sections"][1]["length_m"] = 0.6; },
       {"beams[0].sections", "sum to 0.9", "length_m (1 m)"}},
      {[](Json& b) { b["sections"][1]["length_m"] = 0.8; }, {"beams[0].sections", "sum to 1.1"}},
      {[](Json& b) { b["sections"][1]["ei_n_m2"] = -1.0; },
       {"beams[0].sections[1].ei_n_m2", "> 0"}},
      {[](Json& b) { b["sections"][0]["rho_a_kg_per_m"] = 0.0; },
       {"beams[0].sections[0].rho_a_kg_per_m", "> 0"}},
      {[](Json& b) { b["sections"][0]["length_m"] = 0.0; },
       {"beams[0].sections[0].length_m", "> 0"}},
      {[](Json& b) { b["sections"][0]["length_m"] = 1e-8; },
       {"beams[0].sections[0].length_m", "shorter than"}},
      {[](Json& b) { b["sections"][0].erase("ei_n_m2"); }, {"beams[0].sections[0].ei_n_m2"}},
      {[](Json& b) { b["sections"][0]["ei"] = 1.0; }, {"beams[0].sections[0].ei", "unknown"}},
      {[](Json& b) { b["sections"] = Json::array(); }, {"beams[0].sections", "1 to 1000"}},
      {[](Json& b) { b["sections"] = 3; }, {"beams[0].sections", "from the base up"}},
      {[](Json& b) { b["ei_n_m2"] = 1.5e5; }, {"beams[0].ei_n_m2", "not both"}},
      {[](Json& b) { b["rho_a_kg_per_m"] = 127.0; }, {"beams[0].rho_a_kg_per_m", "not both"}},
      {[](Json& b) { b["point_masses"][0]["height_m"] = 1.5; },
       {"beams[0].point_masses[0].height_m", "outside the beam", "[0, 1.0]"}},
      {[](Json& b) { b["point_masses"][0]["height_m"] = -0.1; },
       {"beams[0].point_masses[0].height_m", "outside the beam"}},
      {[](Json& b) { b["point_masses"][0]["mass_kg"] = 0.0; },
       {"beams[0].point_masses[0].mass_kg", "> 0"}},
      {[](Json& b) { b["point_masses"][0]["mass_kg"] = -2.0; },
       {"beams[0].point_masses[0].mass_kg", "> 0"}},
      {[](Json& b) { b["point_masses"][0]["rotary_inertia_kg_m2"] = -1.0; },
       {"beams[0].point_masses[0].rotary_inertia_kg_m2", "[0.0, 1000000.0]"}},
      {[](Json& b) { b["point_masses"][0].erase("height_m"); },
       {"beams[0].point_masses[0].height_m"}},
      {[](Json& b) { b["point_masses"] = 2.0; }, {"beams[0].point_masses", "at most 1000"}},
      {[](Json& b) {
         b["elements"] = 2;
         b["point_masses"][0]["height_m"] = 0.5;
       },
       {"beams[0].elements", "3 pieces", "elements >= 3"}},
  };
  for (const auto& [change, named] : cases) {
    const std::string message = testing::SceneRefusal(Variant(change));
    ASSERT_FALSE(message.empty()) << named[0];
    for (const std::string& part : named) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "wanted \"" << part << "\" in: " << message;
    }
  }
  // A point mass on a uniform beam is read as well, and refused as well.
  EXPECT_NE(testing::SceneRefusal(Variant(
                                      [](Json& b) {
                                        b["point_masses"] = {{{"height_m", 2.0}, {"mass_kg", 1.0}}};
                                      },
                                      false))
                .find("beams[0].point_masses[0].height_m"),
            std::string::npos);
}

TEST_F(BeamSectionFiles, SimulateRefusesThemWithExitCode2) {
  const std::string file = Variant([](Json& b) { b["sections"][1]["length_m"] = 0.6; });
  const auto r = testing::RunShockmap("simulate --quiet " + file);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("beams[0].sections"), std::string::npos) << r.output;
}

// The shipped native pin (scenes/fuel_pin_native.json) runs: the base shock throws it against
// the stops of both grids, with its energy balance kept (measured 3.5e-5) without a stop pulling.
TEST_F(BeamSectionFiles, TheShippedNativePinRattlesInItsGrids) {
  const auto r =
      testing::RunShockmap("simulate --json --quiet " + std::string(SHOCKMAP_SOURCE_DIR) +
                           "/scenes/fuel_pin_native.json --out " + Path("out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json summary = Json::parse(r.output);
  EXPECT_EQ(summary["status"], "ok");
  EXPECT_EQ(summary["zones"], 8);
  EXPECT_LT(summary["max_energy_ratio"].get<double>(), 1.001);
  std::ifstream forces(Path("out") + "/max_contact_force.csv");
  std::string line;
  std::getline(forces, line);
  int hit = 0;
  while (std::getline(forces, line)) {
    const double force = std::stod(line.substr(line.rfind(',') + 1));
    EXPECT_GE(force, 0.0) << line;
    hit += force > 0.0;
  }
  EXPECT_EQ(hit, 8);
}

}  // namespace
}  // namespace shockmap
