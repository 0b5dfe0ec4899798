#pragma once
// The writer's view of a study database. Exactly one StudyDatabase (one connection, one thread)
// writes; workers never touch SQLite. Every method that writes is one transaction, so a process
// killed at any moment leaves every point either as it was or completely stored.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "db/sqlite_handle.h"

namespace shockmap {

inline constexpr const char* kDefaultDatabasePath = "shockmap.db";

// Parameters of one grid point as stored; point_key identifies it within its study.
struct PointParameters {
  std::string point_key;
  std::string reference_key;
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

struct PointRow {
  std::int64_t point_id = 0;
  PointParameters parameters;
  std::string status;
};

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

struct Provenance {
  std::string code_version, compiler, build_type, host;
  std::int64_t pid = 0;
  int jobs = 1;
};

struct StatusCount {
  std::string study;
  std::string status;
  std::int64_t count = 0;
};

// Points of the canonical problem's studies, or of scene studies (db/scene_points.h).
enum class PointTable { kCanonical, kScene };

class StudyDatabase {
 public:
  // Opens or creates `path` in WAL mode and migrates it. Throws DbError (see MigrateToCurrent).
  explicit StudyDatabase(const std::string& path);

  // Creates the study or, when it exists, records its latest spec. Returns study_id.
  std::int64_t UpsertStudy(const std::string& name, const std::string& spec_json);
  std::optional<std::int64_t> FindStudy(const std::string& name);
  std::optional<std::string> StoredSpec(const std::string& name);
  // Inserts the points not yet in the study as 'pending'; returns how many were new.
  int AddPoints(std::int64_t study_id, const std::vector<PointParameters>& points);

  std::int64_t BeginRun(std::int64_t study_id, const Provenance& provenance);
  void EndRun(std::int64_t run_id);
  // Points left 'running' by a process of this host that no longer exists (or by a run that
  // ended) go back to 'pending'. Returns how many.
  int ReclaimStalePoints(std::int64_t study_id, const std::string& host,
                         PointTable table = PointTable::kCanonical);
  // 'pending' points (and 'failed' ones when retry_failed), in point_id order.
  std::vector<PointRow> PointsToCompute(std::int64_t study_id, bool retry_failed);
  void MarkRunning(const std::vector<std::int64_t>& point_ids, std::int64_t run_id,
                   PointTable table = PointTable::kCanonical);
  // Final status of a point, with its score when it was computed; one transaction.
  void StoreResult(std::int64_t point_id, std::int64_t run_id, const std::string& status,
                   const std::string& message, const std::optional<ScoreRow>& score);

  std::optional<ReferenceRow> FindReference(const std::string& reference_key);
  // Stores a new reference and returns its id.
  std::int64_t StoreReference(const ReferenceRow& reference, std::int64_t run_id);

  std::vector<StatusCount> CountByStatus(const std::optional<std::string>& study);

  Connection& Raw() { return db_; }

 private:
  Connection db_;
};

// The current UTC time as ISO 8601 with milliseconds.
std::string UtcNow();

}  // namespace shockmap
