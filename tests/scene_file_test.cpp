// Scene files end to end: the parser names the JSON path of every mistake, the bundle
// generators build the lattice they promise, and `shockmap simulate` runs the shipped scenes,
// reproduces `compare` on the canonical problem and refuses bad input with exit code 2.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "compare/comparison.h"
#include "compare/output_columns.h"
#include "compare/scene_run.h"
#include "core/input_error.h"
#include "formats/scene_file.h"
#include "tests/run_command.h"
#include "tests/scene_refusal.h"
#include "tests/temp_dir.h"

namespace shockmap {
namespace {

using testing::RunShockmap;
using testing::WriteText;
using Json = nlohmann::json;

const std::string kScenes = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/";

// The first line of a text file, without its end.
std::string FirstLine(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// The names joined by commas, as a CSV header holds them.
std::string Joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ",") + n;
  return text;
}

class SceneFiles : public testing::TempDirTest {
 protected:
  // The canonical scene with one change applied, written to a file.
  std::string Variant(const std::function<void(Json&)>& change) {
    std::ifstream in(kScenes + "cantilever_spring.json");
    Json scene = Json::parse(in);
    change(scene);
    const std::string path = Path("variant.json");
    WriteText(path, scene.dump(2));
    return path;
  }
};

TEST_F(SceneFiles, EveryMistakeIsNamedByItsJsonPath) {
  const std::vector<std::pair<std::function<void(Json&)>, std::vector<std::string>>> cases = {
      {[](Json& s) { s["beams"][0]["lenght_m"] = 1.0; }, {"beams[0].lenght_m", "unknown"}},
      {[](Json& s) { s["beams"][0]["ei_n_m2"] = "stiff"; }, {"beams[0].ei_n_m2"}},
      {[](Json& s) { s["beams"][0]["ei_n_m2"] = -1.0; }, {"beams[0].ei_n_m2", "> 0"}},
      {[](Json& s) {
         s["beams"][0]["ends"] = {"clamped", "glued"};
       },
       {"beams[0].ends[1]"}},
      {[](Json& s) { s["zones"][0]["beam"] = "ghost"; }, {"zones[0].beam", "ghost"}},
      {[](Json& s) { s["zones"][0]["against"] = "beam"; }, {"zones[0].against", "itself"}},
      {[](Json& s) { s["zones"][0]["gap_m"] = 5.0; }, {"zones[0].gap_m", "must lie in"}},
      {[](Json& s) { s["zones"][0]["stiffness_n_per_m"] = 0; }, {"zones[0].stiffness_n_per_m"}},
      {[](Json& s) { s["zones"][0]["height_m"] = 1.5; }, {"zones[0].height_m", "on the beam"}},
      {[](Json& s) {
         s["zones"][0]["normal"] = {0, 0};
       },
       {"zones[0].normal", "zero"}},
      {[](Json& s) { s["effects"]["initial_state"][0]["direction"] = "x"; },
       {"effects.initial_state[0].direction"}},
      {[](Json& s) {
         s["effects"]["modal_damping"] = {{"ratios", {0.02, -1}}};
       },
       {"effects.modal_damping.ratios[1]"}},
      {[](Json& s) { s["effects"]["base_motion"] = Json::object(); }, {"effects.base_motion"}},
      {[](Json& s) {
         s["solver"]["dt"] = {{"rule", "fast"}};
       },
       {"solver.dt.rule", "fast"}},
      {[](Json& s) {
         s["solver"]["dt"] = {{"seconds", 1e-12}};
       },
       {"solver.dt", "at most 100000000 are allowed"}},
      {[](Json& s) { s["solver"].erase("end_time_s"); }, {"solver.end_time_s"}},
      {[](Json& s) { s.erase("solver"); }, {"solver", "missing"}},
      {[](Json& s) { s["outputs"]["displacements"][0]["direction"] = "z"; },
       {"outputs.displacements[0].direction", "planar"}},
      {[](Json& s) { s["outputs"]["energies"] = "yes"; }, {"outputs.energies", "true or false"}},
      {[](Json& s) { s["outputs"]["contact_forces"] = "yes"; },
       {"outputs.contact_forces", "list of zone names"}},
      {[](Json& s) { s["outputs"]["contact_forces"] = {"ghost"}; },
       {"outputs.contact_forces[0]", "ghost"}},
      {[](Json& s) { s["outputs"]["record_stride"] = 0; }, {"outputs.record_stride"}},
      {[](Json& s) {
         s["beams"][0]["ends"] = {"free", "free"};
       },
       {"beams[0].ends", "rigid"}},
  };
  for (const auto& [change, expected] : cases) {
    const std::string message = testing::SceneRefusal(Variant(change));
    ASSERT_FALSE(message.empty()) << expected[0] << " was accepted";
    EXPECT_NE(message.find("variant.json"), std::string::npos) << message;
    for (const auto& part : expected) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

// The contact laws, the statistics' convention and window, the impact table and the wear law
// reach the scene as written (docs/scenes.md).
// A misspelt key is named with the allowed key it most likely misspells: a required one it
// hides, or an optional one it stands beside.
TEST_F(SceneFiles, AMisspeltKeyIsNamedWithTheKeyItMisspells) {
  const std::string required = testing::SceneRefusal(Variant([](Json& s) {
    s["zones"][0]["stifness_n_per_m"] = s["zones"][0]["stiffness_n_per_m"];
    s["zones"][0].erase("stiffness_n_per_m");
  }));
  EXPECT_EQ(required, Path("variant.json") +
                          ": zones[0].stifness_n_per_m: unknown key; did you mean "
                          "\"stiffness_n_per_m\"? (stiffness_n_per_m: required number is missing)");
  const std::string optional =
      testing::SceneRefusal(Variant([](Json& s) { s["beams"][0]["elemnts"] = 20; }));
  EXPECT_EQ(optional.rfind(Path("variant.json") +
                               ": beams[0].elemnts: unknown key; did you mean \"elements\"? "
                               "(allowed here: ",
                           0),
            0u)
      << optional;
  // A key far from every allowed one is not given a guess.
  const std::string far =
      testing::SceneRefusal(Variant([](Json& s) { s["beams"][0]["colour"] = "red"; }));
  EXPECT_NE(far.find("beams[0].colour: unknown key (allowed here: "), std::string::npos) << far;
}

TEST_F(SceneFiles, ContactLawKeysReachTheScene) {
  const Scene scene = LoadScene(Variant([](Json& s) {
    s["bending"] = "both";
    s["zones"][0]["friction"] = {{"coefficient", 0.2},
                                 {"static_coefficient", 0.25},
                                 {"tangential_stiffness_n_per_m", 3e8},
                                 {"tangential_damping_n_s_per_m", 10.0},
                                 {"convention", "code_aster"}};
    Json hertz = s["zones"][0];
    hertz["name"] = "hertz";
    hertz.erase("stiffness_n_per_m");
    hertz.erase("friction");
    hertz["height_m"] = 0.5;
    hertz["power_law"] = {{"coefficient_n_per_m_exponent", 4e10}, {"bound_penetration_m", 1e-5}};
    s["zones"].push_back(hertz);
    s["outputs"]["impact_statistics"] = {{"rest_duration_s", 0},
                                         {"convention", "code_aster"},
                                         {"window_s", {0.01, 0.05}},
                                         {"impact_table", {"hertz"}}};
    s["wear"] = {{"coefficient_m2_per_n", 2e-15}, {"life_s", 3.6e6}};
  }));
  ASSERT_EQ(scene.zones.size(), 2u);
  ASSERT_TRUE(scene.zones[0].friction);
  EXPECT_EQ(scene.zones[0].friction->coefficient, 0.2);
  EXPECT_EQ(scene.zones[0].friction->static_coefficient, 0.25);
  EXPECT_EQ(scene.zones[0].friction->tangential_stiffness_n_per_m, 3e8);
  EXPECT_EQ(scene.zones[0].friction->tangential_damping_n_s_per_m, 10.0);
  EXPECT_EQ(scene.zones[0].friction->convention, FrictionConvention::kCodeAster);
  ASSERT_TRUE(scene.zones[1].power_law);
  EXPECT_EQ(scene.zones[1].power_law->exponent, 1.5);
  // Its stiffness for the bound: 1.5 k d_b^0.5.
  EXPECT_NEAR(scene.zones[1].stiffness_n_per_m, 1.5 * 4e10 * std::sqrt(1e-5), 1e-3);
  EXPECT_EQ(scene.zones[1].Law().normal.exponent, 1.5);
  const ImpactCounting& c = scene.outputs.impact_counting;
  EXPECT_EQ(c.convention, ImpactConvention::kCodeAster);
  EXPECT_EQ(c.rest_duration_s, 0.0);
  EXPECT_EQ(c.window_start_s, 0.01);
  EXPECT_EQ(c.window_end_s, 0.05);
  EXPECT_EQ(scene.outputs.impact_table_zones, std::vector<int>{1});
  ASSERT_TRUE(scene.wear);
  EXPECT_EQ(scene.wear->coefficient_m2_per_n, 2e-15);
  EXPECT_EQ(scene.wear->life_s, 3.6e6);
}

// Each mistake in the new keys names the file, the key's path, the value and what is allowed.
TEST_F(SceneFiles, ContactLawMistakesAreNamedByTheirJsonPath) {
  auto both = [](Json& s) { s["bending"] = "both"; };
  const Json friction = {{"coefficient", 0.3}, {"tangential_stiffness_n_per_m", 1e8}};
  const std::vector<std::pair<std::function<void(Json&)>, std::vector<std::string>>> cases = {
      {[&](Json& s) { s["zones"][0]["friction"] = friction; },
       {"zones[0].friction", "planar", "\"bending\": \"both\""}},
      {[&](Json& s) {
         both(s);
         s["zones"][0]["friction"] = {{"coefficient", -0.1}};
       },
       {"zones[0].friction.coefficient", "-0.1", "> 0 and <= 10"}},
      {[&](Json& s) {
         both(s);
         s["zones"][0]["friction"] = {{"coefficient", 0.3},
                                      {"static_coefficient", 0.2},
                                      {"tangential_stiffness_n_per_m", 1e8}};
       },
       {"zones[0].friction.static_coefficient", "0.2", "[0.3, 10.0]"}},
      {[&](Json& s) {
         both(s);
         s["zones"][0]["friction"] = {{"coefficient", 0.3}};
       },
       {"zones[0].friction.tangential_stiffness_n_per_m", "missing"}},
      {[&](Json& s) {
         both(s);
         s["zones"][0]["friction"] = {{"coefficient", 0.3},
                                      {"tangential_stiffness_n_per_m", 1e8},
                                      {"tangential_damping", 5.0}};
       },
       {"zones[0].friction.tangential_damping", "unknown"}},
      {[&](Json& s) {
         both(s);
         s["zones"][0]["friction"] = {{"coefficient", 0.3},
                                      {"tangential_stiffness_n_per_m", 1e8},
                                      {"convention", "dis_choc"}};
       },
       {"zones[0].friction.convention", "\"dis_choc\"", "\"return_mapping\"", "\"code_aster\""}},
      {[](Json& s) {
         s["zones"][0]["power_law"] = {{"coefficient_n_per_m_exponent", 1e10},
                                       {"bound_penetration_m", 1e-5}};
       },
       {"zones[0].power_law", "not both"}},
      {[](Json& s) {
         s["zones"][0].erase("stiffness_n_per_m");
         s["zones"][0]["power_law"] = {{"coefficient_n_per_m_exponent", 1e10},
                                       {"exponent", 0.5},
                                       {"bound_penetration_m", 1e-5}};
       },
       {"zones[0].power_law.exponent", "0.5", "[1.0, 3.0]"}},
      {[](Json& s) {
         s["zones"][0].erase("stiffness_n_per_m");
         s["zones"][0]["power_law"] = {{"coefficient_n_per_m_exponent", 1e10}};
       },
       {"zones[0].power_law.bound_penetration_m", "missing"}},
      {[](Json& s) {
         s["outputs"]["impact_statistics"] = {{"rest_duration_s", -1}};
       },
       {"outputs.impact_statistics.rest_duration_s", "-1", "[0, 100]"}},
      {[](Json& s) {
         s["outputs"]["impact_statistics"] = {{"rest_duration_s", 0}, {"convention", "aster"}};
       },
       {"outputs.impact_statistics.convention", "aster", "\"code_aster\""}},
      {[](Json& s) {
         s["outputs"]["impact_statistics"] = {{"rest_duration_s", 0}, {"window_s", {0.01, 0.5}}};
       },
       {"outputs.impact_statistics.window_s", "0.5", "solver.end_time_s = 0.06"}},
      {[](Json& s) {
         s["outputs"]["impact_statistics"] = {{"rest_duration_s", 0}, {"window_s", {0.02, 0.01}}};
       },
       {"outputs.impact_statistics.window_s", "start < end"}},
      {[](Json& s) {
         s["outputs"]["impact_statistics"] = {{"rest_duration_s", 0}, {"impact_table", {"ghost"}}};
       },
       {"outputs.impact_statistics.impact_table[0]", "ghost"}},
      {[](Json& s) {
         s["wear"] = {{"coefficient_m2_per_n", 1e-15}, {"life_s", 10}};
       },
       {"wear", "planar"}},
      {[&](Json& s) {
         both(s);
         s["wear"] = {{"coefficient_m2_per_n", 1e-15}, {"life_s", 10}};
       },
       {"wear", "outputs.impact_statistics"}},
      {[&](Json& s) {
         both(s);
         s["outputs"]["impact_statistics"] = {{"rest_duration_s", 0}};
         s["wear"] = {{"coefficient_m2_per_n", 0}, {"life_s", 10}};
       },
       {"wear.coefficient_m2_per_n", "> 0"}},
  };
  for (const auto& [change, expected] : cases) {
    const std::string message = testing::SceneRefusal(Variant(change));
    ASSERT_FALSE(message.empty()) << expected[0] << " was accepted";
    EXPECT_NE(message.find("variant.json"), std::string::npos) << message;
    for (const auto& part : expected) EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

TEST_F(SceneFiles, BaseMotionCsvErrorsNameTheLine) {
  auto with_csv = [&](const std::string& rows) {
    WriteText(Path("shock.csv"), rows);
    return Variant([](Json& s) { s["effects"]["base_motion"] = {{"csv", "shock.csv"}}; });
  };
  EXPECT_NE(testing::SceneRefusal(with_csv("t,a\n0,1\n")).find("line 1"), std::string::npos);
  EXPECT_NE(testing::SceneRefusal(with_csv("t_s,a_m_s2\n0,1\n0.1,x\n")).find("line 3"),
            std::string::npos);
  EXPECT_NE(testing::SceneRefusal(with_csv("t_s,a_m_s2\n0,1\n0,2\n")).find("increase"),
            std::string::npos);
  EXPECT_NE(testing::SceneRefusal(with_csv("t_s,a_m_s2\n0,1\n1,nan\n")).find("finite"),
            std::string::npos);
  EXPECT_NE(testing::SceneRefusal(with_csv("t_s,a_m_s2\n0,1\n")).find("two rows"),
            std::string::npos);
  EXPECT_EQ(testing::SceneRefusal(with_csv("t_s,a_m_s2\n0,1\n0.01,-2\n")), "");
}

// A hexagonal bundle of n rings has 1 + 3 n (n + 1) pins, 3 n (3 n + 1) neighbour pairs and
// 12 n + 6 faces against the wrapper, every pair one pitch apart.
TEST_F(SceneFiles, HexBundleHasTheLatticeOfARealAssembly) {
  for (int rings : {1, 2, 8}) {
    const std::string path = Variant([&](Json& s) {
      std::ifstream in(kScenes + "bundle_hex.json");
      s = Json::parse(in);
      s["bundle"]["rings"] = rings;
      s.erase("zones");
      s["outputs"] = {{"max_contact_force", true}};
    });
    const Scene scene = LoadScene(path);
    const int heights = 7;
    ASSERT_EQ(scene.beams.size(), 2u + 3u * rings * (rings + 1));
    std::map<bool, int> zones;  // against the wrapper -> count
    for (const SceneZone& z : scene.zones) {
      const bool wall = z.beam_b == 0;
      ++zones[wall];
      const SceneBeam &a = scene.beams[z.beam_a], &b = scene.beams[z.beam_b];
      if (!wall) {
        EXPECT_NEAR(std::hypot(b.y_m - a.y_m, b.z_m - a.z_m), 7.2644e-3, 1e-12);
        EXPECT_NEAR(z.normal_y * (b.y_m - a.y_m) + z.normal_z * (b.z_m - a.z_m), 7.2644e-3, 1e-12);
        EXPECT_GE(z.gap_m, 0.0);
      } else {
        EXPECT_EQ(z.gap_m, 3.8e-4);
      }
    }
    EXPECT_EQ(zones[false], heights * 3 * rings * (3 * rings + 1));
    EXPECT_EQ(zones[true], heights * (12 * rings + 6));
  }
}

TEST_F(SceneFiles, BundleZonesNameTheirWireHeightWithoutFloatNoise) {
  // linspace [0.3048, 2.1336, 7] computes 0.9144000000000001 for the third height.
  const Scene scene = LoadScene(kScenes + "bundle_row.json");
  std::set<std::string> heights;
  for (const SceneZone& z : scene.zones) {
    const auto at = z.name.find('@');
    if (at != std::string::npos) heights.insert(z.name.substr(at + 1));
  }
  EXPECT_EQ(heights, (std::set<std::string>{"0.3048", "0.6096", "0.9144", "1.2192", "1.524",
                                            "1.8288", "2.1336"}));
  // Heights closer than a micrometre would give two zones one name: refused.
  const std::string refused = testing::SceneRefusal(Variant([](Json& s) {
    std::ifstream in(kScenes + "bundle_row.json");
    s = Json::parse(in);
    s["bundle"]["wire"]["heights_m"] = {0.5, 0.5000000001};
  }));
  EXPECT_NE(refused.find("given twice (to the micrometre, 0.5 m)"), std::string::npos) << refused;
}

// The direction of a zone's normal in the cross-section, in whole degrees from +y towards +z.
long DegreesOf(const SceneZone& z) {
  const long degrees = std::lround(std::atan2(z.normal_z, z.normal_y) * 180.0 / std::numbers::pi);
  return (degrees + 360) % 360;
}

std::string HeightOf(const SceneZone& z) { return z.name.substr(z.name.find('@')); }

// Zone names label CSV columns, Python's histories and the sizing tables' rows: every zone of
// a generated bundle has its own. A pin that meets the wrapper on several faces (every outer pin
// of a hexagonal bundle, a row's single pin) names each by its direction; the pins at the ends
// of a row meet it on one face and keep the name without one.
TEST_F(SceneFiles, EveryBundleZoneHasItsOwnNameAndEachWrapperFaceItsDirection) {
  const std::string single_pin_row = Variant([](Json& s) {
    std::ifstream in(kScenes + "bundle_row.json");
    s = Json::parse(in);
    s["bundle"]["pins"] = 1;
    s.erase("zones");
    s["outputs"] = {{"max_contact_force", true}};
  });
  for (const std::string& file : {kScenes + "bundle_hex.json", kScenes + "bundle_hex_7.json",
                                  kScenes + "bundle_row.json", single_pin_row}) {
    const Scene scene = LoadScene(file);
    std::set<std::string> names;
    std::map<int, int> faces_of_pin;  // At the first wire height.
    for (const SceneZone& z : scene.zones) {
      EXPECT_TRUE(names.insert(z.name).second) << file << ": " << z.name << " twice";
      if (z.beam_b == 0 && HeightOf(z) == HeightOf(scene.zones.front())) ++faces_of_pin[z.beam_a];
    }
    int named_by_face = 0;
    for (const SceneZone& z : scene.zones) {
      if (z.beam_b != 0) continue;
      const std::string beams = scene.beams[z.beam_a].name + "-wrapper";
      const bool several = faces_of_pin.at(z.beam_a) > 1;
      EXPECT_EQ(z.name,
                beams + (several ? "_" + std::to_string(DegreesOf(z)) + "deg" : "") + HeightOf(z))
          << file;
      named_by_face += several;
    }
    const bool row_of_several = file == kScenes + "bundle_row.json";
    EXPECT_EQ(named_by_face > 0, !row_of_several) << file;
  }
  // The 217-pin bundle's first pin, a corner of the hexagon, meets the wrapper on three faces.
  const Scene hex = LoadScene(kScenes + "bundle_hex.json");
  std::set<std::string> pin_0;
  for (const SceneZone& z : hex.zones) {
    if (z.name.starts_with("pin_0-wrapper") && HeightOf(z) == "@1.2192") pin_0.insert(z.name);
  }
  EXPECT_EQ(pin_0,
            (std::set<std::string>{"pin_0-wrapper_120deg@1.2192", "pin_0-wrapper_180deg@1.2192",
                                   "pin_0-wrapper_240deg@1.2192"}));
}

// A hand-written zone may not take a name another zone has, listed or generated: refused with
// the file, the key, the name and where it was given first, exit code 2.
TEST_F(SceneFiles, AZoneNameGivenTwiceIsRefusedWithWhereItWasGiven) {
  Json scene = Json::parse(std::ifstream(kScenes + "cantilever_spring.json"));
  const std::string name = scene["zones"][0]["name"];
  scene["zones"].push_back(scene["zones"][0]);
  const std::string listed = Path("listed.json");
  WriteText(listed, scene.dump());
  const std::string hex_file = kScenes + "bundle_hex_7.json";
  const std::string generated_name = LoadScene(hex_file).zones.front().name;
  scene = Json::parse(std::ifstream(hex_file));
  scene["zones"][0]["name"] = generated_name;
  const std::string generated = Path("generated.json");
  WriteText(generated, scene.dump());
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {listed,
       {"listed.json", "zones[1].name", "zone \"" + name + "\"", "given at zones[0].name",
        "zone names must be unique"}},
      {generated,
       {"generated.json", "zones[0].name", "zone \"" + generated_name + "\"",
        "of a zone the bundle generates", "zone names must be unique"}},
  };
  for (const auto& [file, parts] : cases) {
    const std::string message = testing::SceneRefusal(file);
    for (const auto& part : parts) EXPECT_NE(message.find(part), std::string::npos) << message;
    const auto run = RunShockmap("simulate " + file);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find("zone names must be unique"), std::string::npos) << run.output;
  }
}

// A scene that lists a pin's wrapper zone by the name every face had before each was named by
// its direction is told the faces' names.
TEST_F(SceneFiles, AnUnnamedWrapperFaceIsAnsweredWithTheFacesNames) {
  const std::string file = Variant([](Json& s) {
    s = Json::parse(std::ifstream(kScenes + "bundle_hex_7.json"));
    s["outputs"]["contact_forces"] = {"pin_0-wrapper@0.3048"};
  });
  const std::string message = testing::SceneRefusal(file);
  EXPECT_NE(message.find("outputs.contact_forces[0]: no zone named \"pin_0-wrapper@0.3048\": the "
                         "pin meets the wrapper on several faces, each named by its direction: "
                         "\"pin_0-wrapper_120deg@0.3048\", \"pin_0-wrapper_180deg@0.3048\", "
                         "\"pin_0-wrapper_240deg@0.3048\""),
            std::string::npos)
      << message;
}

TEST_F(SceneFiles, SeededGapsAreReproducibleAndFollowTheirLaw) {
  auto gaps = [&](int seed) {
    const Scene scene = LoadScene(Variant([&](Json& s) {
      std::ifstream in(kScenes + "bundle_hex.json");
      s = Json::parse(in);
      s["bundle"]["wire"]["gap_m"] = {{"normal", {{"mean", 1e-4}, {"std", 2e-5}, {"seed", seed}}}};
    }));
    std::vector<double> g;
    for (const SceneZone& z : scene.zones) {
      if (z.beam_b > 0) g.push_back(z.gap_m);
    }
    return g;
  };
  const auto a = gaps(7), b = gaps(7), c = gaps(8);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  double mean = 0, var = 0;
  for (double g : a) mean += g / a.size();
  for (double g : a) var += (g - mean) * (g - mean) / (a.size() - 1);
  // 4200 draws: the sample mean lies within 3 standard errors (0.9e-6), the std within 5 %.
  EXPECT_NEAR(mean, 1e-4, 1e-6);
  EXPECT_NEAR(std::sqrt(var), 2e-5, 1e-6);
}

std::vector<std::vector<double>> ReadCsv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST_F(SceneFiles, CanonicalSceneThroughSimulateEqualsCompare) {
  const auto sim =
      RunShockmap("simulate " + kScenes + "cantilever_spring.json --out " + Path("sim"));
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const auto cmp = RunShockmap("compare --rk 3000 --rftrunc 300 --out " + Path("cmp"));
  ASSERT_EQ(cmp.exit_code, 0) << cmp.output;
  const auto tip = ReadCsv(Path("sim/displacements.csv"));
  const auto force = ReadCsv(Path("sim/contact_forces.csv"));
  const auto numerical = ReadCsv(Path("cmp/numerical.csv"));
  ASSERT_EQ(tip.size(), numerical.size());
  double worst_tip = 0, worst_force = 0, peak = 0;
  for (std::size_t i = 0; i < tip.size(); ++i) {
    ASSERT_DOUBLE_EQ(tip[i][0], numerical[i][0]);
    worst_tip = std::max(worst_tip, std::abs(tip[i][1] - numerical[i][1]));
    worst_force = std::max(worst_force, std::abs(force[i][1] - numerical[i][3]));
    peak = std::max(peak, numerical[i][3]);
  }
  ASSERT_GT(peak, 1e3);                     // The run has shocks to compare.
  EXPECT_LT(worst_tip, 1e-12 * 1e-3 * 10);  // 12 digits in the files.
  EXPECT_LT(worst_force, 1e-10 * peak);
}

// The shipped canonical scene is the comparison's reduced model: the scene engine running
// scenes/cantilever_spring.json gives the histories `compare` scores, bit for bit (the same
// FE mesh, modes, initial state, zone and time step; one system integrates both).
TEST_F(SceneFiles, CanonicalSceneFileGivesTheComparisonsHistoriesBitForBit) {
  const SceneRun scene = RunScene(LoadScene(kScenes + "cantilever_spring.json"));
  CantileverImpact problem;
  problem.r_k = 3000.0;
  ComparisonOptions options;
  options.r_ftrunc = 300.0;
  const ComparisonResult cmp = RunComparison(problem, options);
  ASSERT_EQ(cmp.status, RunStatus::kOk) << cmp.message;
  ASSERT_EQ(scene.result.summary.status, RunStatus::kOk) << scene.result.summary.message;
  EXPECT_EQ(scene.result.summary.dt_used_s, cmp.numerical.dt_used_s);
  const TransientResult& a = scene.result;
  const TransientResult& b = cmp.histories;
  ASSERT_GT(
      *std::max_element(b.contact_force_n[0].values.begin(), b.contact_force_n[0].values.end()),
      1e3);  // The run has shocks.
  EXPECT_EQ(a.displacement_m[0].values, b.displacement_m[0].values);
  EXPECT_EQ(a.velocity_m_s[0].values, b.velocity_m_s[0].values);
  EXPECT_EQ(a.contact_force_n[0].values, b.contact_force_n[0].values);
  EXPECT_EQ(a.energy.kinetic_j.values, b.energy.kinetic_j.values);
  EXPECT_EQ(a.energy.strain_j.values, b.energy.strain_j.values);
  EXPECT_EQ(a.energy.contact_j.values, b.energy.contact_j.values);
}

TEST_F(SceneFiles, ShippedScenesRunAndDrawTheirContactForceMaps) {
  for (const char* name : {"bundle_row", "cantilever_spring"}) {
    const auto out = Path(name);
    const auto r = RunShockmap(std::string("simulate --json --quiet ") + kScenes + name +
                               ".json --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    // The headers are their column tables' names.
    EXPECT_EQ(FirstLine(out + "/max_contact_force.csv"), Joined(ColumnNames(kLargestForceColumns)));
    EXPECT_EQ(FirstLine(out + "/energies.csv"), Joined(ColumnNames(kEnergyColumns)));
    const Json summary = Json::parse(r.output);
    EXPECT_EQ(summary["status"], "ok");
    EXPECT_LT(summary["max_energy_ratio"].get<double>(), 1.1);
    EXPECT_GT(summary["largest_contact_force"]["force_n"].get<double>(), 0.0);
    EXPECT_GT(std::filesystem::file_size(out + "/contact_force_map.png"), 10000u);
    // Only the requested outputs are written.
    EXPECT_EQ(std::filesystem::exists(out + "/contact_forces.csv"),
              std::string(name) == "cantilever_spring");
  }
}

// The streamed impact statistics of the canonical scene group its contacts as the shocks of
// its recorded force history do (the same rest duration), and a planar scene has no wear.
TEST_F(SceneFiles, ImpactStatisticsAgreeWithTheShocksOfTheHistory) {
  const std::string path = Variant([](Json& s) {
    s["outputs"]["impact_statistics"] = {{"rest_duration_s", 0.0052}};
  });
  const auto r = RunShockmap("simulate --json --quiet " + path + " --out " + Path("impacts"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json zone = Json::parse(r.output)["zone_results"][0];
  const Json& impacts = zone["impact_statistics"];
  ASSERT_GT(zone["shocks"]["count"].get<int>(), 0);
  EXPECT_EQ(impacts["impacts"], zone["shocks"]["count"]);
  EXPECT_EQ(impacts["contacts"].get<int>(),
            zone["shocks"]["count"].get<int>() + zone["shocks"]["rebounds"].get<int>());
  EXPECT_TRUE(impacts["wear_work_rate_w"].is_null());
  // The summary has a member per column of its table; the CSV files' headers are their column
  // tables' names, after the zone's.
  const Json summary = Json::parse(r.output);
  for (const std::string& name : ColumnNames(kSceneRunColumns)) {
    EXPECT_TRUE(summary.contains(name)) << name;
  }
  EXPECT_EQ(FirstLine(Path("impacts") + "/impact_statistics.csv"),
            "zone," + Joined(ColumnNames(kImpactStatisticsColumns)));
  EXPECT_EQ(FirstLine(Path("impacts") + "/shocks.csv"),
            "zone," + Joined(ColumnNames(kShockColumns)));
}

// The rubbing bundle (scenes/bundle_hex_7_friction.json) over 0.05 s: its zones' wear work rate
// counts the sliding only, each worn volume is K x rate x life, the friction power is at most
// mu_s (0.35) times the wear work rate (|F_t| <= mu_s N), and the listed zones' impacts are in
// impacts.csv.
TEST_F(SceneFiles, RubbingBundleWritesItsWearAndItsImpacts) {
  const std::string path = Variant([](Json& s) {
    std::ifstream in(kScenes + "bundle_hex_7_friction.json");
    s = Json::parse(in);
    s["solver"]["end_time_s"] = 0.05;
    s["outputs"].erase("displacements");
    s["outputs"].erase("energies");
    s["outputs"]["impact_statistics"]["window_s"] = {0.0, 0.05};
  });
  const auto r = RunShockmap("simulate --json --quiet " + path + " --out " + Path("rubbing"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json summary = Json::parse(r.output);
  const double k = summary["wear"]["coefficient_m2_per_n"], life = summary["wear"]["life_s"];
  int worn = 0;
  for (const Json& zone : summary["zone_results"]) {
    const Json& s = zone["impact_statistics"];
    EXPECT_EQ(s["convention"], "code_aster");
    EXPECT_EQ(s["wear_basis"], "sliding_only");
    const double rate = s["wear_work_rate_w"];
    EXPECT_NEAR(s["wear_volume_m3"].get<double>(), k * rate * life, 1e-12 * k * rate * life);
    if (rate > 0.0) {
      ++worn;
      EXPECT_GT(s["friction_power_w"].get<double>(), 0.0) << zone["name"];
      EXPECT_LE(s["friction_power_w"].get<double>(), 0.35 * rate) << zone["name"];
    }
  }
  EXPECT_GT(worn, 10);
  const std::string impacts = testing::ReadBytes(Path("rubbing") + "/impacts.csv");
  EXPECT_EQ(FirstLine(Path("rubbing") + "/impacts.csv"),
            "zone,impact," + Joined(ColumnNames(kImpactRecordColumns)));
  EXPECT_NE(impacts.find("\nduct-pad,1,"), std::string::npos) << impacts;
  const std::string csv = testing::ReadBytes(Path("rubbing") + "/impact_statistics.csv");
  EXPECT_NE(csv.find(",wear_basis,friction_power_w,wear_volume_m3\n"), std::string::npos);
}

TEST_F(SceneFiles, SimulateRefusesBadInputWithExitCode2) {
  WriteText(Path("empty.json"), "");
  WriteText(Path("truncated.json"), "{\"name\": \"x\", \"beams\": [");
  const std::string stride = Variant([](Json& s) {
    s["solver"]["dt"] = {{"rule", "sharp"}, {"factor", 1e-6}};
    s["solver"]["end_time_s"] = 1e3;
  });
  // Every zone's force at every step of the 217-pin bundle: 6.7 GiB, refused before running.
  const std::string histories = Path("histories.json");
  {
    std::ifstream in(kScenes + "bundle_hex.json");
    Json scene = Json::parse(in);
    scene["outputs"] = {{"contact_forces", true}};
    WriteText(histories, scene.dump());
  }
  const std::string rubbing_planar = Path("rubbing_planar.json");
  {
    std::ifstream in(kScenes + "cantilever_spring.json");
    Json scene = Json::parse(in);
    scene["zones"][0]["friction"] = {{"coefficient", 0.3}, {"tangential_stiffness_n_per_m", 1e8}};
    WriteText(rubbing_planar, scene.dump());
  }
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"simulate " + histories, "record_stride"},
      {"simulate " + Path("missing.json"), "missing.json"},
      {"simulate " + Path("empty.json"), "empty.json"},
      {"simulate " + Path("truncated.json"), "truncated.json"},
      {"simulate " + stride, "solver.dt"},
      {"simulate " + rubbing_planar, "zones[0].friction"},
      {"simulate " + kScenes + "cantilever_spring.json --out /proc/shockmap", "/proc/shockmap"},
  };
  for (const auto& [args, named] : cases) {
    const auto r = RunShockmap(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(named), std::string::npos) << r.output;
  }
}

}  // namespace
}  // namespace shockmap
