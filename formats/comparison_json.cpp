#include "formats/comparison_json.h"

#include "compare/output_columns.h"
#include "formats/json_or_null.h"
#include "formats/output_values.h"

namespace shockmap {
namespace {

nlohmann::json FirstShock(const std::vector<Shock>& shocks) {
  return shocks.empty() ? nlohmann::json(nullptr) : ShockToJson(shocks.front());
}

}  // namespace

nlohmann::json ShockToJson(const Shock& shock) { return JsonObjectOf(shock, kShockColumns); }

nlohmann::json ComparisonToJson(const CantileverImpact& problem, const ComparisonOptions& options,
                                const ComparisonResult& result) {
  nlohmann::json json =
      JsonObjectOf(ComparisonOutput{problem, options, result}, kComparisonColumns);
  json["reference_undecided"] = result.undecided;
  json["first_shock_num"] = FirstShock(result.shocks_numerical);
  json["first_shock_ref"] = FirstShock(result.reference->shocks);
  for (const ScoreDefinition& score : Scores()) {
    json[std::string(score.name)] = OrNull(result.scores[score.name]);
  }
  return json;
}

}  // namespace shockmap
