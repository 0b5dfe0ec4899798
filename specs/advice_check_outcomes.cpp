#include "specs/advice_check_outcomes.h"

#include <fmt/format.h>

#include <algorithm>

#include "formats/json_reader.h"
#include "specs/ensemble_draws.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

constexpr const char* kKind = "advice_check_outcomes";

std::vector<std::string> States(JsonObjectReader& r) {
  const Json* states = r.Get("states");
  if (states == nullptr || !states->is_array() || states->empty())
    r.Fail("states", "expected a non-empty list of clearance state names");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < states->size(); ++i) {
    const std::string path = fmt::format("{}[{}]", r.PathOf("states"), i);
    if (!(*states)[i].is_string())
      FailAt(r.File(), path, "expected a state name, got " + Shown((*states)[i]));
    names.push_back(CheckedName((*states)[i].get<std::string>(), r.File(), path));
  }
  return names;
}

AdviceCheckOutcome ParseOutcome(const Json& json, const std::string& file,
                                const std::string& path) {
  JsonObjectReader r(json, file, path);
  AdviceCheckOutcome o;
  o.study = r.RequiredName("study");
  o.scene = r.RequiredName("scene");
  o.scene_digest = r.RequiredName("scene_digest");
  o.criteria = r.RequiredName("criteria");
  o.criteria_digest = r.RequiredName("criteria_digest");
  o.states = States(r);
  o.members = r.Integer("members", 0);
  if (o.members < 1) r.Fail("members", fmt::format("{} is not a positive count", o.members));
  o.window_s = r.RequiredNumber("window_s");
  if (!(o.window_s > 0.0)) r.Fail("window_s", Shown(Json(o.window_s)) + " is not positive");
  o.quantile = r.RequiredNumber("quantile");
  if (!(o.quantile > 0.0 && o.quantile < 1.0))
    r.Fail("quantile", Shown(Json(o.quantile)) + " does not lie in (0, 1)");
  o.tolerance = r.RequiredNumber("tolerance");
  if (!(o.tolerance >= 0.0 && o.tolerance <= 1.0))
    r.Fail("tolerance", Shown(Json(o.tolerance)) + " does not lie in [0, 1]");
  o.pairs = r.Integer("pairs", 0);
  if (o.pairs < 1) r.Fail("pairs", fmt::format("{} is not a positive count", o.pairs));
  o.held = r.Integer("held", -1);
  if (o.held < 0 || o.held > o.pairs)
    r.Fail("held", fmt::format("{} does not lie in [0, pairs = {}]", o.held, o.pairs));
  o.verdict = r.Text("verdict", "");
  r.Finish();
  return o;
}

Json OutcomeJson(const AdviceCheckOutcome& o) {
  return {{"study", o.study},
          {"scene", o.scene},
          {"scene_digest", o.scene_digest},
          {"criteria", o.criteria},
          {"criteria_digest", o.criteria_digest},
          {"states", o.states},
          {"members", o.members},
          {"window_s", o.window_s},
          {"quantile", o.quantile},
          {"tolerance", o.tolerance},
          {"pairs", o.pairs},
          {"held", o.held},
          {"verdict", o.verdict}};
}

}  // namespace

std::string JsonDigest(const Json& json) {
  // Keys are sorted in nlohmann::json's objects; invalid UTF-8 (never in a parsed file) is
  // replaced rather than thrown on.
  const std::string text = json.dump(-1, ' ', false, Json::error_handler_t::replace);
  return fmt::format("fnv1a64:{:016x}", Fnv1a64(text));
}

std::string SceneDigest(const Json& scene_json, const Scene& scene) {
  if (!scene.base_motion || scene.base_motion->table_t_s.empty()) return JsonDigest(scene_json);
  return JsonDigest(
      {{"scene", scene_json},
       {"base_motion_table",
        {{"t_s", scene.base_motion->table_t_s}, {"a_m_s2", scene.base_motion->table_a_m_s2}}}});
}

std::vector<AdviceCheckOutcome> ParseAdviceCheckOutcomes(const Json& json,
                                                         const std::string& file) {
  JsonObjectReader r(json, file, "");
  const std::string kind = r.RequiredString("kind");
  if (kind != kKind) r.Fail("kind", fmt::format("\"{}\" is not \"{}\"", Excerpt(kind), kKind));
  r.Text("description", "");
  const Json* list = r.Get("outcomes");
  if (list == nullptr || !list->is_array()) r.Fail("outcomes", "expected a list of outcomes");
  std::vector<AdviceCheckOutcome> outcomes;
  for (std::size_t i = 0; i < list->size(); ++i)
    outcomes.push_back(ParseOutcome((*list)[i], file, fmt::format("outcomes[{}]", i)));
  r.Finish();
  return outcomes;
}

Json AdviceCheckOutcomesJson(const std::vector<AdviceCheckOutcome>& outcomes) {
  Json list = Json::array();
  for (const AdviceCheckOutcome& o : outcomes) list.push_back(OutcomeJson(o));
  return {{"kind", kKind},
          {"description",
           "Outcomes of `shockmap check-advice --record`: where the advice for a scene held on "
           "its own ensemble (docs/ensembles.md, \"Advice checked on the bundle\"). `advise` "
           "reads them for the scene and criteria files whose digests they name."},
          {"outcomes", list}};
}

void RecordOutcome(std::vector<AdviceCheckOutcome>& outcomes, AdviceCheckOutcome outcome) {
  const auto same = std::ranges::find_if(outcomes, [&](const AdviceCheckOutcome& o) {
    return o.study == outcome.study && o.scene_digest == outcome.scene_digest &&
           o.criteria_digest == outcome.criteria_digest;
  });
  if (same == outcomes.end()) {
    outcomes.push_back(std::move(outcome));
  } else {
    *same = std::move(outcome);
  }
}

const AdviceCheckOutcome* OutcomeFor(const std::vector<AdviceCheckOutcome>& outcomes,
                                     const std::string& scene_digest,
                                     const std::string& criteria_digest) {
  const AdviceCheckOutcome* first = nullptr;
  for (const AdviceCheckOutcome& o : outcomes) {
    if (o.scene_digest != scene_digest || o.criteria_digest != criteria_digest) continue;
    if (o.Held()) return &o;
    if (first == nullptr) first = &o;
  }
  return first;
}

}  // namespace shockmap
