#pragma once
// The members, their listed impacts and nominal runs of ensemble studies in the study database
// (schema version 6; the points table is kEnsembleMembers of db/point_tables.h): written by the one
// StudyDatabase writer, one transaction per call; read by the sizing view. The records and their
// columns are in records/ensemble_records.h.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/study_database.h"
#include "records/ensemble_records.h"

namespace shockmap {

// Sets the member's score columns and replaces its zone rows (none when it was not computed),
// on the writer's connection inside StorePointOutcomes' transaction.
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
// Every impact stored for the study's computed members (the zones their scene lists), with the
// member's point id, state, setting and index and the zone's name: one row per impact, by
// member, zone and time. Throws DbError when the file is not a current shockmap database.
Table EnsembleImpacts(const std::string& database_path, const std::string& study);
// The names of the ensemble studies stored, in order of creation.
std::vector<std::string> EnsembleStudies(Connection& c);

}  // namespace shockmap
