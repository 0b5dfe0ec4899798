#include "db/scene_points.h"

namespace shockmap {

const PointTable kScenePoints{"scene_points", {"parameters_json"}};

namespace {

void WriteScore(Connection& c, std::int64_t point_id, const std::optional<SceneScoreRow>& score) {
  Statement update = c.Prepare(
      "UPDATE scene_points SET reference_id = ?, err = ?, srf = ?, coordinates = ?, zones = ?, "
      "dt_used_s = ?, dt_paper_s = ?, dt_sharp_s = ?, steps = ?, wall_s = ?, cpu_s = ?, "
      "max_energy_ratio = ?, largest_force_n = ?, largest_force_zone = ?, n_shocks = ?, "
      "first_shock_peak_n = ?, first_shock_impulse_n_s = ? WHERE point_id = ?");
  if (score) {
    const SceneScoreRow& r = *score;
    update.Bind(1, r.reference_id)
        .Bind(2, r.err)
        .Bind(3, r.srf)
        .Bind(4, r.coordinates)
        .Bind(5, r.zones)
        .Bind(6, r.dt_used_s)
        .Bind(7, r.dt_paper_s)
        .Bind(8, r.dt_sharp_s)
        .Bind(9, r.steps)
        .Bind(10, r.wall_s)
        .Bind(11, r.cpu_s)
        .Bind(12, r.max_energy_ratio)
        .Bind(13, r.largest_force_n)
        .Bind(14, r.largest_force_zone)
        .Bind(15, r.n_shocks)
        .Bind(16, r.first_shock_peak_n)
        .Bind(17, r.first_shock_impulse_n_s);
  } else {
    for (int i = 1; i <= 17; ++i) update.BindNull(i);
  }
  update.Bind(18, point_id).Run();
}

}  // namespace

void StoreSceneOutcome(StudyDatabase& db, std::int64_t point_id, std::int64_t run_id,
                       const PointOrigin& origin, const std::string& status,
                       const std::string& message, const std::optional<SceneScoreRow>& score) {
  StorePointOutcome(db, kScenePoints, point_id, run_id, origin, status, message,
                    [&](Connection& c) { WriteScore(c, point_id, score); });
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
