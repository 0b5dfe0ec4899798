#pragma once
// The members and nominal runs of ensemble studies in the study database (schema version 6):
// written by the one StudyDatabase writer, one transaction per call; read by the sizing view.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/study_database.h"

namespace shockmap {

// The points table of ensemble studies: one row per member, its parameter columns the
// clearance state's name, the numerical setting as JSON and the member's index.
extern const PointTable kEnsembleMembers;

// One zone of one member: the largest normal force and, when the run streamed them, its
// impact statistics (in the vocabulary of code_aster's POST_DYNA_MODA_T; docs/ensembles.md).
struct EnsembleZoneRow {
  double max_force_n = 0.0;
  std::optional<std::int64_t> impacts;
  std::optional<double> impacts_per_s, rebounds_per_impact, mean_impact_duration_s,
      longest_impact_duration_s, contact_time_fraction, mean_force_n, mean_force_in_contact_n,
      rms_force_n, impulse_n_s, wear_work_rate_w;
};

// The optional statistics of EnsembleZoneRow in their column order (after max_force_n and
// impacts): what every reader and writer of a zone row walks.
inline constexpr std::optional<double> EnsembleZoneRow::*kZoneStatistics[] = {
    &EnsembleZoneRow::impacts_per_s,
    &EnsembleZoneRow::rebounds_per_impact,
    &EnsembleZoneRow::mean_impact_duration_s,
    &EnsembleZoneRow::longest_impact_duration_s,
    &EnsembleZoneRow::contact_time_fraction,
    &EnsembleZoneRow::mean_force_n,
    &EnsembleZoneRow::mean_force_in_contact_n,
    &EnsembleZoneRow::rms_force_n,
    &EnsembleZoneRow::impulse_n_s,
    &EnsembleZoneRow::wear_work_rate_w};

struct EnsembleMemberRow {
  std::int64_t reference_id = 0;
  std::string member_seed;  // 0x and 16 hexadecimal digits.
  int coordinates = 0;
  double dt_used_s = 0.0;
  std::int64_t steps = 0;
  double wall_s = 0.0, cpu_s = 0.0, max_energy_ratio = 0.0;
  std::vector<EnsembleZoneRow> zones;  // In the scene's zone order.
};

struct EnsembleReferenceRow {
  std::int64_t reference_id = 0;
  std::string reference_key, state, status, message;
  // [{"name", "beam_a", "beam_b", "height_m", "y_m", "z_m"}, ...] in the scene's zone order.
  std::string zones_json;
  std::vector<double> max_force_n;
  std::int64_t steps = 0;
  double wall_s = 0.0;
};

// Sets the member's score columns and replaces its zone rows (none when it was not computed),
// on the writer's connection inside StorePointOutcome's transaction.
void WriteScore(Connection& c, std::int64_t point_id,
                const std::optional<EnsembleMemberRow>& score);
std::optional<EnsembleReferenceRow> FindEnsembleReference(StudyDatabase& db,
                                                          const std::string& key);
// Stores a new nominal run and returns its id.
std::int64_t StoreEnsembleReference(StudyDatabase& db, const EnsembleReferenceRow& reference,
                                    std::int64_t run_id);

// What the sizing view reads of one study: every computed member (status 'ok'), with its
// zones, and the others without.
struct StoredMember {
  std::int64_t point_id = 0;
  std::string state, setting_json, status;
  int member = 0;
  double wall_s = 0.0, cpu_s = 0.0;
  std::vector<EnsembleZoneRow> zones;
  std::vector<std::int64_t> zone_indices;  // The stored index of each of zones (0, 1, ...).
};
struct StoredEnsemble {
  std::string database_path, study;  // Where it was read, to name it in a refusal.
  std::string spec_json;
  std::vector<EnsembleReferenceRow> references;  // One per state whose nominal was stored.
  std::vector<StoredMember> members;             // By point_id.
  std::vector<StoredMember> not_ok;              // Pending, running or not ok; no zones.
  std::int64_t pending = 0, failed = 0;          // Of not_ok: not computed yet, or not ok.
  // Computed members the study file, as last run, no longer has (views' CurrentMembers).
  std::int64_t superseded = 0;
};
// Throws DbError when the study does not exist or is not an ensemble study.
StoredEnsemble ReadEnsemble(Connection& c, const std::string& study);
// The names of the ensemble studies stored, in order of creation.
std::vector<std::string> EnsembleStudies(Connection& c);

}  // namespace shockmap
