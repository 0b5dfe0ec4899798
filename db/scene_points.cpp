#include "db/scene_points.h"

#include <sqlite3.h>

namespace shockmap {

int AddScenePoints(StudyDatabase& db, std::int64_t study_id,
                   const std::vector<ScenePointRow>& points) {
  Connection& c = db.Raw();
  Transaction t(c);
  Statement insert = c.Prepare(
      "INSERT OR IGNORE INTO scene_points(study_id, point_key, reference_key, parameters_json, "
      "updated_utc) VALUES (?, ?, ?, ?, ?)");
  const std::string now = UtcNow();
  int added = 0;
  for (const auto& p : points) {
    insert.Bind(1, study_id)
        .Bind(2, p.point_key)
        .Bind(3, p.reference_key)
        .Bind(4, p.parameters_json)
        .Bind(5, now);
    insert.Run();
    added += sqlite3_changes(c.Raw());
  }
  t.Commit();
  return added;
}

std::vector<ScenePointRow> ScenePointsToCompute(StudyDatabase& db, std::int64_t study_id,
                                                bool retry_failed) {
  Statement s = db.Raw().Prepare(
      "SELECT point_id, point_key, reference_key, parameters_json FROM scene_points "
      "WHERE study_id = ? AND (status = 'pending' OR (? AND status = 'failed')) "
      "ORDER BY point_id");
  s.Bind(1, study_id).Bind(2, retry_failed ? 1 : 0);
  std::vector<ScenePointRow> rows;
  while (s.Step()) rows.push_back({s.GetInt(0), s.GetText(1), s.GetText(2), s.GetText(3)});
  return rows;
}

void StoreSceneResult(StudyDatabase& db, std::int64_t point_id, std::int64_t run_id,
                      const std::string& status, const std::string& message,
                      const std::optional<SceneScoreRow>& score) {
  Connection& c = db.Raw();
  Transaction t(c);
  Statement update = c.Prepare(
      "UPDATE scene_points SET status = ?, message = ?, run_id = ?, updated_utc = ?, "
      "reference_id = ?, err = ?, srf = ?, coordinates = ?, zones = ?, dt_used_s = ?, "
      "dt_paper_s = ?, dt_sharp_s = ?, steps = ?, wall_s = ?, cpu_s = ?, max_energy_ratio = ?, "
      "largest_force_n = ?, largest_force_zone = ?, n_shocks = ?, first_shock_peak_n = ?, "
      "first_shock_impulse_n_s = ? WHERE point_id = ?");
  update.Bind(1, status).Bind(2, message).Bind(3, run_id).Bind(4, UtcNow());
  if (score) {
    const SceneScoreRow& r = *score;
    update.Bind(5, r.reference_id)
        .Bind(6, r.err)
        .Bind(7, r.srf)
        .Bind(8, r.coordinates)
        .Bind(9, r.zones)
        .Bind(10, r.dt_used_s)
        .Bind(11, r.dt_paper_s)
        .Bind(12, r.dt_sharp_s)
        .Bind(13, r.steps)
        .Bind(14, r.wall_s)
        .Bind(15, r.cpu_s)
        .Bind(16, r.max_energy_ratio)
        .Bind(17, r.largest_force_n)
        .Bind(18, r.largest_force_zone)
        .Bind(19, r.n_shocks)
        .Bind(20, r.first_shock_peak_n)
        .Bind(21, r.first_shock_impulse_n_s);
  } else {
    for (int i = 5; i <= 21; ++i) update.BindNull(i);
  }
  update.Bind(22, point_id).Run();
  c.Prepare("UPDATE runs SET points_done = points_done + 1 WHERE run_id = ?").Bind(1, run_id).Run();
  t.Commit();
}

std::optional<SceneReferenceRow> FindSceneReference(StudyDatabase& db, const std::string& key) {
  Statement s = db.Raw().Prepare(
      "SELECT reference_id, parameters_json, status, message, output_dt_s, displacement_m, "
      "force_n, steps, wall_s, max_energy_ratio FROM scene_references WHERE reference_key = ?");
  s.Bind(1, key);
  if (!s.Step()) return std::nullopt;
  SceneReferenceRow r;
  r.reference_id = s.GetInt(0);
  r.reference_key = key;
  r.parameters_json = s.GetText(1);
  r.status = s.GetText(2);
  r.message = s.GetText(3);
  r.output_dt_s = s.GetDouble(4);
  r.displacement_m = s.GetBlob(5);
  r.force_n = s.GetBlob(6);
  r.steps = s.GetInt(7);
  r.wall_s = s.GetDouble(8);
  r.max_energy_ratio = s.GetDouble(9);
  return r;
}

std::int64_t StoreSceneReference(StudyDatabase& db, const SceneReferenceRow& r,
                                 std::int64_t run_id) {
  Connection& c = db.Raw();
  Transaction t(c);
  c.Prepare(
       "INSERT INTO scene_references(reference_key, parameters_json, status, message, "
       "output_dt_s, displacement_m, force_n, steps, wall_s, max_energy_ratio, run_id, "
       "created_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .Bind(1, r.reference_key)
      .Bind(2, r.parameters_json)
      .Bind(3, r.status)
      .Bind(4, r.message)
      .Bind(5, r.output_dt_s)
      .Bind(6, r.displacement_m)
      .Bind(7, r.force_n)
      .Bind(8, r.steps)
      .Bind(9, r.wall_s)
      .Bind(10, r.max_energy_ratio)
      .Bind(11, run_id)
      .Bind(12, UtcNow())
      .Run();
  const std::int64_t id = c.LastInsertRowId();
  t.Commit();
  return id;
}

}  // namespace shockmap
