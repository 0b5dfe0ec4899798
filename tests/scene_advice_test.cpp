// Advice for a scene from the shipped criteria (validation/scene_advice.h): each zone's R_k
// against its beam's static bending stiffness at the zone's height, the truncation the criteria
// require for each beam's stiffest zone, and what the advice warns of.

#include "validation/scene_advice.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "formats/criteria_json.h"
#include "formats/json_reader.h"
#include "formats/scene_file.h"
#include "specs/advice_check_outcomes.h"
#include "views/scene_advice_summary.h"

namespace shockmap {
namespace {

ValidityCriteria CriteriaOf(const std::string& baseline) {
  const std::string file = std::string(SHOCKMAP_SOURCE_DIR) + "/studies/baselines/" + baseline;
  return CriteriaFromJson(ReadJsonFile(file), file, nullptr);
}

ValidityCriteria ShippedCriteria() { return CriteriaOf("paper_fig4.json"); }

Scene ShippedScene(const std::string& name) {
  return LoadScene(std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/" + name + ".json");
}

// The paper's Fig. 3 problem as a scene: R_k = k_s / (3 EI / L^3) = 1.35e9 / 4.5e5 = 3000 at the
// tip, and the beam's truncation is the criteria's at that R_k. The local stiffness comes from
// the beam's finite elements (exact at a node for a point load, 1.5e-10 here; between nodes,
// as at 0.5 m of 55 elements, within 1e-6).
TEST(SceneAdvice, ZoneStiffnessRatioAndTruncationFollowTheCriteria) {
  const ValidityCriteria criteria = ShippedCriteria();
  const SceneAdvice a = AdviseScene(ShippedScene("cantilever_spring"), criteria);
  ASSERT_EQ(a.zones.size(), 1u);
  EXPECT_NEAR(a.zones[0].r_k_a, 3000.0, 3000.0 * 1e-9);
  EXPECT_FALSE(a.zones[0].r_k_b);  // Against a stop.
  ASSERT_EQ(a.beams.size(), 1u);
  EXPECT_DOUBLE_EQ(a.beams[0].r_k_max, a.zones[0].r_k_a);
  EXPECT_DOUBLE_EQ(a.beams[0].r_ftrunc, *criteria.RequiredRFtrunc(a.beams[0].r_k_max));
  EXPECT_DOUBLE_EQ(a.dt_ratio, *criteria.dt_ratio_max);
  EXPECT_NEAR(a.dt_s, a.dt_ratio * a.dt_sharp_s, 1e-15 * a.dt_s);
  EXPECT_TRUE(a.warnings.empty()) << a.warnings.front();

  // Half as far from the clamp, the beam is 8 times stiffer there: R_k falls 8-fold.
  Scene lower = ShippedScene("cantilever_spring");
  lower.zones[0].height_m = 0.5;
  EXPECT_NEAR(AdviseScene(lower, criteria).zones[0].r_k_a, 375.0, 375.0 * 1e-6);
}

// A Hertz zone has no single stiffness: the advice takes its tangent p k d_b^(p-1) at the bound
// penetration d_b (what the stability bound takes), and says so, naming the law and d_b.
TEST(SceneAdvice, APowerLawZoneSaysHowItWasLinearised) {
  const std::string file = std::string(SHOCKMAP_SOURCE_DIR) + "/scenes/cantilever_spring.json";
  nlohmann::json json = ReadJsonFile(file);
  json["zones"][0].erase("stiffness_n_per_m");
  json["zones"][0]["power_law"] = {{"coefficient_n_per_m_exponent", 4e10},
                                   {"bound_penetration_m", 1e-5}};
  const Scene scene = ParseScene(json, file);
  const double tangent = 1.5 * 4e10 * std::sqrt(1e-5);
  ASSERT_DOUBLE_EQ(scene.zones[0].stiffness_n_per_m, tangent);
  const SceneAdvice a = AdviseScene(scene, ShippedCriteria());
  const std::string text = SceneAdviceSummary(scene, a, true);
  EXPECT_NE(text.find(fmt::format(
                "power law    zone tip_spring: F = k d^1.5 (k = 4e+10 N/m^1.5) linearised as its "
                "tangent stiffness p k d_b^(p-1) = {:.4g} N/m at the bound penetration d_b = "
                "1e-05 m",
                tangent)),
            std::string::npos)
      << text;
  EXPECT_EQ(
      SceneAdviceSummary(ShippedScene("cantilever_spring"),
                         AdviseScene(ShippedScene("cantilever_spring"), ShippedCriteria()), true)
          .find("power law"),
      std::string::npos);
}

// The shipped bundles' zones lie inside the shipped criteria's R_k (0.01 to 1e6): no warning.
// A zone 10 times stiffer than the stiffest wire lies beyond it, and the advice says so.
TEST(SceneAdvice, ShippedBundlesNeedNoExtrapolationAndAStifferZoneIsNamed) {
  const ValidityCriteria criteria = ShippedCriteria();
  for (const char* name : {"bundle_row", "bundle_hex_7"}) {
    const SceneAdvice a = AdviseScene(ShippedScene(name), criteria);
    ASSERT_FALSE(a.zones.empty()) << name;
    for (const ZoneAdvice& z : a.zones) {
      EXPECT_GE(z.r_k_a, criteria.boundary.front().r_k) << name << " " << z.name;
      EXPECT_LE(z.r_k_a, criteria.boundary.back().r_k) << name << " " << z.name;
    }
    EXPECT_TRUE(a.warnings.empty()) << name << ": " << a.warnings.front();
    for (const BeamAdvice& b : a.beams) {
      EXPECT_DOUBLE_EQ(b.r_ftrunc, *criteria.RequiredRFtrunc(b.r_k_max)) << name << " " << b.name;
    }
  }
  Scene stiffer = ShippedScene("bundle_row");
  const std::vector<ZoneAdvice> zones = AdviseScene(stiffer, criteria).zones;
  const std::string stiffest =
      std::ranges::max_element(zones, {}, [](const ZoneAdvice& z) { return z.r_k_a; })->name;
  std::ranges::find(stiffer.zones, stiffest, &SceneZone::name)->stiffness_n_per_m *= 10.0;
  const SceneAdvice a = AdviseScene(stiffer, criteria);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(a.warnings[0].find("beyond the criteria's studied range [0.01, 1e+06]"),
            std::string::npos)
      << a.warnings[0];
}

// The criteria a scene is advised with by default (the peak force on the mode-resolution grid,
// docs/physics.md §5.1) were studied from R_k = 0.01, below the shipped bundles' softest zone
// side (0.0234): every zone lies inside their R_k and none is called extrapolated.
TEST(SceneAdvice, TheSceneCriteriaWereStudiedOverEveryZoneOfTheShippedBundles) {
  const ValidityCriteria criteria = CriteriaOf("modes_fig4_peak_force.json");
  for (const char* name : {"bundle_row", "bundle_hex_7", "bundle_hex"}) {
    const SceneAdvice a = AdviseScene(ShippedScene(name), criteria);
    ASSERT_FALSE(a.zones.empty()) << name;
    for (const ZoneAdvice& z : a.zones) {
      for (const auto r_k : {std::optional<double>(z.r_k_a), z.r_k_b}) {
        if (!r_k) continue;
        EXPECT_GE(*r_k, criteria.boundary.front().r_k) << name << " " << z.name;
        EXPECT_LE(*r_k, criteria.boundary.back().r_k) << name << " " << z.name;
      }
    }
    for (const std::string& w : a.warnings) {
      EXPECT_EQ(w.find("beyond the criteria's studied range"), std::string::npos) << name << w;
    }
  }
}

// A studied R_k where no truncation passes has no boundary, so the fit's envelope does not
// cover it: around the zones' R_k, the advice names it; away from them, not.
TEST(SceneAdvice, AStudiedRkWithoutAPassingTruncationAroundTheZonesIsNamed) {
  ValidityCriteria criteria = ShippedCriteria();
  const SceneAdvice before = AdviseScene(ShippedScene("bundle_row"), criteria);
  double r_k_max = 0.0;
  for (const ZoneAdvice& z : before.zones) r_k_max = std::max(r_k_max, z.r_k_a);
  // The studied R_k just below the stiffest zone loses its boundary.
  auto below = std::ranges::find_if(criteria.boundary.rbegin(), criteria.boundary.rend(),
                                    [&](const RkBoundary& b) { return b.r_k <= r_k_max; });
  ASSERT_NE(below, criteria.boundary.rend());
  below->r_ftrunc_min.reset();
  const SceneAdvice a = AdviseScene(ShippedScene("bundle_row"), criteria);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(
      a.warnings[0].find(fmt::format("no studied truncation passes at R_k = {:.3g}", below->r_k)),
      std::string::npos)
      << a.warnings[0];
  // With what answers it on the structure itself.
  const std::string summary = SceneAdviceSummary(ShippedScene("bundle_row"), a, false);
  EXPECT_NE(summary.find("warning      no studied truncation passes"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("shockmap check-advice STUDY.json --record FILE"), std::string::npos)
      << summary;
  // Far from the zones' R_k (the Fig. 3 scene's one zone at 3000), a hole at R_k = 1 is not.
  ValidityCriteria far = ShippedCriteria();
  auto one = std::ranges::find(far.boundary, 1.0, &RkBoundary::r_k);
  ASSERT_NE(one, far.boundary.end());
  one->r_ftrunc_min.reset();
  EXPECT_TRUE(AdviseScene(ShippedScene("cantilever_spring"), far).warnings.empty());
}

// An unscored R_k is named where it lies among the studied R_k around the zones', not beyond
// them: the row bundle's zones (up to 6.96e5) are not near an unscored 5.62e6, one at 3000 is
// not near an unscored 1e6, and one at 1e6 is.
TEST(SceneAdvice, AnUnscoredRkIsNamedOnlyAroundTheZones) {
  ValidityCriteria criteria = ShippedCriteria();
  criteria.unscored = {{5.62e6, 40, "far above"}};
  EXPECT_TRUE(AdviseScene(ShippedScene("bundle_row"), criteria).warnings.empty());
  criteria.unscored = {{1e6, 3, "the reference did not converge"}};
  EXPECT_TRUE(AdviseScene(ShippedScene("cantilever_spring"), criteria).warnings.empty());
  const SceneAdvice a = AdviseScene(ShippedScene("bundle_row"), criteria);
  ASSERT_EQ(a.warnings.size(), 1u);
  EXPECT_NE(a.warnings[0].find("left 3 points unscored, at R_k = 1e+06"), std::string::npos)
      << a.warnings[0];
}

std::string Shipped(const std::string& relative) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
}

AdviceCheckOutcome AnOutcome() {
  AdviceCheckOutcome o;
  o.study = "bundle_row_ensemble";
  o.scene = "scenes/bundle_row.json";
  o.scene_digest = JsonDigest(ReadJsonFile(Shipped(o.scene)));
  o.criteria = "studies/baselines/modes_fig4_peak_force.json";
  o.criteria_digest = JsonDigest(ReadJsonFile(Shipped(o.criteria)));
  o.states = {"new", "end_of_life"};
  o.members = 120;
  o.window_s = 0.1;
  o.quantile = 0.95;
  o.tolerance = 0.05;
  o.pairs = 6;
  o.held = 6;
  o.verdict = "Advice held at 6 of 6 state and zone family pairs.";
  return o;
}

// A digest names a file's JSON, not its spelling: spacing and the order of keys leave it, any
// value changed moves it.
TEST(AdviceCheckOutcomes, ADigestFollowsTheJsonNotItsSpelling) {
  const auto a = ParseJsonText(R"({"k": 1.5, "name": "row", "z": [1, 2]})", "a.json");
  const auto b = ParseJsonText("{\"z\":[1,2],\n \"name\":\"row\",\"k\":1.5}", "b.json");
  const auto c = ParseJsonText(R"({"k": 1.6, "name": "row", "z": [1, 2]})", "c.json");
  EXPECT_EQ(JsonDigest(a), JsonDigest(b));
  EXPECT_NE(JsonDigest(a), JsonDigest(c));
  EXPECT_EQ(JsonDigest(a).size(), std::string("fnv1a64:").size() + 16);
}

// A scene's digest is its JSON's, and with a base motion from a table file it also follows the
// table's samples, which the scene's JSON only names.
TEST(AdviceCheckOutcomes, ASceneDigestFollowsItsAccelerationTable) {
  const auto json =
      ParseJsonText(R"({"name": "s", "effects": {"base_motion": {"csv": "a.csv"}}})", "s.json");
  Scene half_sine;
  half_sine.base_motion = BaseMotionEffect{};
  EXPECT_EQ(SceneDigest(json, half_sine), JsonDigest(json));
  Scene table = half_sine;
  table.base_motion->table_t_s = {0.0, 0.01, 0.02};
  table.base_motion->table_a_m_s2 = {0.0, 98.1, 0.0};
  Scene edited = table;
  edited.base_motion->table_a_m_s2[1] = 98.2;
  EXPECT_NE(SceneDigest(json, table), JsonDigest(json));
  EXPECT_NE(SceneDigest(json, table), SceneDigest(json, edited));
  EXPECT_EQ(SceneDigest(json, table), SceneDigest(json, Scene(table)));
}

// Written and read back, an outcome keeps every field; recording the same study, scene and
// criteria again replaces it, another study is added; the one found for a scene and criteria
// is a held one when any is, and none for another scene.
TEST(AdviceCheckOutcomes, RecordedOutcomesReadBackAndTheHeldOneIsFound) {
  std::vector<AdviceCheckOutcome> outcomes;
  AdviceCheckOutcome failed = AnOutcome();
  failed.held = 4;
  RecordOutcome(outcomes, failed);
  AdviceCheckOutcome other = AnOutcome();
  other.study = "row_again";
  RecordOutcome(outcomes, other);
  ASSERT_EQ(outcomes.size(), 2u);
  const AdviceCheckOutcome o = AnOutcome();
  ASSERT_EQ(OutcomeFor(outcomes, o.scene_digest, o.criteria_digest), &outcomes[1]);
  RecordOutcome(outcomes, o);  // Replaces the failed one.
  ASSERT_EQ(outcomes.size(), 2u);
  EXPECT_EQ(OutcomeFor(outcomes, o.scene_digest, o.criteria_digest), &outcomes[0]);
  EXPECT_EQ(OutcomeFor(outcomes, "fnv1a64:0000000000000000", o.criteria_digest), nullptr);

  const auto back = ParseAdviceCheckOutcomes(
      ParseJsonText(AdviceCheckOutcomesJson(outcomes).dump(2), "checks.json"), "checks.json");
  ASSERT_EQ(back.size(), 2u);
  const AdviceCheckOutcome& r = back[0];
  EXPECT_EQ(r, o);  // Every field.
  EXPECT_TRUE(r.Held());
  EXPECT_FALSE(failed.Held());
}

// A bad outcomes file is refused naming the file, the key and what is allowed.
TEST(AdviceCheckOutcomes, ABadFileIsRefusedNamingTheKey) {
  const auto refused = [](const std::function<void(nlohmann::json&)>& spoil) {
    nlohmann::json j = AdviceCheckOutcomesJson({AnOutcome()});
    spoil(j);
    try {
      ParseAdviceCheckOutcomes(j, "checks.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused([](auto& j) { j["kind"] = "criteria"; }).find("checks.json: kind"),
            std::string::npos);
  EXPECT_NE(refused([](auto& j) {
              j["outcomes"][0]["held"] = 7;
            }).find("outcomes[0].held: 7 does not lie in [0, pairs = 6]"),
            std::string::npos);
  EXPECT_NE(refused([](auto& j) { j["outcomes"][0]["quantile"] = 1; }).find("outcomes[0].quantile"),
            std::string::npos);
  EXPECT_NE(refused([](auto& j) {
              j["outcomes"][0].erase("scene_digest");
            }).find("outcomes[0].scene_digest: required string is missing"),
            std::string::npos);
  EXPECT_NE(refused([](auto& j) {
              j["outcomes"][0]["states"] = nlohmann::json::array();
            }).find("outcomes[0].states"),
            std::string::npos);
  EXPECT_NE(refused([](auto& j) {
              j["outcomes"][0]["extra"] = 1;
            }).find("outcomes[0].extra: unknown key"),
            std::string::npos);
  EXPECT_NE(refused([](auto& j) { j["outcomes"] = 3; }).find("checks.json: outcomes"),
            std::string::npos);
}

// Where the advice held on the scene's ensemble, what one beam did not measure is listed as
// such and nothing is a warning; where it failed, it stays a warning with the check's verdict;
// without a check, the warning names the check that would answer it.
TEST(SceneAdvice, AnEnsembleThatHeldTheAdviceAnswersWhatOneBeamDidNotMeasure) {
  ValidityCriteria criteria = ShippedCriteria();
  for (RkBoundary& b : criteria.boundary) {
    if (b.r_k >= 3e5 && b.r_k <= 1e6) b.r_ftrunc_min.reset();
  }
  const Scene scene = ShippedScene("bundle_row");
  const SceneAdvice a = AdviseScene(scene, criteria);
  ASSERT_FALSE(a.warnings.empty());
  const AdviceCheckOutcome held = AnOutcome();
  const std::string checked = SceneAdviceSummary(scene, a, false, &held, "checks.json");
  EXPECT_EQ(checked.find("warning"), std::string::npos) << checked;
  EXPECT_NE(checked.find("checked      on the scene's ensemble: the advice held at 6 of 6"),
            std::string::npos)
      << checked;
  EXPECT_NE(checked.find("P95 of 120 members per state and rung (states new, end_of_life) over "
                         "the first 0.1 s, tolerance 5 %; recorded in checks.json"),
            std::string::npos)
      << checked;
  EXPECT_NE(checked.find("one beam     " + a.warnings[0]), std::string::npos) << checked;

  AdviceCheckOutcome failed = held;
  failed.held = 4;
  const std::string warned = SceneAdviceSummary(scene, a, false, &failed, "checks.json");
  EXPECT_NE(warned.find("warning      on the scene's ensemble the advice held at only 4 of 6"),
            std::string::npos)
      << warned;
  EXPECT_NE(warned.find("warning      " + a.warnings[0]), std::string::npos) << warned;
  EXPECT_EQ(warned.find("one beam"), std::string::npos) << warned;
}

// The shipped outcomes hold the advice for the shipped bundles with the shipped scene criteria,
// and name those files as they are now: editing a bundle or the criteria without checking the
// advice again fails here.
TEST(SceneAdvice, TheShippedBundlesAdviceIsCheckedOnTheirEnsembles) {
  const std::string file = Shipped("studies/baselines/advice_checks.json");
  const auto outcomes = ParseAdviceCheckOutcomes(ReadJsonFile(file), file);
  const std::string criteria =
      JsonDigest(ReadJsonFile(Shipped("studies/baselines/modes_fig4_peak_force.json")));
  for (const char* scene :
       {"scenes/bundle_row.json", "scenes/bundle_hex_7.json", "scenes/bundle_hex.json"}) {
    const AdviceCheckOutcome* o = OutcomeFor(
        outcomes, SceneDigest(ReadJsonFile(Shipped(scene)), LoadScene(Shipped(scene))), criteria);
    ASSERT_NE(o, nullptr) << scene << ": no outcome for the shipped scene and criteria";
    EXPECT_TRUE(o->Held()) << scene << ": " << o->verdict;
    EXPECT_EQ(o->scene, scene);
  }
}

}  // namespace
}  // namespace shockmap
