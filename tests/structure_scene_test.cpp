// Scenes with structures from an FE code (docs/scenes.md, "Structures from an FE code"): a
// cantilever given as matrices behaves as the same cantilever given as a beam, its zones' R_k
// are the beam's, two structures with a clearance between their nodes keep their energy, and
// bad references to structures, nodes and normals are refused.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "compare/scene_run.h"
#include "core/fe_structure.h"
#include "core/scene_model.h"
#include "formats/criteria_json.h"
#include "formats/json_reader.h"
#include "formats/scene_file.h"
#include "formats/structure_files.h"
#include "run_command.h"
#include "temp_dir.h"
#include "validation/scene_advice.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;
using testing::RunShockmap;
using testing::TempDirTest;

// The paper's cantilever (K_bend = 3 EI / L^3 = 4.5e5 N/m), in 20 elements.
SceneBeam Cantilever() {
  SceneBeam b;
  b.name = "beam";
  b.length_m = 1.0;
  b.ei_n_m2 = 1.5e5;
  b.rho_a_kg_per_m = 127.0;
  b.n_elements = 20;
  return b;
}

// The beam's own FE model as a structure: node j (1-based) at x = j L / n, its deflection uy
// and rotation rz, the clamp's DOFs eliminated as the beam's are.
FeStructure AsStructure(const SceneBeam& beam) {
  const FeBeamModel fe = AssembleSceneBeam(beam);
  FeStructure s;
  s.name = beam.name;
  s.stiffness = fe.stiffness;
  s.mass = fe.mass;
  for (int g : fe.global_dof) {
    s.dofs.push_back({g / 2 + 1, g % 2 == 0 ? DofComponent::kUy : DofComponent::kRz});
  }
  for (int j = 0; j <= fe.n_elements; ++j) {
    s.node_coordinates_m[j + 1] = Eigen::Vector3d(beam.length_m * j / fe.n_elements, 0.0, 0.0);
  }
  return s;
}

Json MatrixMarket(const std::string& folder) {
  return {{"stiffness", folder + "/stiffness.mtx"},
          {"mass", folder + "/mass.mtx"},
          {"dofs", folder + "/dofs.csv"},
          {"nodes", folder + "/nodes.csv"}};
}

Json BeamJson(const SceneBeam& b) {
  return {{"name", b.name},
          {"length_m", b.length_m},
          {"ei_n_m2", b.ei_n_m2},
          {"rho_a_kg_per_m", b.rho_a_kg_per_m},
          {"elements", b.n_elements}};
}

Json Solver(const Json& dt, double end_s) {
  return {{"r_ftrunc", 300}, {"dt", dt}, {"end_time_s", end_s}};
}

// The cantilever released from a static tip force of 450 N (1 mm at the tip) onto a stop at its
// tip, R_k = 3000: as a beam, and as a structure written to `folder`.
Json BeamScene(const Json& dt) {
  return {
      {"name", "beam"},
      {"beams", {BeamJson(Cantilever())}},
      {"zones",
       {{{"name", "tip"},
         {"beam", "beam"},
         {"height_m", 1.0},
         {"normal", {-1, 0}},
         {"stiffness_n_per_m", 1.35e9}}}},
      {"effects",
       {{"initial_state",
         {{{"beam", "beam"}, {"direction", "y"}, {"static_force_n", 450.0}, {"height_m", 1.0}}}}}},
      {"solver", Solver(dt, 0.02)},
      {"outputs",
       {{"displacements",
         {{{"name", "tip"}, {"beam", "beam"}, {"height_m", 1.0}, {"direction", "y"}}}},
        {"contact_forces", true},
        {"energies", true}}}};
}

Json StructureSceneJson(const Json& dt, const std::string& folder) {
  return {{"name", "structure"},
          {"structures", {{{"name", "rod"}, {"matrix_market", MatrixMarket(folder)}}}},
          {"zones",
           {{{"name", "tip"},
             {"structure", "rod"},
             {"node", 21},
             {"normal", {0, -1, 0}},
             {"stiffness_n_per_m", 1.35e9}}}},
          {"effects",
           {{"initial_state",
             {{{"structure", "rod"},
               {"node", 21},
               {"direction", {0, 1, 0}},
               {"static_force_n", 450.0}}}}}},
          {"solver", Solver(dt, 0.02)},
          {"outputs",
           {{"displacements",
             {{{"name", "tip"}, {"structure", "rod"}, {"node", 21}, {"direction", {0, 1, 0}}}}},
            {"contact_forces", true},
            {"energies", true}}}};
}

double LargestDifference(const UniformSignal& a, const UniformSignal& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.values.size(), b.values.size()); ++i)
    worst = std::max(worst, std::abs(a.values[i] - b.values[i]));
  return worst;
}

double LargestMagnitude(const UniformSignal& s) {
  double m = 0.0;
  for (double v : s.values) m = std::max(m, std::abs(v));
  return m;
}

class StructureScene : public TempDirTest {
 protected:
  void SetUp() override {
    TempDirTest::SetUp();
    std::filesystem::create_directories(dir_ / "rod");
    WriteMatrixMarketStructure(AsStructure(Cantilever()), Path("rod"));
  }
  Scene Parse(const Json& json) { return ParseScene(json, Path("scene.json")); }
};

// The same cantilever given as a beam and as its matrices: the same modes (the beam's dense
// solve against the structure's, each from the same matrices), so the same tip history and
// contact force. Measured: tip within 1.0e-11 of the amplitude, force within 6.4e-10 of its peak
// over 3202 steps to 0.02 s; the sharp bounds equal to 5e-16.
TEST_F(StructureScene, CantileverFromMatricesGivesTheBeamsOutputs) {
  const SceneRun beam = RunScene(Parse(BeamScene({{"rule", "sharp"}, {"factor", 0.1}})));
  const double dt = beam.result.summary.dt_used_s;
  const SceneRun structure = RunScene(Parse(StructureSceneJson({{"seconds", dt}}, "rod")));
  ASSERT_EQ(structure.coordinates, beam.coordinates);
  ASSERT_EQ(structure.result.summary.steps_taken, beam.result.summary.steps_taken);
  EXPECT_EQ(structure.bounds.dt_sharp_s, structure.bounds.dt_sharp_s);
  EXPECT_NEAR(structure.bounds.dt_sharp_s, beam.bounds.dt_sharp_s, 1e-9 * beam.bounds.dt_sharp_s);

  const UniformSignal& tip = beam.result.displacement_m[0];
  EXPECT_NEAR(tip.values.front(), 1e-3, 1e-6);  // 450 N / 4.5e5 N/m, in the retained modes.
  const double force = LargestMagnitude(beam.result.contact_force_n[0]);
  EXPECT_GT(force, 1e3);  // It hits the stop.
  EXPECT_LT(LargestDifference(tip, structure.result.displacement_m[0]), 1e-10 * 1e-3);
  EXPECT_LT(LargestDifference(beam.result.contact_force_n[0], structure.result.contact_force_n[0]),
            1e-8 * force);
}

// R_k = k_s n^T K^-1 n at the tip node is the beam's k_s / (3 EI / L^3) = 3000, from the
// structure's static flexibility as from the beam's elements (measured: 3000 + 3e-10), and the
// truncation advised is the same to rounding.
TEST_F(StructureScene, AdvisedStiffnessRatioIsTheBeams) {
  const std::string baseline =
      std::string(SHOCKMAP_SOURCE_DIR) + "/studies/baselines/paper_fig4.json";
  const ValidityCriteria criteria = CriteriaFromJson(ReadJsonFile(baseline), baseline, nullptr);
  const Json dt = {{"rule", "sharp"}, {"factor", 0.1}};
  const SceneAdvice beam = AdviseScene(Parse(BeamScene(dt)), criteria);
  const SceneAdvice structure = AdviseScene(Parse(StructureSceneJson(dt, "rod")), criteria);
  ASSERT_EQ(structure.zones.size(), 1u);
  EXPECT_NEAR(structure.zones[0].r_k_a, 3000.0, 3000.0 * 1e-9);
  EXPECT_NEAR(structure.zones[0].r_k_a, beam.zones[0].r_k_a, 1e-10 * beam.zones[0].r_k_a);
  ASSERT_EQ(structure.beams.size(), 1u);
  EXPECT_EQ(structure.beams[0].name, "rod");
  EXPECT_NEAR(structure.beams[0].r_ftrunc, beam.beams[0].r_ftrunc, 1e-9 * beam.beams[0].r_ftrunc);
  EXPECT_NEAR(structure.dt_sharp_s, beam.dt_sharp_s, 1e-9 * beam.dt_sharp_s);
}

// Two cantilevers side by side, 0.2 m apart, their tips 0.5 mm apart: the first released at 0.1
// m/s towards the second, no damping anywhere. Kinetic + strain + contact energy stays the
// initial energy within the central differences' O((omega dt)^2) (measured: 1.4e-4 of it at
// dt = 0.1 of the sharp bound, 15360 steps), and the second rod moves only through the contact.
TEST_F(StructureScene, TwoStructuresAcrossAClearanceKeepTheirEnergy) {
  FeStructure second = AsStructure(Cantilever());
  for (auto& [node, x] : second.node_coordinates_m) x.y() = 0.2;
  std::filesystem::create_directories(dir_ / "other");
  WriteMatrixMarketStructure(second, Path("other"));
  const Json scene = {
      {"name", "pair"},
      {"structures",
       {{{"name", "a"}, {"matrix_market", MatrixMarket("rod")}},
        {{"name", "b"}, {"matrix_market", MatrixMarket("other")}}}},
      {"zones",
       {{{"name", "tips"},
         {"structure", "a"},
         {"node", 21},
         {"against", "b"},
         {"against_node", 21},
         {"normal", {0, 1, 0}},
         {"gap_m", 5e-4},
         {"stiffness_n_per_m", 1e7}}}},
      {"effects",
       {{"initial_state",
         {{{"structure", "a"}, {"direction", {0, 1, 0}}, {"velocity_m_s", 0.1}}}}}},
      {"solver", Solver({{"rule", "sharp"}, {"factor", 0.1}}, 0.1)},
      {"outputs",
       {{"displacements",
         {{{"name", "a"}, {"structure", "a"}, {"node", 21}, {"direction", {0, 1, 0}}},
          {{"name", "b"}, {"structure", "b"}, {"node", 21}, {"direction", {0, 1, 0}}}}},
        {"max_contact_force", true},
        {"energies", true}}}};
  const Scene parsed = Parse(scene);
  EXPECT_EQ(parsed.zones[0].y_m, 0.0);  // At node a.
  const SceneRun run = RunScene(parsed);
  ASSERT_EQ(run.result.summary.status, RunStatus::kOk);
  EXPECT_GT(run.max_contact_force_n[0], 0.0);
  const auto& b_tip = run.result.displacement_m[1];
  EXPECT_GT(LargestMagnitude(b_tip), 1e-5);
  const EnergyHistory& e = run.result.energy;
  const double e0 = e.kinetic_j.values.front() + e.strain_j.values.front();
  EXPECT_GT(e0, 0.0);
  double worst = 0.0;
  for (std::size_t i = 0; i < e.kinetic_j.values.size(); ++i) {
    const double total = e.kinetic_j.values[i] + e.strain_j.values[i] + e.contact_j.values[i];
    worst = std::max(worst, std::abs(total - e0) / e0);
  }
  EXPECT_LT(worst, 1e-3);
  // Until contact, b rests: its tip's first motion follows a's arrival across the gap.
  const auto& a_tip = run.result.displacement_m[0];
  for (std::size_t i = 0; i < b_tip.values.size(); ++i) {
    if (a_tip.values[i] - b_tip.values[i] < 5e-4) {
      EXPECT_EQ(b_tip.values[i], 0.0);
    }
    if (a_tip.values[i] - b_tip.values[i] >= 5e-4) break;
  }
}

// The same two cantilevers, one given as a beam: a zone between a structure's node and a beam's
// height gives the beam-beam zone's histories (measured: force and both tips within 1.1e-11).
TEST_F(StructureScene, NodeAgainstABeamIsTheBeamPairsZone) {
  SceneBeam b = Cantilever();
  const Json common_solver = Solver({{"seconds", 2e-6}}, 0.05);
  auto outputs = [](const Json& a, const Json& other) {
    return Json{{"displacements", {a, other}}, {"max_contact_force", true}};
  };
  Json beams = BeamJson(b);
  Json beams2 = BeamJson(b);
  beams2["name"] = "other";
  const Json pair = {
      {"name", "beams"},
      {"beams", {beams, beams2}},
      {"zones",
       {{{"name", "tips"},
         {"beam", "beam"},
         {"against", "other"},
         {"height_m", 1.0},
         {"normal", {1, 0}},
         {"gap_m", 5e-4},
         {"stiffness_n_per_m", 1e7}}}},
      {"effects",
       {{"initial_state", {{{"beam", "beam"}, {"direction", "y"}, {"velocity_m_s", 0.1}}}}}},
      {"solver", common_solver},
      {"outputs", outputs({{"name", "a"}, {"beam", "beam"}, {"height_m", 1.0}},
                          {{"name", "b"}, {"beam", "other"}, {"height_m", 1.0}})}};
  const Json mixed = {
      {"name", "mixed"},
      {"beams", {beams2}},
      {"structures", {{{"name", "rod"}, {"matrix_market", MatrixMarket("rod")}}}},
      {"zones",
       {{{"name", "tips"},
         {"structure", "rod"},
         {"node", 21},
         {"against", "other"},
         {"height_m", 1.0},
         {"normal", {0, 1, 0}},
         {"gap_m", 5e-4},
         {"stiffness_n_per_m", 1e7}}}},
      {"effects",
       {{"initial_state",
         {{{"structure", "rod"}, {"direction", {0, 1, 0}}, {"velocity_m_s", 0.1}}}}}},
      {"solver", common_solver},
      {"outputs",
       outputs({{"name", "a"}, {"structure", "rod"}, {"node", 21}, {"direction", {0, 1, 0}}},
               {{"name", "b"}, {"beam", "other"}, {"height_m", 1.0}})}};
  const SceneRun p = RunScene(Parse(pair)), m = RunScene(Parse(mixed));
  const double force = p.max_contact_force_n[0];
  EXPECT_GT(force, 0.0);
  EXPECT_NEAR(m.max_contact_force_n[0], force, 1e-8 * force);
  for (int i = 0; i < 2; ++i) {
    const double amplitude = LargestMagnitude(p.result.displacement_m[i]);
    EXPECT_LT(LargestDifference(p.result.displacement_m[i], m.result.displacement_m[i]),
              1e-8 * amplitude)
        << i;
  }
}

// The same verdicts: a scene study of the cantilever given as matrices (R_ftrunc 10 and 300,
// scored against 1000) scores each point as the study of the beam scene does. Measured: Err
// and SRf equal to 1.1e-10 (Err 0.0743 and 7.74e-5, SRf 0.820 and 0.980).
TEST_F(StructureScene, StudyScoresTheStructureAsTheBeam) {
  const Json dt = {{"seconds", 2e-6}};
  testing::WriteText(Path("beam.json"), BeamScene(dt).dump());
  testing::WriteText(Path("structure.json"), StructureSceneJson(dt, "rod").dump());
  auto scores = [&](const std::string& scene) {
    const Json study = {
        {"name", scene},
        {"scene", scene + ".json"},
        {"sweep", {{"solver.r_ftrunc", {10, 300}}}},
        {"reference", {{"solver.r_ftrunc", 1000}}},
        {"scoring", {{"displacement", "tip"}, {"zone", "tip"}, {"rest_duration_s", 0.0052}}}};
    testing::WriteText(Path(scene + "_study.json"), study.dump());
    const std::string db = Path(scene + ".db");
    const auto run =
        RunShockmap("study run --quiet " + Path(scene + "_study.json") + " --db " + db);
    EXPECT_EQ(run.exit_code, 0) << run.output;
    const auto rows = RunShockmap(
        "query --format json --db " + db +
        " \"SELECT json_extract(parameters_json, '$.\\\"solver.r_ftrunc\\\"') AS r, status, err, "
        "srf FROM scene_results ORDER BY r\"");
    EXPECT_EQ(rows.exit_code, 0) << rows.output;
    return Json::parse(rows.output);
  };
  const Json beam = scores("beam"), structure = scores("structure");
  ASSERT_EQ(beam.size(), 2u);
  ASSERT_EQ(structure.size(), 2u);
  EXPECT_GT(beam[0]["err"].get<double>(), beam[1]["err"].get<double>());  // 10 worse than 300.
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(structure[i]["status"], "ok");
    for (const char* score : {"err", "srf"}) {
      EXPECT_NEAR(structure[i][score].get<double>(), beam[i][score].get<double>(), 1e-9)
          << score << " at point " << i;
    }
  }
}

// A structure released in a mode scaled at a node: the cantilever as matrices in its first mode
// with the tip 1 mm up starts where the beam released in its first mode does (to 1e-12 m), and
// a mode that does not move the node along the direction is refused: two uncoupled nodes (K =
// diag(1, 4) kN/m, M = I kg), whose first mode moves node 1 only.
TEST_F(StructureScene, ModeReleaseAtANodeIsTheBeamsAndAModeThatDoesNotMoveItIsRefused) {
  Json beam = BeamScene({{"seconds", 1e-6}});
  beam["effects"]["initial_state"][0] = {
      {"beam", "beam"}, {"direction", "y"}, {"mode", 1}, {"amplitude_m", 1e-3}};
  beam["solver"]["end_time_s"] = 1e-5;
  Json structure = StructureSceneJson({{"seconds", 1e-6}}, "rod");
  structure["effects"]["initial_state"][0] = {{"structure", "rod"},
                                              {"node", 21},
                                              {"direction", {0, 1, 0}},
                                              {"mode", 1},
                                              {"amplitude_m", 1e-3}};
  structure["solver"]["end_time_s"] = 1e-5;
  const SceneRun b = RunScene(Parse(beam)), s = RunScene(Parse(structure));
  EXPECT_NEAR(s.result.displacement_m[0].values.front(), 1e-3, 1e-12);
  EXPECT_NEAR(s.result.displacement_m[0].values.front(), b.result.displacement_m[0].values.front(),
              1e-12);

  FeStructure pair;
  pair.name = "pair";
  pair.stiffness.resize(2, 2);
  pair.stiffness.insert(0, 0) = 1e3;
  pair.stiffness.insert(1, 1) = 4e3;
  pair.mass.resize(2, 2);
  pair.mass.insert(0, 0) = 1.0;
  pair.mass.insert(1, 1) = 1.0;
  pair.dofs = {{1, DofComponent::kUy}, {2, DofComponent::kUy}};
  pair.node_coordinates_m = {{1, Eigen::Vector3d(0.0, 0.0, 0.0)},
                             {2, Eigen::Vector3d(1.0, 0.0, 0.0)}};
  std::filesystem::create_directories(dir_ / "pair");
  WriteMatrixMarketStructure(pair, Path("pair"));
  const Json scene = {
      {"name", "pair"},
      {"structures", {{{"name", "pair"}, {"matrix_market", MatrixMarket("pair")}}}},
      {"effects",
       {{"initial_state",
         {{{"structure", "pair"},
           {"node", 2},
           {"direction", {0, 1, 0}},
           {"mode", 1},
           {"amplitude_m", 1e-3}}}}}},
      {"solver", Solver({{"seconds", 1e-4}}, 1e-3)},
      {"outputs",
       {{"displacements",
         {{{"name", "two"}, {"structure", "pair"}, {"node", 2}, {"direction", {0, 1, 0}}}}}}}};
  testing::WriteText(Path("bad.json"), scene.dump());
  const auto o = RunShockmap("simulate " + Path("bad.json"));
  EXPECT_EQ(o.exit_code, 2) << o.output;
  EXPECT_NE(o.output.find("mode 1 of structure \"pair\" does not move node 2"), std::string::npos)
      << o.output;
}

// Bad references: exit code 2, the file, the key and what is wrong.
TEST_F(StructureScene, BadReferencesAreRefusedNamingTheKey) {
  auto refused = [&](Json scene, const std::string& key, const std::string& what) {
    testing::WriteText(Path("bad.json"), scene.dump());
    const auto o = RunShockmap("simulate " + Path("bad.json"));
    EXPECT_EQ(o.exit_code, 2) << o.output;
    EXPECT_NE(o.output.find(key), std::string::npos) << o.output;
    EXPECT_NE(o.output.find(what), std::string::npos) << o.output;
  };
  const Json good = StructureSceneJson({{"seconds", 1e-6}}, "rod");
  Json s = good;
  s["zones"][0]["structure"] = "plate";
  refused(s, "zones[0].structure", "no structure named \"plate\"");
  s = good;
  s["zones"][0]["node"] = 99;
  refused(s, "zones[0].node", "node 99 is not in the node table of structure \"rod\"");
  s = good;
  s["zones"][0]["node"] = 1;  // The clamp: no free DOF.
  refused(s, "zones[0].node", "no free translational DOF");
  s = good;
  s["zones"][0]["normal"] = {0, -2, 0};
  refused(s, "zones[0].normal", "give a unit vector");
  s = good;
  s["zones"][0]["normal"] = {0, 0, 0};
  refused(s, "zones[0].normal", "must not be zero");
  s = good;
  s["zones"][0]["normal"] = {0, -1};
  refused(s, "zones[0].normal", "expected [x, y, z]");
  s = good;
  s["zones"][0]["normal"] = {0, 0, 1};  // The rod bends in y only: no DOF along z.
  refused(s, "zones[0].normal", "no free DOF along this direction");
  s = good;
  s["zones"][0]["against"] = "rod";
  s["zones"][0]["against_node"] = 21;
  refused(s, "zones[0].against_node", "a node cannot hit itself");
  s = good;
  s["outputs"]["displacements"][0]["node"] = 0;
  refused(s, "outputs.displacements[0].node", "node 0 is not in the node table");
  s = good;
  s["structures"][0]["matrix_market"]["mass"] = "../mass.mtx";
  refused(s, "structures[0].matrix_market.mass", "lies outside the scene's folder");
  s = good;
  s["structures"][0]["name"] = "tip";
  s["beams"] = Json::array({BeamJson(Cantilever())});
  s["beams"][0]["name"] = "tip";
  refused(s, "beams[0].name", "is already the name given at structures[0].name");
}

}  // namespace
}  // namespace shockmap
