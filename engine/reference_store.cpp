#include "engine/reference_store.h"

#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "db/stored_json.h"
#include "formats/comparison_json.h"

namespace shockmap {
namespace {

// The contacts of a shock, one more than its stored "rebounds": DbError unless that is a whole
// number from 0 to one less than the largest int.
int ContactsOf(const nlohmann::json& rebounds, const StoredCell& cell) {
  constexpr std::int64_t kMaxRebounds = std::numeric_limits<int>::max() - 1;
  if (!rebounds.is_number_integer() || rebounds.get<std::int64_t>() < 0 ||
      rebounds.get<std::int64_t>() > kMaxRebounds) {
    ThrowCorruptCell(cell, "rebounds holds " + rebounds.dump() + " (a count from 0 to " +
                               std::to_string(kMaxRebounds) + ")");
  }
  return static_cast<int>(rebounds.get<std::int64_t>()) + 1;
}

Shock ShockFromJson(const nlohmann::json& j, const StoredCell& cell) {
  Shock s;
  s.start_s = j.at("start_s").get<double>();
  s.end_s = j.at("end_s").get<double>();
  s.peak_force_n = j.at("peak_force_n").get<double>();
  s.peak_time_s = j.at("peak_time_s").get<double>();
  s.impulse_n_s = j.at("impulse_n_s").get<double>();
  s.n_contacts = ContactsOf(j.at("rebounds"), cell);
  s.truncated = j.at("truncated").get<bool>();
  return s;
}

// Calls visit(row's member, run's member) for each value a stored reference keeps as its run
// holds it: the one list ToReferenceRow and FromReferenceRow copy through, in opposite
// directions. `Row` and `Run` are ReferenceRow and ReferenceRun, either of them const.
template <typename Row, typename Run, typename Visit>
void VisitStoredValues(Row& row, Run& run, Visit visit) {
  visit(row.r_fref, run.convergence.r_fref);
  visit(row.r_fref_check, run.convergence.r_fref_check);
  visit(row.convergence, run.convergence.difference);
  visit(row.estimate_tip, run.convergence.tip.error);
  visit(row.estimate_impulse, run.convergence.impulse.error);
  visit(row.estimate_err, run.convergence.induced_err.error);
  visit(row.n_modes_free, run.summary.n_modes_free);
  visit(row.n_modes_contact, run.summary.n_modes_contact);
  visit(row.n_transitions, run.summary.n_transitions);
  visit(row.wall_s, run.wall_s);
  visit(row.output_dt_s, run.tip_m.dt_s);  // The force's samples are the tip's.
  visit(row.tip_m, run.tip_m.values);
  visit(row.force_n, run.force_n.values);
}

}  // namespace

ReferenceRow ToReferenceRow(const ReferenceRun& run, const std::string& reference_key, double r_k,
                            double window_s) {
  ReferenceRow row;
  row.reference_key = reference_key;
  row.r_k = r_k;
  row.window_s = window_s;
  VisitStoredValues(row, run, [](auto& stored, const auto& value) { stored = value; });
  nlohmann::json shocks = nlohmann::json::array();
  for (const auto& s : run.shocks) shocks.push_back(ShockToJson(s));
  row.shocks_json = shocks.dump();
  return row;
}

ReferenceRun FromReferenceRow(const ReferenceRow& row, const std::string& database_path) {
  ReferenceRun run;
  VisitStoredValues(row, run, [&row](const auto& stored, auto& value) {
    // A reference stored before its parts were has its whole estimate as each part's bound.
    if constexpr (requires { stored.value_or(row.convergence); }) {
      value = stored.value_or(row.convergence);
    } else {
      value = stored;
    }
  });
  run.force_n.dt_s = run.tip_m.dt_s;
  const StoredCell cell{database_path, "reference " + std::to_string(row.reference_id),
                        "shocks_json"};
  run.shocks = ReadStoredJson(cell, row.shocks_json, [&cell](const nlohmann::json& shocks) {
    std::vector<Shock> read;
    for (const auto& s : shocks.get<std::vector<nlohmann::json>>()) {
      read.push_back(ShockFromJson(s, cell));
    }
    return read;
  });
  return run;
}

}  // namespace shockmap
