#pragma once
// The points, scores and references of studies of the paper's problem (tables points, scores,
// reference_runs), written by the one StudyDatabase writer.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/study_database.h"

namespace shockmap {

// The points table of the paper's problem, with its parameter columns.
extern const PointTable kCanonicalPoints;

// Parameters of one grid point as stored.
struct PointParameters {
  double r_k = 0.0;
  double r_ftrunc = 0.0;
  std::string scheme;
  std::optional<std::string> dt_rule;
  std::optional<double> dt_factor;
  std::optional<double> dt_asked_s;
  double window_s = 0.0;
  int n_elements_asked = 0;
  double mass_damping_per_s = 0.0;
};

// The values of `p` in kCanonicalPoints' parameter columns.
std::vector<SqlValue> ParameterValues(const PointParameters& p);

struct ShockColumns {
  double start_s = 0.0, impulse_n_s = 0.0, peak_n = 0.0, duration_s = 0.0;
  int rebounds = 0;
};

struct ScoreRow {
  std::int64_t reference_id = 0;
  std::optional<double> err, srf;
  int n_modes = 0, n_elements = 0, n_dofs = 0;
  double dt_requested_s = 0.0, dt_used_s = 0.0, dt_paper_s = 0.0, dt_sharp_s = 0.0;
  std::int64_t steps = 0;
  double wall_s = 0.0, cpu_s = 0.0, max_energy_ratio = 0.0;
  int n_shocks = 0;
  std::optional<ShockColumns> first_shock;
  std::string shocks_json = "[]";
  std::string srf_definition = "first_shock";  // What srf compares (paper eq. 9's readings).
};

struct ReferenceRow {
  std::int64_t reference_id = 0;
  std::string reference_key;
  double r_k = 0.0, r_fref = 0.0, r_fref_check = 0.0, window_s = 0.0, convergence = 0.0;
  int n_modes_free = 0, n_modes_contact = 0, n_transitions = 0;
  double wall_s = 0.0, output_dt_s = 0.0;
  std::vector<double> tip_m, force_n;
  std::string shocks_json = "[]";
};

// Replaces the point's score row by `score` (none when it was not computed), on the writer's
// connection inside StorePointOutcome's transaction.
void WriteScore(Connection& c, std::int64_t point_id, const std::optional<ScoreRow>& score);

std::optional<ReferenceRow> FindReference(StudyDatabase& db, const std::string& reference_key);
// Stores a new reference and returns its id.
std::int64_t StoreReference(StudyDatabase& db, const ReferenceRow& reference, std::int64_t run_id);

}  // namespace shockmap
